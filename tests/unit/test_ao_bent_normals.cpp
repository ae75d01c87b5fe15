// Bent normals of the horizon technique's CPU reference: the per-side arc vector against its
// integral, an open plane giving back its normal at any slice count, and the floor beside a wall
// bending away from it by the angle the ray-traced truth's definition gives.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "analytic_scenes.hpp"
#include "sfx/ao.hpp"
#include "sfx/reference/ao_reference.hpp"
#include "sfx/tiers.hpp"
#include "sfx_shared_ao_horizon.h"

using namespace sfx;
namespace sh = sfx::shared;

namespace {

constexpr double kPi = 3.14159265358979323846;

AoConfig horizonConfig(Tier tier, uint32_t slices, uint32_t steps, bool blur) {
    AoSettings s;
    s.technique = AoTechnique::Horizon;
    s.resolution = AoResolution::Full;
    s.blur = blur;
    s.horizon.slices = slices;
    s.horizon.steps = steps;
    Result<AoConfig> c = resolveAoConfig(s, tiers::profile(tier), 1, 120);
    REQUIRE(c.isOk());
    return c.value();
}

// The largest angle in radians between each non-sky pixel's bent normal and `expected` of it.
template <class Expected>
double worstAngle(const tools::AnalyticScene& scene, const std::vector<glm::dvec3>& bent, Expected expected) {
    double worst = 0;
    for (size_t i = 0; i < bent.size(); ++i) {
        if (!(scene.linearDepth.values[i] < scene.reconstruction.maxDepth)) {
            CHECK(bent[i] == glm::dvec3(0.0, 0.0, 1.0));  // sky faces the eye
            continue;
        }
        const double c = std::clamp(glm::dot(bent[i], expected(i)), -1.0, 1.0);
        worst = std::max(worst, std::acos(c));
    }
    return worst;
}

}  // namespace

TEST_CASE("ao bent normals: each side's arc vector is the integral of the direction over the arc", "[ao][horizon][bent]") {
    // Midpoint quadrature of (cos th, sin th) cos(th - n) |sin th| from the view vector to the
    // horizon, against the closed form, for normals on both sides and horizons from the tangent
    // plane to the normal.
    for (double n : {0.0, 0.4, -0.9, 1.3}) {
        for (double e : {0.0, 0.2, 0.7, 1.0}) {
            for (double side : {1.0, -1.0}) {
                const double h = n + side * std::acos(e);
                glm::dvec2 integral(0.0);
                if (side * h > 0.0) {
                    const int steps = 20000;
                    for (int k = 0; k < steps; ++k) {
                        const double th = h * (k + 0.5) / steps;
                        integral += glm::dvec2(std::cos(th), std::sin(th)) * std::cos(th - n) * std::abs(std::sin(th)) * std::abs(h) / double(steps);
                    }
                }
                const glm::dvec2 closed = sh::aoHorizonArcDirection(e, side, n, std::cos(n), std::sin(n));
                INFO("normal " << n << ", horizon sine " << e << ", side " << side);
                CHECK(closed.x == Approx(integral.x).margin(1e-7));
                CHECK(closed.y == Approx(integral.y).margin(1e-7));
            }
        }
    }
}

TEST_CASE("ao bent normals: an open plane gives back its normal, facing the camera or tilted", "[ao][horizon][bent]") {
    // Off the image's centre a facing plane's normal is not the view vector, and a tilted one's
    // is far from it: a few slices' open vectors do not point along the normal, and the
    // correction by the open hemisphere's exact vector (aoHorizonBentNormal) must remove that.
    for (const tools::AnalyticScene& scene : {tools::facingPlaneScene(96, 64), tools::tiltedPlaneScene(96, 64)})
        for (Tier tier : {Tier::Current, Tier::High})
            for (uint32_t slices : {1u, 2u, 3u, 16u}) {
                const AoConfig c = horizonConfig(tier, slices, 8, true);
                const reference::AoInput in = scene.aoInput(true);
                const double raw = worstAngle(scene, reference::rawBentNormals(in, c).normals, [&](size_t i) { return scene.normals[i]; });
                const double blurred = worstAngle(scene, reference::ambientBentNormals(in, c).normals, [&](size_t i) { return scene.normals[i]; });
                INFO(scene.name << ", " << toString(tier) << ", " << slices << " slices: raw off by " << raw << " rad, blurred " << blurred);
                CHECK(raw < 1e-6);
                CHECK(blurred < 1e-6);  // one plane: the blur averages equal vectors
            }
}

