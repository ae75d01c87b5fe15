// GL backend conformance: exact readback of full-screen passes in every colour class, uploads,
// uniform blocks bound by name, mip-to-mip rendering, indexed depth-tested draws with depth
// readback, compute under both tiers, the ceiling's dialect, context switching between two GL
// devices in one process, and shader errors. Skipped on non-GL backends.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <vector>

#include "sfx_shaders.hpp"
#include "test_device.hpp"

#if __has_include("sfx/gl_device.hpp") && __has_include(<EGL/egl.h>) && __has_include(<GL/osmesa.h>)
#define SFX_TEST_GL_WRAP 1
#define EGL_NO_X11 1
#include <EGL/egl.h>
#include <GL/osmesa.h>

#include "sfx/gl_device.hpp"
#endif

namespace sfx {
namespace {

bool isGl(const Device& d) { return d.caps().backend == BackendKind::GLES || d.caps().backend == BackendKind::GL; }

#define SFX_GL_ONLY()                                       \
    if (!isGl(test::device())) {                            \
        SUCCEED("not a GL backend");                        \
        return;                                             \
    }

const CompiledProgram& program(const char* name) {
    Result<const CompiledProgram*> p = shaders::find(name, test::tier());
    INFO(name << ": " << p.status().toString());
    REQUIRE(p.isOk());
    return *p.value();
}

struct FullScreen {
    ProgramHandle program;
    PipelineHandle pipeline;
};

FullScreen makeFullScreen(Device& dev, const char* name, Format format) {
    FullScreen fs;
    Result<ProgramHandle> p = dev.createProgram(program(name));
    INFO(p.status().toString());
    REQUIRE(p.isOk());
    fs.program = p.value();
    GraphicsPipelineDesc pd;
    pd.program = fs.program;
    pd.colorFormats = {format};
    Result<PipelineHandle> pl = dev.createGraphicsPipeline(pd);
    INFO(pl.status().toString());
    REQUIRE(pl.isOk());
    fs.pipeline = pl.value();
    return fs;
}

void destroy(Device& dev, const FullScreen& fs) {
    SFX_REQUIRE_OK(dev.destroyPipeline(fs.pipeline));
    SFX_REQUIRE_OK(dev.destroyProgram(fs.program));
}

Status drawFullScreen(Device& dev, PipelineHandle pipeline, TextureHandle target, uint32_t mip = 0,
                      BindingSet bindings = {}) {
    RenderPassDesc pass;
    pass.colors.push_back({target, mip, LoadOp::Clear, {0, 0, 0, 0}});
    DrawDesc draw;
    draw.pipeline = pipeline;
    draw.bindings = std::move(bindings);
    return dev.renderPass(pass, std::span<const DrawDesc>(&draw, 1));
}

// IEEE half to float, for comparing half readbacks.
float halfToFloat(uint16_t h) {
    const uint32_t sign = uint32_t(h >> 15) << 31, exp = (h >> 10) & 31u, mant = h & 1023u;
    float v;
    if (exp == 0) v = std::ldexp(float(mant), -24);
    else if (exp == 31) v = mant ? NAN : INFINITY;
    else v = std::ldexp(float(mant | 1024u), int(exp) - 25);
    return sign ? -v : v;
}

// The pattern hal_gltest_pattern writes at texel (x, y).
std::array<float, 4> pattern(uint32_t x, uint32_t y) {
    return {float(x) / 256.0f, float(y) / 256.0f, float(x + 2 * y) / 256.0f, 0.5f};
}

void checkPattern(Device& dev, Format format, uint32_t w, uint32_t h) {
    INFO("format " << toString(format) << " on " << test::label());
    const bool isUint = format == Format::R32UI;
    FullScreen fs = makeFullScreen(dev, isUint ? "hal_gltest_pattern_uint" : "hal_gltest_pattern", format);
    Result<TextureHandle> tex = dev.createTexture({w, h, 1, format, kTextureRenderTarget | kTextureSampled});
    INFO(tex.status().toString());
    REQUIRE(tex.isOk());
    SFX_REQUIRE_OK(drawFullScreen(dev, fs.pipeline, tex.value()));
    std::vector<uint8_t> bytes(size_t(w) * h * bytesPerTexel(format));
    SFX_REQUIRE_OK(dev.readTexture(tex.value(), 0, bytes.data(), bytes.size()));
    const uint32_t channels = channelCount(format);
    size_t bad = 0;
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) {
            const size_t i = size_t(y) * w + x;
            const auto want = pattern(x, y);
            for (uint32_t c = 0; c < channels; ++c) {
                bool ok = true;
                if (format == Format::R32UI) {
                    uint32_t v;
                    std::memcpy(&v, &bytes[i * 4], 4);
                    ok = v == x + 1000 * y + 7;
                } else if (format == Format::RGBA8 || format == Format::R8) {
                    const int v = bytes[i * channels + c];
                    ok = std::abs(v - int(std::lround(want[c] * 255.0f))) <= 1;
                } else if (format == Format::R16F || format == Format::RG16F || format == Format::RGBA16F) {
                    uint16_t v;
                    std::memcpy(&v, &bytes[(i * channels + c) * 2], 2);
                    ok = halfToFloat(v) == want[c];
                } else {
                    float v;
                    std::memcpy(&v, &bytes[(i * channels + c) * 4], 4);
                    ok = v == want[c];
                }
                if (!ok && bad++ < 4) UNSCOPED_INFO("texel (" << x << "," << y << ") channel " << c << " differs");
            }
        }
    CHECK(bad == 0);
    SFX_REQUIRE_OK(dev.destroyTexture(tex.value()));
    destroy(dev, fs);
}

TEST_CASE("gl: full-screen pass writes gl_FragCoord patterns exactly", "[hal][gl]") {
    SFX_GL_ONLY();
    Device& dev = test::device();
    checkPattern(dev, Format::RGBA8, 16, 8);
    checkPattern(dev, Format::R32UI, 16, 8);
    if (dev.caps().renderableFormat[size_t(Format::R32F)]) checkPattern(dev, Format::R32F, 16, 8);
    if (dev.caps().renderableFormat[size_t(Format::RGBA16F)]) checkPattern(dev, Format::RGBA16F, 16, 8);
    if (dev.caps().renderableFormat[size_t(Format::RG16F)]) checkPattern(dev, Format::RG16F, 13, 5);
    if (dev.caps().renderableFormat[size_t(Format::RGBA32F)]) checkPattern(dev, Format::RGBA32F, 7, 3);
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("gl: writeTexture, sample with texelFetch, read back", "[hal][gl]") {
    SFX_GL_ONLY();
    Device& dev = test::device();
    const uint32_t w = 9, h = 6;  // odd width: rows are tightly packed, not 4-aligned
    FullScreen fs = makeFullScreen(dev, "copy", Format::RGBA8);
    TextureHandle src = dev.createTexture({w, h, 1, Format::R8, kTextureSampled}).value();
    TextureHandle dst = dev.createTexture({w, h, 1, Format::RGBA8, kTextureRenderTarget}).value();
    std::vector<uint8_t> texels(size_t(w) * h);
    for (size_t i = 0; i < texels.size(); ++i) texels[i] = uint8_t(i * 5 + 1);
    SFX_REQUIRE_OK(dev.writeTexture(src, 0, texels.data(), texels.size()));
    BindingSet b;
    b.textures.push_back({gen::copy::uSource, src, 0, 1, {}});
    SFX_REQUIRE_OK(drawFullScreen(dev, fs.pipeline, dst, 0, b));
    std::vector<uint8_t> out(size_t(w) * h * 4);
    SFX_REQUIRE_OK(dev.readTexture(dst, 0, out.data(), out.size()));
    for (size_t i = 0; i < texels.size(); ++i) {
        INFO("texel " << i);
        REQUIRE(out[i * 4] == texels[i]);
        REQUIRE(out[i * 4 + 1] == 0);
        REQUIRE(out[i * 4 + 3] == 255);
    }
    // R32F and half uploads come back unchanged.
    std::vector<float> f(size_t(w) * h);
    for (size_t i = 0; i < f.size(); ++i) f[i] = float(i) * 0.25f - 3.0f;
    TextureHandle r32 = dev.createTexture({w, h, 1, Format::R32F, kTextureSampled}).value();
    SFX_REQUIRE_OK(dev.writeTexture(r32, 0, f.data(), f.size() * 4));
    if (dev.caps().renderableFormat[size_t(Format::R32F)]) {
        std::vector<float> back(f.size());
        SFX_REQUIRE_OK(dev.readTexture(r32, 0, back.data(), back.size() * 4));
        CHECK(back == f);
    }
    // Missing and extra bindings name the problem.
    CHECK(drawFullScreen(dev, fs.pipeline, dst, 0, {}).code() == StatusCode::InvalidArgument);
    BindingSet extra = b;
    extra.textures.push_back({5, src, 0, 1, {}});
    CHECK(drawFullScreen(dev, fs.pipeline, dst, 0, extra).code() == StatusCode::InvalidArgument);
    SFX_REQUIRE_OK(dev.destroyTexture(r32));
    SFX_REQUIRE_OK(dev.destroyTexture(src));
    SFX_REQUIRE_OK(dev.destroyTexture(dst));
    destroy(dev, fs);
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("gl: uniform block bound by its reflected binding", "[hal][gl]") {
    SFX_GL_ONLY();
    Device& dev = test::device();
    const CompiledProgram& prog = program("hal_gltest_uniform");
    const ShaderResource* block = prog.findResource("GlTestParams");
    REQUIRE(block != nullptr);
    CHECK(block->binding == gen::hal_gltest_uniform::GlTestParams);
    FullScreen fs = makeFullScreen(dev, "hal_gltest_uniform", Format::RGBA8);
    TextureHandle dst = dev.createTexture({8, 4, 1, Format::RGBA8, kTextureRenderTarget}).value();
    const float params[8] = {0.0f, 0.0f, 0.5f, 1.0f, 16.0f / 255.0f, 32.0f / 255.0f, 0.0f, 0.0f};
    BufferHandle ubo = dev.createBuffer({sizeof(params), kBufferUniform}).value();
    SFX_REQUIRE_OK(dev.writeBuffer(ubo, 0, params, sizeof(params)));
    BindingSet b;
    b.uniformBuffers.push_back({gen::hal_gltest_uniform::GlTestParams, ubo, 0, 0});
    SFX_REQUIRE_OK(drawFullScreen(dev, fs.pipeline, dst, 0, b));
    std::vector<uint8_t> out(8 * 4 * 4);
    SFX_REQUIRE_OK(dev.readTexture(dst, 0, out.data(), out.size()));
    for (uint32_t y = 0; y < 4; ++y)
        for (uint32_t x = 0; x < 8; ++x) {
            INFO("texel " << x << "," << y);
            const uint8_t* t = &out[(y * 8 + x) * 4];
            CHECK(std::abs(int(t[0]) - int(16 * x)) <= 1);
            CHECK(std::abs(int(t[1]) - int(32 * y)) <= 1);
            CHECK(std::abs(int(t[2]) - 128) <= 1);
        }
    SFX_REQUIRE_OK(dev.destroyBuffer(ubo));
    SFX_REQUIRE_OK(dev.destroyTexture(dst));
    destroy(dev, fs);
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("gl: render mip i+1 while sampling mip i", "[hal][gl]") {
    SFX_GL_ONLY();
    Device& dev = test::device();
    if (!dev.caps().renderableFormat[size_t(Format::R32F)]) {
        SUCCEED("no R32F targets");
        return;
    }
    const uint32_t w = 16, h = 8, levels = 4;
    FullScreen fs = makeFullScreen(dev, "hal_gltest_downsample", Format::R32F);
    TextureHandle tex = dev.createTexture({w, h, levels, Format::R32F, kTextureSampled | kTextureRenderTarget}).value();
    std::vector<std::vector<float>> want(levels);
    want[0].resize(size_t(w) * h);
    for (size_t i = 0; i < want[0].size(); ++i) want[0][i] = float((i * 37) % 101);
    SFX_REQUIRE_OK(dev.writeTexture(tex, 0, want[0].data(), want[0].size() * 4));
    for (uint32_t m = 1; m < levels; ++m) {
        const uint32_t pw = mipExtent(w, m - 1), ph = mipExtent(h, m - 1);
        const uint32_t cw = mipExtent(w, m), ch = mipExtent(h, m);
        want[m].resize(size_t(cw) * ch);
        for (uint32_t y = 0; y < ch; ++y)
            for (uint32_t x = 0; x < cw; ++x) {
                float v = -1e30f;
                for (uint32_t dy = 0; dy < 2; ++dy)
                    for (uint32_t dx = 0; dx < 2; ++dx)
                        v = std::max(v, want[m - 1][std::min(2 * y + dy, ph - 1) * pw + std::min(2 * x + dx, pw - 1)]);
                want[m][size_t(y) * cw + x] = v;
            }
        BindingSet b;
        b.textures.push_back({gen::hal_gltest_downsample::uPrevious, tex, m - 1, 1, {}});
        SFX_REQUIRE_OK(drawFullScreen(dev, fs.pipeline, tex, m, b));
    }
    // Sampling the very mip the pass renders to is refused, not undefined.
    BindingSet loop;
    loop.textures.push_back({gen::hal_gltest_downsample::uPrevious, tex, 0, 2, {}});
    CHECK(drawFullScreen(dev, fs.pipeline, tex, 1, loop).code() == StatusCode::InvalidArgument);
    for (uint32_t m = 0; m < levels; ++m) {
        std::vector<float> got(want[m].size());
        SFX_REQUIRE_OK(dev.readTexture(tex, m, got.data(), got.size() * 4));
        INFO("mip " << m);
        CHECK(got == want[m]);
    }
    SFX_REQUIRE_OK(dev.destroyTexture(tex));
    destroy(dev, fs);
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("gl: indexed draw with depth test, D32F readback, rows from NDC y = -1", "[hal][gl]") {
    SFX_GL_ONLY();
    Device& dev = test::device();
    const uint32_t w = 8, h = 8;
    ProgramHandle prog = dev.createProgram(program("hal_gltest_mesh")).value();
    GraphicsPipelineDesc pd;
    pd.program = prog;
    pd.vertexLayout.stride = 28;
    pd.vertexLayout.attributes = {{0, VertexFormat::Float3, 0}, {1, VertexFormat::Float4, 12}};
    pd.depth = {true, true, CompareOp::Less};
    pd.cull = CullMode::Back;
    pd.colorFormats = {Format::RGBA8};
    pd.depthFormat = Format::D32F;
    Result<PipelineHandle> pipeline = dev.createGraphicsPipeline(pd);
    INFO(pipeline.status().toString());
    REQUIRE(pipeline.isOk());
    // Quad A: the whole target at z = 0 (depth 0.5), red, drawn second. Quad B: the lower-left
    // quarter (NDC x, y in [-1, 0]) at z = -0.5 (depth 0.25), green, drawn first.
    // Both counter-clockwise in memory rows, so back-face culling keeps them.
    auto quad = [](float x0, float y0, float x1, float y1, float z, std::array<float, 4> c) {
        std::vector<float> v;
        const float corners[4][2] = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
        for (const auto& p : corners) v.insert(v.end(), {p[0], p[1], z, c[0], c[1], c[2], c[3]});
        return v;
    };
    std::vector<float> verts = quad(-1, -1, 0, 0, -0.5f, {0, 1, 0, 1});
    std::vector<float> a = quad(-1, -1, 1, 1, 0.0f, {1, 0, 0, 1});
    verts.insert(verts.end(), a.begin(), a.end());
    // A third, clockwise quad over everything at the nearest depth: culled.
    std::vector<float> cw = quad(-1, -1, 1, 1, -0.9f, {0, 0, 1, 1});
    verts.insert(verts.end(), cw.begin(), cw.end());
    const uint32_t indices[] = {0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7, 8, 10, 9, 8, 11, 10};
    BufferHandle vb = dev.createBuffer({verts.size() * 4, kBufferVertex}).value();
    BufferHandle ib = dev.createBuffer({sizeof(indices), kBufferIndex}).value();
    SFX_REQUIRE_OK(dev.writeBuffer(vb, 0, verts.data(), verts.size() * 4));
    SFX_REQUIRE_OK(dev.writeBuffer(ib, 0, indices, sizeof(indices)));
    TextureHandle color = dev.createTexture({w, h, 1, Format::RGBA8, kTextureRenderTarget}).value();
    TextureHandle depth = dev.createTexture({w, h, 1, Format::D32F, kTextureRenderTarget | kTextureSampled}).value();
    RenderPassDesc pass;
    pass.colors.push_back({color, 0, LoadOp::Clear, {0, 0, 0, 0}});
    pass.depth = {depth, LoadOp::Clear, 1.0f};
    DrawDesc draw;
    draw.pipeline = pipeline.value();
    draw.vertexBuffer = vb;
    draw.indexBuffer = ib;
    draw.count = 18;
    SFX_REQUIRE_OK(dev.renderPass(pass, std::span<const DrawDesc>(&draw, 1)));
    std::vector<uint8_t> rgba(w * h * 4);
    std::vector<float> d(w * h);
    SFX_REQUIRE_OK(dev.readTexture(color, 0, rgba.data(), rgba.size()));
    SFX_REQUIRE_OK(dev.readTexture(depth, 0, d.data(), d.size() * 4));
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) {
            INFO("texel " << x << "," << y);
            const bool near = x < w / 2 && y < h / 2;  // memory rows 0..h/2-1 are NDC y < 0
            const uint8_t* t = &rgba[(y * w + x) * 4];
            CHECK(int(t[0]) == (near ? 0 : 255));
            CHECK(int(t[1]) == (near ? 255 : 0));
            CHECK(int(t[2]) == 0);
            CHECK(d[y * w + x] == (near ? 0.25f : 0.5f));
        }
    SFX_REQUIRE_OK(dev.destroyTexture(color));
    SFX_REQUIRE_OK(dev.destroyTexture(depth));
    SFX_REQUIRE_OK(dev.destroyBuffer(vb));
    SFX_REQUIRE_OK(dev.destroyBuffer(ib));
    SFX_REQUIRE_OK(dev.destroyPipeline(pipeline.value()));
    SFX_REQUIRE_OK(dev.destroyProgram(prog));
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("gl: depth formats upload and read back", "[hal][gl]") {
    SFX_GL_ONLY();
    Device& dev = test::device();
    const uint32_t w = 5, h = 3;
    std::vector<float> f(w * h);
    for (size_t i = 0; i < f.size(); ++i) f[i] = float(i) / 16.0f;
    TextureHandle d32 = dev.createTexture({w, h, 1, Format::D32F, kTextureSampled | kTextureRenderTarget}).value();
    SFX_REQUIRE_OK(dev.writeTexture(d32, 0, f.data(), f.size() * 4));
    std::vector<float> back(f.size());
    SFX_REQUIRE_OK(dev.readTexture(d32, 0, back.data(), back.size() * 4));
    CHECK(back == f);
    std::vector<uint16_t> u16(w * h);
    for (size_t i = 0; i < u16.size(); ++i) u16[i] = uint16_t(i * 4000);
    TextureHandle d16 = dev.createTexture({w, h, 1, Format::D16, kTextureSampled | kTextureRenderTarget}).value();
    SFX_REQUIRE_OK(dev.writeTexture(d16, 0, u16.data(), u16.size() * 2));
    std::vector<uint16_t> back16(u16.size());
    SFX_REQUIRE_OK(dev.readTexture(d16, 0, back16.data(), back16.size() * 2));
    CHECK(back16 == u16);
    // D24S8: depth in the high 24 bits; GL ES reads depth through a shader, so allow one step.
    std::vector<uint32_t> u24(w * h);
    for (size_t i = 0; i < u24.size(); ++i) u24[i] = uint32_t(i * 1000003u % 16777216u) << 8;
    TextureHandle d24 = dev.createTexture({w, h, 1, Format::D24S8, kTextureSampled | kTextureRenderTarget}).value();
    SFX_REQUIRE_OK(dev.writeTexture(d24, 0, u24.data(), u24.size() * 4));
    std::vector<uint32_t> back24(u24.size());
    SFX_REQUIRE_OK(dev.readTexture(d24, 0, back24.data(), back24.size() * 4));
    for (size_t i = 0; i < u24.size(); ++i) {
        INFO("D24S8 texel " << i);
        CHECK(std::abs(int64_t(back24[i] >> 8) - int64_t(u24[i] >> 8)) <= 1);
    }
    SFX_REQUIRE_OK(dev.destroyTexture(d24));
    SFX_REQUIRE_OK(dev.destroyTexture(d32));
    SFX_REQUIRE_OK(dev.destroyTexture(d16));
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("gl: compute with storage buffer atomics, refused under the ceiling", "[hal][gl]") {
    SFX_GL_ONLY();
    Device& dev = test::device();
    Result<const CompiledProgram*> atomic = shaders::find("hal_atomic_count", Tier::High);
    REQUIRE(atomic.isOk());
    if (dev.caps().ceiling != CapabilityCeiling::None) {
        CHECK(!dev.caps().computeShaders);
        CHECK(!dev.caps().storageBuffers);
        CHECK(!dev.caps().atomics);
        CHECK(dev.createProgram(*atomic.value()).status().code() == StatusCode::UnsupportedFeature);
        CHECK(dev.createBuffer({256, kBufferStorage}).status().code() == StatusCode::UnsupportedFeature);
        CHECK(dev.dispatch(DispatchDesc{}).code() == StatusCode::UnsupportedFeature);
        SFX_REQUIRE_NO_VALIDATION_MESSAGES();
        return;
    }
    REQUIRE(dev.caps().computeShaders);
    REQUIRE(dev.caps().atomics);
    Result<ProgramHandle> prog = dev.createProgram(*atomic.value());
    INFO(prog.status().toString());
    REQUIRE(prog.isOk());
    PipelineHandle pipeline = dev.createComputePipeline({prog.value()}).value();
    const uint32_t n = 256;
    BufferHandle buf = dev.createBuffer({8 + n * 4, kBufferStorage}).value();
    DispatchDesc d;
    d.pipeline = pipeline;
    d.bindings.storageBuffers.push_back({gen::hal_atomic_count::Counters, buf, 0, 0});
    d.groupsX = n / 64;
    SFX_REQUIRE_OK(dev.dispatch(d));
    std::vector<uint32_t> out(2 + n);
    SFX_REQUIRE_OK(dev.readBuffer(buf, 0, out.data(), out.size() * 4));
    CHECK(out[0] == n);
    CHECK(out[1] == n * (n - 1) / 2);
    for (uint32_t i = 0; i < n; ++i) REQUIRE(out[2 + i] == 3 * i);
    SFX_REQUIRE_OK(dev.destroyBuffer(buf));
    SFX_REQUIRE_OK(dev.destroyPipeline(pipeline));
    SFX_REQUIRE_OK(dev.destroyProgram(prog.value()));
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("gl: caps and the dialect under the ceiling", "[hal][gl]") {
    SFX_GL_ONLY();
    const DeviceCaps& c = test::device().caps();
    const bool es = c.backend == BackendKind::GLES;
    CHECK(c.platform == test::backendConfig().platform);
    CHECK(c.clipDepth == ClipDepthRange::MinusOneToOne);
    CHECK(c.origin == FramebufferOrigin::LowerLeft);
    CHECK(c.timing == TimingSource::WallClockAfterFinish);
    CHECK(c.apiName.find(es ? "OpenGL ES" : "OpenGL") != std::string::npos);
    if (c.ceiling == CapabilityCeiling::GLES30) {
        CHECK(c.dialect == (es ? ShaderDialect::Essl300 : ShaderDialect::Glsl330));
        CHECK(!c.storageImages);
    } else {
        CHECK(c.dialect == (es ? ShaderDialect::Essl310 : ShaderDialect::Glsl450));
    }
    // Timers measure wall time between glFinish calls.
    Device& dev = test::device();
    TimerHandle t = dev.createTimer().value();
    SFX_REQUIRE_OK(dev.beginTimer(t));
    SFX_REQUIRE_OK(dev.endTimer(t));
    Result<TimerReading> r = dev.readTimer(t);
    REQUIRE(r.isOk());
    CHECK(r->milliseconds >= 0);
    CHECK(r->source == TimingSource::WallClockAfterFinish);
    SFX_REQUIRE_OK(dev.destroyTimer(t));
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("gl: a GLSL error is a ShaderError with the info log", "[hal][gl]") {
    SFX_GL_ONLY();
    Device& dev = test::device();
    CompiledProgram broken = program("copy");
    std::string& frag = broken.stages[1].glsl[size_t(dev.caps().dialect)];
    frag = frag.substr(0, frag.find('\n') + 1) + "void main() { this is not glsl; }\n";
    Result<ProgramHandle> p = dev.createProgram(broken);
    CHECK(p.status().code() == StatusCode::ShaderError);
    CHECK(p.status().message().find("copy") != std::string::npos);
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("gl: two GL devices in one process switch contexts", "[hal][gl]") {
    SFX_GL_ONLY();
    Device& a = test::device();
    // The other platform: EGL GL ES beside OSMesa, OSMesa beside either EGL device.
    const BackendConfig other = test::backendConfig().platform == "osmesa" ? BackendConfig{BackendKind::GLES, "egl"}
                                                                          : BackendConfig{BackendKind::GL, "osmesa"};
    DeviceOptions options;
    options.ceiling = a.caps().ceiling;
    Result<std::unique_ptr<Device>> opened = openDevice(other, options);
    if (!opened) {
        WARN("second GL device unavailable: " << opened.status().toString());
        return;
    }
    Device& b = *opened.value();
    FullScreen fa = makeFullScreen(a, "hal_gltest_pattern", Format::RGBA8);
    FullScreen fb = makeFullScreen(b, "hal_gltest_pattern_uint", Format::R32UI);
    TextureHandle ta = a.createTexture({12, 6, 1, Format::RGBA8, kTextureRenderTarget}).value();
    TextureHandle tb = b.createTexture({12, 6, 1, Format::R32UI, kTextureRenderTarget}).value();
    for (int round = 0; round < 2; ++round) {
        SFX_REQUIRE_OK(drawFullScreen(a, fa.pipeline, ta));
        SFX_REQUIRE_OK(drawFullScreen(b, fb.pipeline, tb));
        std::vector<uint8_t> ra(12 * 6 * 4);
        std::vector<uint32_t> rb(12 * 6);
        SFX_REQUIRE_OK(a.readTexture(ta, 0, ra.data(), ra.size()));
        SFX_REQUIRE_OK(b.readTexture(tb, 0, rb.data(), rb.size() * 4));
        for (uint32_t y = 0; y < 6; ++y)
            for (uint32_t x = 0; x < 12; ++x) {
                INFO("round " << round << " texel " << x << "," << y);
                REQUIRE(std::abs(int(ra[(y * 12 + x) * 4 + 1]) - int(std::lround(y / 256.0 * 255.0))) <= 1);
                REQUIRE(rb[y * 12 + x] == x + 1000 * y + 7);
            }
    }
    // Resources of one device are foreign to the other.
    CHECK(b.destroyTexture(ta).code() == StatusCode::ForeignHandle);
    SFX_REQUIRE_OK(b.destroyTexture(tb));
    destroy(b, fb);
    CHECK(b.takeValidationMessages().empty());
    opened.value().reset();
    // The first device still renders after the second is gone.
    SFX_REQUIRE_OK(drawFullScreen(a, fa.pipeline, ta));
    std::vector<uint8_t> ra(12 * 6 * 4);
    SFX_REQUIRE_OK(a.readTexture(ta, 0, ra.data(), ra.size()));
    CHECK(int(ra[(5 * 12 + 11) * 4]) == int(std::lround(11 / 256.0 * 255.0)));
    SFX_REQUIRE_OK(a.destroyTexture(ta));
    destroy(a, fa);
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

#ifdef SFX_TEST_GL_WRAP
TEST_CASE("gl: a host's current context wrapped as a device", "[hal][gl]") {
    SFX_GL_ONLY();
    Device& host = test::device();
    SFX_REQUIRE_OK(host.flush());  // the test device's context is now current: play the host
    const bool osmesa = test::backendConfig().platform == "osmesa";
    gl::GetProcAddressFn loader = osmesa ? reinterpret_cast<gl::GetProcAddressFn>(&OSMesaGetProcAddress)
                                         : reinterpret_cast<gl::GetProcAddressFn>(&eglGetProcAddress);
    DeviceOptions options;
    options.ceiling = host.caps().ceiling;
    options.validation = false;  // KHR_debug's callback belongs to the test device here
    const gl::Api api = host.caps().backend == BackendKind::GLES ? gl::Api::GLES : gl::Api::DesktopGL;
    Result<std::unique_ptr<Device>> wrapped = gl::wrapCurrentContext(loader, api, options);
    INFO(wrapped.status().toString());
    REQUIRE(wrapped.isOk());
    Device& dev = *wrapped.value();
    CHECK(dev.caps().platform == "host");
    CHECK(dev.caps().dialect == host.caps().dialect);
    FullScreen fs = makeFullScreen(dev, "hal_gltest_pattern_uint", Format::R32UI);
    TextureHandle t = dev.createTexture({4, 3, 1, Format::R32UI, kTextureRenderTarget}).value();
    CHECK(gl::wrapCurrentContext(nullptr, api, options).status().code() == StatusCode::InvalidArgument);
    SFX_REQUIRE_OK(drawFullScreen(dev, fs.pipeline, t));
    std::vector<uint32_t> out(12);
    SFX_REQUIRE_OK(dev.readTexture(t, 0, out.data(), out.size() * 4));
    CHECK(out[2 * 4 + 3] == 3 + 2000 + 7);
    SFX_REQUIRE_OK(dev.destroyTexture(t));
    destroy(dev, fs);
    wrapped.value().reset();
    // The host's context survives the wrapper.
    SFX_REQUIRE_OK(host.flush());
    checkPattern(host, Format::RGBA8, 4, 4);
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("gl: an API the platform lacks is BackendUnavailable", "[hal][gl]") {
    SFX_GL_ONLY();
    Result<std::unique_ptr<Device>> es = gl::createDevice(gl::Platform::OSMesa, gl::Api::GLES, {});
    CHECK(es.status().code() == StatusCode::BackendUnavailable);
    CHECK(es.status().message().find("OSMesa") != std::string::npos);
    // The test device still works after the refused open.
    checkPattern(test::device(), Format::RGBA8, 3, 2);
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}
#endif

}  // namespace
}  // namespace sfx
