// HAL conformance: textures: uploads sampled and read back, mip-to-mip rendering (and the feedback loop
// refused), depth formats in the HAL's byte layout.
// Runs on whatever backend and tier the run opened (tests/support/hal_fixture.hpp).
#include <algorithm>
#include <cmath>

#include "hal_fixture.hpp"

using namespace sfx;
using namespace sfx::test;

TEST_CASE("hal: writeTexture, sample, read back", "[hal]") {
    Cleanup c;
    std::vector<uint8_t> data(kW * kH * 4);
    for (size_t i = 0; i < data.size(); ++i) data[i] = uint8_t((i * 37 + 11) & 0xff);
    TextureHandle source = makeTexture(c, kW, kH, Format::RGBA8, kTextureSampled);
    SFX_REQUIRE_OK(dev().writeTexture(source, 0, data.data(), data.size()));
    // Straight back, without a pass.
    REQUIRE(readLevel<uint8_t>(source) == data);

    TextureHandle target = makeTexture(c, kW, kH, Format::RGBA8, kTextureSampled | kTextureRenderTarget);
    PipelineHandle copy = fullscreenPipeline(c, "copy", Format::RGBA8);
    fullscreenPass(target, copy, {.textures = {{gen::copy::uSource, source}}});
    REQUIRE(readLevel<uint8_t>(target) == data);

    if (renderable(Format::R32F)) {
        std::vector<float> values(kW * kH);
        for (size_t i = 0; i < values.size(); ++i) values[i] = float(i) * 0.5f - 3.25f;
        TextureHandle fsource = makeTexture(c, kW, kH, Format::R32F, kTextureSampled);
        SFX_REQUIRE_OK(dev().writeTexture(fsource, 0, values.data(), values.size() * sizeof(float)));
        REQUIRE(sampledThroughCopy(c, fsource, kW, kH) == values);
    }
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("hal: rendering into mip 1 while sampling mip 0 of the same texture", "[hal]") {
    Cleanup c;
    const uint32_t size = 16;
    TextureHandle pyramid = makeTexture(c, size, size, Format::RGBA8, kTextureSampled | kTextureRenderTarget, 3);
    std::vector<uint8_t> level0(size * size * 4);
    for (size_t i = 0; i < level0.size(); ++i) level0[i] = uint8_t((i * 131 + 7) % 251);
    SFX_REQUIRE_OK(dev().writeTexture(pyramid, 0, level0.data(), level0.size()));
    PipelineHandle down = fullscreenPipeline(c, "hal_test_downsample", Format::RGBA8);
    for (uint32_t mip = 1; mip < 3; ++mip)
        fullscreenPass(pyramid, down, {.textures = {{gen::hal_test_downsample::uSource, pyramid, mip - 1, 1}}}, mip);

    // CPU reference of the same maxima.
    std::vector<uint8_t> expected = level0;
    uint32_t w = size;
    for (uint32_t mip = 1; mip < 3; ++mip) {
        const uint32_t nw = w / 2;
        std::vector<uint8_t> next(nw * nw * 4);
        for (uint32_t y = 0; y < nw; ++y)
            for (uint32_t x = 0; x < nw; ++x)
                for (uint32_t ch = 0; ch < 4; ++ch) {
                    uint8_t m = 0;
                    for (uint32_t dy = 0; dy < 2; ++dy)
                        for (uint32_t dx = 0; dx < 2; ++dx) m = std::max(m, expected[((2 * y + dy) * w + 2 * x + dx) * 4 + ch]);
                    next[(y * nw + x) * 4 + ch] = m;
                }
        expected = next;
        w = nw;
        INFO("mip " << mip);
        REQUIRE(readLevel<uint8_t>(pyramid, mip) == expected);
    }
    // baseMip is the shader's lod 0: copying with baseMip 2 gives mip 2's texels.
    TextureHandle small = makeTexture(c, 4, 4, Format::RGBA8, kTextureSampled | kTextureRenderTarget);
    PipelineHandle copy = fullscreenPipeline(c, "copy", Format::RGBA8);
    fullscreenPass(small, copy, {.textures = {{gen::copy::uSource, pyramid, 2, 1}}});
    REQUIRE(readLevel<uint8_t>(small) == expected);
    REQUIRE(readLevel<uint8_t>(pyramid, 0) == level0);

    // Sampling the very mip the pass renders to is refused with a named error, not undefined.
    RenderPassDesc loopPass;
    loopPass.colors = {{pyramid, 1, LoadOp::Load, {}}};
    DrawDesc loopDraw;
    loopDraw.pipeline = down;
    loopDraw.bindings.textures = {{gen::hal_test_downsample::uSource, pyramid, 0, 2, {}}};
    const Status loop = dev().renderPass(loopPass, {&loopDraw, 1});
    CHECK(loop.code() == StatusCode::InvalidArgument);
    CHECK(loop.message().find("which the pass renders to") != std::string::npos);
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("hal: depth formats upload and read back in the HAL's byte layout", "[hal]") {
    Cleanup c;
    const uint32_t w = 5, h = 3;
    std::vector<float> f(w * h);
    for (size_t i = 0; i < f.size(); ++i) f[i] = float(i) / 16.0f;
    TextureHandle d32 = makeTexture(c, w, h, Format::D32F, kTextureSampled | kTextureRenderTarget);
    SFX_REQUIRE_OK(dev().writeTexture(d32, 0, f.data(), f.size() * 4));
    CHECK(readLevel<float>(d32) == f);
    std::vector<uint16_t> u16(w * h);
    for (size_t i = 0; i < u16.size(); ++i) u16[i] = uint16_t(i * 4000);
    TextureHandle d16 = makeTexture(c, w, h, Format::D16, kTextureSampled | kTextureRenderTarget);
    SFX_REQUIRE_OK(dev().writeTexture(d16, 0, u16.data(), u16.size() * 2));
    CHECK(readLevel<uint16_t>(d16) == u16);
    // D24S8: depth in the high 24 bits, stencil in the low 8, which the upload may drop and the
    // readback gives as 0 (the SDK never writes stencil). GL ES reads depth through a shader as a
    // float, so one step of the 24 bits is allowed.
    std::vector<uint32_t> u24(w * h);
    for (size_t i = 0; i < u24.size(); ++i) u24[i] = (uint32_t(i * 1000003u % 16777216u) << 8) | 0x5Au;
    // A device without D24S8 (SwiftShader can neither sample it nor render to it: the format
    // properties say so) refuses it by name; the SDK's effects never need it.
    if (!dev().caps().renderableFormat[size_t(Format::D24S8)]) {
        const Status refused = dev().createTexture({w, h, 1, Format::D24S8, kTextureRenderTarget}).status();
        CHECK(refused.code() == StatusCode::UnsupportedFormat);
        CHECK(refused.message().find("TextureDesc.format is D24S8, which this device cannot render to") != std::string::npos);
        SFX_REQUIRE_NO_VALIDATION_MESSAGES();
        return;
    }
    // Renderable but not sampled: the sampled usage is refused by name, the attachment still
    // uploads and reads back.
    const bool d24Sampled = dev().caps().sampledFormat[size_t(Format::D24S8)];
    if (!d24Sampled) {
        const Status refused = dev().createTexture({w, h, 1, Format::D24S8, kTextureSampled | kTextureRenderTarget}).status();
        CHECK(refused.code() == StatusCode::UnsupportedFormat);
        CHECK(refused.message().find("TextureDesc.format is D24S8, which this device cannot sample") != std::string::npos);
    }
    TextureHandle d24 = makeTexture(c, w, h, Format::D24S8, kTextureRenderTarget | (d24Sampled ? kTextureSampled : 0u));
    SFX_REQUIRE_OK(dev().writeTexture(d24, 0, u24.data(), u24.size() * 4));
    std::vector<uint32_t> back24 = readLevel<uint32_t>(d24);
    for (size_t i = 0; i < u24.size(); ++i) {
        INFO("D24S8 texel " << i << ": wrote 0x" << std::hex << u24[i] << ", read 0x" << back24[i]);
        CHECK(std::abs(int64_t(back24[i] >> 8) - int64_t(u24[i] >> 8)) <= 1);
        CHECK(((back24[i] & 0xFFu) == 0 || (back24[i] & 0xFFu) == 0x5Au));
    }
    // A cleared D24S8 attachment reads back as depth 1.0: 0xFFFFFF in the high bits.
    RenderPassDesc pass;
    pass.depth = {d24, LoadOp::Clear, 1.0f};
    SFX_REQUIRE_OK(dev().renderPass(pass, {}));
    for (uint32_t v : readLevel<uint32_t>(d24)) REQUIRE((v >> 8) == 0xFFFFFFu);
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}
