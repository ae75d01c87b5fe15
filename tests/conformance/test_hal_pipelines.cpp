// HAL conformance: pipelines and draws that would go wrong are named errors: vertex layouts, draw counts past
// their buffers, unknown pipeline state, bad texture bindings.
// Runs on whatever backend and tier the run opened (tests/support/hal_fixture.hpp).
#include "hal_fixture.hpp"

using namespace sfx;
using namespace sfx::test;

TEST_CASE("hal: vertex layouts and draws that would read past their buffers are named errors", "[hal]") {
    Cleanup c;
    const ProgramHandle mesh = makeProgram(c, program("hal_test_mesh"));
    auto tryPipeline = [&](GraphicsPipelineDesc d) {
        d.program = mesh;
        Result<PipelineHandle> p = dev().createGraphicsPipeline(d);
        if (p.isOk()) (void)dev().destroyPipeline(p.value());
        return p.status();
    };
    {
        // 0xFFFFFFFC + 16 wraps to 12 in 32 bits; the check must not.
        GraphicsPipelineDesc d = meshPipelineDesc(Format::RGBA8, Format::Undefined);
        d.vertexLayout.attributes[1].offset = 0xFFFFFFFCu;
        checkNamed(tryPipeline(d), StatusCode::InvalidArgument, "vertexLayout.attributes[1].offset");
    }
    {
        GraphicsPipelineDesc d = meshPipelineDesc(Format::RGBA8, Format::Undefined);
        d.vertexLayout.attributes[1].offset = 13;  // 13 + 16 > 28
        checkNamed(tryPipeline(d), StatusCode::InvalidArgument, "vertexLayout.attributes[1].offset");
    }
    {
        GraphicsPipelineDesc d = meshPipelineDesc(Format::RGBA8, Format::Undefined);
        d.vertexLayout.attributes[0].location = 16;
        checkNamed(tryPipeline(d), StatusCode::InvalidArgument, "vertexLayout.attributes[0].location");
        d.vertexLayout.attributes[0].location = 0xFFFFFFFFu;
        checkNamed(tryPipeline(d), StatusCode::InvalidArgument, "vertexLayout.attributes[0].location");
        d.vertexLayout.attributes[0].location = 1;  // twice
        checkNamed(tryPipeline(d), StatusCode::InvalidArgument, "vertexLayout.attributes[1].location");
    }
    {
        GraphicsPipelineDesc d = meshPipelineDesc(Format::RGBA8, Format::Undefined);
        d.vertexLayout.attributes[0].format = VertexFormat(7);
        checkNamed(tryPipeline(d), StatusCode::InvalidArgument, "vertexLayout.attributes[0].format");
    }

    // Three vertices exactly fill the buffer; a fourth would be read past its end.
    TextureHandle color = makeTexture(c, 8, 8, Format::RGBA8, kTextureSampled | kTextureRenderTarget);
    PipelineHandle pipeline = makePipeline(c, meshPipelineDesc(Format::RGBA8, Format::Undefined), "hal_test_mesh");
    const MeshVertex vertices[] = {{-1, -1, 0.5f, 1, 0, 0, 1}, {3, -1, 0.5f, 1, 0, 0, 1}, {-1, 3, 0.5f, 1, 0, 0, 1}};
    BufferHandle vb = makeBuffer(c, sizeof(vertices), kBufferVertex, vertices);
    const uint32_t indices[] = {0, 1, 2};
    BufferHandle ib = makeBuffer(c, sizeof(indices), kBufferIndex, indices);
    RenderPassDesc pass;
    pass.colors = {{color, 0, LoadOp::Clear, {0, 0, 0, 0}}};
    DrawDesc draw;
    draw.pipeline = pipeline;
    draw.vertexBuffer = vb;
    draw.count = 3;
    SFX_REQUIRE_OK(dev().renderPass(pass, {&draw, 1}));
    draw.count = 4;
    checkNamed(dev().renderPass(pass, {&draw, 1}), StatusCode::InvalidArgument, "DrawDesc.count");
    draw.count = 0xFFFFFFFFu;  // (count - 1) * stride overflows 32 bits
    checkNamed(dev().renderPass(pass, {&draw, 1}), StatusCode::InvalidArgument, "DrawDesc.count");
    draw.count = 3;
    draw.instanceCount = 0;
    checkNamed(dev().renderPass(pass, {&draw, 1}), StatusCode::InvalidArgument, "DrawDesc.instanceCount");
    draw.instanceCount = 1;
    draw.vertexBuffer = ib;  // an index buffer as vertices
    checkNamed(dev().renderPass(pass, {&draw, 1}), StatusCode::InvalidArgument, "DrawDesc.vertexBuffer");
    draw.vertexBuffer = vb;
    draw.indexBuffer = ib;
    SFX_REQUIRE_OK(dev().renderPass(pass, {&draw, 1}));
    draw.count = 4;  // 16 bytes of indices in a 12-byte buffer
    checkNamed(dev().renderPass(pass, {&draw, 1}), StatusCode::InvalidArgument, "DrawDesc.count");
    // The refused draws left the target as the last good pass made it.
    std::vector<uint8_t> rgba = readLevel<uint8_t>(color);
    for (size_t i = 0; i < rgba.size(); i += 4) REQUIRE(rgba[i] == 255);
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("hal: unknown pipeline state and bad texture bindings are refused alike on every backend", "[hal]") {
    Cleanup c;
    const ProgramHandle pattern = makeProgram(c, program("hal_test_pattern"));
    auto tryPipeline = [&](GraphicsPipelineDesc d) {
        d.program = pattern;
        if (d.colorFormats.empty()) d.colorFormats = {Format::RGBA8};
        Result<PipelineHandle> p = dev().createGraphicsPipeline(d);
        if (p.isOk()) (void)dev().destroyPipeline(p.value());
        return p.status();
    };
    {
        GraphicsPipelineDesc d;
        d.depth.compare = CompareOp(99);
        checkNamed(tryPipeline(d), StatusCode::InvalidArgument, "GraphicsPipelineDesc.depth.compare");
    }
    {
        GraphicsPipelineDesc d;
        d.cull = CullMode(3);
        checkNamed(tryPipeline(d), StatusCode::InvalidArgument, "GraphicsPipelineDesc.cull");
    }
    {
        GraphicsPipelineDesc d;
        d.blend = {true, BlendFactor(6), BlendFactor::Zero};
        checkNamed(tryPipeline(d), StatusCode::InvalidArgument, "GraphicsPipelineDesc.blend.src");
        d.blend = {true, BlendFactor::One, BlendFactor(0x80000000u)};
        checkNamed(tryPipeline(d), StatusCode::InvalidArgument, "GraphicsPipelineDesc.blend.dst");
    }
    {
        GraphicsPipelineDesc d;
        d.colorFormats = {Format::R32UI};
        d.blend = {true, BlendFactor::SrcAlpha, BlendFactor::OneMinusSrcAlpha};
        checkNamed(tryPipeline(d), StatusCode::InvalidArgument, "GraphicsPipelineDesc.blend.enable");
    }

    // baseMip + mipCount wraps to 0 in 32 bits; the range is still refused.
    PipelineHandle copy = fullscreenPipeline(c, "copy", Format::RGBA8);
    TextureHandle target = makeTexture(c, 8, 8, Format::RGBA8, kTextureSampled | kTextureRenderTarget);
    TextureHandle source = makeTexture(c, 8, 8, Format::RGBA8, kTextureSampled, 2);
    TextureHandle notSampled = makeTexture(c, 8, 8, Format::RGBA8, kTextureRenderTarget);
    RenderPassDesc pass;
    pass.colors = {{target, 0}};
    DrawDesc draw;
    draw.pipeline = copy;
    for (auto [base, count] : {std::pair<uint32_t, uint32_t>{1, 0xFFFFFFFFu}, {0xFFFFFFFFu, 1}, {2, 1}, {0, 0}, {1, 2}}) {
        INFO("mips " << base << "+" << count);
        draw.bindings.textures = {{gen::copy::uSource, source, base, count}};
        checkNamed(dev().renderPass(pass, {&draw, 1}), StatusCode::InvalidArgument, "baseMip+mipCount");
    }
    draw.bindings.textures = {{gen::copy::uSource, notSampled}};
    checkNamed(dev().renderPass(pass, {&draw, 1}), StatusCode::InvalidArgument, "with usage sampled");
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}
