// Ambient obscurance on a real backend and tier against the CPU reference, plus the analytic
// properties every correct implementation has. Tolerances are justified in docs/ao.md.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <map>

#include "analytic_scenes.hpp"
#include "effect_runs.hpp"
#include "portability_rows.hpp"
#include "sfx/ao.hpp"
#include "sfx/reference/ao_reference.hpp"
#include "skips.hpp"
#include "test_device.hpp"

using namespace sfx;
using reference::Grid;

namespace {

// The worst pixel against the reference, per tier (docs/ao.md states them beside the measured
// worst values): high, a half-float output (11-bit mantissa; the AO target itself is 32-bit)
// plus float-vs-double taps; current, two
// 8-bit roundings of the AO (before and after the blur, 2 x 1/510) on top of that.
constexpr double kAoWorstPixelHigh = 0.005, kAoWorstPixelCurrent = 0.01;
using test::kAoHorizonTrigBound;
// The mean signed error over occluded pixels: rounding averages out; a biased term does not.
constexpr double kAoOccludedBiasBound = 0.002;

const AoTechnique kTechniques[] = {AoTechnique::Alchemy, AoTechnique::Scalable, AoTechnique::Crease, AoTechnique::Horizon};

bool drawsNothing() { return test::device().caps().backend == BackendKind::Null; }

using test::GpuAo;

GpuAo runAo(const tools::AnalyticScene& scene, const AoSettings& settings, DepthKind descInput = DepthKind::Linear) {
    GpuAo result = test::runAo(test::device(), test::tierProfile(), scene, settings, descInput);
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
    return result;
}

// GPU-vs-reference bounds per tier, lowest first (the current tier's 4 mirrored taps and 6
// Alchemy samples average fewer taps, so one moved tap weighs more).
struct Tolerance {
    double rmse;   // whole image
    double pixel;  // per pixel: at most 1% of pixels may be off by more
    double worst;  // the worst pixel
};
const Tolerance kTolerance[kTierCount] = {{0.02, 0.05, kAoWorstPixelCurrent}, {0.01, 0.03, kAoWorstPixelHigh}};
const Tolerance& tolerance() { return kTolerance[size_t(test::tier())]; }

AoSettings settingsFor(AoTechnique t, double scale = 1.0) { return test::aoTestSettings(t, scale); }

// A GPU result against its reference: every pixel finite and in [0, 1], then the figures the
// tier's Tolerance and kAoOccludedBiasBound bound.
struct AgainstReference {
    double rmse = 0, worst = 0, occludedBias = 0, meanAbs = 0;
    size_t off = 0, occluded = 0;  // pixels off by more than Tolerance::pixel; pixels the reference occludes
};
AgainstReference compareWithReference(const Grid& gpu, const Grid& ref) {
    AgainstReference r;
    double sq = 0, occludedSigned = 0, sumAbs = 0;
    for (size_t i = 0; i < ref.values.size(); ++i) {
        const double g = gpu.values[i];
        REQUIRE(std::isfinite(g));
        REQUIRE(g >= 0.0);
        REQUIRE(g <= 1.0);
        const double e = std::abs(g - ref.values[i]);
        sq += e * e;
        sumAbs += e;
        r.worst = std::max(r.worst, e);
        r.off += e > tolerance().pixel;
        if (ref.values[i] < 1.0 - 1e-6) {
            occludedSigned += g - ref.values[i];
            ++r.occluded;
        }
    }
    r.rmse = std::sqrt(sq / double(ref.values.size()));
    r.meanAbs = sumAbs / double(ref.values.size());
    r.occludedBias = r.occluded ? occludedSigned / double(r.occluded) : 0.0;
    return r;
}
// The four bounds, with the figures in the message.
void checkWithinTolerance(const AgainstReference& r, size_t pixels, AoTechnique t) {
    INFO("rmse " << r.rmse << " worst pixel " << r.worst << " pixels off " << r.off << " mean signed error over " << r.occluded << " occluded pixels "
                 << r.occludedBias);
    CHECK(r.rmse < tolerance().rmse);
    CHECK(double(r.off) < 0.01 * double(pixels));
    CHECK(r.worst <= tolerance().worst + (t == AoTechnique::Horizon ? kAoHorizonTrigBound : 0.0));
    CHECK(std::abs(r.occludedBias) <= kAoOccludedBiasBound);
}

// One dispatch of an existing context on `scene` (linear depth read in place, R32F output
// where renderable, else RGBA8), read back.
Grid dispatchOn(Device& dev, AmbientObscurance& ao, const tools::AnalyticScene& scene) {
    std::vector<float> depth(scene.linearDepth.values.begin(), scene.linearDepth.values.end());
    TextureHandle depthTex = dev.createTexture({scene.width, scene.height, 1, Format::R32F, kTextureSampled, "ao-test-depth"}).value();
    SFX_REQUIRE_OK(dev.writeTexture(depthTex, 0, depth.data(), depth.size() * sizeof(float)));
    const bool r32 = dev.caps().renderableFormat[size_t(Format::R32F)];
    const Format of = r32 ? Format::R32F : Format::RGBA8;
    TextureHandle outTex = dev.createTexture({scene.width, scene.height, 1, of, kTextureSampled | kTextureRenderTarget, "ao-test-out"}).value();
    AoInputs in;
    in.depth = DepthSource{depthTex, DepthKind::Linear, scene.camera};
    in.output = outTex;
    SFX_REQUIRE_OK(ao.dispatch(in));
    SFX_REQUIRE_OK(dev.flush());
    const size_t n = size_t(scene.width) * scene.height;
    Grid out(scene.width, scene.height);
    if (r32) {
        std::vector<float> px(n);
        SFX_REQUIRE_OK(dev.readTexture(outTex, 0, px.data(), px.size() * sizeof(float)));
        for (size_t i = 0; i < n; ++i) out.values[i] = px[i];
    } else {
        std::vector<uint8_t> px(n * 4);
        SFX_REQUIRE_OK(dev.readTexture(outTex, 0, px.data(), px.size()));
        for (size_t i = 0; i < n; ++i) out.values[i] = px[i * 4] / 255.0;
    }
    for (TextureHandle t : {depthTex, outTex}) SFX_REQUIRE_OK(dev.destroyTexture(t));
    return out;
}

}  // namespace

