// GL backend conformance: exact readback of full-screen passes in every colour class, uploads,
// uniform blocks bound by name, mip-to-mip rendering, indexed depth-tested draws with depth
// readback, compute under both tiers, the ceiling's dialect, context switching between two GL
// devices in one process, and shader errors. Tagged [gl]: conformance_main runs them only on
// GL backends, so they are never counted as passes on Vulkan.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <vector>

#include "hal_fixture.hpp"

#if __has_include("sfx/gl_device.hpp") && __has_include(<EGL/egl.h>) && __has_include(<GL/osmesa.h>)
#define SFX_TEST_GL_WRAP 1
#define EGL_NO_X11 1
#include <EGL/egl.h>
#include <GL/osmesa.h>

#include "sfx/gl_device.hpp"
#include "sfx/half.hpp"
#endif

namespace sfx {
namespace {

using test::program;

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

Status drawFullScreen(Device& dev, PipelineHandle pipeline, TextureHandle target, uint32_t mip = 0, BindingSet bindings = {}) {
    RenderPassDesc pass;
    pass.colors.push_back({target, mip, LoadOp::Clear, {0, 0, 0, 0}});
    DrawDesc draw;
    draw.pipeline = pipeline;
    draw.bindings = std::move(bindings);
    return dev.renderPass(pass, std::span<const DrawDesc>(&draw, 1));
}

// The pattern hal_gltest_pattern writes at texel (x, y).
std::array<float, 4> pattern(uint32_t x, uint32_t y) { return {float(x) / 256.0f, float(y) / 256.0f, float(x + 2 * y) / 256.0f, 0.5f}; }

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
    Device& dev = test::device();
    checkPattern(dev, Format::RGBA8, 16, 8);
    checkPattern(dev, Format::R32UI, 16, 8);
    if (dev.caps().renderableFormat[size_t(Format::R32F)]) checkPattern(dev, Format::R32F, 16, 8);
    if (dev.caps().renderableFormat[size_t(Format::RGBA16F)]) checkPattern(dev, Format::RGBA16F, 16, 8);
    if (dev.caps().renderableFormat[size_t(Format::RG16F)]) checkPattern(dev, Format::RG16F, 13, 5);
    if (dev.caps().renderableFormat[size_t(Format::RGBA32F)]) checkPattern(dev, Format::RGBA32F, 7, 3);
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("gl: caps and the dialect under the ceiling", "[hal][gl]") {
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
    // GL timers are the wall clock between glFinish calls (timer queries under-report on
    // llvmpipe); what they measure is checked in the shared "timers" test.
    CHECK(c.timing == TimingSource::WallClockAfterFinish);
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("gl: two GL devices in one process switch contexts", "[hal][gl]") {
    Device& a = test::device();
    // The other platform: EGL GL ES beside OSMesa, OSMesa beside either EGL device.
    const BackendConfig other = test::backendConfig().platform == "osmesa" ? BackendConfig{BackendKind::GLES, "egl"}
                                                                           : BackendConfig{BackendKind::GL, "osmesa"};
    DeviceOptions options;
    options.ceiling = a.caps().ceiling;
    options.validation = true;
    Result<std::unique_ptr<Device>> opened = openDevice(other, options);
    if (!opened) {
        SFX_SKIP("second GL device unavailable: " << opened.status().toString());
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
    Device& host = test::device();
    SFX_REQUIRE_OK(host.flush());  // the test device's context is now current: play the host
    const bool osmesa = test::backendConfig().platform == "osmesa";
    gl::GetProcAddressFn loader = osmesa ? reinterpret_cast<gl::GetProcAddressFn>(&OSMesaGetProcAddress)
                                         : reinterpret_cast<gl::GetProcAddressFn>(&eglGetProcAddress);
    DeviceOptions options;
    options.ceiling = host.caps().ceiling;
    options.validation = true;  // per-call checks on; the host's debug callback must survive
    using GetPointerv = void (*)(GLenum, void**);
    using GetError = GLenum (*)();
    using Enable = void (*)(GLenum);
    auto getPointerv = reinterpret_cast<GetPointerv>(loader("glGetPointerv"));
    auto getError = reinterpret_cast<GetError>(loader("glGetError"));
    auto enable = reinterpret_cast<Enable>(loader("glEnable"));
    REQUIRE(getPointerv);
    REQUIRE(getError);
    REQUIRE(enable);
    void* hostCallback = nullptr;
    void* hostUserParam = nullptr;
    getPointerv(0x8244 /* GL_DEBUG_CALLBACK_FUNCTION */, &hostCallback);
    getPointerv(0x8245 /* GL_DEBUG_CALLBACK_USER_PARAM */, &hostUserParam);
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
    // An error the host's own call left pending is not the SDK call's failure.
    enable(0xFFFFu);  // GL_INVALID_ENUM, on the host's account
    SFX_REQUIRE_OK(drawFullScreen(dev, fs.pipeline, t));
    CHECK(dev.takeValidationMessages().empty());
    std::vector<uint32_t> out(12);
    SFX_REQUIRE_OK(dev.readTexture(t, 0, out.data(), out.size() * 4));
    CHECK(out[2 * 4 + 3] == 3 + 2000 + 7);
    SFX_REQUIRE_OK(dev.destroyTexture(t));
    destroy(dev, fs);
    wrapped.value().reset();
    // The host's debug callback was neither replaced nor removed by the wrapper.
    void* callbackAfter = nullptr;
    void* userParamAfter = nullptr;
    getPointerv(0x8244, &callbackAfter);
    getPointerv(0x8245, &userParamAfter);
    CHECK(callbackAfter == hostCallback);
    CHECK(userParamAfter == hostUserParam);
    // The host's invalid glEnable reached the host's own debug callback (here the test device
    // plays the host), not the SDK device's list.
    bool hostSawItsError = false;
    for (const std::string& m : host.takeValidationMessages()) hostSawItsError |= m.find("glEnable") != std::string::npos;
    CHECK(hostSawItsError);
    // The host's context survives the wrapper.
    SFX_REQUIRE_OK(host.flush());
    checkPattern(host, Format::RGBA8, 4, 4);
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("gl: an API the platform lacks is BackendUnavailable", "[hal][gl]") {
    DeviceOptions options;
    options.validation = true;
    Result<std::unique_ptr<Device>> es = gl::createDevice(gl::Platform::OSMesa, gl::Api::GLES, options);
    CHECK(es.status().code() == StatusCode::BackendUnavailable);
    CHECK(es.status().message().find("OSMesa") != std::string::npos);
    // The test device still works after the refused open.
    checkPattern(test::device(), Format::RGBA8, 3, 2);
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}
#endif

}  // namespace
}  // namespace sfx
