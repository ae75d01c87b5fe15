// Sizes at the edges: 1x1, one row, one column, odd and prime sizes. Every effect runs on them
// with finite output and agrees with its CPU reference, so the motion blur tiles and the AO
// depth MIP chain are right where the size is no multiple of the tile or of 2; a size above the
// device's limit is a named error.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "analytic_scenes.hpp"
#include "effect_runs.hpp"
#include "sfx/half.hpp"
#include "skips.hpp"
#include "test_device.hpp"

using namespace sfx;
using namespace sfx::reference;

namespace {

struct Size {
    uint32_t w, h;
};
// The small odd and prime sizes compared with the references texel by texel.
const Size kSmallSizes[] = {{1, 1}, {1, 37}, {37, 1}, {2, 3}, {127, 61}};

bool drawsNothing() { return test::device().caps().backend == BackendKind::Null; }

}  // namespace

TEST_CASE("sizes: AO at 1x1, one row, one column and odd sizes matches the reference", "[sizes][ao]") {
    if (drawsNothing()) SFX_SKIP("the null backend draws nothing: GPU results are not compared on " << test::label());
    // The AO conformance test's per-pixel bound (docs/ao.md: float-vs-double taps), which at most
    // 1% of pixels may exceed (none at all below 100 pixels).
    const double worstBound = test::tier() == Tier::High ? 0.03 : 0.05;
    for (const Size& sz : kSmallSizes)
        for (AoTechnique t : {AoTechnique::Alchemy, AoTechnique::Scalable, AoTechnique::Crease}) {
            INFO(test::label() << " " << sz.w << "x" << sz.h << " " << toString(t));
            const samples::AnalyticScene scene = samples::cornerScene(sz.w, sz.h, 1.0);
            AoSettings s = test::aoTestSettings(t);
            const test::GpuAo gpu = test::runAo(test::device(), test::tierProfile(), scene, s);
            const Grid ref = ambientVisibility(scene.aoInput(false), gpu.config);
            size_t off = 0;
            for (size_t i = 0; i < ref.values.size(); ++i) {
                REQUIRE(std::isfinite(gpu.visibility.values[i]));
                if (std::abs(gpu.visibility.values[i] - ref.values[i]) > worstBound) ++off;
            }
            INFO("pixels beyond " << worstBound << ": " << off << " of " << ref.values.size());
            CHECK(double(off) <= 0.01 * double(ref.values.size()));
        }
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("sizes: motion blur tiles at 1x1, one row, one column and odd sizes match the reference", "[sizes][motion_blur]") {
    if (drawsNothing()) SFX_SKIP("the null backend draws nothing: GPU results are not compared on " << test::label());
    for (const Size& sz : kSmallSizes) {
        INFO(test::label() << " " << sz.w << "x" << sz.h);
        std::mt19937 rng(sz.w * 131 + sz.h);
        // Velocities below the radius: lengths clamped to it would tie in the tile max.
        std::uniform_real_distribution<double> u(0.0, 1.0), v(-3.0, 3.0);
        ColorGrid c(sz.w, sz.h);
        Grid z(sz.w, sz.h);
        VelocityGrid vel(sz.w, sz.h);
        for (auto& px : c.values) px = {roundToHalf(u(rng)), roundToHalf(u(rng)), roundToHalf(u(rng)), 1.0};
        for (auto& d : z.values) d = 2.0 + 6.0 * u(rng);
        for (auto& e : vel.values) e = {v(rng), v(rng)};
        MotionBlurSettings s;
        s.maxRadiusPx = 5;  // tiles of 5: no size above is a multiple of it
        s.referenceRows = 0;
        const ColorGrid gpu = test::runMotionBlur(test::device(), test::tierProfile(), c, z, &vel, s);
        const MotionBlurParams p = resolveMotionBlur(test::tierProfile(), s, sz.h).value();
        const double maxDepth = makeDepthReconstruction(test::motionBlurTestCamera(sz.w, sz.h), sz.w, sz.h).value().maxDepth;
        const ColorGrid ref = motionBlur(c, z, vel, p, maxDepth).color;
        // The motion blur conformance bound: 2e-3 per channel, at most 3% of channels beyond it.
        size_t far = 0;
        for (size_t i = 0; i < ref.values.size(); ++i)
            for (int ch = 0; ch < 4; ++ch) {
                REQUIRE(std::isfinite(gpu.values[i][ch]));
                if (std::abs(gpu.values[i][ch] - ref.values[i][ch]) > 2e-3) ++far;
            }
        INFO("channels beyond 2e-3: " << far);
        CHECK(double(far) <= 0.03 * double(ref.values.size() * 4));
    }
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("sizes: above the device's maximum texture size is a named error", "[sizes]") {
    Device& d = test::device();
    const uint32_t tooWide = d.caps().limits.maxTextureSize + 1;
    AoDesc ao{tooWide, 4, test::tierProfile(), test::aoTestSettings(AoTechnique::Alchemy), DepthKind::Linear};
    Result<std::unique_ptr<AmbientObscurance>> a = AmbientObscurance::create(d, ao);
    INFO(a.status().toString());
    CHECK(a.status().code() == StatusCode::InvalidArgument);
    CHECK(a.status().message().find("width") != std::string::npos);
    Result<std::unique_ptr<MotionBlur>> m = MotionBlur::create(d, {4, tooWide, test::tierProfile(), Format::RGBA16F, DepthKind::Linear});
    INFO(m.status().toString());
    CHECK(m.status().code() == StatusCode::InvalidArgument);
    CHECK(m.status().message().find("height") != std::string::npos);
}

TEST_CASE("sizes: large and odd sizes run every effect with finite output", "[sizes]") {
    if (drawsNothing()) SFX_SKIP("the null backend draws nothing: GPU results are not compared on " << test::label());
    // 641x359 (odd, prime width) every technique; 3840x2160 one technique per effect, to keep
    // the suite short. Only finiteness here: the small sizes above compare with the references.
    struct Run {
        Size size;
        std::vector<AoTechnique> techniques;
    };
    const Run runs[] = {{{641, 359}, {AoTechnique::Alchemy, AoTechnique::Scalable, AoTechnique::Crease}},
                        {{3840, 2160}, {AoTechnique::Scalable}}};
    for (const Run& r : runs) {
        const uint32_t w = r.size.w, h = r.size.h;
        INFO(test::label() << " " << w << "x" << h);
        const samples::AnalyticScene scene = samples::cornerScene(w, h, 1.0);
        for (AoTechnique t : r.techniques) {
            const test::GpuAo gpu = test::runAo(test::device(), test::tierProfile(), scene, test::aoTestSettings(t));
            size_t nonFinite = 0;
            for (double v : gpu.visibility.values) nonFinite += std::isfinite(v) ? 0 : 1;
            INFO(toString(t));
            CHECK(nonFinite == 0);
        }
        ColorGrid c(w, h, {0.5, 0.25, 0.75, 1.0});
        VelocityGrid vel(w, h, {40.0, -7.0});
        const ColorGrid out = test::runMotionBlur(test::device(), test::tierProfile(), c, scene.linearDepth, &vel, {});
        size_t nonFinite = 0;
        for (const auto& px : out.values)
            for (double ch : px) nonFinite += std::isfinite(ch) ? 0 : 1;
        CHECK(nonFinite == 0);
    }
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}
