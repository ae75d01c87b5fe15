// Host GL textures in, SDK textures out (sfx::gl::importTexture / nativeTexture) on a device
// wrapping the host's current context: AO reads the host's depth texture and writes the host's
// output texture, matching the SDK's own textures; bad imports are named errors; the SDK never
// deletes a host texture. Tagged [gl]: conformance_main runs it on GL backends only.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

#include "analytic_scenes.hpp"
#include "hal_fixture.hpp"
#include "sfx/ao.hpp"
#include "sfx/motion_blur.hpp"
#include "sfx/null_device.hpp"
#include "sfx/validation_errors.hpp"

#if __has_include("sfx/gl_device.hpp") && __has_include(<EGL/egl.h>) && __has_include(<GL/osmesa.h>)
#define SFX_TEST_GL_IMPORT 1
#define EGL_NO_X11 1
#include <EGL/egl.h>
#include <GL/osmesa.h>

#include "effect_runs.hpp"
#include "sfx/gl_device.hpp"
#include "sfx/half.hpp"
#endif

#ifdef SFX_TEST_GL_IMPORT
namespace sfx {
namespace {

// Two GPU runs of the same AO on the same context and inputs differ by at most one R16F step at 1.
constexpr double kSamePathTolerance = 1.0 / 1024.0;

// The host's own GL calls, through its loader.
struct HostGl {
    void (*genTextures)(int, uint32_t*);
    void (*deleteTextures)(int, const uint32_t*);
    void (*bindTexture)(uint32_t, uint32_t);
    void (*texStorage2D)(uint32_t, int, uint32_t, int, int);
    void (*texSubImage2D)(uint32_t, int, int, int, int, int, uint32_t, uint32_t, const void*);
    void (*pixelStorei)(uint32_t, int);
    unsigned char (*isTexture)(uint32_t);
    explicit HostGl(gl::GetProcAddressFn loader) {
        genTextures = reinterpret_cast<decltype(genTextures)>(loader("glGenTextures"));
        deleteTextures = reinterpret_cast<decltype(deleteTextures)>(loader("glDeleteTextures"));
        bindTexture = reinterpret_cast<decltype(bindTexture)>(loader("glBindTexture"));
        texStorage2D = reinterpret_cast<decltype(texStorage2D)>(loader("glTexStorage2D"));
        texSubImage2D = reinterpret_cast<decltype(texSubImage2D)>(loader("glTexSubImage2D"));
        pixelStorei = reinterpret_cast<decltype(pixelStorei)>(loader("glPixelStorei"));
        isTexture = reinterpret_cast<decltype(isTexture)>(loader("glIsTexture"));
    }
    // A GL_TEXTURE_2D with one level of immutable storage, filled from `data` when given.
    uint32_t texture(uint32_t internalFormat, uint32_t w, uint32_t h, uint32_t format = 0, uint32_t type = 0, const void* data = nullptr) {
        uint32_t name = 0;
        genTextures(1, &name);
        bindTexture(0x0DE1, name);
        texStorage2D(0x0DE1, 1, internalFormat, int(w), int(h));
        if (data) {
            pixelStorei(0x0CF5 /* GL_UNPACK_ALIGNMENT */, 1);
            texSubImage2D(0x0DE1, 0, 0, 0, int(w), int(h), format, type, data);
        }
        bindTexture(0x0DE1, 0);
        return name;
    }
};

// Visibility of an R16F or RGBA8 output, as doubles.
std::vector<double> visibility(Device& d, TextureHandle t, Format f, uint32_t w, uint32_t h) {
    std::vector<double> out(size_t(w) * h);
    if (f == Format::R16F) {
        std::vector<uint16_t> texels(out.size());
        SFX_REQUIRE_OK(d.readTexture(t, 0, texels.data(), texels.size() * 2));
        for (size_t i = 0; i < out.size(); ++i) out[i] = halfToFloat(texels[i]);
    } else {
        std::vector<uint8_t> texels(out.size() * 4);
        SFX_REQUIRE_OK(d.readTexture(t, 0, texels.data(), texels.size()));
        for (size_t i = 0; i < out.size(); ++i) out[i] = texels[4 * i] / 255.0;
    }
    return out;
}

// The test device's context, current on this thread and played as a host's: the platform's GL
// loader and the API of the test device.
struct TestContext {
    bool osmesa;
    gl::GetProcAddressFn loader;
    gl::Api api;
};
TestContext currentTestContext(Device& host) {
    SFX_REQUIRE_OK(host.flush());  // the test device's context is now current
    TestContext c;
    c.osmesa = test::backendConfig().platform == "osmesa";
    c.loader = c.osmesa ? reinterpret_cast<gl::GetProcAddressFn>(&OSMesaGetProcAddress) : reinterpret_cast<gl::GetProcAddressFn>(&eglGetProcAddress);
    c.api = host.caps().backend == BackendKind::GLES ? gl::Api::GLES : gl::Api::DesktopGL;
    return c;
}

// The SDK on that context, with the test device's ceiling and validation.
std::unique_ptr<Device> wrapTestContext(Device& host, const TestContext& c) {
    DeviceOptions options;
    options.ceiling = host.caps().ceiling;
    options.validation = true;
    Result<std::unique_ptr<Device>> wrapped = gl::wrapCurrentContext(c.loader, c.api, options);
    INFO(wrapped.status().toString());
    REQUIRE(wrapped.isOk());
    return std::move(wrapped.value());
}

// The test device's context played as a host's: the host's own GL entry points for its
// textures, and the SDK wrapped on that context.
struct PlayedHost {
    HostGl gl;
    std::unique_ptr<Device> sdk;
    PlayedHost(Device& host, const TestContext& c) : gl(c.loader) {
        REQUIRE(gl.isTexture);
        sdk = wrapTestContext(host, c);
    }
};

}  // namespace

TEST_CASE("gl import: AO reads a host depth texture and writes a host texture", "[gl][import]") {
    Device& host = test::device();
    PlayedHost played(host, currentTestContext(host));
    HostGl& hostGl = played.gl;
    Device& d = *played.sdk;

    constexpr uint32_t w = 96, h = 54;
    const tools::AnalyticScene scene = tools::cornerScene(w, h);
    const std::vector<float> depth(scene.linearDepth.values.begin(), scene.linearDepth.values.end());
    const bool halfOut = d.caps().renderableFormat[size_t(Format::R16F)];
    const Format outFormat = halfOut ? Format::R16F : Format::RGBA8;
    const uint32_t outInternal = halfOut ? 0x822D /* GL_R16F */ : 0x8058 /* GL_RGBA8 */;
    const uint32_t depthName = hostGl.texture(0x822E /* GL_R32F */, w, h, 0x1903 /* GL_RED */, 0x1406 /* GL_FLOAT */, depth.data());
    const uint32_t outName = hostGl.texture(outInternal, w, h);

    gl::ExternalTexture de;
    de.name = depthName;
    de.format = Format::R32F;
    de.width = w;
    de.height = h;
    gl::ExternalTexture oe = de;
    oe.name = outName;
    oe.format = Format::Undefined;
    oe.internalFormat = outInternal;
    oe.usage = kTextureSampled | kTextureRenderTarget;
    Result<TextureHandle> depthTex = gl::importTexture(d, de);
    Result<TextureHandle> outTex = gl::importTexture(d, oe);
    INFO(depthTex.status().toString() << " / " << outTex.status().toString());
    REQUIRE((depthTex.isOk() && outTex.isOk()));
    CHECK(d.textureDesc(outTex.value()).value().format == outFormat);
    Result<gl::NativeTexture> native = gl::nativeTexture(d, outTex.value());
    REQUIRE(native.isOk());
    CHECK(native->name == outName);
    CHECK(native->internalFormat == outInternal);

    Result<std::unique_ptr<AmbientObscurance>> ao = AmbientObscurance::create(d, {w, h, test::tierProfile(), AoSettings{}, DepthKind::Linear});
    INFO(ao.status().toString());
    REQUIRE(ao.isOk());
    AoInputs in;
    in.depth = DepthSource{depthTex.value(), DepthKind::Linear, scene.camera};
    in.output = outTex.value();
    SFX_REQUIRE_OK(ao.value()->dispatch(in));
    const std::vector<double> imported = visibility(d, outTex.value(), outFormat, w, h);

    // The SDK's own textures holding the same depth.
    TextureHandle ownDepth = d.createTexture({w, h, 1, Format::R32F, kTextureSampled}).value();
    SFX_REQUIRE_OK(d.writeTexture(ownDepth, 0, depth.data(), depth.size() * 4));
    TextureHandle ownOut = d.createTexture({w, h, 1, outFormat, kTextureSampled | kTextureRenderTarget}).value();
    in.depth.texture = ownDepth;
    in.output = ownOut;
    SFX_REQUIRE_OK(ao.value()->dispatch(in));
    const std::vector<double> own = visibility(d, ownOut, outFormat, w, h);
    double worst = 0;
    for (size_t i = 0; i < own.size(); ++i) worst = std::max(worst, std::abs(imported[i] - own[i]));
    WARN(test::label() << ": AO of imported GL textures vs the SDK's own, worst pixel " << worst);
    CHECK(worst <= kSamePathTolerance);
    CHECK(*std::min_element(own.begin(), own.end()) < 0.9);  // the corner occludes: not a blank picture

    // Bad imports are named errors.
    auto refused = [&](gl::ExternalTexture e, const char* argument, const char* allowed) {
        Result<TextureHandle> r = gl::importTexture(d, e);
        INFO(argument << ": " << r.status().toString());
        REQUIRE_FALSE(r.isOk());
        CHECK(r.status().code() == StatusCode::InvalidArgument);
        CHECK(r.status().message().find(argument) != std::string::npos);
        CHECK(r.status().message().find(allowed) != std::string::npos);
    };
    gl::ExternalTexture e = de;
    e.name = 0;
    refused(e, "ExternalTexture.name", "texture name");
    e = de;
    e.target = 0x8513;  // GL_TEXTURE_CUBE_MAP
    refused(e, "ExternalTexture.target", "GL_TEXTURE_2D");
    e = de;
    e.internalFormat = 0x8051;  // GL_RGB8
    refused(e, "ExternalTexture.internalFormat", "GL_RGBA16F");
    e = de;
    e.internalFormat = outInternal;  // disagrees with format R32F
    refused(e, "ExternalTexture.format", "Undefined or the format of internalFormat");
    e = de;
    e.format = Format::Undefined;
    refused(e, "ExternalTexture.format", "internalFormat");
    e = de;
    e.name = 0x7fffffffu;  // no texture of this context
    refused(e, "ExternalTexture.name", "a texture of this context");
    e = de;
    e.height = 0;
    refused(e, "importTexture", "height");
    CHECK(gl::nativeTexture(d, TextureHandle{}).status().code() == StatusCode::InvalidHandle);

    // destroyTexture forgets: the host's textures live on, with their contents.
    ao.value().reset();
    for (TextureHandle t : {depthTex.value(), outTex.value(), ownDepth, ownOut}) SFX_REQUIRE_OK(d.destroyTexture(t));
    CHECK(hostGl.isTexture(depthName));
    CHECK(hostGl.isTexture(outName));
    Result<TextureHandle> again = gl::importTexture(d, oe);
    REQUIRE(again.isOk());
    CHECK(visibility(d, again.value(), outFormat, w, h) == imported);
    CHECK(d.takeValidationMessages().empty());
    played.sdk.reset();                // with `again` still imported
    CHECK(hostGl.isTexture(outName));  // nor does the device's teardown delete it
    hostGl.deleteTextures(1, &depthName);
    hostGl.deleteTextures(1, &outName);
    SFX_REQUIRE_OK(host.flush());
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

// Motion blur into a host texture (MotionBlurInputs::output): the host's RGBA16F texture holds
// exactly the bits of the effect's own output() from the same inputs, and the SDK never deletes it.
TEST_CASE("gl import: motion blur writes a host texture, bit for bit as output()", "[gl][import][motion_blur]") {
    Device& host = test::device();
    PlayedHost played(host, currentTestContext(host));
    HostGl& hostGl = played.gl;
    Device& d = *played.sdk;

    const reference::MotionScene scene = test::movingAndStillLayersScene();
    const reference::SceneFrame f = scene.render(0);
    const uint32_t w = scene.width, h = scene.height;
    const uint32_t outName = hostGl.texture(0x881A /* GL_RGBA16F */, w, h);
    gl::ExternalTexture oe;
    oe.name = outName;
    oe.internalFormat = 0x881A;
    oe.width = w;
    oe.height = h;
    oe.usage = kTextureSampled | kTextureRenderTarget;
    Result<TextureHandle> outTex = gl::importTexture(d, oe);
    INFO(outTex.status().toString());
    REQUIRE(outTex.isOk());

    Result<std::unique_ptr<MotionBlur>> mb = MotionBlur::create(d, {w, h, test::tierProfile(), Format::RGBA16F, DepthKind::Linear});
    INFO(mb.status().toString());
    REQUIRE(mb.isOk());
    {  // the inputs live on the wrapped device: released before it is
        test::MotionBlurGpuInputs in(d, f.color, f.depth, &f.velocity);
        MotionBlurSettings s;
        s.maxRadiusPx = 7;
        s.referenceRows = 0;
        MotionBlurInputs inputs{in.color, {in.depth, DepthKind::Linear, test::motionBlurTestCamera(w, h)}, in.velocity, {}, {}};
        const size_t bytes = size_t(w) * h * 8;
        auto read = [&](TextureHandle t) {
            std::vector<uint16_t> texels(bytes / 2);
            SFX_REQUIRE_OK(d.readTexture(t, 0, texels.data(), bytes));
            return texels;
        };
        SFX_REQUIRE_OK(mb.value()->dispatch(inputs, s));
        const std::vector<uint16_t> own = read(mb.value()->output());
        inputs.output = outTex.value();
        SFX_REQUIRE_OK(mb.value()->dispatch(inputs, s));
        const std::vector<uint16_t> imported = read(outTex.value());
        CHECK(imported == own);
        CHECK(imported != read(in.color));  // the scene blurs: not a copy of the input
    }

    mb.value().reset();
    SFX_REQUIRE_OK(d.destroyTexture(outTex.value()));
    CHECK(hostGl.isTexture(outName));
    CHECK(d.takeValidationMessages().empty());
    played.sdk.reset();
    hostGl.deleteTextures(1, &outName);
    SFX_REQUIRE_OK(host.flush());
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

// Misuse of the GL host-integration entry points: each refusal is a row of the validation table
// with its whole message (validation_cases.cpp lists these rows as covered here).
TEST_CASE("gl entry points: no loader, no current context, a device of another API", "[gl][validation]") {
    Device& host = test::device();
    const TestContext context = currentTestContext(host);
    const bool osmesa = context.osmesa;
    const gl::GetProcAddressFn loader = context.loader;
    const gl::Api api = context.api;
    auto refused = [](const Status& s, validation::Error rule, const std::string& expected) {
        INFO(validation::entry(rule).name << " -> " << s.toString());
        CHECK(s.code() == validation::entry(rule).code);
        CHECK(s.message() == expected);
    };
    refused(gl::wrapCurrentContext(nullptr, api, DeviceOptions{}).status(), validation::Error::ExternalObjectNull,
            "getProcAddress is null; allowed the host's GL loader");

    // No context current on this thread: unbind the test device's, wrap, bind it again.
    Status unbound;
    if (osmesa) {
        OSMesaContext ctx = OSMesaGetCurrentContext();
        REQUIRE(ctx);
        GLint w = 0, h = 0, format = 0;
        void* buffer = nullptr;
        REQUIRE(OSMesaGetColorBuffer(ctx, &w, &h, &format, &buffer));
        REQUIRE(OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0));
        unbound = gl::wrapCurrentContext(loader, api, DeviceOptions{}).status();
        REQUIRE(OSMesaMakeCurrent(ctx, buffer, 0x1401 /* GL_UNSIGNED_BYTE */, w, h));
    } else {
        const EGLDisplay display = eglGetCurrentDisplay();
        const EGLContext ctx = eglGetCurrentContext();
        const EGLSurface draw = eglGetCurrentSurface(EGL_DRAW), read = eglGetCurrentSurface(EGL_READ);
        REQUIRE(ctx != EGL_NO_CONTEXT);
        REQUIRE(eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT));
        unbound = gl::wrapCurrentContext(loader, api, DeviceOptions{}).status();
        REQUIRE(eglMakeCurrent(display, draw, read, ctx));
    }
    refused(unbound, validation::Error::GlNoCurrentContext,
            "wrapCurrentContext: no GL context is current on this thread (glGetString(GL_VERSION) is null); allowed a call "
            "with the host's context current");

    std::unique_ptr<Device> nullDevice = null::createDevice();
    refused(gl::importTexture(*nullDevice, gl::ExternalTexture{}).status(), validation::Error::DeviceWrongApi,
            "importTexture: device is a null device; allowed a GL or GL ES device");
    refused(gl::nativeTexture(*nullDevice, TextureHandle{}).status(), validation::Error::DeviceWrongApi,
            "nativeTexture: device is a null device; allowed a GL or GL ES device");
    SFX_REQUIRE_OK(host.flush());
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

}  // namespace sfx
#endif
