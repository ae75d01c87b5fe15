// The horizon technique's CPU reference against closed forms: an open plane is unoccluded, the
// floor beside a perpendicular wall sees the circular-segment visibility of the ray-traced
// truth's definition, the shared per-slice terms integrate the visible arc exactly, and a
// slice's steps are evenly spread over the radius.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include "analytic_scenes.hpp"
#include "effect_runs.hpp"
#include "sfx/ao.hpp"
#include "sfx/reference/ao_reference.hpp"
#include "sfx/tiers.hpp"
#include "sfx_shared_ao_horizon.h"

using namespace sfx;
using reference::Grid;

namespace {

constexpr double kPi = 3.14159265358979323846;

// Many slices and steps, a sharp edge at the radius, no blur, full size: the estimator near its
// limit, where it should agree with the closed forms.
AoConfig convergedHorizon(double radius) {
    AoSettings s;
    s.technique = AoTechnique::Horizon;
    s.radius = float(radius);
    s.blur = false;
    s.resolution = AoResolution::Full;
    s.horizon.slices = 16;
    s.horizon.steps = 32;
    s.horizon.falloff = 0.02f;
    s.horizon.thickness = 1.0f;
    Result<AoConfig> c = resolveAoConfig(s, tiers::profile(Tier::Current), 1, 120);
    REQUIRE(c.isOk());
    return c.value();
}

// The cosine-weighted share of the hemisphere of a floor point at distance d from an infinite
// perpendicular wall whose rays reach the wall within r (the truth's definition, binary).
double wedgeVisibility(double d, double r) {
    const double a = d / r;
    if (a >= 1.0) return 1.0;
    return 1.0 - (std::acos(a) - a * std::sqrt(1.0 - a * a)) / kPi;
}

double sliceVisibility(double plusSin, double minusSin, const glm::dvec3& projected) {
    return sfx::shared::aoHorizonSliceVisibility(plusSin, minusSin, projected, sfx::shared::aoHorizonNormalAngle(projected));
}

// One side's arc with its horizon angle's acos result off by dAlpha radians (the shared
// aoHorizonArc at dAlpha 0, which the test checks).
double arcWithError(double e, double side, double nAngle, double cosN, double sinN, double dAlpha) {
    const double h = nAngle + side * (std::acos(std::clamp(e, 0.0, 1.0)) + dAlpha);
    if (!(side * h > 0.0)) return 0.0;
    return 0.25 * (cosN + 2.0 * h * sinN - std::cos(2.0 * h - nAngle));
}

}  // namespace

TEST_CASE("ao horizon: the conformance allowance covers the specified acos precision", "[ao][horizon]") {
    // Vulkan bounds acos to 4096 ulp, within 1e-3 radian for results up to pi. The visibility is
    // the mean of the slices' ratios r = visible / open weighted by their open arcs, so an error
    // moves it by at most the largest change of one slice's ratio plus the largest relative
    // change of one open arc (a weighted mean of values in [0, 1]). Every acos of a slice (the
    // normal's angle, both horizons, both open sides) is pushed 1e-3 either way over normals
    // facing the eye and horizons from the tangent plane to the normal.
    namespace sh = sfx::shared;
    const double err = 1e-3;
    double worstRatio = 0, worstOpen = 0;
    for (int gi = 0; gi <= 60; ++gi) {
        const double g = -kPi / 2 + kPi * gi / 60.0;
        const double c = std::cos(g), s = std::sin(g);
        for (int pi = 0; pi <= 20; ++pi)
            for (int mi = 0; mi <= 20; ++mi) {
                const double ep = pi / 20.0, em = mi / 20.0;
                const double visible = arcWithError(ep, 1, g, c, s, 0) + arcWithError(em, -1, g, c, s, 0);
                const double open = arcWithError(0, 1, g, c, s, 0) + arcWithError(0, -1, g, c, s, 0);
                CHECK(visible == Approx(sh::aoHorizonSliceVisibility(ep, em, glm::dvec3{1.0, c, s}, g)).margin(1e-12));
                if (!(open > 1e-9)) continue;
                for (int m = 0; m < 32; ++m) {
                    auto d = [&](int bit) { return (m >> bit) & 1 ? err : -err; };
                    const double n = g + d(0);
                    const double v2 = arcWithError(ep, 1, n, c, s, d(1)) + arcWithError(em, -1, n, c, s, d(2));
                    const double o2 = arcWithError(0, 1, n, c, s, d(3)) + arcWithError(0, -1, n, c, s, d(4));
                    worstRatio = std::max(worstRatio, std::abs(v2 / o2 - visible / open));
                    worstOpen = std::max(worstOpen, std::abs(o2 / open - 1.0));
                }
            }
    }
    INFO("slice ratio moves " << worstRatio << ", open arc " << worstOpen);
    CHECK(worstRatio + worstOpen / (1.0 - worstOpen) <= test::kAoHorizonTrigBound);
}

