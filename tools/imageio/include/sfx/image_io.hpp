// Reading and writing the image files the tools, samples and tests exchange: PNG (libpng),
// OpenEXR (OpenEXR) and PFM (Portable Float Map, written here: it has no Debian library).
// In memory, row 0 is the top of the picture and channels are interleaved floats.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "sfx/status.hpp"

namespace sfx::io {

struct Image {
    uint32_t width = 0, height = 0, channels = 0;  // channels 1..4
    std::vector<float> pixels;                     // width * height * channels, row 0 = top

    Image() = default;
    Image(uint32_t w, uint32_t h, uint32_t c, float fill = 0.0f) : width(w), height(h), channels(c), pixels(size_t(w) * h * c, fill) {}
    float& at(uint32_t x, uint32_t y, uint32_t c = 0) { return pixels[(size_t(y) * width + x) * channels + c]; }
    float at(uint32_t x, uint32_t y, uint32_t c = 0) const { return pixels[(size_t(y) * width + x) * channels + c]; }
};

// The largest picture a reader accepts: sides up to 65536 and at most 2^25 pixels (8K UHD,
// 7680x4320, is 33,177,600). A header claiming more is a FileError before anything is allocated.
inline constexpr uint64_t kMaxImageSide = 65536;
inline constexpr uint64_t kMaxImagePixels = uint64_t(1) << 25;

// The file name's extension, lower-cased, with its dot (".pfm"); empty when it has none. The one
// rule readImage/writeImage and the tools use to pick a format.
std::string extensionOf(const std::string& path);

// By extension: .png (8/16-bit, gray/RGB/RGBA, values scaled to [0,1]), .pfm (1 or 3 channels),
// .exr (channels Y, or R G B [A], or any names sorted; half or float). FileError names the
// file and what is wrong with it.
Result<Image> readImage(const std::string& path);
// The same decoders on a file's bytes already in memory; `path` picks the format by its
// extension and names the file in messages. maxPixels lowers the pixel limit (the fuzz targets
// of tests/fuzz use a small one so they explore the parsers instead of filling large images).
Result<Image> decodeImage(const std::string& path, const void* data, size_t size, uint64_t maxPixels = kMaxImagePixels);

// PNG stores [0,1] as 8 bits (values clamped, NaN written as 0); 1-4 channels.
Status writePng(const std::string& path, const Image& image);
// PFM stores 1 or 3 channels (2 or 4 are widened to 3 / narrowed), rows bottom to top as the format says.
Status writePfm(const std::string& path, const Image& image);
// EXR stores float channels: Y; or R,G,B[,A]; two channels are written as R,G.
Status writeExr(const std::string& path, const Image& image);
// By extension: .png, .pfm, .exr.
Status writeImage(const std::string& path, const Image& image);

}  // namespace sfx::io
