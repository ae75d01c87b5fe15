// Horizon's bent normals (AoSettings.bentNormals) compared between every pair of backends and
// drivers at each tier: full and half resolution, blur on and off, into RGBA8 and a float
// target. Each backend evaluates the same float taps, so only the arc terms' acos may differ
// (each within kBentTrigAllowance of the exact terms: two within twice that), and every rounding
// to an intermediate or output target may land on neighbouring codes (one step each). The
// bound is per pixel, from the reference's vector lengths (docs/conformance.md).
#include <catch2/catch.hpp>

#include <algorithm>
#include <map>
#include <optional>

#include "analytic_scenes.hpp"
#include "cross_compare.hpp"
#include "effect_runs.hpp"
#include "sfx/reference/ao_reference.hpp"
#include "sfx/tiers.hpp"

using namespace sfx;
using namespace sfx::test;

namespace {

void compareBentNormals(Tier tier) {
    SFX_OPEN_AT_LEAST_TWO(devices, tier);
    const TierProfile& profile = tiers::profile(tier);
    const Format intermediate = profile.aoPackedDepthTarget ? Format::RGBA8 : Format::RGBA16F;
    for (AoResolution resolution : {AoResolution::Full, AoResolution::Half})
        for (bool blur : {false, true})
            for (bool floatOutput : {false, true})
                for (auto make : {&tools::columnsScene, &tools::cornerScene}) {
                    const int scale = resolution == AoResolution::Half ? 2 : 1;
                    const tools::AnalyticScene scene = make(96 * scale, 64 * scale, 1.0);
                    AoSettings s = aoTestSettings(AoTechnique::Horizon);
                    s.bentNormals = true;
                    s.blur = blur;
                    s.resolution = resolution;
                    std::map<std::string, std::vector<double>> results;
                    std::optional<AoConfig> config;
                    Format coarsestOutput = Format::RGBA32F;
                    for (Opened& o : devices) {
                        const Format out = floatOutput ? pickFormat(*o.device, {Format::RGBA32F, Format::RGBA16F}, true) : Format::RGBA8;
                        if (bentRounding(out) > bentRounding(coarsestOutput)) coarsestOutput = out;
                        INFO(o.name << " / " << toString(tier) << " " << scene.name << " into " << toString(out));
                        const GpuAo gpu = runAo(*o.device, profile, scene, s, DepthKind::Linear, out);
                        REQUIRE(gpu.bentNormals.size() == size_t(scene.width) * scene.height);
                        config = gpu.config;
                        std::vector<double>& flat = results[o.name];
                        for (const glm::dvec3& n : gpu.bentNormals) flat.insert(flat.end(), {n.x, n.y, n.z});
                    }
                    requireNoValidation(devices);
                    // Agreement means something only where the normals bend: the corner's and the
                    // columns' floors lean away from their walls by tenths of a radian.
                    const std::vector<double>& any = results.begin()->second;
                    double bend = 0;
                    for (size_t i = 0; i < scene.normals.size(); ++i)
                        bend = std::max(bend, glm::length(glm::dvec3(any[i * 3], any[i * 3 + 1], any[i * 3 + 2]) - scene.normals[i]));
                    CHECK(bend > 0.1);
                    const reference::BentNormals ref = reference::ambientBentNormals(scene.aoInput(false), *config);
                    const int intermediates = bentIntermediates(*config);
                    std::vector<double> bounds;
                    for (size_t i = 0; i < ref.normals.size(); ++i) {
                        const double b = bentComponentBound(2 * kBentTrigAllowance, ref.vectorLength[i], ref.resolveLength[i], intermediate,
                                                            intermediates, coarsestOutput);
                        bounds.insert(bounds.end(), {b, b, b});
                    }
                    requirePairsWithinEach(results, bounds,
                                           std::string("bent normals ") + scene.name + (blur ? " blur" : "") + " " + toString(resolution) +
                                               " resolution into " + (floatOutput ? "float" : "RGBA8") + " at tier " + toString(tier));
                }
}

}  // namespace

TEST_CASE("horizon's bent normals agree across backends: high tier", "[cross-backend][ao][bent]") { compareBentNormals(Tier::High); }
TEST_CASE("horizon's bent normals agree across backends: current tier", "[cross-backend][ao][bent]") { compareBentNormals(Tier::Current); }