TEST_CASE("ao: each technique matches its CPU reference, at full and half resolution", "[ao]") {
    if (drawsNothing()) SFX_SKIP("the null backend draws nothing: GPU results are not compared on " << test::label());
    // Float vs double tap positions move a rare tap to the neighbouring pixel (docs/ao.md):
    // an RMSE bound, a bound on the share of pixels off by more than `pixelTol`, a bound on the
    // worst pixel, and a bound on the mean signed error over the occluded pixels (reference
    // below 1), which the many unoccluded pixels cannot dilute and which catches a bias. At half
    // resolution the reference runs the same half-size pipeline and upsample (config.halfResolution).
    const double worstTol = tolerance().worst;
    const double biasTol = kAoOccludedBiasBound;
    double worstSeen = 0, worstBias = 0;
    std::map<AoTechnique, std::pair<double, double>> perTechnique;  // worst pixel, summed mean |error|
    for (AoResolution resolution : {AoResolution::Full, AoResolution::Half})
        for (AoTechnique t : kTechniques)
            for (bool blur : {false, true})
                for (bool gbuffer : {false, true})
                    for (auto make : {&tools::cornerScene, &tools::sphereOnPlaneScene, &tools::columnsScene}) {
                        // Even sizes: an odd width puts a pixel centre exactly on the corner's crease, where the
                        // normal rule's tie (both neighbours equally close) falls either way in float.
                        const bool half = resolution == AoResolution::Half;
                        const tools::AnalyticScene scene = make(96, 64, 1.0);
                        AoSettings s = settingsFor(t);
                        s.blur = blur;
                        s.resolution = resolution;
                        s.normals = gbuffer ? AoNormals::FromTexture : AoNormals::FromDepth;
                        INFO(test::label() << " " << toString(t) << " " << scene.name << " " << toString(resolution) << (blur ? " blur" : "")
                                           << (gbuffer ? " gbuffer-normals" : ""));
                        const GpuAo gpu = runAo(scene, s);
                        REQUIRE(gpu.config.halfResolution == half);
                        const Grid ref = reference::ambientVisibility(scene.aoInput(gbuffer), gpu.config);
                        const AgainstReference r = compareWithReference(gpu.visibility, ref);
                        worstSeen = std::max(worstSeen, r.worst);
                        worstBias = std::max(worstBias, std::abs(r.occludedBias));
                        perTechnique[t].first = std::max(perTechnique[t].first, r.worst);
                        perTechnique[t].second += r.meanAbs / 24.0;  // 2 resolutions x 2 blurs x 2 normals x 3 scenes
                        checkWithinTolerance(r, ref.values.size(), t);
                    }
    for (const auto& [t, figures] : perTechnique) test::addPortabilityRow(std::string("AO ") + toString(t), figures.first, figures.second);
    // The measured worst values, for docs/ao.md and docs/conformance.md beside the bounds.
    WARN(test::label() << ": worst pixel " << worstSeen << " (bound " << worstTol << "), worst |mean signed error| " << worstBias << " (bound "
                       << biasTol << ")");
}

