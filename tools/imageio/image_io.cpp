#include "sfx/image_io.hpp"

#include <Iex.h>
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfVersion.h>
#include <ImfXdr.h>
#include <png.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <sstream>

namespace sfx::io {

std::string extensionOf(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

namespace {

Status fileError(const std::string& path, const std::string& what) { return {StatusCode::FileError, path + ": " + what}; }

Status checkImage(const Image& image, const std::string& path) {
    if (image.width == 0 || image.height == 0 || image.channels == 0 || image.channels > 4 ||
        image.pixels.size() != size_t(image.width) * image.height * image.channels)
        return fileError(path,
                         "image to write is malformed (" + std::to_string(image.width) + "x" + std::to_string(image.height) + "x" +
                             std::to_string(image.channels) + ", " + std::to_string(image.pixels.size()) + " values)");
    return Status::ok();
}

// Refuses a header's size before anything of that size is allocated: a small file may claim
// (or, compressed, really hold) more pixels than the tools and effects take.
Status checkDecodedSize(const std::string& path, const char* format, uint64_t width, uint64_t height, uint64_t maxPixels) {
    if (width <= kMaxImageSide && height <= kMaxImageSide && width * height <= maxPixels) return Status::ok();
    return fileError(path,
                     std::string(format) + " size " + std::to_string(width) + "x" + std::to_string(height) + " is over the limit (sides up to " +
                         std::to_string(kMaxImageSide) + ", up to " + std::to_string(maxPixels) + " pixels)");
}

// ---- PNG ------------------------------------------------------------------------------------
Result<Image> decodePng(const std::string& path, const uint8_t* data, size_t size, uint64_t maxPixels) {
    png_image png;
    std::memset(&png, 0, sizeof png);
    png.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_memory(&png, data, size)) return fileError(path, std::string("not a readable PNG: ") + png.message);
    if (Status fits = checkDecodedSize(path, "PNG", png.width, png.height, maxPixels); !fits) {
        png_image_free(&png);
        return fits;
    }
    const uint32_t channels = PNG_IMAGE_SAMPLE_CHANNELS(png.format);
    png.format = channels == 1 ? PNG_FORMAT_GRAY : channels == 2 ? PNG_FORMAT_GA : channels == 3 ? PNG_FORMAT_RGB : PNG_FORMAT_RGBA;
    std::vector<uint8_t> bytes(PNG_IMAGE_SIZE(png));
    if (!png_image_finish_read(&png, nullptr, bytes.data(), 0, nullptr)) {
        png_image_free(&png);
        return fileError(path, std::string("corrupt PNG: ") + png.message);
    }
    Image image(png.width, png.height, channels);
    for (size_t i = 0; i < bytes.size(); ++i) image.pixels[i] = bytes[i] / 255.0f;
    return image;
}

Status writePngFile(const std::string& path, const Image& image) {
    png_image png;
    std::memset(&png, 0, sizeof png);
    png.version = PNG_IMAGE_VERSION;
    png.width = image.width;
    png.height = image.height;
    png.format = image.channels == 1 ? PNG_FORMAT_GRAY : image.channels == 2 ? PNG_FORMAT_GA : image.channels == 3 ? PNG_FORMAT_RGB : PNG_FORMAT_RGBA;
    std::vector<uint8_t> bytes(image.pixels.size());
    for (size_t i = 0; i < bytes.size(); ++i) {
        float v = image.pixels[i];
        v = std::isnan(v) ? 0.0f : std::clamp(v, 0.0f, 1.0f);
        bytes[i] = uint8_t(std::lround(v * 255.0f));
    }
    if (!png_image_write_to_file(&png, path.c_str(), 0, bytes.data(), 0, nullptr))
        return fileError(path, std::string("cannot write PNG: ") + png.message);
    return Status::ok();
}

// ---- PFM ------------------------------------------------------------------------------------
// Header: "PF" (RGB) or "Pf" (grey), "width height", scale (negative: little endian); then
// float rows from the bottom of the picture to the top.
Result<Image> decodePfm(const std::string& path, const uint8_t* data, size_t size, uint64_t maxPixels) {
    std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
    std::string magic;
    long long w = 0, h = 0;
    double scale = 0;
    in >> magic >> w >> h >> scale;
    if (!in || (magic != "PF" && magic != "Pf")) return fileError(path, "not a PFM file (expected 'PF' or 'Pf', width, height and scale)");
    // Sides first, so the byte count below cannot overflow.
    if (w <= 0 || h <= 0 || w > static_cast<long long>(kMaxImageSide) || h > static_cast<long long>(kMaxImageSide))
        return fileError(path, "PFM size " + std::to_string(w) + "x" + std::to_string(h) + " is outside 1.." + std::to_string(kMaxImageSide));
    if (scale == 0 || !std::isfinite(scale)) return fileError(path, "PFM scale must be a non-zero number");
    in.get();  // the single whitespace character after the scale
    const uint32_t channels = magic == "PF" ? 3 : 1;
    // Check the data is really there before allocating what the header claims.
    const std::streamoff dataStart = in.tellg();
    const long long available = dataStart < 0 ? 0 : static_cast<long long>(size) - dataStart;
    const long long needed = w * h * channels * 4;
    if (dataStart < 0 || available < needed)
        return fileError(path,
                         "PFM header says " + std::to_string(w) + "x" + std::to_string(h) + "x" + std::to_string(channels) + " floats (" +
                             std::to_string(needed) + " bytes) but the file holds " + std::to_string(std::max<long long>(available, 0)) +
                             " bytes of data");
    // Uncompressed, so the data check above already bounds the allocation by the file's size;
    // the limit is the same as for the other formats.
    SFX_TRY(checkDecodedSize(path, "PFM", uint64_t(w), uint64_t(h), maxPixels));
    Image image(uint32_t(w), uint32_t(h), channels);
    const size_t rowValues = size_t(w) * channels;
    const bool littleEndian = scale < 0;
    for (uint32_t r = 0; r < image.height; ++r) {
        const uint8_t* row = data + dataStart + size_t(r) * rowValues * 4;
        float* dst = &image.pixels[size_t(image.height - 1 - r) * rowValues];
        for (size_t i = 0; i < rowValues; ++i) {
            uint8_t b[4];
            std::memcpy(b, &row[i * 4], 4);
            if (!littleEndian) std::swap(b[0], b[3]), std::swap(b[1], b[2]);
            std::memcpy(&dst[i], b, 4);
        }
    }
    return image;
}

Status writePfmFile(const std::string& path, const Image& image) {
    const uint32_t outChannels = image.channels == 1 ? 1 : 3;
    std::ofstream out(path, std::ios::binary);
    if (!out) return fileError(path, "cannot open for writing");
    out << (outChannels == 3 ? "PF" : "Pf") << "\n" << image.width << " " << image.height << "\n-1.0\n";
    std::vector<float> row(size_t(image.width) * outChannels);
    for (uint32_t r = 0; r < image.height; ++r) {
        const uint32_t y = image.height - 1 - r;
        for (uint32_t x = 0; x < image.width; ++x)
            for (uint32_t c = 0; c < outChannels; ++c) row[size_t(x) * outChannels + c] = c < image.channels ? image.at(x, y, c) : 0.0f;
        out.write(reinterpret_cast<const char*>(row.data()), std::streamsize(row.size() * 4));
    }
    if (!out) return fileError(path, "write failed");
    return Status::ok();
}

// ---- EXR ------------------------------------------------------------------------------------
// OpenEXR reads through this stream so a file in memory decodes like one on disk.
class MemoryIStream final : public Imf::IStream {
public:
    MemoryIStream(const std::string& name, const uint8_t* data, size_t size) : Imf::IStream(name.c_str()), data_(data), size_(size) {}
    // OpenEXR's contract: false when the end of the file was reached exactly, throw past it.
    bool read(char c[], int n) override {
        if (n < 0 || uint64_t(n) > size_ - position_) THROW(Iex::InputExc, "unexpected end of file");
        std::memcpy(c, data_ + position_, size_t(n));
        position_ += uint64_t(n);
        return position_ < size_;
    }
    uint64_t tellg() override { return position_; }
    void seekg(uint64_t position) override {
        if (position > size_) THROW(Iex::InputExc, "seek past the end of the file");
        position_ = position;
    }

private:
    const uint8_t* data_;
    uint64_t size_, position_ = 0;
};

// OpenEXR 3.1 allocates each header attribute at the size the file claims before reading it
// (a 300-byte file claiming a 1.6 GB attribute cost seconds): every attribute of the single
// header (name, type, int32 size, value; a 0 byte ends the list) must fit in the file.
// Whether a value of `type` is exactly `length` bytes as OpenEXR 3.1 reads it: fixed-size
// types by their size, a channel list up to its empty name, a preview by its pixel count.
// Types read by the size field (strings, vectors, opaque ones) always match.
bool exrValueMatchesSize(const std::string& type, const uint8_t* value, size_t length) {
    static const std::pair<const char*, size_t> kFixed[] = {{"box2i", 16},
                                                            {"box2f", 16},
                                                            {"chromaticities", 32},
                                                            {"compression", 1},
                                                            {"deepImageState", 1},
                                                            {"double", 8},
                                                            {"envmap", 1},
                                                            {"float", 4},
                                                            {"int", 4},
                                                            {"keycode", 28},
                                                            {"lineOrder", 1},
                                                            {"m33f", 36},
                                                            {"m33d", 72},
                                                            {"m44f", 64},
                                                            {"m44d", 128},
                                                            {"rational", 8},
                                                            {"tiledesc", 9},
                                                            {"timecode", 8},
                                                            {"v2i", 8},
                                                            {"v2f", 8},
                                                            {"v2d", 16},
                                                            {"v3i", 12},
                                                            {"v3f", 12},
                                                            {"v3d", 24}};
    for (const auto& [name, bytes] : kFixed)
        if (type == name) return length == bytes;
    if (type == "chlist") {  // (name NUL, 16 bytes of channel)*, then NUL
        size_t pos = 0;
        while (pos < length && value[pos] != 0) {
            const void* end = std::memchr(value + pos, 0, length - pos);
            if (!end) return false;
            pos = size_t(static_cast<const uint8_t*>(end) - value) + 1 + 16;
        }
        return pos + 1 == length;
    }
    if (type == "preview") {  // uint32 width, height, then RGBA8 pixels
        if (length < 8) return false;
        auto u32 = [&](size_t at) {
            return uint64_t(value[at]) | uint64_t(value[at + 1]) << 8 | uint64_t(value[at + 2]) << 16 | uint64_t(value[at + 3]) << 24;
        };
        return 8 + u32(0) * u32(4) * 4 == length;
    }
    return true;
}

// Names and types longer than OpenEXR's limit (31 bytes, 255 with the long-names flag) are
// refused: OpenEXR would stop reading them there, out of step with this walk.
Status checkExrAttributeSizes(const std::string& path, const uint8_t* data, size_t size, int version) {
    const size_t maxName = (version & Imf::LONG_NAMES_FLAG) ? 255 : 31;
    size_t pos = 8;  // magic number and version
    auto cString = [&](std::string* out) {
        const void* end = pos < size ? std::memchr(data + pos, 0, std::min(size - pos, maxName + 1)) : nullptr;
        if (!end) return false;
        out->assign(reinterpret_cast<const char*>(data + pos), static_cast<const uint8_t*>(end) - (data + pos));
        pos += out->size() + 1;
        return true;
    };
    while (pos < size && data[pos] != 0) {
        std::string name, type;
        if (!cString(&name) || !cString(&type) || size - pos < 4)
            return fileError(path, "not a readable EXR: a header attribute's name is over " + std::to_string(maxName) + " bytes or cut short");
        const uint8_t* le = data + pos;  // little endian
        const int32_t length = int32_t(uint32_t(le[0]) | uint32_t(le[1]) << 8 | uint32_t(le[2]) << 16 | uint32_t(le[3]) << 24);
        pos += 4;
        if (length < 0 || uint64_t(length) > size - pos)
            return fileError(path,
                             "not a readable EXR: attribute '" + name + "' claims " + std::to_string(length) + " bytes; " +
                                 std::to_string(size - pos) + " are left in the file");
        // OpenEXR reads the values of the types it knows by their content, not by the size
        // field: the two must agree, or its reading and this walk part ways.
        if (!exrValueMatchesSize(type, data + pos, size_t(length)))
            return fileError(
                path, "not a readable EXR: attribute '" + name + "' of type " + type + " does not fill its " + std::to_string(length) + " bytes");
        pos += size_t(length);
    }
    if (pos >= size) return fileError(path, "not a readable EXR: the header is cut short");
    return Status::ok();
}

Result<Image> decodeExr(const std::string& path, const uint8_t* data, size_t size, uint64_t maxPixels) {
    try {
        // OpenEXR refuses headers over this size itself, before it allocates its offset tables.
        Imf::Header::setMaxImageSize(int(kMaxImageSide), int(kMaxImageSide));
        Imf::Header::setMaxTileSize(int(kMaxImageSide), int(kMaxImageSide));
        MemoryIStream stream(path, data, size);
        // The header alone first: OpenEXR sizes its line and tile buffers from it while opening
        // the file, so the size limit must hold before then (a 300-byte file could claim a
        // 65536-wide image of 65536-pixel tiles and cost seconds of zero-filling).
        int magic = 0, version = 0;
        Imf::Xdr::read<Imf::StreamIO>(stream, magic);
        Imf::Xdr::read<Imf::StreamIO>(stream, version);
        if (magic != Imf::MAGIC) return fileError(path, "not a readable EXR: no OpenEXR magic number");
        if (Imf::isNonImage(version) || Imf::isMultiPart(version)) return fileError(path, "deep or multi-part EXR files are not supported");
        SFX_TRY(checkExrAttributeSizes(path, data, size, version));
        Imf::Header peek;
        peek.readFrom(stream, version);
        const Imath::Box2i dw = peek.dataWindow();
        // In 64 bits: a data window from INT_MIN to INT_MAX overflows int.
        const int64_t w = int64_t(dw.max.x) - dw.min.x + 1, h = int64_t(dw.max.y) - dw.min.y + 1;
        if (w <= 0 || h <= 0) return fileError(path, "EXR has an empty data window");
        SFX_TRY(checkDecodedSize(path, "EXR", uint64_t(w), uint64_t(h), maxPixels));
        if (peek.hasTileDescription())
            SFX_TRY(checkDecodedSize(path, "EXR tile", peek.tileDescription().xSize, peek.tileDescription().ySize, maxPixels));
        stream.seekg(0);
        Imf::InputFile file(stream);
        std::vector<std::string> names;
        for (auto it = file.header().channels().begin(); it != file.header().channels().end(); ++it) names.push_back(it.name());
        // Conventional orders first; otherwise the channels in the file's (alphabetical) order.
        std::vector<std::string> order;
        auto has = [&](const char* n) { return std::find(names.begin(), names.end(), n) != names.end(); };
        if (has("R") && has("G") && has("B"))
            order = has("A") ? std::vector<std::string>{"R", "G", "B", "A"} : std::vector<std::string>{"R", "G", "B"};
        else if (has("R") && has("G"))
            order = {"R", "G"};
        else if (has("Y"))
            order = {"Y"};
        else
            order = names;
        if (order.empty() || order.size() > 4) return fileError(path, "EXR has " + std::to_string(order.size()) + " channels; 1 to 4 are supported");
        Image image(uint32_t(w), uint32_t(h), uint32_t(order.size()));
        Imf::FrameBuffer fb;
        const size_t xStride = sizeof(float) * image.channels, yStride = xStride * size_t(w);
        for (size_t c = 0; c < order.size(); ++c)  // Slice::Make offsets by the data window's origin safely
            fb.insert(order[c].c_str(), Imf::Slice::Make(Imf::FLOAT, image.pixels.data() + c, dw, xStride, yStride));
        file.setFrameBuffer(fb);
        file.readPixels(dw.min.y, dw.max.y);
        return image;
    } catch (const std::exception& e) {
        return fileError(path, std::string("not a readable EXR: ") + e.what());
    }
}

Status writeExrFile(const std::string& path, const Image& image) {
    try {
        static const char* kNames[4][4] = {{"Y"}, {"R", "G"}, {"R", "G", "B"}, {"R", "G", "B", "A"}};
        Imf::Header header(int(image.width), int(image.height));
        for (uint32_t c = 0; c < image.channels; ++c) header.channels().insert(kNames[image.channels - 1][c], Imf::Channel(Imf::FLOAT));
        Imf::OutputFile file(path.c_str(), header);
        Imf::FrameBuffer fb;
        const size_t xStride = sizeof(float) * image.channels, yStride = xStride * image.width;
        for (uint32_t c = 0; c < image.channels; ++c)
            fb.insert(kNames[image.channels - 1][c], Imf::Slice(Imf::FLOAT, (char*)(image.pixels.data() + c), xStride, yStride));
        file.setFrameBuffer(fb);
        file.writePixels(int(image.height));
        return Status::ok();
    } catch (const std::exception& e) {
        return fileError(path, std::string("cannot write EXR: ") + e.what());
    }
}

}  // namespace

Result<Image> decodeImage(const std::string& path, const void* data, size_t size, uint64_t maxPixels) {
    const auto* bytes = static_cast<const uint8_t*>(data);
    const std::string ext = extensionOf(path);
    if (ext == ".png") return decodePng(path, bytes, size, maxPixels);
    if (ext == ".pfm") return decodePfm(path, bytes, size, maxPixels);
    if (ext == ".exr") return decodeExr(path, bytes, size, maxPixels);
    return fileError(path, "unknown image extension '" + ext + "'; allowed .png, .pfm, .exr");
}

Result<Image> readImage(const std::string& path) {
    if (!std::filesystem::exists(path)) return fileError(path, "no such file");
    const std::string ext = extensionOf(path);
    if (ext != ".png" && ext != ".pfm" && ext != ".exr") return fileError(path, "unknown image extension '" + ext + "'; allowed .png, .pfm, .exr");
    std::ifstream in(path, std::ios::binary);
    if (!in) return fileError(path, "cannot open for reading");
    const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) return fileError(path, "read failed");
    return decodeImage(path, bytes.data(), bytes.size());
}

Status writePng(const std::string& path, const Image& image) {
    SFX_TRY(checkImage(image, path));
    return writePngFile(path, image);
}
Status writePfm(const std::string& path, const Image& image) {
    SFX_TRY(checkImage(image, path));
    return writePfmFile(path, image);
}
Status writeExr(const std::string& path, const Image& image) {
    SFX_TRY(checkImage(image, path));
    return writeExrFile(path, image);
}

Status writeImage(const std::string& path, const Image& image) {
    const std::string ext = extensionOf(path);
    if (ext == ".png") return writePng(path, image);
    if (ext == ".pfm") return writePfm(path, image);
    if (ext == ".exr") return writeExr(path, image);
    return fileError(path, "unknown image extension '" + ext + "'; allowed .png, .pfm, .exr");
}

}  // namespace sfx::io
