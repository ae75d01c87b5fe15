// Bent normals of the horizon technique (AoSettings.bentNormals) on a real backend and tier
// against the CPU reference, within the bound docs/ao.md derives ("Bent normals"); the floor
// beside a wall bending away from it; the named errors; the plan's extra bytes.
#include <catch2/catch.hpp>

#include <cmath>

#include "analytic_scenes.hpp"
#include "bench_device.hpp"
#include "effect_runs.hpp"
#include "sfx/ao.hpp"
#include "sfx/reference/ao_reference.hpp"
#include "skips.hpp"
#include "test_device.hpp"

using namespace sfx;
using reference::Grid;

namespace {

bool drawsNothing() { return test::device().caps().backend == BackendKind::Null; }

// A tap the float position moves to the neighbouring pixel moves a horizon: the bent vector by
// what it moves the visibility, which the tier's visibility bound allows (test_ao.cpp).
double bentTapAllowance() { return test::tier() == Tier::High ? 0.005 : 0.01; }

test::GpuAo runBent(const tools::AnalyticScene& scene, const AoSettings& settings, Format bentFormat) {
    test::GpuAo r = test::runAo(test::device(), test::tierProfile(), scene, settings, DepthKind::Linear, bentFormat);
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
    REQUIRE(r.bentNormals.size() == r.visibility.values.size());
    return r;
}

AoSettings bentSettings(AoResolution resolution, bool blur) {
    AoSettings s = test::aoTestSettings(AoTechnique::Horizon);
    s.bentNormals = true;
    s.resolution = resolution;
    s.blur = blur;
    return s;
}

}  // namespace

TEST_CASE("ao bent normals: match the CPU reference at full and half resolution, blurred or not", "[ao][horizon][bent]") {
    if (drawsNothing()) SFX_SKIP("the null backend draws nothing: GPU results are not compared on " << test::label());
    const Format intermediate = test::tierProfile().aoPackedDepthTarget ? Format::RGBA8 : Format::RGBA16F;
    const Format floatOut = test::pickFormat(test::device(), {Format::RGBA32F, Format::RGBA16F}, true);
    double worstRatio = 0, worstError = 0;
    for (AoResolution resolution : {AoResolution::Full, AoResolution::Half})
        for (bool blur : {false, true})
            for (Format out : {Format::RGBA8, floatOut})
                for (auto make : {&tools::cornerScene, &tools::sphereOnPlaneScene, &tools::columnsScene}) {
                    const tools::AnalyticScene scene = make(96, 64, 1.0);
                    const AoSettings s = bentSettings(resolution, blur);
                    INFO(test::label() << " " << scene.name << " " << toString(resolution) << (blur ? " blur" : "") << " into " << toString(out));
                    const test::GpuAo gpu = runBent(scene, s, out);
                    const reference::BentNormals ref = reference::ambientBentNormals(scene.aoInput(false), gpu.config);
                    // The visibility beside them is the technique's own (test_ao.cpp bounds it): the
                    // same reference, the tier's worst-pixel bound.
                    const Grid vis = reference::ambientVisibility(scene.aoInput(false), gpu.config);
                    double worstVis = 0;
                    for (size_t i = 0; i < vis.values.size(); ++i) worstVis = std::max(worstVis, std::abs(vis.values[i] - gpu.visibility.values[i]));
                    CHECK(worstVis <= bentTapAllowance() + test::kAoHorizonTrigBound);
                    const int intermediates = test::bentIntermediates(gpu.config);
                    size_t failures = 0;
                    for (size_t i = 0; i < gpu.bentNormals.size(); ++i) {
                        const glm::dvec3 g = gpu.bentNormals[i];
                        REQUIRE(std::isfinite(g.x + g.y + g.z));
                        const glm::dvec3 d = glm::abs(g - ref.normals[i]);
                        const double e = std::max(d.x, std::max(d.y, d.z));
                        const double bound = test::bentComponentBound(bentTapAllowance() + test::kBentTrigAllowance, ref.vectorLength[i],
                                                                      ref.resolveLength[i], intermediate, intermediates, out);
                        worstError = std::max(worstError, e);
                        if (std::isfinite(ref.vectorLength[i])) worstRatio = std::max(worstRatio, e / bound);  // sky is one rounding
                        if (e > bound && failures++ < 3) {
                            INFO("pixel " << i % scene.width << "," << i / scene.width << ": gpu " << g.x << " " << g.y << " " << g.z
                                          << ", reference " << ref.normals[i].x << " " << ref.normals[i].y << " " << ref.normals[i].z << ", off by "
                                          << e << ", bound " << bound << " (vector length " << ref.vectorLength[i] << ", resolve length "
                                          << ref.resolveLength[i] << ")");
                            CHECK(e <= bound);
                        }
                    }
                    CHECK(failures == 0);
                }
    WARN(test::label() << ": bent normals' worst component error " << worstError << ", worst error / bound off the sky " << worstRatio);
}

