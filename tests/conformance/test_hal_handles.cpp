// HAL conformance: bad input on every call, and destroyed, null and foreign handles, are named errors.
// Runs on whatever backend and tier the run opened (tests/support/hal_fixture.hpp).
#include <memory>

#include "sfx/null_device.hpp"

#include "hal_fixture.hpp"

using namespace sfx;
using namespace sfx::test;

TEST_CASE("hal: bad input is a named error on every call", "[hal]") {
    Cleanup c;
    const DeviceCaps& caps = dev().caps();
    // Descriptions.
    CHECK(dev().createTexture({0, 4, 1, Format::RGBA8, kTextureSampled}).status().code() == StatusCode::InvalidArgument);
    CHECK(dev().createTexture({caps.limits.maxTextureSize + 1, 4, 1, Format::RGBA8, kTextureSampled}).status().code() == StatusCode::InvalidArgument);
    CHECK(dev().createTexture({4, 4, 4, Format::RGBA8, kTextureSampled}).status().code() == StatusCode::InvalidArgument);
    CHECK(dev().createTexture({4, 4, 1, Format(999), kTextureSampled}).status().code() == StatusCode::UnsupportedFormat);
    CHECK(dev().createTexture({4, 4, 1, Format::RGBA8, 0}).status().code() == StatusCode::InvalidArgument);
    CHECK(dev().createBuffer({0, kBufferUniform}).status().code() == StatusCode::InvalidArgument);
    CHECK(dev().createBuffer({caps.limits.maxBufferSize + 1, kBufferVertex}).status().code() == StatusCode::InvalidArgument);
    CHECK(dev().createSampler({Filter(7)}).status().code() == StatusCode::InvalidArgument);

    // Sizes and mips of reads and writes.
    TextureHandle tex = makeTexture(c, 8, 8, Format::RGBA8, kTextureSampled | kTextureRenderTarget, 2);
    std::vector<uint8_t> bytes(8 * 8 * 4);
    CHECK(dev().writeTexture(tex, 0, bytes.data(), bytes.size() - 1).code() == StatusCode::InvalidArgument);
    CHECK(dev().writeTexture(tex, 2, bytes.data(), 4).code() == StatusCode::InvalidArgument);
    CHECK(dev().readTexture(tex, 5, bytes.data(), bytes.size()).code() == StatusCode::InvalidArgument);
    CHECK(dev().writeTexture(tex, 0, nullptr, bytes.size()).code() == StatusCode::InvalidArgument);
    BufferHandle buf = makeBuffer(c, 16, kBufferUniform);
    CHECK(dev().writeBuffer(buf, 8, bytes.data(), 9).code() == StatusCode::InvalidArgument);
    CHECK(dev().writeBuffer(buf, 0, bytes.data(), 0).code() == StatusCode::InvalidArgument);
    CHECK(dev().readBuffer(buf, 16, bytes.data(), 1).code() == StatusCode::InvalidArgument);

    // Destroyed, null and foreign handles.
    Result<TextureHandle> gone = dev().createTexture({4, 4, 1, Format::RGBA8, kTextureSampled});
    REQUIRE(gone.isOk());
    SFX_REQUIRE_OK(dev().destroyTexture(gone.value()));
    CHECK(dev().destroyTexture(gone.value()).code() == StatusCode::StaleHandle);
    CHECK(dev().textureDesc(gone.value()).status().code() == StatusCode::StaleHandle);
    CHECK(dev().writeTexture(gone.value(), 0, bytes.data(), 64).code() == StatusCode::StaleHandle);
    CHECK(dev().destroyBuffer(BufferHandle{}).code() == StatusCode::InvalidHandle);
    std::unique_ptr<Device> other = null::createDevice();
    Result<TextureHandle> foreign = other->createTexture({4, 4, 1, Format::RGBA8, kTextureSampled | kTextureRenderTarget});
    REQUIRE(foreign.isOk());
    CHECK(dev().destroyTexture(foreign.value()).code() == StatusCode::ForeignHandle);
    Result<BufferHandle> foreignBuffer = other->createBuffer({16, kBufferUniform});
    REQUIRE(foreignBuffer.isOk());
    CHECK(dev().readBuffer(foreignBuffer.value(), 0, bytes.data(), 4).code() == StatusCode::ForeignHandle);

    // Render passes: no attachments, foreign attachment, bad mip, missing and unknown bindings.
    CHECK(dev().renderPass({}, {}).code() == StatusCode::InvalidArgument);
    RenderPassDesc foreignPass;
    foreignPass.colors = {{foreign.value()}};
    CHECK(dev().renderPass(foreignPass, {}).code() == StatusCode::ForeignHandle);
    RenderPassDesc badMip;
    badMip.colors = {{tex, 2}};
    CHECK(dev().renderPass(badMip, {}).code() == StatusCode::InvalidArgument);

    PipelineHandle copy = fullscreenPipeline(c, "copy", Format::RGBA8);
    TextureHandle source = makeTexture(c, 8, 8, Format::RGBA8, kTextureSampled);
    RenderPassDesc pass;
    pass.colors = {{tex, 0}};
    DrawDesc draw;
    draw.pipeline = copy;
    {
        Status s = dev().renderPass(pass, {&draw, 1});  // uSource missing
        CHECK(s.code() == StatusCode::InvalidArgument);
        CHECK(s.message().find("uSource") != std::string::npos);
    }
    draw.bindings.textures = {{gen::copy::uSource, source}, {gen::copy::uSource + 7, source}};
    CHECK(dev().renderPass(pass, {&draw, 1}).code() == StatusCode::InvalidArgument);  // binding the program lacks
    draw.bindings.textures = {{gen::copy::uSource, source, 0, 2}};
    CHECK(dev().renderPass(pass, {&draw, 1}).code() == StatusCode::InvalidArgument);  // mips past the texture
    draw.bindings.textures = {{gen::copy::uSource, gone.value()}};
    CHECK(dev().renderPass(pass, {&draw, 1}).code() == StatusCode::StaleHandle);
    draw.bindings.textures = {{gen::copy::uSource, source}};
    draw.pipeline = PipelineHandle{};
    CHECK(dev().renderPass(pass, {&draw, 1}).code() == StatusCode::InvalidHandle);

    // Timers and pipelines.
    CHECK(dev().readTimer(TimerHandle{}).status().code() == StatusCode::InvalidHandle);
    GraphicsPipelineDesc noProgram;
    noProgram.colorFormats = {Format::RGBA8};
    CHECK(dev().createGraphicsPipeline(noProgram).status().code() == StatusCode::InvalidHandle);

    // Corrupted shader code in every dialect: a ShaderError, not a crash.
    CompiledProgram broken = program("copy");
    for (StageCode& s : broken.stages) {
        for (size_t i = 5; i < s.spirv.size(); ++i) s.spirv[i] = 0xdeadbeefu;
        for (std::string& g : s.glsl)
            if (!g.empty()) g = g.substr(0, g.find('\n') + 1) + "void main() { this is not glsl; }\n";
    }
    CHECK(dev().createProgram(broken).status().code() == StatusCode::ShaderError);
    for (StageCode& s : broken.stages) s.spirv.assign(3, 0u);
    for (StageCode& s : broken.stages)
        for (std::string& g : s.glsl) g.clear();
    CHECK(dev().createProgram(broken).status().code() == StatusCode::ShaderError);
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}
