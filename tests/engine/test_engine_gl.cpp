// samples/engine_gl as a test: the sample's own renderer (its EGL context, GL textures,
// framebuffers and programs) runs 60 animated frames with the SDK's AO and motion blur on its
// textures, with the SDK's per-call GL error checks and the host's glGetError on. Checked:
//   (a) the AO and motion-blur results equal the SDK's own path: the same inputs, read back once
//       after the frames, uploaded into SDK textures on a device the SDK opened, same settings;
//   (b) the steady frames make nothing: Device::stats() unchanged (creation totals, readback
//       copies and memory included) and no host glGen*/storage/upload/glReadPixels;
//   (c) the GL state contract (docs/integration.md, "The GL state contract") after each SDK call.
// "[gles]" runs on GL ES 3.x, "[desktop]" on desktop GL core, both through EGL.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include "frame_loop.hpp"
#include "sfx/gl_device.hpp"
#include "sfx/half.hpp"
#include "skips.hpp"

// The call's Status must be ok; its message is shown when it is not.
// clang-format off
#define ENGINE_REQUIRE_OK(expr)                              \
    do {                                                     \
        const ::sfx::Status engine_st_ = (expr);             \
        INFO(#expr << " -> " << engine_st_.toString());      \
        REQUIRE(engine_st_.isOk());                          \
    } while (0)
// clang-format on

namespace {

using namespace engine_gl;
using sfx::Format;
using sfx::TextureHandle;

constexpr uint32_t kWidth = 320, kHeight = 180;
constexpr uint32_t kWarmupFrames = 5, kSteadyFrames = 55;
// The conformance bounds, worst pixel: AO as tests/conformance/test_ao.cpp (per tier: an R16F
// output plus float taps on high, two 8-bit roundings on current); motion blur as the per-channel
// bound of ordinary pixels in tests/conformance/test_motion_blur.cpp. Here both paths run the
// same shaders on the same inputs, so anything above them is a difference of the host's path.
constexpr double kAoWorstHigh = 0.005, kAoWorstCurrent = 0.01;
constexpr double kBlurWorst = 2e-3;

// One texture's texels as floats, whatever its format (D32F, R16F, RG16F, RGBA16F).
std::vector<float> readFloats(sfx::Device& d, TextureHandle t) {
    const sfx::TextureDesc desc = d.textureDesc(t).value();
    const size_t texels = size_t(desc.width) * desc.height;
    if (desc.format == Format::D32F || desc.format == Format::R32F) {
        std::vector<float> out(texels);
        ENGINE_REQUIRE_OK(d.readTexture(t, 0, out.data(), out.size() * 4));
        return out;
    }
    const size_t channels = desc.format == Format::R16F ? 1 : desc.format == Format::RG16F ? 2 : 4;
    REQUIRE((desc.format == Format::R16F || desc.format == Format::RG16F || desc.format == Format::RGBA16F));
    std::vector<uint16_t> halves(texels * channels);
    ENGINE_REQUIRE_OK(d.readTexture(t, 0, halves.data(), halves.size() * 2));
    std::vector<float> out(halves.size());
    for (size_t i = 0; i < out.size(); ++i) out[i] = sfx::halfToFloat(halves[i]);
    return out;
}

// The same texels back into a texture of the same format.
void writeFloats(sfx::Device& d, TextureHandle t, const std::vector<float>& values) {
    const sfx::TextureDesc desc = d.textureDesc(t).value();
    if (desc.format == Format::D32F) {
        ENGINE_REQUIRE_OK(d.writeTexture(t, 0, values.data(), values.size() * 4));
        return;
    }
    std::vector<uint16_t> halves(values.size());
    for (size_t i = 0; i < values.size(); ++i) halves[i] = sfx::floatToHalf(values[i]);
    ENGINE_REQUIRE_OK(d.writeTexture(t, 0, halves.data(), halves.size() * 2));
}

double worstDifference(const std::vector<float>& a, const std::vector<float>& b) {
    REQUIRE(a.size() == b.size());
    double worst = 0;
    for (size_t i = 0; i < a.size(); ++i) {
        REQUIRE(std::isfinite(a[i]));
        worst = std::max(worst, std::fabs(double(a[i]) - double(b[i])));
    }
    return worst;
}

std::string describe(const sfx::DeviceStats& s) {
    auto c = [](const char* n, const sfx::ObjectCount& o) {
        return std::string(n) + " " + std::to_string(o.live) + "/" + std::to_string(o.created) + " ";
    };
    return c("textures", s.textures) + c("buffers", s.buffers) + c("samplers", s.samplers) + c("programs", s.programs) + c("pipelines", s.pipelines) +
        c("timers", s.timers) + c("memory", s.memoryAllocations) + c("readback-copies", s.stagingBuffers) + c("framebuffers", s.framebuffers) +
        "bytes " + std::to_string(s.deviceMemoryBytes);
}

std::string describe(const HostGlCounts& c) {
    return "objects created " + std::to_string(c.objectsCreated) + ", deleted " + std::to_string(c.objectsDeleted) + ", storage " +
        std::to_string(c.allocations) + ", uploads " + std::to_string(c.uploads) + ", readbacks " + std::to_string(c.readbacks);
}

// (c): the GL state the docs promise after an SDK call, and the host's state it must not touch:
// a host texture and sampler parked on the last unit, and every other unit either cleared or as
// the host left it.
struct StateContract {
    HostGl* gl = nullptr;
    GLuint parkedTexture = 0, parkedSampler = 0;
    GLint parkedUnit = 0, units = 0;
    std::vector<GLint> texturesBefore, samplersBefore;
    uint32_t callsChecked = 0;
    std::string violations;

    GLint get(GLenum pname) const {
        GLint v = -1;
        gl->GetIntegerv(pname, &v);
        return v;
    }
    void before(SdkCall call) {
        if (call == SdkCall::Flush) return;
        gl->ActiveTexture(GL_TEXTURE0 + GLenum(parkedUnit));
        gl->BindTexture(GL_TEXTURE_2D, parkedTexture);
        gl->BindSampler(GLuint(parkedUnit), parkedSampler);
        gl->ActiveTexture(GL_TEXTURE0);
        gl->PixelStorei(GL_PACK_ALIGNMENT, 4);
        gl->PixelStorei(GL_UNPACK_ALIGNMENT, 4);
        texturesBefore.assign(size_t(units), 0);
        samplersBefore.assign(size_t(units), 0);
        for (GLint u = 0; u < units; ++u) {
            gl->ActiveTexture(GL_TEXTURE0 + GLenum(u));
            texturesBefore[size_t(u)] = get(GL_TEXTURE_BINDING_2D);
            samplersBefore[size_t(u)] = get(GL_SAMPLER_BINDING);
        }
        gl->ActiveTexture(GL_TEXTURE0);
    }
    void after(SdkCall call) {
        if (call == SdkCall::Flush) return;
        ++callsChecked;
        const std::string what = call == SdkCall::AmbientObscurance ? "after AO: " : "after motion blur: ";
        auto expect = [&](bool ok, const std::string& text) {
            if (!ok) violations += what + text + "\n";
        };
        expect(gl->GetError() == GL_NO_ERROR, "a GL error is pending");
        expect(get(GL_DRAW_FRAMEBUFFER_BINDING) == 0, "draw framebuffer " + std::to_string(get(GL_DRAW_FRAMEBUFFER_BINDING)));
        expect(get(GL_READ_FRAMEBUFFER_BINDING) == 0, "read framebuffer " + std::to_string(get(GL_READ_FRAMEBUFFER_BINDING)));
        expect(get(GL_CURRENT_PROGRAM) == 0, "program " + std::to_string(get(GL_CURRENT_PROGRAM)));
        expect(get(GL_VERTEX_ARRAY_BINDING) == 0, "vertex array " + std::to_string(get(GL_VERTEX_ARRAY_BINDING)));
        expect(get(GL_PACK_ALIGNMENT) == 1 && get(GL_UNPACK_ALIGNMENT) == 1, "PACK/UNPACK_ALIGNMENT not 1");
        const GLint active = get(GL_ACTIVE_TEXTURE);
        for (GLint u = 0; u < units; ++u) {
            gl->ActiveTexture(GL_TEXTURE0 + GLenum(u));
            const GLint t = get(GL_TEXTURE_BINDING_2D), s = get(GL_SAMPLER_BINDING);
            expect(t == 0 || t == texturesBefore[size_t(u)], "unit " + std::to_string(u) + " holds texture " + std::to_string(t));
            expect(s == 0 || s == samplersBefore[size_t(u)], "unit " + std::to_string(u) + " holds sampler " + std::to_string(s));
        }
        gl->ActiveTexture(GLenum(active));
        gl->ActiveTexture(GL_TEXTURE0 + GLenum(parkedUnit));
        expect(get(GL_TEXTURE_BINDING_2D) == GLint(parkedTexture), "the host's texture on the last unit is gone");
        expect(get(GL_SAMPLER_BINDING) == GLint(parkedSampler), "the host's sampler on the last unit is gone");
        gl->ActiveTexture(GL_TEXTURE0);
    }
};

// What the host's frames left, read back once after them, and what the SDK made of it.
struct HostResults {
    std::vector<float> depth, normals, velocity, lit, ao, blurred;
    sfx::AoDesc aoDesc;
    sfx::MotionBlurDesc blurDesc;
    sfx::MotionBlurSettings blurSettings;
    sfx::CameraProjection camera;
    sfx::Tier tier = sfx::Tier::Current;
};

void runEngine(ContextApi api) {
    const std::string label = std::string("engine_gl ") + toString(api);
    sfx::Result<std::unique_ptr<EglContext>> context = EglContext::open(api);
    if (!context && context.status().code() == sfx::StatusCode::BackendUnavailable)
        SFX_SKIP(label << ": no EGL context here: " << context.status().toString());
    INFO(context.status().toString());
    REQUIRE(context.isOk());

    RendererOptions options;
    options.width = kWidth;
    options.height = kHeight;
    options.debug = true;  // the SDK's per-call GL error checks and the host's glGetError
    std::vector<std::string> logged;
    options.log = [&](sfx::LogSeverity, std::string_view m) { logged.emplace_back(m); };
    HostResults host;
    {
        sfx::Result<std::unique_ptr<Renderer>> created = Renderer::create(*context.value(), options);
        if (!created && created.status().code() == sfx::StatusCode::FileError)
            SFX_SKIP(label << ": " << created.status().toString());  // the bunny (glmark2-data) is missing
        INFO(created.status().toString());
        REQUIRE(created.isOk());
        Renderer& r = *created.value();
        INFO(label << ", " << r.tier().reason);

        StateContract contract;
        contract.gl = &r.gl();
        contract.units = std::min<GLint>(contract.get(GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS), 32);
        contract.parkedUnit = contract.units - 1;
        contract.parkedTexture = r.gl().genTexture();  // before the frames: not a steady frame's
        r.gl().BindTexture(GL_TEXTURE_2D, contract.parkedTexture);
        r.gl().texStorage2D(GL_TEXTURE_2D, 1, GL_RGBA8, 4, 4);
        r.gl().BindTexture(GL_TEXTURE_2D, 0);
        contract.parkedSampler = r.gl().genSampler();
        r.hooks.before = [&](SdkCall c) { contract.before(c); };
        r.hooks.after = [&](SdkCall c) { contract.after(c); };

        sfx::Result<FrameLoopResult> loop = runFrames(r, kWarmupFrames, kSteadyFrames);
        INFO(loop.status().toString());
        REQUIRE(loop.isOk());
        WARN(label << ": " << kWarmupFrames + kSteadyFrames << " frames at " << kWidth << "x" << kHeight << ", median " << loop->medianFrameMs
                   << " ms per steady frame (" << loop->medianDispatchMs << " ms in the dispatch() calls); SDK stats " << describe(loop->sdkAtEnd));
        CHECK(loop->sdkMessages.empty());
        INFO(loop->sdkMessages);

        // (b) Nothing made, uploaded or read back in the steady frames, by the SDK or the host.
        INFO("after warm-up: " << describe(loop->sdkAfterWarmup) << "\nat the end:    " << describe(loop->sdkAtEnd));
        CHECK(loop->sdkAfterWarmup == loop->sdkAtEnd);
        CHECK(loop->sdkAtEnd.stagingBuffers.created == 0);  // not one readback copy in any frame
        INFO("host after warm-up: " << describe(loop->hostAfterWarmup) << "\nhost at the end:    " << describe(loop->hostAtEnd));
        CHECK(loop->hostAfterWarmup == loop->hostAtEnd);
        CHECK(loop->hostAtEnd.readbacks == 0);
        CHECK(loop->hostAtEnd.uploads == 4);  // the two meshes' vertex and index buffers, at create

        // (c) The state contract held after every SDK call of every frame.
        CHECK(contract.callsChecked == 2 * (kWarmupFrames + kSteadyFrames));
        INFO(contract.violations);
        CHECK(contract.violations.empty());
        r.hooks = {};
        r.gl().deleteTexture(contract.parkedTexture);
        r.gl().deleteSampler(contract.parkedSampler);

        // The sample's PNG, where the tests keep their pictures.
        if (const char* dir = std::getenv("SFX_TEST_OUTPUT")) {
            const std::string path = std::string(dir) + "/engine_gl_" + toString(api) + ".png";
            ENGINE_REQUIRE_OK(writePresentedPng(r, path));
        }

        // The inputs and results of the last frame, read back once (the SDK's readTexture on the
        // imported textures: the G-buffer exactly as the host rendered it).
        sfx::Device& d = r.device();
        const ImportedTextures& t = r.imported();
        host.depth = readFloats(d, t.depth);
        host.normals = readFloats(d, t.normals);
        host.velocity = readFloats(d, t.velocity);
        host.lit = readFloats(d, t.lit);
        host.ao = readFloats(d, t.ao);
        host.blurred = readFloats(d, t.blurred);
        host.aoDesc = r.aoDesc();
        host.blurDesc = r.motionBlurDesc();
        host.blurSettings = r.motionBlurSettings();
        host.camera = r.camera();
        host.tier = r.tier().tier;
        CHECK(d.takeValidationMessages().empty());
    }
    context.value().reset();  // the host is gone before the SDK opens its own device
    CHECK(logged.empty());

    // The scene moved: velocity reaches several pixels, so the blur had work to do.
    double fastest = 0;
    for (size_t i = 0; i < host.velocity.size(); i += 2) fastest = std::max(fastest, double(std::hypot(host.velocity[i], host.velocity[i + 1])));
    CHECK(fastest > 3.0);

    // (a) The SDK's own path: a device it opened, its own textures, the same inputs and settings.
    const sfx::gl::Api sdkApi = api == ContextApi::GLES ? sfx::gl::Api::GLES : sfx::gl::Api::DesktopGL;
    sfx::DeviceOptions sdkOptions;
    sdkOptions.validation = true;
    sfx::Result<std::unique_ptr<sfx::Device>> opened = sfx::gl::createDevice(sfx::gl::Platform::EGL, sdkApi, sdkOptions);
    INFO(opened.status().toString());
    REQUIRE(opened.isOk());
    sfx::Device& d = *opened.value();
    auto texture = [&](Format f, uint32_t usage, const std::vector<float>& data) {
        sfx::Result<TextureHandle> made = d.createTexture({kWidth, kHeight, 1, f, usage, "engine reference"});
        INFO(made.status().toString());
        REQUIRE(made.isOk());
        if (!data.empty()) writeFloats(d, made.value(), data);
        return made.value();
    };
    const uint32_t sampled = sfx::kTextureSampled, target = sfx::kTextureSampled | sfx::kTextureRenderTarget;
    const TextureHandle depth = texture(Format::D32F, sampled, host.depth);
    const TextureHandle normals = texture(Format::RGBA16F, sampled, host.normals);
    const TextureHandle velocity = texture(Format::RG16F, sampled, host.velocity);
    const TextureHandle lit = texture(Format::RGBA16F, sampled, host.lit);
    const TextureHandle ao = texture(Format::R16F, target, {});
    sfx::Result<std::unique_ptr<sfx::AmbientObscurance>> aoEffect = sfx::AmbientObscurance::create(d, host.aoDesc);
    sfx::Result<std::unique_ptr<sfx::MotionBlur>> blur = sfx::MotionBlur::create(d, host.blurDesc);
    INFO(aoEffect.status().toString() << " / " << blur.status().toString());
    REQUIRE((aoEffect.isOk() && blur.isOk()));
    sfx::AoInputs aoIn;
    aoIn.depth = {depth, sfx::DepthKind::Hardware, host.camera};
    aoIn.normals = normals;
    aoIn.output = ao;
    ENGINE_REQUIRE_OK(aoEffect.value()->dispatch(aoIn));
    sfx::MotionBlurInputs blurIn;
    blurIn.color = lit;
    blurIn.depth = aoIn.depth;
    blurIn.velocity = velocity;
    ENGINE_REQUIRE_OK(blur.value()->dispatch(blurIn, host.blurSettings));
    ENGINE_REQUIRE_OK(d.flush());
    const std::vector<float> sdkAo = readFloats(d, ao);
    const std::vector<float> sdkBlurred = readFloats(d, blur.value()->output());
    CHECK(d.takeValidationMessages().empty());

    const double aoWorst = worstDifference(host.ao, sdkAo);
    const double blurWorst = worstDifference(host.blurred, sdkBlurred);
    WARN(label << ": host path vs the SDK's own, worst pixel: AO " << aoWorst << ", motion blur " << blurWorst);
    CHECK(aoWorst <= (host.tier == sfx::Tier::High ? kAoWorstHigh : kAoWorstCurrent));
    CHECK(blurWorst <= kBlurWorst);
    // Not blank pictures: the bunny occludes the floor, and the blur moved colour.
    CHECK(*std::min_element(sdkAo.begin(), sdkAo.end()) < 0.8f);
    CHECK(worstDifference(host.lit, host.blurred) > 0.05);
}

}  // namespace

TEST_CASE("engine_gl: the sample's GL ES renderer with AO and motion blur on its own textures", "[gles]") { runEngine(ContextApi::GLES); }

TEST_CASE("engine_gl: the sample's desktop GL renderer with AO and motion blur on its own textures", "[desktop]") {
    runEngine(ContextApi::DesktopGL);
}