TEST_CASE("ao bent normals: the floor beside a wall bends away from it on the device", "[ao][horizon][bent]") {
    if (drawsNothing()) SFX_SKIP("the null backend draws nothing: GPU results are not compared on " << test::label());
    // The corner's plane A within the radius of the crease: its bent normals lean away from
    // plane B, along B's normal (which points out of B into the open corner; A's normal is
    // orthogonal to it), the more the nearer the crease; a sign or axis slip in the arc vector
    // (along V and t swapped, a side's sign) turns them toward it.
    const tools::AnalyticScene scene = tools::cornerScene(96, 64, 1.0);
    for (AoResolution resolution : {AoResolution::Full, AoResolution::Half}) {
        const test::GpuAo gpu = runBent(scene, bentSettings(resolution, true), Format::RGBA8);
        double nearSum = 0, farSum = 0;
        size_t nearCount = 0, farCount = 0;
        for (size_t i = 0; i < gpu.bentNormals.size(); ++i) {
            if (!tools::onCornerPlaneA(scene.positions[i], scene.normals[i])) continue;
            const double d = tools::distanceToCrease(scene.positions[i]), lean = glm::dot(gpu.bentNormals[i], tools::kCornerNormalB);
            if (d > 0.05 && d < 0.2) {
                nearSum += lean;
                ++nearCount;
            } else if (d > 0.3 && d < 0.45) {
                farSum += lean;
                ++farCount;
            }
        }
        REQUIRE(nearCount > 10);
        REQUIRE(farCount > 10);
        INFO(test::label() << " " << toString(resolution) << ": mean lean away from the wall near it " << nearSum / double(nearCount) << ", farther "
                           << farSum / double(farCount));
        CHECK(nearSum / double(nearCount) > 0.2);  // the converged reference tilts 0.31 to 0.46 rad there
        CHECK(nearSum / double(nearCount) > farSum / double(farCount));
    }
}

TEST_CASE("ao bent normals: setSettings turns them on and off; the visibility beside them is the same", "[ao][horizon][bent]") {
    if (drawsNothing()) SFX_SKIP("the null backend draws nothing: GPU results are not compared on " << test::label());
    // The bent variants compute the visibility with the plain programs' code: within the 1e-5
    // the backends agree to where only the order of float operations may differ
    // (docs/conformance.md), whichever program ran.
    Device& dev = test::device();
    const tools::AnalyticScene scene = tools::cornerScene(64, 48, 1.0);
    AoSettings on = bentSettings(AoResolution::Tier, true), off = on;
    off.bentNormals = false;
    Result<std::unique_ptr<AmbientObscurance>> ao = AmbientObscurance::create(dev, {64, 48, test::tierProfile(), off, DepthKind::Linear});
    REQUIRE(ao.isOk());
    std::vector<float> depth(scene.linearDepth.values.begin(), scene.linearDepth.values.end());
    TextureHandle depthTex = dev.createTexture({64, 48, 1, Format::R32F, kTextureSampled, "bent-toggle-depth"}).value();
    SFX_REQUIRE_OK(dev.writeTexture(depthTex, 0, depth.data(), depth.size() * sizeof(float)));
    const Format of = test::pickFormat(dev, {Format::R32F}, true);
    TextureHandle outTex = dev.createTexture({64, 48, 1, of, kTextureSampled | kTextureRenderTarget, "bent-toggle-ao"}).value();
    TextureHandle bentTex = dev.createTexture({64, 48, 1, Format::RGBA8, kTextureSampled | kTextureRenderTarget, "bent-toggle-bent"}).value();
    AoInputs in;
    in.depth = DepthSource{depthTex, DepthKind::Linear, scene.camera};
    in.output = outTex;
    auto visibility = [&] {
        SFX_REQUIRE_OK(dev.flush());
        std::vector<double> v(64 * 48);
        if (of == Format::R32F) {
            std::vector<float> px(v.size());
            SFX_REQUIRE_OK(dev.readTexture(outTex, 0, px.data(), px.size() * sizeof(float)));
            for (size_t i = 0; i < v.size(); ++i) v[i] = px[i];
        } else {
            std::vector<uint8_t> px(v.size() * 4);
            SFX_REQUIRE_OK(dev.readTexture(outTex, 0, px.data(), px.size()));
            for (size_t i = 0; i < v.size(); ++i) v[i] = px[i * 4] / 255.0;
        }
        return v;
    };
    SFX_REQUIRE_OK(ao.value()->dispatch(in));
    const std::vector<double> plain = visibility();
    SFX_REQUIRE_OK(ao.value()->setSettings(on));
    CHECK(ao.value()->dispatch(in).code() == StatusCode::InvalidArgument);  // no bent target given
    in.bentNormals = bentTex;
    SFX_REQUIRE_OK(ao.value()->dispatch(in));
    const std::vector<double> withBent = visibility();
    // A second frame (a replayed recording on Vulkan) writes the same bytes.
    auto bentBytes = [&] {
        std::vector<uint8_t> px(64 * 48 * 4);
        SFX_REQUIRE_OK(dev.readTexture(bentTex, 0, px.data(), px.size()));
        return px;
    };
    const std::vector<uint8_t> firstBent = bentBytes();
    SFX_REQUIRE_OK(ao.value()->dispatch(in));
    CHECK(visibility() == withBent);
    CHECK(bentBytes() == firstBent);
    double worst = 0;
    for (size_t i = 0; i < plain.size(); ++i) worst = std::max(worst, std::abs(plain[i] - withBent[i]));
    CHECK(worst <= (of == Format::R32F ? 1e-5 : 1.0 / 255.0));
    SFX_REQUIRE_OK(ao.value()->setSettings(off));
    in.bentNormals = {};
    SFX_REQUIRE_OK(ao.value()->dispatch(in));
    SFX_REQUIRE_OK(dev.flush());
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
    for (TextureHandle t : {depthTex, outTex, bentTex}) SFX_REQUIRE_OK(dev.destroyTexture(t));
}