TEST_CASE("ao bent normals: the floor beside a perpendicular wall bends away from it", "[ao][horizon][bent]") {
    // The corner's plane A (the floor, normal N) beside plane B (the wall, toward it W = -nB).
    // With rays blocked where they reach the wall within r, a point at distance d sees the
    // directions with w = dot(omega, W) <= d / r: the cosine-weighted mean of those lies in the
    // plane of N and W (the crease's axis cancels), tilted away from the wall by an angle that
    // the quadrature below integrates. The converged estimator must follow it.
    const double r = 0.5;
    const tools::AnalyticScene scene = tools::cornerScene(320, 240);
    const std::vector<glm::dvec3> bent = reference::rawBentNormals(scene.aoInput(true),
                                                                   [&] {
                                                                       AoConfig c = horizonConfig(Tier::Current, 16, 32, false);
                                                                       c.radius = r;
                                                                       c.horizon.falloff = 0.02;
                                                                       return c;
                                                                   }())
                                             .normals;
    const glm::dvec3 N = tools::kCornerNormalA, W = -tools::kCornerNormalB;
    auto truthTilt = [&](double d) {
        // Hemisphere about N in (theta from N, phi from W's side): omega = sin cos phi W + sin sin phi X + cos N.
        double alongN = 0, alongW = 0;
        const int nt = 400, np = 800;
        for (int i = 0; i < nt; ++i) {
            const double th = (i + 0.5) / nt * kPi / 2;
            for (int j = 0; j < np; ++j) {
                const double ph = (j + 0.5) / np * 2 * kPi;
                const double w = std::sin(th) * std::cos(ph);
                if (w > d / r) continue;
                const double dw = std::cos(th) * std::sin(th);  // cosine weight times the solid angle's sin
                alongN += std::cos(th) * dw;
                alongW += w * dw;
            }
        }
        return std::atan2(-alongW, alongN);  // positive: away from the wall
    };
    const std::vector<double> edges{0.05, 0.1, 0.15, 0.2, 0.25, 0.3, 0.35, 0.4, 0.6};
    for (size_t b = 0; b + 1 < edges.size(); ++b) {
        double sum = 0, sumAcross = 0;
        size_t count = 0;
        for (size_t i = 0; i < bent.size(); ++i) {
            const glm::dvec3 p = scene.positions[i];
            if (!tools::onCornerPlaneA(p, scene.normals[i])) continue;
            const double d = tools::distanceToCrease(p);
            if (d < edges[b] || d >= edges[b + 1]) continue;
            sum += std::atan2(-glm::dot(bent[i], W), glm::dot(bent[i], N));
            sumAcross += std::abs(bent[i].x);
            ++count;
        }
        REQUIRE(count > 20);
        const double mid = 0.5 * (edges[b] + edges[b + 1]), tilt = sum / double(count), expected = truthTilt(mid);
        INFO("distance " << mid << ": tilt away from the wall " << tilt << " rad, truth " << expected << ", |x| " << sumAcross / double(count));
        if (mid < r) CHECK(tilt > 0.02);  // bends away from the wall inside the radius
        CHECK(std::abs(tilt - expected) < 0.05);
        CHECK(sumAcross / double(count) < 0.05);  // the crease's axis cancels
    }
}
