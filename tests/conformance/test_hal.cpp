// HAL conformance: the contract of sfx::Device, checked with exact readbacks on whatever backend
// and tier the run opened. Backend-agnostic: only the HAL and the embedded test programs.
#include <catch2/catch.hpp>

#include <algorithm>

#include <cmath>
#include <cstring>
#include <functional>
#include <vector>

#include "sfx/half.hpp"
#include "sfx/null_device.hpp"
#include "sfx_shaders.hpp"
#include "test_device.hpp"

using namespace sfx;

namespace {

Device& dev() { return test::device(); }

// Destroys what a test made, in reverse order, however the test ends.
struct Cleanup {
    std::vector<std::function<void()>> steps;
    ~Cleanup() {
        for (auto it = steps.rbegin(); it != steps.rend(); ++it) (*it)();
    }
};

const CompiledProgram& program(const char* name, Tier tier = test::tier()) {
    Result<const CompiledProgram*> p = shaders::find(name, tier);
    INFO(name << ": " << p.status().toString());
    REQUIRE(p.isOk());
    return *p.value();
}

TextureHandle makeTexture(Cleanup& c, uint32_t w, uint32_t h, Format f, uint32_t usage, uint32_t mips = 1) {
    Result<TextureHandle> t = dev().createTexture({w, h, mips, f, usage, "hal test texture"});
    INFO("createTexture " << toString(f) << ": " << t.status().toString());
    REQUIRE(t.isOk());
    TextureHandle handle = t.value();
    c.steps.push_back([handle] { (void)dev().destroyTexture(handle); });
    return handle;
}

BufferHandle makeBuffer(Cleanup& c, uint64_t size, uint32_t usage, const void* data = nullptr) {
    Result<BufferHandle> b = dev().createBuffer({size, usage, "hal test buffer"});
    INFO("createBuffer: " << b.status().toString());
    REQUIRE(b.isOk());
    BufferHandle handle = b.value();
    c.steps.push_back([handle] { (void)dev().destroyBuffer(handle); });
    if (data) SFX_REQUIRE_OK(dev().writeBuffer(handle, 0, data, size));
    return handle;
}

ProgramHandle makeProgram(Cleanup& c, const CompiledProgram& p) {
    Result<ProgramHandle> h = dev().createProgram(p);
    INFO("createProgram " << p.name << ": " << h.status().toString());
    REQUIRE(h.isOk());
    ProgramHandle handle = h.value();
    c.steps.push_back([handle] { (void)dev().destroyProgram(handle); });
    return handle;
}

PipelineHandle makePipeline(Cleanup& c, GraphicsPipelineDesc desc, const char* programName) {
    desc.program = makeProgram(c, program(programName));
    Result<PipelineHandle> p = dev().createGraphicsPipeline(desc);
    INFO("createGraphicsPipeline " << programName << ": " << p.status().toString());
    REQUIRE(p.isOk());
    PipelineHandle handle = p.value();
    c.steps.push_back([handle] { (void)dev().destroyPipeline(handle); });
    return handle;
}

PipelineHandle fullscreenPipeline(Cleanup& c, const char* programName, Format color) {
    GraphicsPipelineDesc d;
    d.colorFormats = {color};
    return makePipeline(c, d, programName);
}

bool renderable(Format f) { return dev().caps().renderableFormat[size_t(f)]; }


template <class T>
std::vector<T> readLevel(TextureHandle t, uint32_t mip = 0) {
    TextureDesc d = dev().textureDesc(t).value();
    std::vector<T> out(mipLevelBytes(d, mip) / sizeof(T));
    SFX_REQUIRE_OK(dev().readTexture(t, mip, out.data(), out.size() * sizeof(T)));
    return out;
}

// Full-screen pass of `pipeline` into `target` with the given bindings.
void fullscreenPass(TextureHandle target, PipelineHandle pipeline, BindingSet bindings = {}, uint32_t mip = 0) {
    RenderPassDesc pass;
    pass.colors = {{target, mip, LoadOp::Clear, {0, 0, 0, 0}}};
    DrawDesc draw;
    draw.pipeline = pipeline;
    draw.bindings = std::move(bindings);
    SFX_REQUIRE_OK(dev().renderPass(pass, {&draw, 1}));
}

struct MeshVertex {
    float x, y, z;
    float r, g, b, a;
};

GraphicsPipelineDesc meshPipelineDesc(Format color, Format depth) {
    GraphicsPipelineDesc d;
    d.colorFormats = {color};
    d.depthFormat = depth;
    d.vertexLayout.stride = sizeof(MeshVertex);
    d.vertexLayout.attributes = {{0, VertexFormat::Float3, 0}, {1, VertexFormat::Float4, 12}};
    return d;
}

constexpr uint32_t kW = 16, kH = 8;  // not square, so a transposed readback shows

}  // namespace

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
    if (!renderable(Format::R32UI)) {
        WARN("R32UI is not renderable on " << test::label() << "; skipped");
        return;
    }
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
        TextureHandle ftarget = makeTexture(c, kW, kH, Format::R32F, kTextureSampled | kTextureRenderTarget);
        PipelineHandle fcopy = fullscreenPipeline(c, "copy", Format::R32F);
        fullscreenPass(ftarget, fcopy, {.textures = {{gen::copy::uSource, fsource}}});
        REQUIRE(readLevel<float>(ftarget) == values);
    }
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

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

