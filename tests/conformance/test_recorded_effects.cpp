// Effects replayed in steady frames (Vulkan: Device::beginReplay; elsewhere the same frames
// recorded directly): what a replayed frame writes is, byte for byte, what a fresh effect writes
// on the same inputs and settings, after the host changed an input's contents, a setting or the
// camera between frames; and the replayed frames made no recording. Every backend and tier.
#include <catch2/catch.hpp>

#include <array>
#include <tuple>

#include <glm/gtc/matrix_transform.hpp>

#include "analytic_scenes.hpp"
#include "fault_injection.hpp"
#include "hal_fixture.hpp"
#include "sfx/ao.hpp"
#include "sfx/half.hpp"
#include "sfx/motion_blur.hpp"
#include "test_device.hpp"

using namespace sfx;

namespace {

constexpr uint32_t kWidth = 64, kHeight = 36;

void writeDepth(TextureHandle t, const tools::AnalyticScene& scene) {
    const std::vector<float> depth(scene.linearDepth.values.begin(), scene.linearDepth.values.end());
    SFX_REQUIRE_OK(test::device().writeTexture(t, 0, depth.data(), depth.size() * sizeof(float)));
}

// One frame: the effect's dispatch, the flush, and the output read back (every frame the same,
// so that every frame starts from the states the last one left).
template <class Dispatch>
std::vector<uint8_t> frame(Dispatch&& dispatch, TextureHandle output) {
    SFX_REQUIRE_OK(dispatch());
    SFX_REQUIRE_OK(test::device().flush());
    return test::readLevel<uint8_t>(output);
}

// Replays made no recording: the count of recordings ever made is the same.
void checkNoRecordingMade(const DeviceStats& before, const char* what) {
    const DeviceStats after = test::device().stats();
    INFO(what << ": recordings made " << before.recordings.created << " -> " << after.recordings.created);
    CHECK(after.recordings.created == before.recordings.created);
}

}  // namespace

