// The backends compared with each other: the same inputs through every pair of backends this
// machine has, at each tier (current: under the GL ES 3.0 ceiling), must give the same output
// of every effect - here linear depth and its pyramid, AO per technique with and without blur,
// motion blur; OIT and multilayer AO in test_cross_oit.cpp, the scene renderer in
// test_cross_render.cpp - with the worst pixel within a stated bound (cross_bounds.hpp,
// docs/conformance.md). Fewer than two backends at a tier is a skip (CTest "skipped"), or a
// failure under SFX_REQUIRE_ALL_BACKENDS=1.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <optional>

#include "cross_bounds.hpp"
#include "cross_compare.hpp"
#include "effect_runs.hpp"
#include "sfx/backends.hpp"
#include "sfx/depth.hpp"
#include "sfx/tiers.hpp"
#include "sfx_shared.h"
#include "skips.hpp"

using namespace sfx;
using namespace sfx::test;

namespace {

void compareAo(Tier tier) {
    SFX_OPEN_AT_LEAST_TWO(devices, tier);
    // Both resolutions, each named: at half resolution the scene is twice the size so that the
    // obscurance pass sees the same 96x64 texels and the same occlusion to agree on.
    for (AoResolution resolution : {AoResolution::Full, AoResolution::Half})
        for (AoTechnique t : {AoTechnique::Alchemy, AoTechnique::Scalable, AoTechnique::Crease, AoTechnique::Horizon})
            for (bool blur : {false, true}) {
                const int scale = resolution == AoResolution::Half ? 2 : 1;
                const tools::AnalyticScene scene = tools::columnsScene(96 * scale, 64 * scale, 1.0);
                AoSettings s = test::aoTestSettings(t);
                s.blur = blur;
                s.resolution = resolution;
                // The article's crease look, its diamond at the radius, spans under 0.05 here:
                // four times its intensity gives the backends occlusion to agree on.
                if (t == AoTechnique::Crease) s.intensity = 4.0f;
                std::map<std::string, std::vector<double>> results;
                for (Opened& o : devices) {
                    INFO(o.name << " / " << toString(tier) << " " << toString(t));
                    results[o.name] = test::runAo(*o.device, tiers::profile(tier), scene, s).visibility.values;
                }
                requireNoValidation(devices);
                // Agreement means something only if there is occlusion to agree on: not a constant image.
                const std::vector<double>& any = results.begin()->second;
                const auto [lo, hi] = std::minmax_element(any.begin(), any.end());
                CHECK(*hi - *lo > 0.05);
                const double bound = t != AoTechnique::Horizon ? kAoPairWorst : kAoHorizonPairWorst + (tier == Tier::Current ? kUnorm8Step : 0.0);
                requirePairsWithin(
                    results, bound,
                    std::string("ao ") + toString(t) + (blur ? " blur" : "") + " " + toString(resolution) + " resolution at tier " + toString(tier));
            }
}

void compareMotionBlur(Tier tier) {
    SFX_OPEN_AT_LEAST_TWO(devices, tier);
    using namespace reference;
    const MotionScene scene = test::movingAndStillLayersScene();
    const SceneFrame f = scene.render(0);
    for (std::optional<float> radius : {std::optional<float>{}, std::optional<float>{7.0f}}) {
        MotionBlurSettings s;
        s.maxRadiusPx = radius;
        s.referenceRows = 0;
        std::map<std::string, std::vector<double>> results, velocities;
        for (Opened& o : devices) {
            INFO(o.name << " / " << toString(tier) << " radius " << (radius ? std::to_string(*radius) : "the tier's"));
            const GpuMotionBlur out = test::runMotionBlurPasses(*o.device, tiers::profile(tier), f.color, f.depth, &f.velocity, s);
            std::vector<double>& flat = results[o.name];
            for (const auto& px : out.color.values) flat.insert(flat.end(), px.begin(), px.end());
            for (const auto& v : out.radiusPx.values) velocities[o.name].insert(velocities[o.name].end(), v.begin(), v.end());
        }
        requireNoValidation(devices);
        // Agreement means something only if the output is blurred: far from the input somewhere.
        double moved = 0;
        const std::vector<double>& any = results.begin()->second;
        for (size_t i = 0; i < f.color.values.size(); ++i)
            for (size_t c = 0; c < 4; ++c) moved = std::max(moved, std::abs(any[i * 4 + c] - f.color.values[i][c]));
        CHECK(moved > 0.1);
        const std::string what = "motion blur radius " + std::to_string(int(radius.value_or(0))) + " at tier " + toString(tier);
        requirePairsWithin(results, kMotionBlurPairWorst, what);
        requirePairsWithin(velocities, kVelocityPairWorst, what + ", pass-1 velocities");
    }
}

}  // namespace