TEST_CASE("ao: at 360 rows crease's wide diamond and Scalable's scaled clamp match the reference", "[ao]") {
    if (drawsNothing()) SFX_SKIP("the null backend draws nothing: GPU results are not compared on " << test::label());
    // The sizes of the test above leave crease's stride near 1 pixel; at 360 rows and radius 2 the
    // diamond's outer ring lies tens of pixels out (its stride follows the projected radius, each
    // tap rounded as aoTap rounds it), and the current tier's clamp is 40 and 80 pixels (docs/ao.md). The high tier
    // has no clamp: its Scalable is left to the test above (at this radius its MIP taps put a
    // rare pixel 0.05 off, a float-vs-double tap rounding that the clamp does not touch).
    const bool clamped = test::tierProfile().aoScalableMaxRadiusPx > 0.0f;
    for (AoResolution resolution : {AoResolution::Full, AoResolution::Half})
        for (AoTechnique t : {AoTechnique::Scalable, AoTechnique::Crease}) {
            if (t == AoTechnique::Scalable && !clamped) continue;
            const tools::AnalyticScene scene = tools::sphereOnPlaneScene(128, 360, 1.0);
            AoSettings s = settingsFor(t);
            s.resolution = resolution;
            s.radius = 2.0f;  // projects past the clamp on the current tier
            INFO(test::label() << " " << toString(t) << " " << toString(resolution));
            const GpuAo gpu = runAo(scene, s);
            const bool half = resolution == AoResolution::Half;
            if (t == AoTechnique::Scalable) CHECK(gpu.config.maxRadiusPx == Approx(half ? 40.0 : 80.0));
            const Grid ref = reference::ambientVisibility(scene.aoInput(false), gpu.config);
            const AgainstReference r = compareWithReference(gpu.visibility, ref);
            REQUIRE(r.occluded > ref.values.size() / 100);  // the contact shadow is there to compare
            checkWithinTolerance(r, ref.values.size(), t);
        }
}

TEST_CASE("ao: at the smallest radius and epsilon the GPU matches the reference, no NaN", "[ao][bad-input]") {
    if (drawsNothing()) SFX_SKIP("the null backend draws nothing: GPU results are not compared on " << test::label());
    // Nearly every tap lands on the centre pixel: the guard !(|v|^2 > epsilon r^2) must drop it
    // on the GPU (float) exactly as in the reference (double), never dividing 0 by 0.
    for (AoTechnique t : kTechniques)
        for (bool blur : {false, true}) {
            const tools::AnalyticScene scene = tools::cornerScene(64, 48, 1.0);
            AoSettings s = settingsFor(t);
            s.radius = kAoMinRadius;
            s.crease.range = 0.01f;  // the smallest, in units of the radius
            s.epsilon = 1e-8f;
            s.blur = blur;
            INFO(test::label() << " " << toString(t) << (blur ? " blur" : ""));
            const GpuAo gpu = runAo(scene, s);
            const Grid ref = reference::ambientVisibility(scene.aoInput(false), gpu.config);
            double maxErr = 0;
            for (size_t i = 0; i < ref.values.size(); ++i) {
                REQUIRE(std::isfinite(gpu.visibility.values[i]));
                REQUIRE(std::isfinite(ref.values[i]));
                maxErr = std::max(maxErr, std::abs(gpu.visibility.values[i] - ref.values[i]));
            }
            INFO("max error " << maxErr);
            CHECK(maxErr < 0.01);  // a radius far below a pixel finds no occluder on either side
        }
}

