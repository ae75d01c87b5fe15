// HAL conformance: buffers: uniform contents reach the shader, writes are ordered with passes, partial writes
// read back.
// Runs on whatever backend and tier the run opened (tests/support/hal_fixture.hpp).
#include "hal_fixture.hpp"

using namespace sfx;
using namespace sfx::test;

TEST_CASE("hal: uniform buffer contents reach the shader, and writes are ordered with passes", "[hal]") {
    Cleanup c;
    TextureHandle first = makeTexture(c, kW, kH, Format::RGBA8, kTextureSampled | kTextureRenderTarget);
    TextureHandle second = makeTexture(c, kW, kH, Format::RGBA8, kTextureSampled | kTextureRenderTarget);
    PipelineHandle pipeline = fullscreenPipeline(c, "hal_test_uniform", Format::RGBA8);
    const float oldColor[4] = {0.2f, 0.4f, 0.6f, 1.0f};
    const float newColor[4] = {1.0f, 0.0f, 0.8f, 0.0f};
    BufferHandle params = makeBuffer(c, sizeof(oldColor), kBufferUniform, oldColor);
    const BindingSet bindings{.uniformBuffers = {{gen::hal_test_uniform::ColorParams, params}}};
    fullscreenPass(first, pipeline, bindings);
    SFX_REQUIRE_OK(dev().writeBuffer(params, 0, newColor, sizeof(newColor)));
    fullscreenPass(second, pipeline, bindings);
    SFX_REQUIRE_OK(dev().flush());

    std::vector<uint8_t> a = readLevel<uint8_t>(first), b = readLevel<uint8_t>(second);
    for (size_t i = 0; i < a.size(); i += 4) {
        REQUIRE(a[i] == 51);
        REQUIRE(a[i + 1] == 102);
        REQUIRE(a[i + 2] == 153);
        REQUIRE(a[i + 3] == 255);
        REQUIRE(b[i] == 255);
        REQUIRE(b[i + 1] == 0);
        REQUIRE(b[i + 2] == 204);
        REQUIRE(b[i + 3] == 0);
    }
    // A partial write at an offset, read back through readBuffer.
    const float green = 0.5f;
    SFX_REQUIRE_OK(dev().writeBuffer(params, 4, &green, sizeof(green)));
    float back[4];
    SFX_REQUIRE_OK(dev().readBuffer(params, 0, back, sizeof(back)));
    CHECK(back[0] == 1.0f);
    CHECK(back[1] == 0.5f);
    CHECK(back[2] == 0.8f);
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}
