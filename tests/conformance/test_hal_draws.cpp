// HAL conformance: draws: indexed meshes with depth test, culling winding, alpha blending.
// Runs on whatever backend and tier the run opened (tests/support/hal_fixture.hpp).
#include <cmath>

#include "hal_fixture.hpp"

using namespace sfx;
using namespace sfx::test;

TEST_CASE("hal: indexed mesh with depth test, nearer wins; depth reads back; rows start at NDC y=-1", "[hal]") {
    if (!renderable(Format::D32F)) SFX_SKIP("D32F is not renderable on " << test::label());
    Cleanup c;
    const uint32_t n = 8;
    TextureHandle color = makeTexture(c, n, n, Format::RGBA8, kTextureSampled | kTextureRenderTarget);
    TextureHandle depth = makeTexture(c, n, n, Format::D32F, kTextureSampled | kTextureRenderTarget);
    GraphicsPipelineDesc desc = meshPipelineDesc(Format::RGBA8, Format::D32F);
    desc.depth = {true, true, CompareOp::Less};
    PipelineHandle pipeline = makePipeline(c, desc, "hal_test_mesh");
    // Near red triangle over the lower-left half (rows near 0 are NDC y = -1), drawn first;
    // then a far green one over everything, which must lose where they overlap.
    const MeshVertex vertices[] = {
        {-1, -1, 0.25f, 1, 0, 0, 1}, {1, -1, 0.25f, 1, 0, 0, 1}, {-1, 1, 0.25f, 1, 0, 0, 1},
        {-1, -1, 0.75f, 0, 1, 0, 1}, {3, -1, 0.75f, 0, 1, 0, 1}, {-1, 3, 0.75f, 0, 1, 0, 1},
    };
    const uint32_t indices[] = {0, 1, 2, 3, 4, 5};
    BufferHandle vb = makeBuffer(c, sizeof(vertices), kBufferVertex, vertices);
    BufferHandle ib = makeBuffer(c, sizeof(indices), kBufferIndex, indices);
    RenderPassDesc pass;
    pass.colors = {{color, 0, LoadOp::Clear, {0, 0, 0, 0}}};
    pass.depth = {depth, LoadOp::Clear, 1.0f};
    DrawDesc draw;
    draw.pipeline = pipeline;
    draw.vertexBuffer = vb;
    draw.indexBuffer = ib;
    draw.count = 6;
    SFX_REQUIRE_OK(dev().renderPass(pass, {&draw, 1}));
    std::vector<uint8_t> rgba = readLevel<uint8_t>(color);
    std::vector<float> z = readLevel<float>(depth);
    for (uint32_t y = 0; y < n; ++y)
        for (uint32_t x = 0; x < n; ++x) {
            if (x + y == n - 1) continue;  // on the near triangle's edge
            const bool nearSide = x + y < n - 1;
            INFO("texel " << x << "," << y);
            const uint8_t* t = &rgba[(y * n + x) * 4];
            REQUIRE(t[0] == (nearSide ? 255 : 0));
            REQUIRE(t[1] == (nearSide ? 0 : 255));
            // Clip z lands in the depth buffer by the API's convention (caps.clipDepth).
            const float clipZ = nearSide ? 0.25f : 0.75f;
            const float stored = dev().caps().clipDepth == ClipDepthRange::ZeroToOne ? clipZ : clipZ * 0.5f + 0.5f;
            REQUIRE(z[y * n + x] == stored);
        }
    // The depth attachment, sampled right after the pass that wrote it.
    if (renderable(Format::R32F)) {
        REQUIRE(sampledThroughCopy(c, depth, n, n) == z);
    }
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("hal: culling treats counter-clockwise (rows upward) as front", "[hal]") {
    Cleanup c;
    const uint32_t n = 4;
    TextureHandle color = makeTexture(c, n, n, Format::RGBA8, kTextureSampled | kTextureRenderTarget);
    const MeshVertex ccw[] = {{-1, -1, 0.5f, 1, 1, 1, 1}, {3, -1, 0.5f, 1, 1, 1, 1}, {-1, 3, 0.5f, 1, 1, 1, 1}};
    const MeshVertex cw[] = {{-1, -1, 0.5f, 1, 1, 1, 1}, {-1, 3, 0.5f, 1, 1, 1, 1}, {3, -1, 0.5f, 1, 1, 1, 1}};
    BufferHandle ccwBuffer = makeBuffer(c, sizeof(ccw), kBufferVertex, ccw);
    BufferHandle cwBuffer = makeBuffer(c, sizeof(cw), kBufferVertex, cw);
    for (CullMode cull : {CullMode::None, CullMode::Back, CullMode::Front}) {
        GraphicsPipelineDesc desc = meshPipelineDesc(Format::RGBA8, Format::Undefined);
        desc.cull = cull;
        PipelineHandle pipeline = makePipeline(c, desc, "hal_test_mesh");
        for (bool counterClockwise : {true, false}) {
            RenderPassDesc pass;
            pass.colors = {{color, 0, LoadOp::Clear, {0, 0, 0, 0}}};
            DrawDesc draw;
            draw.pipeline = pipeline;
            draw.vertexBuffer = counterClockwise ? ccwBuffer : cwBuffer;
            SFX_REQUIRE_OK(dev().renderPass(pass, {&draw, 1}));
            const bool drawn = cull == CullMode::None || (cull == CullMode::Back) == counterClockwise;
            INFO("cull " << int(cull) << (counterClockwise ? " ccw" : " cw"));
            REQUIRE(readLevel<uint8_t>(color)[0] == (drawn ? 255 : 0));
        }
    }
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("hal: alpha blending over the cleared colour", "[hal]") {
    Cleanup c;
    TextureHandle color = makeTexture(c, kW, kH, Format::RGBA8, kTextureSampled | kTextureRenderTarget);
    GraphicsPipelineDesc desc;
    desc.colorFormats = {Format::RGBA8};
    desc.blend = {true, BlendFactor::SrcAlpha, BlendFactor::OneMinusSrcAlpha};
    PipelineHandle pipeline = makePipeline(c, desc, "hal_test_uniform");
    const float src[4] = {1.0f, 0.0f, 0.0f, 0.5f};
    BufferHandle params = makeBuffer(c, sizeof(src), kBufferUniform, src);
    RenderPassDesc pass;
    pass.colors = {{color, 0, LoadOp::Clear, {0, 0, 1, 1}}};
    DrawDesc draw;
    draw.pipeline = pipeline;
    draw.bindings.uniformBuffers = {{gen::hal_test_uniform::ColorParams, params}};
    SFX_REQUIRE_OK(dev().renderPass(pass, {&draw, 1}));
    // rgb = src * 0.5 + dst * 0.5; alpha = 0.5 * 0.5 + 1 * 0.5.
    std::vector<uint8_t> t = readLevel<uint8_t>(color);
    for (size_t i = 0; i < t.size(); i += 4) {
        REQUIRE(std::abs(int(t[i]) - 128) <= 1);
        REQUIRE(t[i + 1] == 0);
        REQUIRE(std::abs(int(t[i + 2]) - 128) <= 1);
        REQUIRE(std::abs(int(t[i + 3]) - 191) <= 1);
    }
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}