TEST_CASE("ao: non-finite and out-of-range depth neighbours follow the reference's normal rule", "[ao][bad-input]") {
    if (drawsNothing()) SFX_SKIP("the null backend draws nothing: GPU results are not compared on " << test::label());
    // The host's linear depth read in place, with NaN, +-inf, 0, negative and past-the-far-plane
    // texels: the shader and the reference both read them as sky (sfx_shared_ao.h), so the derived
    // normals of their neighbours, and the obscurance there, agree. Those pixels themselves are sky.
    tools::AnalyticScene scene = tools::cornerScene(64, 48, 1.0);
    const double bad[] = {
        std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(), 0.0, -1.0, 1e30};
    std::vector<std::pair<uint32_t, uint32_t>> poked;
    for (uint32_t k = 0; k < 24; ++k) {
        const uint32_t x = 5 + (k % 6) * 9, y = 6 + (k / 6) * 10;
        scene.linearDepth.at(x, y) = bad[k % std::size(bad)];
        poked.push_back({x, y});
    }
    for (AoTechnique t : kTechniques) {
        AoSettings s = settingsFor(t);
        s.blur = false;
        s.normals = AoNormals::FromDepth;
        INFO(test::label() << " " << toString(t));
        const GpuAo gpu = runAo(scene, s);
        const Grid ref = reference::ambientVisibility(scene.aoInput(false), gpu.config);
        for (size_t i = 0; i < ref.values.size(); ++i) {
            REQUIRE(std::isfinite(gpu.visibility.values[i]));
            REQUIRE(std::isfinite(ref.values[i]));
        }
        double worstNeighbour = 0;
        std::string worstAt;
        for (auto [px, py] : poked) {
            CHECK(gpu.visibility.at(px, py) == 1.0);  // sky: unoccluded
            CHECK(ref.at(px, py) == 1.0);
            for (auto [dx, dy] : {std::pair{-1, 0}, std::pair{1, 0}, std::pair{0, -1}, std::pair{0, 1}}) {
                const uint32_t x = uint32_t(int(px) + dx), y = uint32_t(int(py) + dy);
                const double e = std::abs(gpu.visibility.at(x, y) - ref.at(x, y));
                if (e > worstNeighbour)
                    worstAt = "(" + std::to_string(x) + ", " + std::to_string(y) + ") next to depth " + std::to_string(scene.linearDepth.at(px, py)) +
                        ": gpu " + std::to_string(gpu.visibility.at(x, y)) + " reference " + std::to_string(ref.at(x, y));
                worstNeighbour = std::max(worstNeighbour, e);
            }
        }
        // The neighbours' normals come from the other side on both; what remains is the float-vs-
        // double tap rounding the technique test bounds per pixel (its pixelTol).
        INFO("worst error next to a non-finite depth " << worstNeighbour << " at " << worstAt);
        CHECK(worstNeighbour < tolerance().pixel);
    }
}

TEST_CASE("ao: linear depth read in place gives the same output as the copy, one pass fewer", "[ao][plan]") {
    // At half resolution without a pyramid neither runs a linearisation pass: the half-size
    // depth pass and the upsample linearize hardware depth as they fetch it. With one (high-tier
    // Scalable) the pyramid starts at half size: no pass at half resolution is full size but
    // the upsample.
    if (drawsNothing()) SFX_SKIP("the null backend draws nothing: GPU results are not compared on " << test::label());
    const tools::AnalyticScene scene = tools::sphereOnPlaneScene(64, 48);
    for (AoTechnique t : kTechniques)
        for (bool blur : {false, true}) {
            INFO(test::label() << " " << toString(t) << (blur ? " blur" : ""));
            AoSettings s = settingsFor(t);
            s.blur = blur;
            const GpuAo copied = runAo(scene, s, DepthKind::Hardware);
            const GpuAo inPlace = runAo(scene, s, DepthKind::Linear);
            CHECK(inPlace.visibility.values == copied.visibility.values);
            // Only a depth MIP (high-tier Scalable) still needs LinearDepth's own texture.
            const bool mip = copied.config.depthMipLevels > 1;
            const bool readersLinearize = copied.config.halfResolution && !mip;
            CHECK(inPlace.plan.passes.size() == copied.plan.passes.size() - (mip || readersLinearize ? 0 : 1));
            CHECK((inPlace.plan.bytesOf("depth") > 0) == mip);
            CHECK(copied.plan.bytesOf("depth") > 0);  // the texture, or the readers' constants
            bool linearizePass = false, fullSizeLinearize = false;
            for (const PlannedPass& pass : copied.plan.passes)
                if (pass.name.rfind("linearize", 0) == 0) {
                    linearizePass = true;
                    fullSizeLinearize = fullSizeLinearize || pass.width == scene.width;
                }
            CHECK(linearizePass == !readersLinearize);
            CHECK(fullSizeLinearize == !copied.config.halfResolution);
        }
}

