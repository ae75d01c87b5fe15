// HAL conformance: render passes: full-screen patterns read back exactly on float, unorm and integer targets;
// clear values and load ops.
// Runs on whatever backend and tier the run opened (tests/support/hal_fixture.hpp).
#include <cmath>

#include "hal_fixture.hpp"
#include "sfx/half.hpp"

using namespace sfx;
using namespace sfx::test;

TEST_CASE("hal: full-screen pattern reads back exactly on float and unorm targets", "[hal]") {
    Cleanup c;
    for (Format f : {Format::R32F, Format::RGBA16F, Format::RGBA8}) {
        if (!renderable(f)) {
            WARN(toString(f) << " is not renderable on " << test::label() << "; skipped");
            continue;
        }
        INFO(toString(f));
        TextureHandle target = makeTexture(c, kW, kH, f, kTextureSampled | kTextureRenderTarget);
        PipelineHandle pipeline = fullscreenPipeline(c, "hal_test_pattern", f);
        const float s = f == Format::RGBA8 ? 1.0f / 255.0f : 1.0f;
        const float scale[4] = {s, s, s, 1.0f};
        BufferHandle params = makeBuffer(c, sizeof(scale), kBufferUniform, scale);
        fullscreenPass(target, pipeline, {.uniformBuffers = {{gen::hal_test_pattern::PatternParams, params}}});
        if (f == Format::R32F) {
            std::vector<float> texels = readLevel<float>(target);
            for (uint32_t y = 0; y < kH; ++y)
                for (uint32_t x = 0; x < kW; ++x) REQUIRE(texels[y * kW + x] == float(x + 16 * y));
        } else if (f == Format::RGBA16F) {
            std::vector<uint16_t> texels = readLevel<uint16_t>(target);
            for (uint32_t y = 0; y < kH; ++y)
                for (uint32_t x = 0; x < kW; ++x) {
                    const uint16_t* t = &texels[(y * kW + x) * 4];
                    REQUIRE(halfToFloat(t[0]) == float(x + 16 * y));
                    REQUIRE(halfToFloat(t[1]) == float(y));
                    REQUIRE(halfToFloat(t[2]) == float(x));
                    REQUIRE(halfToFloat(t[3]) == 1.0f);
                }
        } else {
            std::vector<uint8_t> texels = readLevel<uint8_t>(target);
            for (uint32_t y = 0; y < kH; ++y)
                for (uint32_t x = 0; x < kW; ++x) {
                    const uint8_t* t = &texels[(y * kW + x) * 4];
                    REQUIRE(t[0] == x + 16 * y);
                    REQUIRE(t[1] == y);
                    REQUIRE(t[2] == x);
                    REQUIRE(t[3] == 255);
                }
        }
    }
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("hal: integer target takes the integer pattern and integer clear values", "[hal]") {
    if (!renderable(Format::R32UI)) SFX_SKIP("R32UI is not renderable on " << test::label());
    Cleanup c;
    TextureHandle target = makeTexture(c, kW, kH, Format::R32UI, kTextureSampled | kTextureRenderTarget);
    PipelineHandle pipeline = fullscreenPipeline(c, "hal_test_pattern_uint", Format::R32UI);
    fullscreenPass(target, pipeline);
    std::vector<uint32_t> texels = readLevel<uint32_t>(target);
    for (uint32_t y = 0; y < kH; ++y)
        for (uint32_t x = 0; x < kW; ++x) REQUIRE(texels[y * kW + x] == x + 1000 * y);

    RenderPassDesc clearOnly;
    clearOnly.colors = {{target, 0, LoadOp::Clear, {77, 0, 0, 0}}};
    SFX_REQUIRE_OK(dev().renderPass(clearOnly, {}));
    for (uint32_t v : readLevel<uint32_t>(target)) REQUIRE(v == 77u);
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("hal: clear values and load ops", "[hal]") {
    Cleanup c;
    TextureHandle color = makeTexture(c, kW, kH, Format::RGBA8, kTextureSampled | kTextureRenderTarget);
    RenderPassDesc pass;
    pass.colors = {{color, 0, LoadOp::Clear, {1.0f, 0.0f, 0.2f, 1.0f}}};
    SFX_REQUIRE_OK(dev().renderPass(pass, {}));
    std::vector<uint8_t> texels = readLevel<uint8_t>(color);
    for (size_t i = 0; i < texels.size(); i += 4) {
        REQUIRE(texels[i] == 255);
        REQUIRE(texels[i + 1] == 0);
        REQUIRE(texels[i + 2] == 51);
        REQUIRE(texels[i + 3] == 255);
    }
    // Load keeps what is there.
    pass.colors[0].load = LoadOp::Load;
    pass.colors[0].clearColor = {0, 1, 0, 0};
    SFX_REQUIRE_OK(dev().renderPass(pass, {}));
    REQUIRE(readLevel<uint8_t>(color) == texels);

    if (renderable(Format::D32F)) {
        TextureHandle depth = makeTexture(c, kW, kH, Format::D32F, kTextureSampled | kTextureRenderTarget);
        RenderPassDesc depthOnly;
        depthOnly.depth = {depth, LoadOp::Clear, 0.375f};
        SFX_REQUIRE_OK(dev().renderPass(depthOnly, {}));
        for (float d : readLevel<float>(depth)) REQUIRE(d == 0.375f);
    }
    if (renderable(Format::D16)) {
        TextureHandle depth = makeTexture(c, kW, kH, Format::D16, kTextureSampled | kTextureRenderTarget);
        RenderPassDesc depthOnly;
        depthOnly.depth = {depth, LoadOp::Clear, 0.5f};
        SFX_REQUIRE_OK(dev().renderPass(depthOnly, {}));
        for (uint16_t d : readLevel<uint16_t>(depth)) REQUIRE(std::abs(int(d) - 32768) <= 1);
    }
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}
