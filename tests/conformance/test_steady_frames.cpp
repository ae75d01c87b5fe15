// Steady frames: once an effect (AO, motion blur, transparency) has run at a size and settings, the frames after it make no
// object (Device::stats() the same before and after, creation totals included) and the
// process's resident memory stays flat, on every backend and tier.
#include <catch2/catch.hpp>

#include <cstdio>

#include <glm/gtc/matrix_transform.hpp>

#include "analytic_scenes.hpp"
#include "effect_runs.hpp"
#include "sfx/ao.hpp"
#include "sfx/half.hpp"
#include "sfx/motion_blur.hpp"
#include "sfx/oit.hpp"
#include "steady_frames.hpp"
#include "test_device.hpp"

using namespace sfx;

namespace {

constexpr uint32_t kWidth = 160, kHeight = 90;
constexpr int kWarmupFrames = 5;
constexpr int kSteadyFrames = 300;
// Runs `frame` (record and flush one frame) for warm-up, then for the steady frames, and checks
// that the steady ones made nothing and kept memory flat.
template <class Frame>
void checkSteady(const std::string& what, Frame&& frame) {
    Device& dev = test::device();
    for (int i = 0; i < kWarmupFrames; ++i) {
        SFX_REQUIRE_OK(frame());
        SFX_REQUIRE_OK(dev.flush());
    }
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
    const DeviceStats before = dev.stats();
    const double rssBefore = test::residentMiB();
    for (int i = 0; i < kSteadyFrames; ++i) {
        Status s = frame();
        if (s) s = dev.flush();
        if (!s) FAIL(what << " frame " << i << ": " << s.toString());
    }
    const double growth = test::residentMiB() - rssBefore;
    const DeviceStats after = dev.stats();
    std::printf("steady frames %s %s: %d frames, resident %+.2f MiB, device memory %llu bytes in %llu allocations\n", test::label().c_str(),
                what.c_str(), kSteadyFrames, growth, static_cast<unsigned long long>(after.deviceMemoryBytes),
                static_cast<unsigned long long>(after.memoryAllocations.live));
    INFO(what);
    test::checkNothingMade(before, after);
    test::checkResidentFlat(dev.caps().backend, growth);
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

}  // namespace

TEST_CASE("steady frames: AO of each technique makes no object and keeps memory flat", "[steady][ao]") {
    Device& dev = test::device();
    const tools::AnalyticScene scene = tools::cornerScene(kWidth, kHeight);
    const std::vector<float> depth(scene.linearDepth.values.begin(), scene.linearDepth.values.end());
    TextureHandle depthTex = dev.createTexture({kWidth, kHeight, 1, Format::R32F, kTextureSampled, "steady-depth"}).value();
    SFX_REQUIRE_OK(dev.writeTexture(depthTex, 0, depth.data(), depth.size() * sizeof(float)));
    const Format outFormat = dev.caps().renderableFormat[size_t(Format::R16F)] ? Format::R16F : Format::RGBA8;
    TextureHandle outTex = dev.createTexture({kWidth, kHeight, 1, outFormat, kTextureSampled | kTextureRenderTarget, "steady-ao"}).value();
    for (AoTechnique technique : {AoTechnique::Alchemy, AoTechnique::Scalable, AoTechnique::Crease, AoTechnique::Horizon}) {
        AoSettings settings;
        settings.technique = technique;
        // Hardware depth in the desc: the linearisation pass (and on the high tier the MIP) runs too.
        Result<std::unique_ptr<AmbientObscurance>> ao = AmbientObscurance::create(
            dev, {kWidth, kHeight, test::tierProfile(), settings, DepthKind::Hardware});
        INFO(ao.status().toString());
        REQUIRE(ao.isOk());
        AoInputs in;
        in.depth = DepthSource{depthTex, DepthKind::Linear, scene.camera};
        in.output = outTex;
        checkSteady(std::string("ao ") + toString(technique), [&] { return ao.value()->dispatch(in); });
    }
    SFX_REQUIRE_OK(dev.destroyTexture(depthTex));
    SFX_REQUIRE_OK(dev.destroyTexture(outTex));
}

TEST_CASE("steady frames: motion blur makes no object and keeps memory flat", "[steady][motionblur]") {
    Device& dev = test::device();
    const tools::AnalyticScene scene = tools::tiltedPlaneScene(kWidth, kHeight);
    const std::vector<float> depth(scene.linearDepth.values.begin(), scene.linearDepth.values.end());
    TextureHandle depthTex = dev.createTexture({kWidth, kHeight, 1, Format::R32F, kTextureSampled, "steady-depth"}).value();
    SFX_REQUIRE_OK(dev.writeTexture(depthTex, 0, depth.data(), depth.size() * sizeof(float)));
    std::vector<uint16_t> color(size_t(kWidth) * kHeight * 4, floatToHalf(1.0f));
    std::vector<float> velocity(size_t(kWidth) * kHeight * 4);
    for (size_t i = 0; i < size_t(kWidth) * kHeight; ++i) {
        color[i * 4 + 0] = floatToHalf(float(i % kWidth) / kWidth);
        color[i * 4 + 1] = floatToHalf(float(i / kWidth) / kHeight);
        velocity[i * 4 + 0] = 6.0f;  // pixels per shutter interval
        velocity[i * 4 + 1] = -3.0f;
    }
    TextureHandle colorTex = dev.createTexture({kWidth, kHeight, 1, Format::RGBA16F, kTextureSampled, "steady-colour"}).value();
    TextureHandle velocityTex = dev.createTexture({kWidth, kHeight, 1, Format::RGBA32F, kTextureSampled, "steady-velocity"}).value();
    SFX_REQUIRE_OK(dev.writeTexture(colorTex, 0, color.data(), color.size() * sizeof(uint16_t)));
    SFX_REQUIRE_OK(dev.writeTexture(velocityTex, 0, velocity.data(), velocity.size() * sizeof(float)));
    Result<std::unique_ptr<MotionBlur>> mb = MotionBlur::create(dev, {kWidth, kHeight, test::tierProfile(), Format::RGBA16F, DepthKind::Hardware});
    INFO(mb.status().toString());
    REQUIRE(mb.isOk());
    MotionBlurInputs in;
    in.color = colorTex;
    in.depth = DepthSource{depthTex, DepthKind::Linear, scene.camera};
    in.velocity = velocityTex;
    checkSteady("motion blur (velocity texture)", [&] { return mb.value()->dispatch(in); });
    in.velocity = {};  // camera-only velocity from depth
    in.camera.previousViewProjection[3][0] = 0.02;
    checkSteady("motion blur (camera velocity)", [&] { return mb.value()->dispatch(in); });
    for (TextureHandle t : {depthTex, colorTex, velocityTex}) SFX_REQUIRE_OK(dev.destroyTexture(t));
}

namespace {

// The depth texture, AO output, colour and velocity of one size, for the resize cases.
struct SizedInputs {
    TextureHandle depth, aoOut, color, velocity;
    tools::AnalyticScene scene;
};

SizedInputs makeInputs(uint32_t w, uint32_t h) {
    Device& dev = test::device();
    SizedInputs s{{}, {}, {}, {}, tools::cornerScene(w, h)};
    const std::vector<float> depth(s.scene.linearDepth.values.begin(), s.scene.linearDepth.values.end());
    s.depth = dev.createTexture({w, h, 1, Format::R32F, kTextureSampled, "resize-depth"}).value();
    SFX_REQUIRE_OK(dev.writeTexture(s.depth, 0, depth.data(), depth.size() * sizeof(float)));
    const Format outFormat = dev.caps().renderableFormat[size_t(Format::R16F)] ? Format::R16F : Format::RGBA8;
    s.aoOut = dev.createTexture({w, h, 1, outFormat, kTextureSampled | kTextureRenderTarget, "resize-ao"}).value();
    const std::vector<uint16_t> color(size_t(w) * h * 4, floatToHalf(0.5f));
    std::vector<float> velocity(size_t(w) * h * 4, 0.0f);
    for (size_t i = 0; i < size_t(w) * h; ++i) velocity[i * 4] = 5.0f;
    s.color = dev.createTexture({w, h, 1, Format::RGBA16F, kTextureSampled, "resize-colour"}).value();
    s.velocity = dev.createTexture({w, h, 1, Format::RGBA32F, kTextureSampled, "resize-velocity"}).value();
    SFX_REQUIRE_OK(dev.writeTexture(s.color, 0, color.data(), color.size() * sizeof(uint16_t)));
    SFX_REQUIRE_OK(dev.writeTexture(s.velocity, 0, velocity.data(), velocity.size() * sizeof(float)));
    return s;
}

void destroyInputs(const SizedInputs& s) {
    for (TextureHandle t : {s.depth, s.aoOut, s.color, s.velocity}) SFX_REQUIRE_OK(test::device().destroyTexture(t));
}

// Resizes with `resize`, dispatches at the new size with `frame`, and checks that no program or
// pipeline was made (and that the size-dependent textures were: the resize did happen).
template <class Resize, class Frame>
void checkResizeKeepsPipelines(const std::string& what, Resize&& resize, Frame&& frame) {
    Device& dev = test::device();
    const DeviceStats before = dev.stats();
    SFX_REQUIRE_OK(resize());
    SFX_REQUIRE_OK(frame());
    SFX_REQUIRE_OK(dev.flush());
    const DeviceStats after = dev.stats();
    INFO(what << ": programs created " << before.programs.created << " -> " << after.programs.created << ", pipelines created "
              << before.pipelines.created << " -> " << after.pipelines.created);
    CHECK(after.programs.created == before.programs.created);
    CHECK(after.pipelines.created == before.pipelines.created);
    CHECK(after.textures.created > before.textures.created);
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

}  // namespace

TEST_CASE("steady frames: transparency makes no object and keeps memory flat", "[steady][oit]") {
    // The high tier's A-buffer with compressed lists and layer AO (brute force and compressed,
    // filtered), the current tier's weighted blended OIT. (The filter's vertical pipeline was once
    // made again at every frame: 300 pipelines and about 1 MiB a frame.)
    Device& dev = test::device();
    const test::TranslucentQuads quads(dev, kWidth, kHeight, 0.8f, {0.3f, 0.1f});
    TextureHandle color = dev.createTexture({kWidth, kHeight, 1, Format::RGBA16F, kTextureSampled | kTextureRenderTarget, "steady-opaque"}).value();
    const std::vector<uint16_t> grey(size_t(kWidth) * kHeight * 4, floatToHalf(0.5f));
    SFX_REQUIRE_OK(dev.writeTexture(color, 0, grey.data(), grey.size() * sizeof(uint16_t)));
    const bool layers = test::tierProfile().abufferOit;
    std::vector<std::pair<std::string, TransparencyDesc>> configs;
    TransparencyDesc plain;
    plain.width = kWidth;
    plain.height = kHeight;
    plain.profile = test::tierProfile();
    configs.push_back({layers ? "a-buffer" : "weighted blended", plain});
    if (layers) {
        for (TransparencyAoOccluders occ : {TransparencyAoOccluders::BruteForce, TransparencyAoOccluders::Compressed}) {
            TransparencyDesc d = plain;
            d.compressedNodes = 4;
            d.ao.enabled = true;
            d.ao.config.technique = AoTechnique::Scalable;
            d.ao.config.radius = 0.5;
            d.ao.config.samples = 9;
            d.ao.occluders = occ;
            d.ao.filterRadius = dev.caps().renderableFormat[size_t(Format::RGBA32F)] ? 2 : 0;
            configs.push_back({occ == TransparencyAoOccluders::Compressed ? "a-buffer, compressed AO" : "a-buffer, brute-force AO", d});
        }
    }
    for (const auto& [name, desc] : configs) {
        Result<std::unique_ptr<Transparency>> oit = Transparency::create(dev, desc);
        INFO(oit.status().toString());
        REQUIRE(oit.isOk());
        TransparencyInputs in;
        in.opaqueColor = color;
        in.opaqueDepth = quads.opaqueDepth;
        // Compression and layer AO need a perspective camera (the quads' own is orthographic).
        const bool zeroToOne = dev.caps().clipDepth == ClipDepthRange::ZeroToOne;
        const float aspect = float(kWidth) / float(kHeight), fovY = glm::radians(60.0f);
        in.projection = desc.compressedNodes == 0 ? quads.projection
            : zeroToOne                           ? glm::perspectiveRH_ZO(fovY, aspect, 0.5f, 20.0f)
                                                  : glm::perspectiveRH_NO(fovY, aspect, 0.5f, 20.0f);
        in.draws = quads.draws;
        checkSteady("transparency (" + name + ")", [&] { return oit.value()->render(in); });
    }
    SFX_REQUIRE_OK(dev.destroyTexture(color));
}

TEST_CASE("resize: AO and motion blur rebuild textures, never programs or pipelines", "[steady][resize]") {
    Device& dev = test::device();
    constexpr uint32_t kW2 = 200, kH2 = 120;  // the same depth MIP level count as 160x90
    const SizedInputs a = makeInputs(kWidth, kHeight), b = makeInputs(kW2, kH2);
    for (AoTechnique technique : {AoTechnique::Alchemy, AoTechnique::Scalable, AoTechnique::Crease, AoTechnique::Horizon}) {
        AoSettings settings;
        settings.technique = technique;
        Result<std::unique_ptr<AmbientObscurance>> ao = AmbientObscurance::create(
            dev, {kWidth, kHeight, test::tierProfile(), settings, DepthKind::Hardware});
        INFO(ao.status().toString());
        REQUIRE(ao.isOk());
        auto aoFrame = [&](const SizedInputs& s) {
            AoInputs in;
            in.depth = DepthSource{s.depth, DepthKind::Linear, s.scene.camera};
            in.output = s.aoOut;
            return ao.value()->dispatch(in);
        };
        SFX_REQUIRE_OK(aoFrame(a));
        SFX_REQUIRE_OK(dev.flush());
        const std::string what = std::string("ao ") + toString(technique);
        checkResizeKeepsPipelines(
            what + " grow", [&] { return ao.value()->resize(kW2, kH2); }, [&] { return aoFrame(b); });
        checkResizeKeepsPipelines(
            what + " shrink", [&] { return ao.value()->resize(kWidth, kHeight); }, [&] { return aoFrame(a); });
    }

    Result<std::unique_ptr<MotionBlur>> mb = MotionBlur::create(dev, {kWidth, kHeight, test::tierProfile(), Format::RGBA16F, DepthKind::Hardware});
    INFO(mb.status().toString());
    REQUIRE(mb.isOk());
    MotionBlurSettings settings;
    settings.referenceRows = 0;  // the radius in output pixels, so the tile size does not follow the height
    auto mbFrame = [&](const SizedInputs& s) {
        MotionBlurInputs in;
        in.color = s.color;
        in.depth = DepthSource{s.depth, DepthKind::Linear, s.scene.camera};
        in.velocity = s.velocity;
        return mb.value()->dispatch(in, settings);
    };
    SFX_REQUIRE_OK(mbFrame(a));
    SFX_REQUIRE_OK(dev.flush());
    checkResizeKeepsPipelines(
        "motion blur grow", [&] { return mb.value()->resize(kW2, kH2); }, [&] { return mbFrame(b); });
    checkResizeKeepsPipelines(
        "motion blur shrink", [&] { return mb.value()->resize(kWidth, kHeight); }, [&] { return mbFrame(a); });
    destroyInputs(a);
    destroyInputs(b);
}