TEST_CASE("ao: analytic properties hold on the GPU", "[ao]") {
    if (drawsNothing()) SFX_SKIP("the null backend draws nothing: no analytic checks on " << test::label());
    const std::vector<double> creaseEdges{0.0, 0.05, 0.1, 0.15, 0.2, 0.3, 0.4, 0.6, 0.9};
    for (AoTechnique t : kTechniques) {
        INFO(test::label() << " " << toString(t));
        const GpuAo plane = runAo(tools::facingPlaneScene(96, 64), settingsFor(t));
        for (double v : plane.visibility.values) REQUIRE(v > 0.99);
        const GpuAo corner = runAo(tools::cornerScene(160, 120), settingsFor(t));
        const auto bins = tools::occlusionBins(tools::cornerScene(160, 120), corner.visibility, 1.0, creaseEdges, tools::onCornerPlaneA,
                                               tools::distanceToCrease);
        for (size_t i = 0; i + 1 < bins.size(); ++i) CHECK(bins[i] >= bins[i + 1] - 0.025);
        CHECK(bins.front() > bins.back() + 0.01);
        const GpuAo scaled = runAo(tools::cornerScene(160, 120, 10.0), settingsFor(t, 10.0));
        CHECK(compareWithReference(scaled.visibility, corner.visibility).meanAbs < 0.005);
        // The tier's own look, which may follow the radius in metres: the scaled scene with its
        // scale stated is the same scene.
        AoSettings look;
        look.technique = t;
        const GpuAo lookCorner = runAo(tools::cornerScene(160, 120), look);
        look.radius *= 10.0f, look.metresPerUnit = 0.1f;
        look.crease.fadeStart *= 10.0f, look.crease.fadeEnd *= 10.0f;  // depths, in the scene's units
        const GpuAo lookScaled = runAo(tools::cornerScene(160, 120, 10.0), look);
        CHECK(compareWithReference(lookScaled.visibility, lookCorner.visibility).meanAbs < 0.005);
    }
}

TEST_CASE("ao: plan holds a depth MIP only for high-tier Scalable and Horizon, blur targets only with blur", "[ao]") {
    Device& dev = test::device();
    for (AoTechnique t : kTechniques)
        for (bool blur : {false, true}) {
            AoSettings s;
            s.technique = t;
            s.blur = blur;
            auto ao = AmbientObscurance::create(dev, {64, 32, test::tierProfile(), s});
            REQUIRE(ao.isOk());
            const EffectPlan plan = ao.value()->plan();
            bool mip = false, blurPass = false;
            for (const PlannedPass& p : plan.passes) {
                mip |= p.name.rfind("depth_mip", 0) == 0;
                blurPass |= p.name.find("blur") != std::string::npos;
            }
            CHECK(mip == ((t == AoTechnique::Scalable || t == AoTechnique::Horizon) && test::tierProfile().aoUsesDepthMip));
            CHECK(blurPass == blur);
            CHECK(plan.bytesOf("ao") > 0);
        }
}

