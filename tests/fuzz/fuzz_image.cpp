// One image decoder (tools/imageio) on arbitrary bytes; SFX_FUZZ_IMAGE_NAME's extension picks
// which. A decoder must return an image or a FileError, never crash, hang or over-allocate,
// and an image it returns must be consistent with its own size.
#include <cmath>
#include <cstdlib>

#include "sfx/image_io.hpp"

// A small pixel limit: a header claiming millions of pixels is refused (that path is tested)
// instead of each such input zero-filling half a gigabyte, which would slow fuzzing to a crawl.
constexpr uint64_t kFuzzMaxPixels = uint64_t(1) << 16;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    sfx::Result<sfx::io::Image> image = sfx::io::decodeImage(SFX_FUZZ_IMAGE_NAME, data, size, kFuzzMaxPixels);
    if (!image) {
        if (image.status().code() != sfx::StatusCode::FileError) std::abort();
        return 0;
    }
    const sfx::io::Image& im = image.value();
    if (im.width == 0 || im.height == 0 || im.channels == 0 || im.channels > 4 || uint64_t(im.width) * im.height > kFuzzMaxPixels ||
        im.pixels.size() != size_t(im.width) * im.height * im.channels)
        std::abort();
    return 0;
}