TEST_CASE("ao agrees across backends, per technique, blur on and off: high tier", "[cross-backend][ao]") { compareAo(Tier::High); }
TEST_CASE("ao agrees across backends, per technique, blur on and off: current tier", "[cross-backend][ao]") { compareAo(Tier::Current); }
TEST_CASE("motion blur agrees across backends: high tier", "[cross-backend][motion_blur]") { compareMotionBlur(Tier::High); }
TEST_CASE("motion blur agrees across backends: current tier", "[cross-backend][motion_blur]") { compareMotionBlur(Tier::Current); }

TEST_CASE("linear depth and its pyramid agree across backends", "[cross-backend][depth]") {
    for (Tier tier : {Tier::High, Tier::Current}) {
        std::vector<Opened> devices = openAll(tier);
        if (devices.size() < 2) {
            test::recordSkip(Catch::getResultCapture().getCurrentTestName(),
                             std::string("fewer than two backends at tier ") + toString(tier) + ": nothing to compare");
            continue;
        }
        const uint32_t W = 45, H = 29;
        const uint32_t levels = std::min(4u, tiers::profile(tier).aoDepthMipLevels);  // the tier's pyramid, up to 4
        PerspectiveDesc pd;
        pd.aspect = double(W) / H;
        pd.reversedZ = true;
        pd.farPlane = std::numeric_limits<double>::infinity();
        CameraProjection cam = makePerspective(pd).value();
        std::vector<float> stored(size_t(W) * H);
        for (size_t i = 0; i < stored.size(); ++i)
            stored[i] = float(storedDepthFromLinear(cam, 0.1 * std::pow(500.0, double(i) / double(stored.size()))));

        std::map<std::string, std::vector<std::vector<float>>> results;
        for (Opened& o : devices) {
            INFO(o.name << " / " << toString(tier));
            Device& d = *o.device;
            TextureHandle src = d.createTexture({W, H, 1, Format::R32F, kTextureSampled}).value();
            REQUIRE(d.writeTexture(src, 0, stored.data(), stored.size() * 4).isOk());
            auto linear = LinearDepth::create(d, {W, H, tier, levels});
            INFO(linear.status().toString());
            REQUIRE(linear.isOk());
            REQUIRE(linear.value()->dispatch({src, DepthKind::Hardware, cam}).isOk());
            for (uint32_t m = 0; m < levels; ++m) {
                std::vector<float> level(size_t(mipExtent(W, m)) * mipExtent(H, m));
                REQUIRE(d.readTexture(linear.value()->texture(), m, level.data(), level.size() * 4).isOk());
                results[o.name].push_back(std::move(level));
            }
            (void)d.destroyTexture(src);
        }
        requireNoValidation(devices);
        // Reversed-Z is well conditioned: a few ulps each way (docs/conformance.md). The pyramid
        // levels copy the same source texels on every backend, so they agree within the same bound.
        for (auto a = results.begin(); a != results.end(); ++a)
            for (auto b = std::next(a); b != results.end(); ++b) {
                INFO(a->first << " vs " << b->first << " at tier " << toString(tier));
                for (uint32_t m = 0; m < levels; ++m) {
                    REQUIRE(a->second[m].size() == b->second[m].size());
                    for (size_t i = 0; i < a->second[m].size(); ++i) {
                        const double x = a->second[m][i], y = b->second[m][i];
                        INFO("level " << m << " texel " << i << ": " << x << " vs " << y);
                        REQUIRE(std::abs(x - y) <= 2.0 * x * 10.0 * std::ldexp(1.0, -23));
                    }
                }
            }
    }
}

TEST_CASE("openBestDevice picks the highest tier and says why", "[cross-backend][selection]") {
    DeviceOptions options;
    options.validation = false;
    Result<DeviceSelection> best = openBestDevice(options);
    INFO(best.status().toString());
    REQUIRE(best.isOk());
    // Every backend here reaches the high tier; the first in preference order wins the tie.
    CHECK(best->tier.tier == Tier::High);
    CHECK(toString(best->config) == toString(compiledBackends().front()));
    CHECK(best->reason.find(toString(best->config)) != std::string::npos);
    CHECK(best->reason.find("tier 'high'") != std::string::npos);
    CHECK(best->rejected.size() + 1 == compiledBackends().size());

    // Under the ceiling every device reaches only the current tier, and says what it lacks.
    options.ceiling = CapabilityCeiling::GLES30;
    Result<DeviceSelection> capped = openBestDevice(options);
    REQUIRE(capped.isOk());
    CHECK(capped->tier.tier == Tier::Current);
    CHECK(capped->tier.reason.find("compute shaders") != std::string::npos);
}