TEST_CASE("ao: at half resolution the plan holds half-size passes and textures and the upsample", "[ao][plan]") {
    Device& dev = test::device();
    const TierProfile& profile = test::tierProfile();
    for (AoTechnique t : kTechniques)
        for (bool blur : {false, true}) {
            INFO(test::label() << " " << toString(t) << (blur ? " blur" : ""));
            AoSettings s;
            s.technique = t;
            s.blur = blur;
            s.resolution = AoResolution::Half;
            auto ao = AmbientObscurance::create(dev, {65, 33, profile, s});
            REQUIRE(ao.isOk());
            const EffectPlan plan = ao.value()->plan();
            // Depth MIP level 1 is the half-size depth only where the pyramid exists anyway.
            const bool mipHalf = (t == AoTechnique::Scalable || t == AoTechnique::Horizon) && profile.aoUsesDepthMip;
            size_t halfPasses = 0, upsample = 0, halfDepthPass = 0;
            for (const PlannedPass& p : plan.passes) {
                if (p.effect != "ao") continue;
                const bool isUpsample = p.name.find("upsample") != std::string::npos;
                upsample += isUpsample;
                halfDepthPass += p.name.rfind("half-size depth", 0) == 0;
                if (isUpsample) {
                    CHECK(p.width == 65);
                    CHECK(p.height == 33);
                } else {
                    CHECK(p.width == 32);
                    CHECK(p.height == 16);
                    ++halfPasses;
                }
            }
            CHECK(upsample == 1);
            CHECK(halfDepthPass == (mipHalf ? 0u : 1u));
            CHECK(halfPasses == (mipHalf ? 0u : 1u) + 1u + (blur ? 2u : 0u));
            size_t halfDepthTexture = 0;
            for (const PlannedResource& r : plan.resources) {
                if (r.effect != "ao" || r.format == Format::Undefined) continue;
                CHECK(r.width == 32);  // every AO texture is half size
                CHECK(r.height == 16);
                halfDepthTexture += r.name.rfind("half-size depth", 0) == 0;
            }
            CHECK(halfDepthTexture == (mipHalf ? 0u : 1u));
            // Its full-resolution twin holds more AO bytes (full-size targets) unless it has none.
            s.resolution = AoResolution::Full;
            auto full = AmbientObscurance::create(dev, {65, 33, profile, s});
            REQUIRE(full.isOk());
            if (blur) CHECK(full.value()->plan().bytesOf("ao") > plan.bytesOf("ao"));
        }
}

TEST_CASE("ao: switching resolution with setSettings and resize keeps matching the reference", "[ao]") {
    if (drawsNothing()) SFX_SKIP("the null backend draws nothing: GPU results are not compared on " << test::label());
    // runAo creates a fresh context; here one context goes full -> half -> resized -> full.
    Device& dev = test::device();
    for (AoTechnique t : kTechniques) {
        INFO(test::label() << " " << toString(t));
        AoSettings s = settingsFor(t);
        s.resolution = AoResolution::Full;
        auto created = AmbientObscurance::create(dev, {40, 30, test::tierProfile(), s});
        REQUIRE(created.isOk());
        AmbientObscurance& ao = *created.value();
        s.resolution = AoResolution::Half;
        SFX_REQUIRE_OK(ao.setSettings(s));
        CHECK(ao.config().halfResolution);
        // 96x360: the current tier's clamp follows the rows, so the resized
        // context must hold the config of its new size, as a fresh context of that size does.
        for (auto [w, h] : {std::pair{40u, 30u}, std::pair{57u, 41u}, std::pair{96u, 360u}}) {
            SFX_REQUIRE_OK(ao.resize(w, h));
            auto fresh = AmbientObscurance::create(dev, {w, h, test::tierProfile(), s});
            REQUIRE(fresh.isOk());
            CHECK(ao.config().maxRadiusPx == fresh.value()->config().maxRadiusPx);
            const tools::AnalyticScene scene = tools::sphereOnPlaneScene(w, h);
            const Grid gpu = dispatchOn(dev, ao, scene);
            SFX_REQUIRE_NO_VALIDATION_MESSAGES();
            const Grid ref = reference::ambientVisibility(scene.aoInput(false), ao.config());
            double worst = 0;
            for (size_t i = 0; i < ref.values.size(); ++i) worst = std::max(worst, std::abs(gpu.values[i] - ref.values[i]));
            INFO(w << "x" << h << " worst pixel " << worst);
            CHECK(worst <= tolerance().worst + (t == AoTechnique::Horizon ? kAoHorizonTrigBound : 0.0));
        }
    }
}