TEST_CASE("ao bent normals: named errors, and the plan lists their targets", "[ao][horizon][bent][bad-input]") {
    Device& dev = test::device();
    const TierProfile& profile = test::tierProfile();
    AoSettings s = test::aoTestSettings(AoTechnique::Scalable);
    s.bentNormals = true;
    Status st = AmbientObscurance::create(dev, {64, 48, profile, s}).status();
    CHECK(st.code() == StatusCode::InvalidArgument);
    CHECK(st.message().find("AoSettings.bentNormals") != std::string::npos);
    CHECK(st.message().find("horizon") != std::string::npos);

    s = bentSettings(AoResolution::Tier, true);
    Result<std::unique_ptr<AmbientObscurance>> ao = AmbientObscurance::create(dev, {64, 48, profile, s});
    REQUIRE(ao.isOk());
    AoSettings off = s;
    off.bentNormals = false;
    Result<std::unique_ptr<AmbientObscurance>> plain = AmbientObscurance::create(dev, {64, 48, profile, off});
    REQUIRE(plain.isOk());
    const uint64_t bentBytes = ao.value()->plan().totalBytes(), plainBytes = plain.value()->plan().totalBytes();
    CHECK(bentBytes > plainBytes);                                                    // the raw and blur bent normal targets
    const uint64_t pixels = ao.value()->config().halfResolution ? 32 * 24 : 64 * 48;  // the passes' size
    CHECK(bentBytes - plainBytes == 2 * pixels * (profile.aoPackedDepthTarget ? 4 : 8));

    TextureHandle depth = dev.createTexture({64, 48, 1, Format::R32F, kTextureSampled, "bent-err-depth"}).value();
    TextureHandle out = dev.createTexture({64, 48, 1, Format::RGBA8, kTextureSampled | kTextureRenderTarget, "bent-err-out"}).value();
    TextureHandle wrong = dev.createTexture({64, 48, 1, Format::R8, kTextureSampled | kTextureRenderTarget, "bent-err-r8"}).value();
    TextureHandle small = dev.createTexture({32, 48, 1, Format::RGBA8, kTextureSampled | kTextureRenderTarget, "bent-err-small"}).value();
    AoInputs in;
    in.depth = DepthSource{depth, DepthKind::Linear, tools::facingPlaneScene(64, 48).camera};
    in.output = out;
    for (TextureHandle b : {TextureHandle{}, wrong, small}) {
        in.bentNormals = b;
        const Status d = ao.value()->dispatch(in);
        INFO(d.message());
        CHECK(d.code() == StatusCode::InvalidArgument);
        CHECK(d.message().find("AoInputs.bentNormals") != std::string::npos);
    }
    for (TextureHandle t : {depth, out, wrong, small}) SFX_REQUIRE_OK(dev.destroyTexture(t));
}