TEST_CASE("ao horizon: a slice's steps are evenly spread, no gap wider than the radius over the steps", "[ao][horizon]") {
    // The truth counts every occluder within the radius, so an occluder in a wide gap between
    // two steps is missed: step j lies at (j + jitter) / steps of the screen radius for every
    // jitter, the first within one gap of the pixel and the last inside the radius.
    namespace sh = sfx::shared;
    const float screenRadius = 64.0f;
    for (int steps : {2, 4, 6, 12})
        for (int jitter = 0; jitter < 256; jitter += 15) {
            INFO(steps << " steps, jitter index " << jitter);
            const double gap = double(screenRadius) / steps, xi = (jitter + 0.5) / 256.0;
            for (int j = 0; j < steps; ++j) {
                const double rho = sh::aoHorizonStepRadius(j, steps, jitter, screenRadius);
                CHECK(rho == Approx(std::max((j + xi) * gap, double(sh::SFX_AO_HORIZON_MIN_STEP_PX))).epsilon(1e-6));
                CHECK(rho < double(screenRadius));
                if (j > 0) CHECK(rho - sh::aoHorizonStepRadius(j - 1, steps, jitter, screenRadius) <= gap * (1 + 1e-6));
            }
        }
}

TEST_CASE("ao horizon: the visible arc of an open slice integrates the cosine over the hemisphere", "[ao][horizon]") {
    namespace sh = sfx::shared;
    // Unoccluded horizons (the tangent plane's) about a normal at angle a in the slice, projected
    // length 1: the slice's arc is cos a + a sin a, whose mean over the slices of a normal tilted
    // by a from the view is 1 (the projected angle and length vary with the slice).
    for (double a : {0.0, 0.3, -0.7, 1.2}) {
        const glm::dvec3 projected{1.0, std::cos(a), std::sin(a)};
        CHECK(sliceVisibility(0.0, 0.0, projected) == Approx(std::cos(a) + a * std::sin(a)).margin(1e-12));
    }
    for (double tilt : {0.0, 0.4, 1.0, 1.4}) {
        const glm::dvec3 n{std::sin(tilt), 0.0, std::cos(tilt)}, V{0, 0, 1};
        double sum = 0;
        const int slices = 4096;
        for (int i = 0; i < slices; ++i) {
            const double phi = (i + 0.5) / slices * kPi;
            const glm::dvec3 t = sh::aoHorizonSliceTangent(sh::aoHorizonSliceDirection(std::cos(phi), std::sin(phi), 1.0, 1.0, V));
            const glm::dvec3 p = sh::aoHorizonProjectedNormal(n, V, t);
            sum += sliceVisibility(0.0, 0.0, p);
        }
        INFO("normal tilted " << tilt << " rad from the view");
        CHECK(sum / slices == Approx(1.0).margin(1e-5));
    }
    // Horizons along the normal on both sides leave nothing, for a facing or a tilted normal.
    CHECK(sliceVisibility(1.0, 1.0, glm::dvec3{1.0, 1.0, 0.0}) == Approx(0.0).margin(1e-12));
    // Tilted by n toward the + side, the - side's horizon stops at the view vector (a tap on that
    // side lies on that side of it): what remains is the arc from the view vector to the normal.
    CHECK(sliceVisibility(1.0, 1.0, glm::dvec3{1.0, std::cos(0.5), std::sin(0.5)}) == Approx(0.5 * 0.5 * std::sin(0.5)).margin(1e-12));
    // A horizon 45 degrees up on one side of a facing normal: that side keeps cos^2(45) of its half.
    CHECK(sliceVisibility(std::sin(kPi / 4), 0.0, glm::dvec3{1.0, 1.0, 0.0}) == Approx(0.25 + 0.5).margin(1e-12));
}

