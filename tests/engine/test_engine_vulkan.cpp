// The engine sample (samples/engine_vulkan) as it runs: its renderer, on its own Vulkan device
// with validation and synchronization validation, records the SDK's AO and motion blur into its
// own command buffer between its own passes for 60 frames. Checked: after warm-up no frame makes
// an SDK object of any kind or a host object, allocation, descriptor write or staging copy; no
// validation message; and the AO and motion blur of the last frame equal what the SDK's own path
// (SDK textures holding the same inputs, the SDK's own command buffers) computes, within the
// conformance tests' worst-pixel bounds.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "engine_renderer.hpp"
#include "half_bytes.hpp"
#include "skips.hpp"

using namespace sfx;

namespace {

constexpr uint32_t kWidth = 192, kHeight = 108;
constexpr uint32_t kWarmupFrames = 4, kFrames = 60;
// The conformance bounds: the AO's worst pixel on the high tier (tests/conformance/test_ao.cpp,
// kAoWorstPixelHigh) and motion blur's per-value bound on ordinary pixels
// (tests/conformance/test_motion_blur.cpp). The same device on the same inputs should agree
// far better; these are the ceilings.
constexpr double kAoWorstPixel = 0.005;
constexpr double kMotionBlurWorstValue = 2e-3;

double worstDifference(const std::vector<double>& a, const std::vector<double>& b) {
    REQUIRE(a.size() == b.size());
    double worst = 0;
    for (size_t i = 0; i < a.size(); ++i) {
        REQUIRE(std::isfinite(a[i]));
        worst = std::max(worst, std::abs(a[i] - b[i]));
    }
    return worst;
}

void checkSame(const char* kind, const ObjectCount& before, const ObjectCount& after) {
    INFO(kind << ": live " << before.live << " -> " << after.live << ", created " << before.created << " -> " << after.created);
    CHECK(before == after);
}

void checkNothingMade(const DeviceStats& a, const DeviceStats& b) {
    checkSame("textures", a.textures, b.textures);
    checkSame("buffers", a.buffers, b.buffers);
    checkSame("samplers", a.samplers, b.samplers);
    checkSame("programs", a.programs, b.programs);
    checkSame("pipelines", a.pipelines, b.pipelines);
    checkSame("timers", a.timers, b.timers);
    checkSame("recordings", a.recordings, b.recordings);
    checkSame("memoryAllocations", a.memoryAllocations, b.memoryAllocations);
    checkSame("stagingBuffers", a.stagingBuffers, b.stagingBuffers);
    checkSame("descriptorSets", a.descriptorSets, b.descriptorSets);
    checkSame("descriptorPools", a.descriptorPools, b.descriptorPools);
    checkSame("imageViews", a.imageViews, b.imageViews);
    checkSame("framebuffers", a.framebuffers, b.framebuffers);
    CHECK(a.deviceMemoryBytes == b.deviceMemoryBytes);
}

TextureHandle upload(Device& d, Format format, const std::vector<uint8_t>& bytes, uint32_t usage = kTextureSampled) {
    Result<TextureHandle> t = d.createTexture({kWidth, kHeight, 1, format, usage, "engine test input"});
    INFO(t.status().toString());
    REQUIRE(t.isOk());
    if (!bytes.empty()) REQUIRE(d.writeTexture(t.value(), 0, bytes.data(), bytes.size()).isOk());
    return t.value();
}

std::vector<uint8_t> hostImage(engine::EngineRenderer& r, engine::HostImageKind kind, size_t bytes) {
    Result<std::vector<uint8_t>> texels = r.readImage(kind);
    INFO(texels.status().toString());
    REQUIRE(texels.isOk());
    REQUIRE(texels->size() == bytes);
    return texels.value();
}

std::vector<uint8_t> readBack(Device& d, TextureHandle t, size_t bytes) {
    std::vector<uint8_t> out(bytes);
    const Status s = d.readTexture(t, 0, out.data(), out.size());
    INFO(s.toString());
    REQUIRE(s.isOk());
    return out;
}

}  // namespace