TEST_CASE("recordings: replayed AO frames equal a fresh effect's after the depth and the settings changed", "[recordings][ao]") {
    Device& dev = test::device();
    const tools::AnalyticScene corner = tools::cornerScene(kWidth, kHeight);
    const tools::AnalyticScene sphere = tools::sphereOnPlaneScene(kWidth, kHeight);
    TextureHandle depth = dev.createTexture({kWidth, kHeight, 1, Format::R32F, kTextureSampled, "replay-depth"}).value();
    const Format outFormat = dev.caps().renderableFormat[size_t(Format::R16F)] ? Format::R16F : Format::RGBA8;
    TextureHandle out = dev.createTexture({kWidth, kHeight, 1, outFormat, kTextureSampled | kTextureRenderTarget, "replay-ao"}).value();
    for (AoTechnique technique : {AoTechnique::Alchemy, AoTechnique::Scalable, AoTechnique::Crease, AoTechnique::Horizon}) {
        INFO(test::label() << " " << toString(technique));
        AoSettings settings;
        settings.technique = technique;
        const AoDesc desc{kWidth, kHeight, test::tierProfile(), settings, DepthKind::Linear};
        std::unique_ptr<AmbientObscurance> ao = AmbientObscurance::create(dev, desc).value();
        AoInputs in;
        in.depth = DepthSource{depth, DepthKind::Linear, corner.camera};
        in.output = out;
        auto dispatch = [&] { return ao->dispatch(in); };
        writeDepth(depth, corner);
        std::vector<uint8_t> cornerAo;
        for (int i = 0; i < 3; ++i) cornerAo = frame(dispatch, out);  // recorded, recorded again, replayed

        const DeviceStats before = dev.stats();
        writeDepth(depth, sphere);
        const std::vector<uint8_t> sphereReplayed = frame(dispatch, out);
        checkNoRecordingMade(before, "after the host rewrote the depth");
        CHECK(sphereReplayed != cornerAo);  // the new contents were read

        AoSettings wider = settings;  // uniforms of every technique (crease reads no radius)
        wider.radius = settings.radius * 2.0f;
        wider.intensity = 0.3f;
        SFX_REQUIRE_OK(ao->setSettings(wider));
        std::vector<uint8_t> widerReplayed;
        for (int i = 0; i < 2; ++i) widerReplayed = frame(dispatch, out);
        CHECK(widerReplayed != sphereReplayed);
        ao.reset();

        for (const auto& [s, replayed, what] : {std::tuple{settings, sphereReplayed, "the depth rewritten"},
                                                std::tuple{wider, widerReplayed, "the radius doubled and the intensity set"}}) {
            AoDesc freshDesc = desc;
            freshDesc.settings = s;
            std::unique_ptr<AmbientObscurance> fresh = AmbientObscurance::create(dev, freshDesc).value();
            const std::vector<uint8_t> direct = frame([&] { return fresh->dispatch(in); }, out);
            INFO(what);
            CHECK(replayed == direct);
        }
    }
    SFX_REQUIRE_OK(dev.destroyTexture(depth));
    SFX_REQUIRE_OK(dev.destroyTexture(out));
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("recordings: replayed motion blur frames equal a fresh effect's as the camera moves", "[recordings][motionblur]") {
    Device& dev = test::device();
    const tools::AnalyticScene scene = tools::tiltedPlaneScene(kWidth, kHeight);
    TextureHandle depth = dev.createTexture({kWidth, kHeight, 1, Format::R32F, kTextureSampled, "replay-depth"}).value();
    writeDepth(depth, scene);
    std::vector<uint16_t> color(size_t(kWidth) * kHeight * 4, floatToHalf(1.0f));
    for (size_t i = 0; i < size_t(kWidth) * kHeight; ++i) {
        color[i * 4 + 0] = floatToHalf(float((i % kWidth) % 8) / 8.0f);  // stripes: blur shows
        color[i * 4 + 1] = floatToHalf(float(i / kWidth) / kHeight);
    }
    TextureHandle colorTex = dev.createTexture({kWidth, kHeight, 1, Format::RGBA16F, kTextureSampled, "replay-colour"}).value();
    SFX_REQUIRE_OK(dev.writeTexture(colorTex, 0, color.data(), color.size() * sizeof(uint16_t)));
    TextureHandle out = dev.createTexture({kWidth, kHeight, 1, Format::RGBA16F, kTextureSampled | kTextureRenderTarget, "replay-blurred"}).value();
    const MotionBlurDesc desc{kWidth, kHeight, test::tierProfile(), Format::RGBA16F, DepthKind::Linear};
    std::unique_ptr<MotionBlur> mb = MotionBlur::create(dev, desc).value();
    MotionBlurInputs in;
    in.color = colorTex;
    in.depth = DepthSource{depth, DepthKind::Linear, scene.camera};
    in.output = out;  // camera-only velocity: the motion is a uniform
    auto moved = [&](double dx) { in.camera.previousViewProjection = glm::translate(glm::dmat4(1.0), glm::dvec3(dx, 0.0, 0.0)); };
    auto dispatch = [&] { return mb->dispatch(in); };
    moved(0.02);
    for (int i = 0; i < 3; ++i) (void)frame(dispatch, out);
    const DeviceStats before = dev.stats();
    std::vector<std::vector<uint8_t>> replayed;
    for (double dx : {0.05, -0.03, 0.0}) {
        moved(dx);
        replayed.push_back(frame(dispatch, out));
    }
    checkNoRecordingMade(before, "as the camera moved");
    mb.reset();
    CHECK(replayed[0] != replayed[1]);
    for (size_t i = 0; i < replayed.size(); ++i) {
        moved(std::array{0.05, -0.03, 0.0}[i]);
        std::unique_ptr<MotionBlur> fresh = MotionBlur::create(dev, desc).value();
        const std::vector<uint8_t> direct = frame([&] { return fresh->dispatch(in); }, out);
        INFO("camera motion " << i);
        CHECK(replayed[i] == direct);
    }
    for (TextureHandle t : {depth, colorTex, out}) SFX_REQUIRE_OK(dev.destroyTexture(t));
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("recordings: a frame whose new recording failed is recorded again at the next frame", "[recordings][motionblur]") {
    // A settings change makes the kept recording stale; if the same frame's new recording then
    // fails (a device error at its last call), the next frame must record afresh rather than
    // try to replay a recording that was never made.
    Device& dev = test::device();
    test::FaultInjectingDevice fd(dev);
    const tools::AnalyticScene scene = tools::tiltedPlaneScene(kWidth, kHeight);
    TextureHandle depth = dev.createTexture({kWidth, kHeight, 1, Format::R32F, kTextureSampled, "refail-depth"}).value();
    writeDepth(depth, scene);
    const std::vector<uint16_t> color(size_t(kWidth) * kHeight * 4, floatToHalf(0.5f));
    TextureHandle colorTex = dev.createTexture({kWidth, kHeight, 1, Format::RGBA16F, kTextureSampled, "refail-colour"}).value();
    SFX_REQUIRE_OK(dev.writeTexture(colorTex, 0, color.data(), color.size() * sizeof(uint16_t)));
    TextureHandle out = dev.createTexture({kWidth, kHeight, 1, Format::RGBA16F, kTextureSampled | kTextureRenderTarget, "refail-blurred"}).value();
    const MotionBlurDesc desc{kWidth, kHeight, test::tierProfile(), Format::RGBA16F, DepthKind::Linear};
    MotionBlurInputs in;
    in.color = colorTex;
    in.depth = DepthSource{depth, DepthKind::Linear, scene.camera};
    in.output = out;
    in.camera.previousViewProjection = glm::translate(glm::dmat4(1.0), glm::dvec3(0.03, 0.0, 0.0));
    MotionBlurSettings first, second;
    second.samples = 5;  // another pipeline: the kept recording's calls no longer match

    // The calls of the frame with the new settings, counted on an effect that runs it cleanly.
    uint64_t calls = 0;
    {
        std::unique_ptr<MotionBlur> mb = MotionBlur::create(fd, desc).value();
        for (int i = 0; i < 3; ++i) (void)frame([&] { return mb->dispatch(in, first); }, out);
        fd.resetCounts();
        SFX_REQUIRE_OK(mb->dispatch(in, second));
        calls = fd.calls();
        SFX_REQUIRE_OK(fd.flush());
    }
    std::unique_ptr<MotionBlur> mb = MotionBlur::create(fd, desc).value();
    for (int i = 0; i < 3; ++i) (void)frame([&] { return mb->dispatch(in, first); }, out);
    fd.loseDevice(calls);  // the frame's last call fails
    const Status failed = mb->dispatch(in, second);
    fd.clearFaults();
    INFO(failed.toString());
    CHECK(failed.code() == StatusCode::DeviceError);
    SFX_REQUIRE_OK(fd.flush());
    std::vector<uint8_t> recovered;
    for (int i = 0; i < 3; ++i) recovered = frame([&] { return mb->dispatch(in, second); }, out);
    mb.reset();
    std::unique_ptr<MotionBlur> fresh = MotionBlur::create(dev, desc).value();
    CHECK(recovered == frame([&] { return fresh->dispatch(in, second); }, out));
    fresh.reset();
    for (TextureHandle t : {depth, colorTex, out}) SFX_REQUIRE_OK(dev.destroyTexture(t));
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}
