// AO at different output sizes: the tier's pixel extents defined at SFX_AO_REFERENCE_ROWS
// (Scalable's radius clamp, crease's tap spacing) follow the output's rows, so a look fitted at
// one size holds at another (docs/trade.md, "The looks").
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

TEST_CASE("ao config: Scalable's clamp and crease's tap spacing follow the output's rows", "[ao]") {
    // Both are output pixels at SFX_AO_REFERENCE_ROWS (720), scaled with the rows and halved at
    // half size, so the look fitted at 320x180 covers the same share of the image at every size.
    const auto clamp = [](uint32_t rows, AoResolution r) { return resolved(AoTechnique::Scalable, Tier::Current, rows, r).maxRadiusPx; };
    CHECK(clamp(180, AoResolution::Half) == Approx(20));
    CHECK(clamp(720, AoResolution::Half) == Approx(80));
    CHECK(clamp(1080, AoResolution::Half) == Approx(120));
    CHECK(clamp(720, AoResolution::Full) == Approx(160));
    CHECK(clamp(1, AoResolution::Half) == Approx(1));                          // at least one pass pixel
    CHECK(resolved(AoTechnique::Scalable, Tier::High, 720).maxRadiusPx == 0);  // no clamp
    for (Tier tier : kTiers) {
        INFO(toString(tier));
        const auto stride = [tier](uint32_t rows, AoResolution r) { return resolved(AoTechnique::Crease, tier, rows, r).creaseStride; };
        CHECK(stride(1, AoResolution::Half) == 1);  // at least one pixel
        CHECK(stride(64, AoResolution::Half) == 1);
        CHECK(stride(180, AoResolution::Half) == 2);  // 12 px at 720 rows: 1.5 half-size pixels, rounded
        CHECK(stride(360, AoResolution::Half) == 3);
        CHECK(stride(720, AoResolution::Half) == 6);
        CHECK(stride(1080, AoResolution::Half) == 9);
        CHECK(stride(180, AoResolution::Full) == 3);
        CHECK(stride(720, AoResolution::Full) == 12);
    }
    // The reference's taps step by the stride.
    const auto rec = tools::facingPlaneScene(64, 48).reconstruction;
    const AoConfig c = resolved(AoTechnique::Crease, Tier::High, 480, AoResolution::Half);
    REQUIRE(c.creaseStride == 4);
    const std::vector<reference::AoTap> taps = reference::aoTaps(c, rec, 64, 48, 30, 20, 5.0);
    REQUIRE(taps.size() == 24);
    for (int j = 0; j < shared::SFX_AO_CREASE_HALF_TAPS; ++j) {
        CHECK(taps[2 * j].x == 30 + 4 * shared::SFX_AO_CREASE_HALF_0[j].x);
        CHECK(taps[2 * j].y == 20 + 4 * shared::SFX_AO_CREASE_HALF_0[j].y);
        CHECK(taps[2 * j + 1].x == 30 + 4 * shared::SFX_AO_CREASE_HALF_1[j].x);
    }
}

TEST_CASE("ao config: no output rows or a hand-filled crease spacing out of range is a named error", "[ao][bad-input]") {
    const Status rows = resolveAoConfig(AoSettings{}, tiers::profile(Tier::Current), 1, 0).status();
    CHECK(rows.code() == StatusCode::InvalidArgument);
    CHECK(rows.message().find("outputRows") != std::string::npos);
    for (float spacing : {0.0f, -1.0f, 65.0f, std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity()}) {
        INFO("aoCreaseSpacingPx " << spacing);
        TierProfile p = tiers::profile(Tier::High);
        p.aoCreaseSpacingPx = spacing;
        const Status s = validateAoSettings(AoSettings{}, p);
        CHECK(s.code() == StatusCode::InvalidArgument);
        CHECK(s.message().find("AoDesc.profile") != std::string::npos);
    }
}

TEST_CASE("ao reference: where crease's spacing doubles with the rows, its band keeps its width", "[ao]") {
    // From 360 to 720 rows crease's spacing doubles with them (3 then 6 half-size pixels), so its
    // diamond spans the same world distance and the band it darkens along the corner's crease
    // keeps its width: compared where either is occluded, with the tier's look (the papers' is
    // too faint to tell): 0.009 and 0.011 (high, current); a spacing left at 3 pixels at 720
    // rows differs by more than 0.1.
    for (Tier tier : kTiers) {
        INFO(toString(tier));
        const AoConfig lo = resolved(AoTechnique::Crease, tier, 360);
        const AoConfig hi = resolved(AoTechnique::Crease, tier, 720);
        REQUIRE(lo.creaseStride == 3);
        REQUIRE(hi.creaseStride == 6);
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