TEST_CASE("hal: indexed mesh with depth test, nearer wins; depth reads back; rows start at NDC y=-1", "[hal]") {
    if (!renderable(Format::D32F)) {
        WARN("D32F is not renderable on " << test::label() << "; skipped");
        return;
    }
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
        TextureHandle linear = makeTexture(c, n, n, Format::R32F, kTextureSampled | kTextureRenderTarget);
        PipelineHandle copy = fullscreenPipeline(c, "copy", Format::R32F);
        fullscreenPass(linear, copy, {.textures = {{gen::copy::uSource, depth}}});
        REQUIRE(readLevel<float>(linear) == z);
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

TEST_CASE("hal: compute, storage buffers and atomics on the high tier; refused under the ceiling", "[hal]") {
    const CompiledProgram& counting = program("hal_atomic_count", Tier::High);
    if (test::tier() == Tier::Current) {
        CHECK_FALSE(dev().caps().computeShaders);
        CHECK(dev().caps().limits.maxStorageBufferSize == 0);
        CHECK(dev().createProgram(counting).status().code() == StatusCode::UnsupportedFeature);
        CHECK(dev().createBuffer({64, kBufferStorage}).status().code() == StatusCode::UnsupportedFeature);
        DispatchDesc d;
        CHECK(dev().dispatch(d).code() == StatusCode::UnsupportedFeature);
        SFX_REQUIRE_NO_VALIDATION_MESSAGES();
        return;
    }
    REQUIRE(dev().caps().computeShaders);
    REQUIRE(dev().caps().atomics);
    Cleanup c;
    const uint32_t invocations = 256;  // 4 groups of 64
    std::vector<uint32_t> initial(2 + invocations, 0);
    BufferHandle counters = makeBuffer(c, initial.size() * 4, kBufferStorage, initial.data());
    ProgramHandle prog = makeProgram(c, counting);
    Result<PipelineHandle> pipeline = dev().createComputePipeline({prog, "hal_atomic_count"});
    REQUIRE(pipeline.isOk());
    c.steps.push_back([p = pipeline.value()] { (void)dev().destroyPipeline(p); });
    DispatchDesc d;
    d.pipeline = pipeline.value();
    d.groupsX = invocations / 64;
    d.bindings.storageBuffers = {{gen::hal_atomic_count::Counters, counters}};
    SFX_REQUIRE_OK(dev().dispatch(d));
    SFX_REQUIRE_OK(dev().dispatch(d));  // twice: the second sees the first's atomics
    std::vector<uint32_t> out(initial.size());
    SFX_REQUIRE_OK(dev().readBuffer(counters, 0, out.data(), out.size() * 4));
    CHECK(out[0] == 2 * invocations);
    CHECK(out[1] == 2 * (invocations * (invocations - 1) / 2));
    for (uint32_t i = 0; i < invocations; ++i) REQUIRE(out[2 + i] == 3 * i);
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("hal: compute writes a storage image mip, then it is sampled (high tier)", "[hal]") {
    if (test::tier() == Tier::Current) {
        CHECK(dev().createTexture({8, 8, 1, Format::R32F, kTextureStorage}).status().code() ==
              StatusCode::UnsupportedFeature);
        SFX_REQUIRE_NO_VALIDATION_MESSAGES();
        return;
    }
    Cleanup c;
    TextureHandle image = makeTexture(c, 32, 16, Format::R32F, kTextureSampled | kTextureStorage, 2);
    ProgramHandle prog = makeProgram(c, program("hal_test_storage_image"));
    Result<PipelineHandle> pipeline = dev().createComputePipeline({prog, "hal_test_storage_image"});
    REQUIRE(pipeline.isOk());
    c.steps.push_back([p = pipeline.value()] { (void)dev().destroyPipeline(p); });
    DispatchDesc d;
    d.pipeline = pipeline.value();
    d.groupsX = 2;  // mip 1 is 16x8
    d.groupsY = 1;
    d.bindings.storageImages = {{gen::hal_test_storage_image::uImage, image, 1}};
    SFX_REQUIRE_OK(dev().dispatch(d));
    std::vector<float> texels = readLevel<float>(image, 1);
    for (uint32_t y = 0; y < 8; ++y)
        for (uint32_t x = 0; x < 16; ++x) REQUIRE(texels[y * 16 + x] == float(x + 16 * y));
    if (renderable(Format::R32F)) {
        TextureHandle target = makeTexture(c, 16, 8, Format::R32F, kTextureSampled | kTextureRenderTarget);
        PipelineHandle copy = fullscreenPipeline(c, "copy", Format::R32F);
        fullscreenPass(target, copy, {.textures = {{gen::copy::uSource, image, 1, 1}}});
        REQUIRE(readLevel<float>(target) == texels);
    }
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
    TextureHandle d24 = makeTexture(c, w, h, Format::D24S8, kTextureSampled | kTextureRenderTarget);
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

TEST_CASE("hal: timers measure a flushed pass", "[hal]") {
    Cleanup c;
    TextureHandle target = makeTexture(c, 256, 256, Format::RGBA8, kTextureSampled | kTextureRenderTarget);
    PipelineHandle pipeline = fullscreenPipeline(c, "hal_test_pattern", Format::RGBA8);
    const float scale[4] = {0.001f, 0.001f, 0.001f, 1.0f};
    BufferHandle params = makeBuffer(c, sizeof(scale), kBufferUniform, scale);
    Result<TimerHandle> timer = dev().createTimer();
    REQUIRE(timer.isOk());
    c.steps.push_back([t = timer.value()] { (void)dev().destroyTimer(t); });
    CHECK(dev().endTimer(timer.value()).code() == StatusCode::InvalidArgument);  // not begun
    SFX_REQUIRE_OK(dev().beginTimer(timer.value()));
    for (int i = 0; i < 4; ++i)
        fullscreenPass(target, pipeline, {.uniformBuffers = {{gen::hal_test_pattern::PatternParams, params}}});
    SFX_REQUIRE_OK(dev().endTimer(timer.value()));
    SFX_REQUIRE_OK(dev().flush());
    Result<TimerReading> reading = dev().readTimer(timer.value());
    INFO(reading.status().toString());
    REQUIRE(reading.isOk());
    CHECK(reading->milliseconds > 0.0);
    CHECK(reading->milliseconds < 10000.0);
    CHECK(reading->source == dev().caps().timing);

    // A timer measures the work between its ends: 48 passes over a 512x512 target take longer
    // than one (median of three tries each, so a busy machine does not decide it).
    TextureHandle big = makeTexture(c, 512, 512, Format::RGBA8, kTextureSampled | kTextureRenderTarget);
    auto measure = [&](int passes) {
        std::vector<double> ms;
        for (int attempt = 0; attempt < 3; ++attempt) {
            REQUIRE(dev().beginTimer(timer.value()).isOk());
            for (int i = 0; i < passes; ++i)
                fullscreenPass(big, pipeline, {.uniformBuffers = {{gen::hal_test_pattern::PatternParams, params}}});
            REQUIRE(dev().endTimer(timer.value()).isOk());
            REQUIRE(dev().flush().isOk());
            ms.push_back(dev().readTimer(timer.value())->milliseconds);
        }
        std::sort(ms.begin(), ms.end());
        return ms[1];
    };
    const double light = measure(1), heavy = measure(48);
    INFO(test::label() << ": 1 pass " << light << " ms, 48 passes " << heavy << " ms");
    CHECK(heavy > light);
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

// The status names the field and the allowed range, the same words on every backend.
static void checkNamed(const Status& s, StatusCode code, const char* field) {
    INFO(s.toString());
    CHECK(s.code() == code);
    CHECK(s.message().find(field) != std::string::npos);
}

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
    const MeshVertex vertices[] = {
        {-1, -1, 0.5f, 1, 0, 0, 1}, {3, -1, 0.5f, 1, 0, 0, 1}, {-1, 3, 0.5f, 1, 0, 0, 1}};
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

TEST_CASE("hal: bad input is a named error on every call", "[hal]") {
    Cleanup c;
    const DeviceCaps& caps = dev().caps();
    // Descriptions.
    CHECK(dev().createTexture({0, 4, 1, Format::RGBA8, kTextureSampled}).status().code() == StatusCode::InvalidArgument);
    CHECK(dev().createTexture({caps.limits.maxTextureSize + 1, 4, 1, Format::RGBA8, kTextureSampled}).status().code() ==
          StatusCode::InvalidArgument);
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
