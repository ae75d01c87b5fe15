// Image files: round trips, row order, and malformed files as named errors (never a crash or
// an allocation of whatever a header claims).
#include <catch2/catch.hpp>

#include <cstdio>
#include <filesystem>

#include "sfx/image_io.hpp"

using namespace sfx;

namespace {
// The files this test writes go to the system's temporary directory, never into whatever
// directory the test binary is started from (a run from the repository root once left them in
// the checkout).
std::string scratch(const char* name) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "sfx_image_io_test";
    std::filesystem::create_directories(dir);
    return (dir / name).string();
}
}  // namespace

TEST_CASE("image files round-trip with row 0 at the top", "[io]") {
    io::Image rgb(5, 3, 3);
    for (size_t i = 0; i < rgb.pixels.size(); ++i) rgb.pixels[i] = float(i) * 0.01f;
    for (const char* ext : {".pfm", ".exr"}) {
        const std::string path = scratch((std::string("io_roundtrip") + ext).c_str());
        REQUIRE(io::writeImage(path, rgb).isOk());
        Result<io::Image> back = io::readImage(path);
        REQUIRE(back.isOk());
        CHECK(back->width == 5);
        CHECK(back->height == 3);
        CHECK(back->channels == 3);
        CHECK(back->pixels == rgb.pixels);
    }
    io::Image grey(4, 2, 1);
    grey.at(0, 0) = 1.0f;  // top-left white
    REQUIRE(io::writePng(scratch("io_roundtrip.png"), grey).isOk());
    Result<io::Image> png = io::readImage(scratch("io_roundtrip.png"));
    REQUIRE(png.isOk());
    CHECK(png->at(0, 0) == 1.0f);
    CHECK(png->at(3, 1) == 0.0f);
}

TEST_CASE("malformed image files are named errors", "[io][bad-input]") {
    // A PFM header claiming 60000 x 60000 RGB floats with a few bytes behind it.
    const std::string hugePath = scratch("io_huge.pfm");
    std::FILE* f = std::fopen(hugePath.c_str(), "wb");
    REQUIRE(f);
    std::fputs("PF\n60000 60000\n-1.0\n", f);
    std::fputs("abcd", f);
    std::fclose(f);
    Result<io::Image> huge = io::readImage(hugePath);
    REQUIRE_FALSE(huge.isOk());
    CHECK(huge.status().code() == StatusCode::FileError);
    CHECK(huge.status().message().find(hugePath) != std::string::npos);
    CHECK(huge.status().message().find("holds 4 bytes") != std::string::npos);

    const std::string garbagePath = scratch("io_garbage.exr");
    f = std::fopen(garbagePath.c_str(), "wb");
    REQUIRE(f);
    std::fputs("not an exr", f);
    std::fclose(f);
    CHECK(io::readImage(garbagePath).status().code() == StatusCode::FileError);
    CHECK(io::readImage(scratch("io_missing.pfm")).status().message().find("no such file") != std::string::npos);
    CHECK(io::readImage(scratch("io_roundtrip.bmp")).status().code() == StatusCode::FileError);
    CHECK(io::writePng(scratch("io_empty.png"), io::Image()).code() == StatusCode::FileError);
}