TEST_CASE("ao: profiling times exactly the planned passes and leaves the output unchanged", "[ao][profiling]") {
    Device& dev = test::device();
    const tools::AnalyticScene scene = tools::sphereOnPlaneScene(64, 48);
    std::vector<float> depth(scene.linearDepth.values.begin(), scene.linearDepth.values.end());
    TextureHandle depthTex = dev.createTexture({scene.width, scene.height, 1, Format::R32F, kTextureSampled, "ao-profile-depth"}).value();
    SFX_REQUIRE_OK(dev.writeTexture(depthTex, 0, depth.data(), depth.size() * sizeof(float)));
    // RGBA8 is renderable everywhere; the comparison is bitwise, so any format would do.
    TextureHandle outTex =
        dev.createTexture({scene.width, scene.height, 1, Format::RGBA8, kTextureSampled | kTextureRenderTarget, "ao-profile-out"}).value();
    AoInputs in;
    in.depth = DepthSource{depthTex, DepthKind::Linear, scene.camera};
    in.output = outTex;
    auto runOnce = [&](AmbientObscurance& ao) {
        SFX_REQUIRE_OK(ao.dispatch(in));
        SFX_REQUIRE_OK(dev.flush());
        std::vector<uint8_t> px(size_t(scene.width) * scene.height * 4);
        SFX_REQUIRE_OK(dev.readTexture(outTex, 0, px.data(), px.size()));
        return px;
    };
    for (AoTechnique t : kTechniques)
        for (bool blur : {false, true}) {
            INFO(test::label() << " " << toString(t) << (blur ? " blur" : ""));
            AoSettings s = settingsFor(t);
            s.blur = blur;
            auto created = AmbientObscurance::create(dev, {scene.width, scene.height, test::tierProfile(), s});
            REQUIRE(created.isOk());
            AmbientObscurance& ao = *created.value();
            CHECK_FALSE(ao.profiling());
            CHECK(ao.passTimings().status().code() == StatusCode::InvalidArgument);
            const std::vector<uint8_t> plain = runOnce(ao);

            SFX_REQUIRE_OK(ao.setProfiling(true));
            CHECK(ao.passTimings().status().code() == StatusCode::InvalidArgument);  // nothing flushed yet
            const std::vector<uint8_t> profiled = runOnce(ao);
            CHECK(profiled == plain);
            Result<std::vector<PassTiming>> timings = ao.passTimings();
            INFO(timings.status().toString());
            REQUIRE(timings.isOk());
            const EffectPlan plan = ao.plan();
            REQUIRE(timings->size() == plan.passes.size());
            for (size_t i = 0; i < plan.passes.size(); ++i) {
                CHECK(timings.value()[i].effect == plan.passes[i].effect);
                CHECK(timings.value()[i].name == plan.passes[i].name);
                CHECK(timings.value()[i].reading.milliseconds > 0.0);  // every pass does real work
                CHECK(timings.value()[i].reading.source == dev.caps().timing);
            }

            // Timers follow the pass list when settings change what runs, and go with profiling off.
            AoSettings other = s;
            other.blur = !blur;
            SFX_REQUIRE_OK(ao.setSettings(other));
            CHECK(ao.profiling());
            (void)runOnce(ao);
            timings = ao.passTimings();
            REQUIRE(timings.isOk());
            CHECK(timings->size() == ao.plan().passes.size());
            SFX_REQUIRE_OK(ao.setProfiling(false));
            CHECK(ao.passTimings().status().code() == StatusCode::InvalidArgument);
        }
    for (TextureHandle t : {depthTex, outTex}) SFX_REQUIRE_OK(dev.destroyTexture(t));
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("ao: bad inputs are named errors", "[ao][bad-input]") {
    Device& dev = test::device();
    AoSettings s;
    s.radius = 0;
    auto bad = AmbientObscurance::create(dev, {64, 32, test::tierProfile(), s});
    REQUIRE_FALSE(bad.isOk());
    CHECK(bad.status().message().find("AoSettings.radius") != std::string::npos);
    auto ao = AmbientObscurance::create(dev, {64, 32, test::tierProfile(), AoSettings{}});
    REQUIRE(ao.isOk());
    TextureHandle depth = dev.createTexture({64, 32, 1, Format::R32F, kTextureSampled}).value();
    TextureHandle wrong = dev.createTexture({32, 32, 1, Format::RGBA8, kTextureSampled | kTextureRenderTarget}).value();
    AoInputs in;
    in.depth = DepthSource{depth, DepthKind::Linear, makePerspective({}).value()};
    in.output = wrong;
    Status st = ao.value()->dispatch(in);
    CHECK(st.code() == StatusCode::InvalidArgument);
    CHECK(st.message().find("AoInputs.output size") != std::string::npos);
    AoSettings withNormals;
    withNormals.normals = AoNormals::FromTexture;
    SFX_REQUIRE_OK(ao.value()->setSettings(withNormals));
    TextureHandle out = dev.createTexture({64, 32, 1, Format::RGBA8, kTextureSampled | kTextureRenderTarget}).value();
    in.output = out;
    CHECK(ao.value()->dispatch(in).message().find("AoInputs.normals") != std::string::npos);
    for (TextureHandle t : {depth, wrong, out}) SFX_REQUIRE_OK(dev.destroyTexture(t));
}