TEST_CASE("engine vulkan: the sample's frames make nothing and match the SDK's own path", "[engine][vulkan]") {
    engine::EngineOptions options;
    options.width = kWidth;
    options.height = kHeight;
    options.tier = Tier::High;
    options.validation = true;
    Result<std::unique_ptr<engine::EngineRenderer>> created = engine::EngineRenderer::create(options);
    if (created.status().code() == StatusCode::BackendUnavailable || created.status().code() == StatusCode::FileError)
        SFX_SKIP(created.status().toString());
    INFO(created.status().toString());
    REQUIRE(created.isOk());
    engine::EngineRenderer& r = *created.value();
    Device& d = r.sfxDevice();

    for (uint32_t f = 0; f < kWarmupFrames; ++f) REQUIRE(r.renderFrame().isOk());
    REQUIRE(r.finish().isOk());
    const DeviceStats sdkBefore = d.stats();
    const engine::HostCounts hostBefore = r.hostCounts();
    for (uint32_t f = kWarmupFrames; f < kFrames; ++f) {
        const Status s = r.renderFrame();
        INFO("frame " << f << ": " << s.toString());
        REQUIRE(s.isOk());
    }
    REQUIRE(r.finish().isOk());
    const DeviceStats sdkAfter = d.stats();
    const engine::HostCounts hostAfter = r.hostCounts();
    checkNothingMade(sdkBefore, sdkAfter);
    // The steady frames replayed the effects' recordings inside the host's command buffers
    // (AO and motion blur keep one each; a key whose replays keep failing drops its recording).
    if (d.caps().reusableRecordings) CHECK(sdkAfter.recordings.live >= 2);
    INFO("host: allocations " << hostBefore.memoryAllocations << " -> " << hostAfter.memoryAllocations << ", objects " << hostBefore.objectsCreated
                              << " -> " << hostAfter.objectsCreated << ", descriptor writes " << hostBefore.descriptorWrites << " -> "
                              << hostAfter.descriptorWrites << ", staging copies " << hostBefore.stagingCopies << " -> " << hostAfter.stagingCopies);
    CHECK(hostAfter.memoryAllocations == hostBefore.memoryAllocations);
    CHECK(hostAfter.objectsCreated == hostBefore.objectsCreated);
    CHECK(hostAfter.descriptorWrites == hostBefore.descriptorWrites);
    CHECK(hostAfter.stagingCopies == hostBefore.stagingCopies);
    CHECK(hostAfter.submits == hostBefore.submits + (kFrames - kWarmupFrames));  // the loop did run: one submit a frame

    // The last frame's inputs and outputs, read back once, after the measured frames.
    const size_t n = size_t(kWidth) * kHeight;
    const std::vector<uint8_t> depth = hostImage(r, engine::HostImageKind::Depth, n * 4);
    const std::vector<uint8_t> normals = hostImage(r, engine::HostImageKind::Normals, n * 8);
    const std::vector<uint8_t> velocity = hostImage(r, engine::HostImageKind::Velocity, n * 4);
    const std::vector<uint8_t> lit = hostImage(r, engine::HostImageKind::Lit, n * 8);
    const std::vector<uint8_t> hostAo = hostImage(r, engine::HostImageKind::Ao, n * 2);
    const std::vector<uint8_t> hostBlur = hostImage(r, engine::HostImageKind::Blurred, n * 8);  // MotionBlurInputs::output

    // Not a blank picture: the bunny occludes the floor, and it moves.
    const std::vector<double> aoValues = test::halfBytesToDoubles(hostAo), velocityValues = test::halfBytesToDoubles(velocity);
    CHECK(*std::min_element(aoValues.begin(), aoValues.end()) < 0.8);
    double fastest = 0;
    for (size_t i = 0; i < n; ++i) fastest = std::max(fastest, std::hypot(velocityValues[2 * i], velocityValues[2 * i + 1]));
    WARN("engine vulkan: fastest pixel moves " << fastest << " px a frame");
    CHECK(fastest > 1.0);
    CHECK(worstDifference(test::halfBytesToDoubles(lit), test::halfBytesToDoubles(hostBlur)) > 0.01);  // the blur changed the picture

    // The SDK's own path: the same inputs in SDK textures, new effects with the sample's
    // descriptions and settings, dispatched on the SDK's own command buffers.
    {
        const TextureHandle depthTex = upload(d, Format::D32F, depth);
        const TextureHandle normalTex = upload(d, Format::RGBA16F, normals);
        const TextureHandle velocityTex = upload(d, Format::RG16F, velocity);
        const TextureHandle litTex = upload(d, Format::RGBA16F, lit);
        const TextureHandle aoOut = upload(d, Format::R16F, {}, kTextureSampled | kTextureRenderTarget);
        Result<std::unique_ptr<AmbientObscurance>> ao = AmbientObscurance::create(d, r.ao().desc());
        Result<std::unique_ptr<MotionBlur>> mb = MotionBlur::create(d, r.motionBlur().desc());
        REQUIRE((ao.isOk() && mb.isOk()));
        AoInputs aoIn;
        aoIn.depth = DepthSource{depthTex, DepthKind::Hardware, r.camera()};
        aoIn.normals = normalTex;
        aoIn.output = aoOut;
        REQUIRE(ao.value()->dispatch(aoIn).isOk());
        MotionBlurInputs mbIn;
        mbIn.color = litTex;
        mbIn.depth = DepthSource{depthTex, DepthKind::Hardware, r.camera()};
        mbIn.velocity = velocityTex;
        REQUIRE(mb.value()->dispatch(mbIn, r.motionBlurSettings()).isOk());
        REQUIRE(d.flush().isOk());
        const double aoDiff = worstDifference(aoValues, test::halfBytesToDoubles(readBack(d, aoOut, n * 2)));
        const double mbDiff = worstDifference(test::halfBytesToDoubles(hostBlur), test::halfBytesToDoubles(readBack(d, mb.value()->output(), n * 8)));
        WARN("engine vulkan: worst pixel against the SDK's own path: AO " << aoDiff << ", motion blur " << mbDiff);
        CHECK(aoDiff <= kAoWorstPixel);
        CHECK(mbDiff <= kMotionBlurWorstValue);
        ao.value().reset();
        mb.value().reset();
        for (TextureHandle t : {depthTex, normalTex, velocityTex, litTex, aoOut}) REQUIRE(d.destroyTexture(t).isOk());
    }

    const std::vector<std::string> messages = r.takeValidationMessages();
    for (const std::string& m : messages) UNSCOPED_INFO("validation: " << m);
    CHECK(messages.empty());
}
