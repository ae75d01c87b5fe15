// AO at different output sizes: Scalable's radius clamp, defined at SFX_AO_REFERENCE_ROWS,
// follows the output's rows, and crease's diamond follows the projected radius, so a look fitted
// at one size holds at another (docs/trade.md, "The looks").
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "analytic_scenes.hpp"
#include "sfx/ao.hpp"
#include "sfx/reference/ao_reference.hpp"
#include "sfx/tiers.hpp"
#include "sfx_shared_ao.h"

using namespace sfx;
using reference::Grid;

namespace {

const Tier kTiers[] = {Tier::Current, Tier::High};

// The tier's defaults (its look), resolved for an output of `rows` rows.
AoConfig resolved(AoTechnique t, Tier tier, uint32_t rows, AoResolution resolution = AoResolution::Tier) {
    AoSettings s;
    s.technique = t;
    s.resolution = resolution;
    Result<AoConfig> c = resolveAoConfig(s, tiers::profile(tier), 5, rows);
    REQUIRE(c.isOk());
    return c.value();
}

}  // namespace

TEST_CASE("ao config: Scalable's clamp follows the output's rows", "[ao]") {
    // Output pixels at SFX_AO_REFERENCE_ROWS (720), scaled with the rows and halved at half size,
    // so the look fitted at 320x180 covers the same share of the image at every size.
    const auto clamp = [](uint32_t rows, AoResolution r) { return resolved(AoTechnique::Scalable, Tier::Current, rows, r).maxRadiusPx; };
    CHECK(clamp(180, AoResolution::Half) == Approx(20));
    CHECK(clamp(720, AoResolution::Half) == Approx(80));
    CHECK(clamp(1080, AoResolution::Half) == Approx(120));
    CHECK(clamp(720, AoResolution::Full) == Approx(160));
    CHECK(clamp(1, AoResolution::Half) == Approx(1));                          // at least one pass pixel
    CHECK(resolved(AoTechnique::Scalable, Tier::High, 720).maxRadiusPx == 0);  // no clamp
}

TEST_CASE("ao config: crease's range is in units of the radius", "[ao]") {
    for (Tier tier : kTiers) {
        INFO(toString(tier));
        AoSettings s;
        s.technique = AoTechnique::Crease;
        for (float radius : {0.25f, 0.5f, 2.0f}) {
            s.radius = radius;
            Result<AoConfig> c = resolveAoConfig(s, tiers::profile(tier), 5, 720);
            REQUIRE(c.isOk());
            CHECK(c->crease.range == Approx(tiers::profile(tier).aoLook[uint32_t(AoTechnique::Crease)].creaseRange * radius));
        }
        s.crease.range = 3.0f;
        Result<AoConfig> c = resolveAoConfig(s, tiers::profile(tier), 5, 720);
        REQUIRE(c.isOk());
        CHECK(c->crease.range == Approx(6.0));
    }
}

TEST_CASE("ao reference: crease's diamond reaches the radius, one pass pixel per stride at least", "[ao]") {
    // The outer ring (4 strides along the axes) lands at the pixel's screen radius, rounded as
    // every tap is (aoTap); where the radius projects below 4 pixels the stride stays 1.
    const auto rec = tools::facingPlaneScene(64, 48).reconstruction;
    for (double radius : {0.5, 0.05, 1e-3}) {
        INFO("radius " << radius);
        AoConfig c = resolved(AoTechnique::Crease, Tier::High, 48, AoResolution::Full);
        c.radius = radius;
        const double z = 5.0;
        const double screenRadius = radius * rec.pixelsPerUnitAtUnitDepth / z;
        const double stride = std::max(1.0, screenRadius / 4);
        const std::vector<reference::AoTap> taps = reference::aoTaps(c, rec, 64, 48, 30, 20, z);
        REQUIRE(taps.size() == 24);
        for (int j = 0; j < shared::SFX_AO_CREASE_HALF_TAPS; ++j) {
            for (int half = 0; half < 2; ++half) {
                const auto o = half == 0 ? shared::SFX_AO_CREASE_HALF_0[j] : shared::SFX_AO_CREASE_HALF_1[j];
                const reference::AoTap& t = taps[size_t(2 * j + half)];
                CHECK(t.x == std::clamp(30 + int(std::floor(0.5 + o.x * stride)), 0, 63));
                CHECK(t.y == std::clamp(20 + int(std::floor(0.5 + o.y * stride)), 0, 47));
            }
        }
        if (screenRadius < 4) CHECK(taps[8].x == 30 + 4);  // HALF_0[4] is (4, 0): one pixel per stride
    }
}

TEST_CASE("ao config: no output rows is a named error", "[ao][bad-input]") {
    const Status rows = resolveAoConfig(AoSettings{}, tiers::profile(Tier::Current), 1, 0).status();
    CHECK(rows.code() == StatusCode::InvalidArgument);
    CHECK(rows.message().find("outputRows") != std::string::npos);
}

TEST_CASE("ao reference: where the resolution doubles, crease's band keeps its width", "[ao]") {
    // From 360 to 720 rows the projected radius doubles, and with it the diamond's stride, so the
    // diamond spans the same world distance and the band it darkens along the corner's crease
    // keeps its width: compared where either is occluded, with the tier's look (the papers' is
    // too faint to tell).
    for (Tier tier : kTiers) {
        INFO(toString(tier));
        const AoConfig lo = resolved(AoTechnique::Crease, tier, 360);
        const AoConfig hi = resolved(AoTechnique::Crease, tier, 720);
        const Grid a = reference::ambientVisibility(tools::cornerScene(640, 360, 1.0).aoInput(false), lo);
        const Grid b = tools::downsample2x(reference::ambientVisibility(tools::cornerScene(1280, 720, 1.0).aoInput(false), hi));
        double meanAbs = 0;
        size_t n = 0;
        for (size_t i = 0; i < a.values.size(); ++i)
            if (std::min(a.values[i], b.values[i]) < 0.95) meanAbs += std::abs(a.values[i] - b.values[i]), ++n;
        REQUIRE(n > a.values.size() / 50);
        meanAbs /= double(n);
        INFO("mean |difference| " << meanAbs << " over " << n << " occluded pixels");
        CHECK(meanAbs < 0.03);
    }
}
