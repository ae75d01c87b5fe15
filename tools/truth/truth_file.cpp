#include "sfx/truth_file.hpp"

#include "sfx/image_io.hpp"

namespace sfx::truth {

Status writeImageFile(const std::string& path, const Image& t) {
    io::Image im(t.width, t.height, 2);
    for (size_t i = 0; i < t.visibility.size(); ++i) {
        im.pixels[2 * i] = t.visibility[i];
        im.pixels[2 * i + 1] = t.surface[i] ? 1.0f : 0.0f;
    }
    return io::writeImage(path, im);
}

Result<Image> readImageFile(const std::string& path) {
    Result<io::Image> im = io::readImage(path);
    if (!im) return im.status();
    if (im->channels < 2)
        return Status{StatusCode::FileError,
                      path + ": " + std::to_string(im->channels) + " channel(s); a truth image has visibility and a surface mask"};
    Image t;
    t.width = im->width;
    t.height = im->height;
    const size_t n = size_t(t.width) * t.height;
    t.visibility.resize(n);
    t.surface.resize(n);
    for (size_t i = 0; i < n; ++i) {
        t.visibility[i] = im->pixels[i * im->channels];
        t.surface[i] = im->pixels[i * im->channels + 1] > 0.5f ? 1 : 0;
    }
    return t;
}

}  // namespace sfx::truth