TEST_CASE("ao horizon: an open plane facing the camera or tilted from it is unoccluded", "[ao][horizon]") {
    const tools::AnalyticScene scene = tools::facingPlaneScene(96, 64);
    AoConfig c = convergedHorizon(0.5);
    const Grid v = reference::rawVisibility(scene.aoInput(true), c);
    // The centre pixel's normal is the view vector: every slice's arc is exactly 1.
    CHECK(v.at(48, 32) == Approx(1.0).margin(1e-6));
    double worst = 0;
    for (double x : v.values) worst = std::max(worst, std::abs(x - 1.0));
    INFO("worst pixel off by " << worst);
    CHECK(worst < 0.01);  // 16 slices average the arc of a normal up to 35 degrees off the view
    // The tier defaults' few slices: each slice's visible arc is its open arc, and their ratio
    // is 1 at any slice count, wherever the normal points.
    for (Tier tier : {Tier::Current, Tier::High})
        for (uint32_t slices : {1u, 2u, 3u}) {
            AoSettings s;
            s.technique = AoTechnique::Horizon;
            s.resolution = AoResolution::Full;
            s.horizon.slices = slices;
            Result<AoConfig> d = resolveAoConfig(s, tiers::profile(tier), 1, 64);
            REQUIRE(d.isOk());
            const Grid b = reference::ambientVisibility(scene.aoInput(false), d.value());
            double lowest = 1;
            for (double x : b.values) lowest = std::min(lowest, x);
            INFO(toString(tier) << ", " << slices << " slices");
            CHECK(lowest > 0.999);
        }
    // A tilted open plane too, where every pixel's normal is far from its view vector.
    AoSettings s;
    s.technique = AoTechnique::Horizon;
    s.resolution = AoResolution::Full;
    s.horizon.slices = 2;
    Result<AoConfig> d = resolveAoConfig(s, tiers::profile(Tier::Current), 1, 64);
    REQUIRE(d.isOk());
    const tools::AnalyticScene tilted = tools::tiltedPlaneScene(96, 64);
    const Grid b = reference::ambientVisibility(tilted.aoInput(false), d.value());
    double lowest = 1;
    for (double x : b.values) lowest = std::min(lowest, x);
    CHECK(lowest > 0.999);
}

TEST_CASE("ao horizon: the floor beside a perpendicular wall sees the truth's circular segment", "[ao][horizon]") {
    // The corner's plane A beside plane B: for a point at distance d from the crease, rays toward
    // B within the radius r are blocked, 1 - (acos(d/r) - (d/r) sqrt(1 - (d/r)^2)) / pi remains;
    // in the crease itself one half.
    const double r = 0.5;
    const tools::AnalyticScene scene = tools::cornerScene(320, 240);
    const Grid v = reference::rawVisibility(scene.aoInput(true), convergedHorizon(r));
    const std::vector<double> edges{0.02, 0.05, 0.1, 0.15, 0.2, 0.25, 0.3, 0.35, 0.4, 0.45, 0.6, 0.8};
    const std::vector<double> occlusion = tools::occlusionBins(scene, v, 1.0, edges, tools::onCornerPlaneA, tools::distanceToCrease);
    for (size_t b = 0; b + 1 < edges.size(); ++b) {
        REQUIRE(occlusion[b] >= 0.0);
        const double mid = 0.5 * (edges[b] + edges[b + 1]);
        const double expected = wedgeVisibility(mid, r);
        INFO("distance " << mid << ": expected " << expected << ", horizon " << 1.0 - occlusion[b]);
        CHECK(std::abs((1.0 - occlusion[b]) - expected) < 0.03);
    }
    CHECK(wedgeVisibility(0.0, r) == Approx(0.5));
}

TEST_CASE("ao horizon: settings are validated with named errors and resolve to the tier's", "[ao][horizon][bad-input]") {
    const TierProfile& high = tiers::profile(Tier::High);
    AoSettings s;
    s.technique = AoTechnique::Horizon;
    CHECK(validateAoSettings(s, high).isOk());
    Result<AoConfig> c = resolveAoConfig(s, high, 8, 720);
    REQUIRE(c.isOk());
    CHECK(c.value().horizon.slices == high.aoHorizonSlices);
    CHECK(c.value().horizon.steps == high.aoHorizonSteps);
    CHECK(c.value().samples == high.aoHorizonSlices);
    CHECK(c.value().depthMipLevels > 1);  // the high tier's far steps read the depth MIP
    s.horizon.slices = 0;
    CHECK(validateAoSettings(s, high).message() == "AoSettings.horizon.slices is 0; allowed [1, 16]");
    s = {};
    s.technique = AoTechnique::Horizon;
    s.horizon.steps = 33;
    CHECK(validateAoSettings(s, high).message() == "AoSettings.horizon.steps is 33; allowed [1, 32]");
    s.horizon.steps = {};
    s.horizon.falloff = 0.0f;
    CHECK(validateAoSettings(s, high).message().find("AoSettings.horizon.falloff") != std::string::npos);
    s.horizon.falloff = {};
    s.horizon.thickness = std::nanf("");
    CHECK(validateAoSettings(s, high).message().find("AoSettings.horizon.thickness") != std::string::npos);
    s.horizon.thickness = {};
    s.samples = 8;
    CHECK(validateAoSettings(s, high).message().find("AoSettings.samples") != std::string::npos);
    s.samples = {};
    s.depthLayers = 2;
    CHECK(validateAoSettings(s, high).message().find("AoSettings.depthLayers") != std::string::npos);
    AoTechnique parsed{};
    CHECK(parseAoTechnique("horizon", &parsed));
    CHECK(parsed == AoTechnique::Horizon);
    CHECK(std::string(toString(AoTechnique::Horizon)) == "horizon");
}
