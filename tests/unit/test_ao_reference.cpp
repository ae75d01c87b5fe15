// The AO CPU references against analytic scenes: properties any correct implementation has
// (open planes unoccluded, monotonic toward creases and contacts, scale invariance, stable
// under doubled resolution, never NaN or outside [0, 1]), plus settings validation.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <set>
#include <vector>

#include "analytic_scenes.hpp"
#include "sfx/ao.hpp"
#include "sfx/image_io.hpp"
#include "sfx/reference/ao_reference.hpp"
#include "sfx/tiers.hpp"
#include "sfx_shared_ao.h"

using namespace sfx;
using reference::Grid;

namespace {

const AoTechnique kTechniques[] = {AoTechnique::Alchemy, AoTechnique::Scalable, AoTechnique::Crease};
const Tier kTiers[] = {Tier::Current, Tier::High};

// rows: the output's height (the scenes here are mostly 96x64).
AoConfig configFor(AoTechnique t, Tier tier, double scale = 1.0, bool blur = true, double radius = 0.5, AoResolution resolution = AoResolution::Tier,
                   uint32_t rows = 64) {
    AoSettings s;
    s.technique = t;
    s.resolution = resolution;
    s.radius = float(radius * scale);
    s.blur = blur;
    // Scalable's squared sum makes faint occlusion fainter; 2 keeps the contact shadow measurable.
    // The papers' look (the tier's calibrated one would move the analytic expectations).
    s.intensity = t == AoTechnique::Scalable ? 2.0f : 1.0f;
    s.contrast = 1.0f;
    if (t != AoTechnique::Crease) s.bias = t == AoTechnique::Alchemy ? kAoAlchemyDefaultBias : kAoScalableDefaultBias;
    s.sumExponent = kAoScalableCourseSumExponent;
    s.radiusExponent = 0.0f;               // one intensity at every radius, as the papers
    s.metresPerUnit = float(1.0 / scale);  // a scaled scene is the same scene in other units
    s.crease.bias = 0.25f;
    s.crease.range = float(1.0 / radius);  // the article's 1 world unit at scale 1, in units of the radius
    s.crease.fadeStart = float(50 * scale);
    s.crease.fadeEnd = float(100 * scale);
    Result<AoConfig> c = resolveAoConfig(s, tiers::profile(tier), 5, rows);
    REQUIRE(c.isOk());
    return c.value();
}

void requireValid(const Grid& g) {
    for (double v : g.values) {
        REQUIRE(std::isfinite(v));
        REQUIRE(v >= 0.0);
        REQUIRE(v <= 1.0);
    }
}

std::string name(AoTechnique t, Tier tier) { return std::string(toString(t)) + "/" + toString(tier); }

}  // namespace

TEST_CASE("ao settings: out-of-range values are named errors", "[ao][bad-input]") {
    // Scalable as each tier's unset technique: the sample counts and looks checked below are a
    // sampling technique's (the high tier's default runs horizon, whose counts are its own).
    TierProfile high = tiers::profile(Tier::High);
    high.aoTechnique = AoTechnique::Scalable;
    TierProfile current = tiers::profile(Tier::Current);
    current.aoTechnique = AoTechnique::Scalable;
    CHECK(validateAoSettings(AoSettings{}, high).isOk());
    AoSettings s;
    s.radius = -1;
    Status st = validateAoSettings(s, high);
    CHECK(st.code() == StatusCode::InvalidArgument);
    CHECK(st.message().find("AoSettings.radius") != std::string::npos);
    CHECK(st.message().find("[1e-4, 1000]") != std::string::npos);
    // The minimum keeps epsilon * r^2 a normal float (the centre-tap guard); below it is refused.
    s.radius = kAoMinRadius;
    CHECK(validateAoSettings(s, high).isOk());
    for (float tiny : {9e-5f, 1e-21f, 1e-40f /* denormal */}) {
        s.radius = tiny;
        st = validateAoSettings(s, high);
        CHECK(st.code() == StatusCode::InvalidArgument);
        CHECK(st.message().find("AoSettings.radius") != std::string::npos);
    }
    s = {};
    s.epsilon = 1e-8f;  // the documented minimum, as a float
    CHECK(validateAoSettings(s, high).isOk());
    s = {};
    s.crease.range = 0.01f;  // the documented minimum, in units of the radius
    CHECK(validateAoSettings(s, high).isOk());
    for (float tiny : {0.0099f, 1e-21f, 1e-40f}) {
        s.crease.range = tiny;
        st = validateAoSettings(s, high);
        CHECK(st.code() == StatusCode::InvalidArgument);
        CHECK(st.message().find("AoSettings.crease.range") != std::string::npos);
    }
    s.radius = std::numeric_limits<float>::quiet_NaN();
    CHECK(validateAoSettings(s, high).message().find("AoSettings.radius") != std::string::npos);
    s = {};
    s.samples = 3;
    CHECK(validateAoSettings(s, high).isOk());
    CHECK(validateAoSettings(s, current).message().find("AoSettings.samples") != std::string::npos);
    s.samples = 65;
    CHECK(validateAoSettings(s, high).message().find("AoSettings.samples") != std::string::npos);
    s = {};
    s.technique = AoTechnique::Crease;
    for (uint32_t taps : {12u, 24u}) {  // the diamond's checkerboard half or all of it, on either tier
        s.samples = taps;
        CHECK(validateAoSettings(s, high).isOk());
        CHECK(validateAoSettings(s, current).isOk());
    }
    for (uint32_t taps : {1u, 13u, 25u}) {
        s.samples = taps;
        st = validateAoSettings(s, high);
        CHECK(st.message().find("AoSettings.samples") != std::string::npos);
        CHECK(st.message().find("12 (half the diamond per pixel) or 24") != std::string::npos);
    }
    s = {};
    TierProfile oddCrease = tiers::profile(Tier::Current);
    oddCrease.aoCreaseTaps = 16;  // a hand-filled profile outside the two patterns
    CHECK(validateAoSettings(s, oddCrease).message().find("AoDesc.profile") != std::string::npos);
    s = {};
    s.crease.fadeEnd = 10;
    s.crease.fadeStart = 20;
    CHECK(validateAoSettings(s, high).message().find("AoSettings.crease.fadeEnd") != std::string::npos);
    s = {};
    s.bias = 2;
    CHECK(validateAoSettings(s, high).message().find("AoSettings.bias") != std::string::npos);
    for (float e : {0.4f, 4.5f, std::numeric_limits<float>::quiet_NaN()}) {
        s = {};
        s.sumExponent = e;
        CHECK(validateAoSettings(s, high).message().find("AoSettings.sumExponent") != std::string::npos);
    }
    s = {};
    TierProfile handFilled = high;
    handFilled.aoLook[uint32_t(AoTechnique::Scalable)].sumExponent = 0;
    CHECK(validateAoSettings(s, handFilled).message().find("AoDesc.profile.aoLook.sumExponent") != std::string::npos);
    s.sumExponent = 1.5f;  // a value set does not read the look
    CHECK(validateAoSettings(s, handFilled));
    s = {};
    s.blurRadius = 9;
    CHECK(validateAoSettings(s, high).message().find("AoSettings.blurRadius") != std::string::npos);
    // Counts are unset for the tier's: 0 is no longer a way to say so, it is out of range.
    s.blurRadius = 0;
    CHECK(validateAoSettings(s, high).message() == "AoSettings.blurRadius is 0; allowed [1, 8]");
    s = {};
    s.samples = 0;
    CHECK(validateAoSettings(s, high).message() == "AoSettings.samples is 0; allowed [1, 64]");
    s = {};
    s.contrast = 0;
    CHECK(validateAoSettings(s, high).message().find("AoSettings.contrast") != std::string::npos);
    s = {};
    s.resolution = static_cast<AoResolution>(3);
    const Status badResolution = validateAoSettings(s, high);
    CHECK(badResolution.code() == StatusCode::InvalidArgument);
    CHECK(badResolution.message().find("AoSettings.resolution") != std::string::npos);
    CHECK(badResolution.message().find("Tier, Full or Half") != std::string::npos);
}

TEST_CASE("ao settings resolve to the tier table", "[ao]") {
    // The blur's depth source is a profile field, matching ao_blur.frag's tier variants.
    CHECK(tiers::profile(Tier::Current).aoPackedDepthTarget);
    CHECK_FALSE(tiers::profile(Tier::High).aoPackedDepthTarget);
    // Unset look fields take the tier preset's calibrated AoLook; a value set wins.
    for (Tier tier : kTiers)
        for (AoTechnique t : kTechniques) {
            const AoLook& look = tiers::profile(tier).aoLook[uint32_t(t)];
            AoSettings d;
            d.technique = t;
            const AoConfig c = resolveAoConfig(d, tiers::profile(tier), 5, 64).value();
            CHECK(c.intensity == Approx(look.intensity));
            CHECK(c.contrast == Approx(look.contrast));
            if (t != AoTechnique::Crease) CHECK(c.bias == Approx(look.bias));
            if (t == AoTechnique::Scalable) CHECK(c.sumExponent == Approx(look.sumExponent));
            CHECK(c.crease.range == Approx(look.creaseRange * d.radius));  // in units of the radius
            CHECK(c.crease.bias == Approx(look.creaseBias));
            d.intensity = 3.0f, d.contrast = 2.0f, d.crease.range = 0.7f;
            const AoConfig set = resolveAoConfig(d, tiers::profile(tier), 5, 64).value();
            CHECK(set.intensity == Approx(3.0));
            CHECK(set.contrast == Approx(2.0));
            CHECK(set.crease.range == Approx(0.7 * d.radius));
        }
    const AoConfig aHigh = configFor(AoTechnique::Alchemy, Tier::High);
    CHECK(aHigh.samples == 12);
    CHECK(aHigh.bias == Approx(1e-4));
    CHECK(configFor(AoTechnique::Alchemy, Tier::Current).samples == 6);
    const AoConfig sHigh = configFor(AoTechnique::Scalable, Tier::High);
    CHECK(sHigh.samples == 9);
    CHECK_FALSE(sHigh.mirrored);
    CHECK(sHigh.maxRadiusPx == 0);
    // The default presets run at half resolution: pixel counts are half-size ones, the pyramid
    // is read from level 1 (one level fewer), the blur keeps its footprint with (r + 1) / 2 taps.
    CHECK(sHigh.halfResolution);
    CHECK(sHigh.depthMipLevels == 4);
    CHECK(sHigh.blurRadius == 3);
    const AoConfig sHighFull = configFor(AoTechnique::Scalable, Tier::High, 1.0, true, 0.5, AoResolution::Full);
    CHECK_FALSE(sHighFull.halfResolution);
    CHECK(sHighFull.depthMipLevels == 5);
    CHECK(sHighFull.blurRadius == 6);
    const AoConfig sCur = configFor(AoTechnique::Scalable, Tier::Current, 1.0, true, 0.5, AoResolution::Tier, 180);
    CHECK(sCur.samples == 4);
    CHECK(sCur.mirrored);
    CHECK(sCur.halfResolution);
    CHECK(sCur.maxRadiusPx == Approx(20));  // 160 px at 720 rows: 40 output px at 180 rows, 20 half-size texels
    CHECK(sCur.depthMipLevels == 1);
    CHECK(sCur.blurRadius == 1);
    const AoConfig sCurFull = configFor(AoTechnique::Scalable, Tier::Current, 1.0, true, 0.5, AoResolution::Full, 180);
    CHECK(sCurFull.maxRadiusPx == Approx(40));
    CHECK(sCurFull.blurRadius == 2);
    CHECK(configFor(AoTechnique::Crease, Tier::High, 1.0, false).blurRadius == 0);
    CHECK(configFor(AoTechnique::Crease, Tier::High, 1.0, true).samples == 24);
    CHECK(configFor(AoTechnique::Crease, Tier::Current, 1.0, true).samples == 12);
}

TEST_CASE("ao shared patterns: the crease diamond is 24 distinct stippled taps", "[ao]") {
    std::vector<shared::ivec2> diamond;
    for (int j = 0; j < shared::SFX_AO_CREASE_HALF_TAPS; ++j)
        diamond.push_back(shared::SFX_AO_CREASE_HALF_0[j]), diamond.push_back(shared::SFX_AO_CREASE_HALF_1[j]);
    REQUIRE(diamond.size() == size_t(shared::SFX_AO_CREASE_TAPS));
    for (size_t i = 0; i < diamond.size(); ++i) {
        const auto o = diamond[i];
        const int m = std::abs(o.x) + std::abs(o.y);
        CHECK((m == 2 || m == 4));
        for (size_t j = 0; j < i; ++j) CHECK_FALSE((diamond[j].x == o.x && diamond[j].y == o.y));
    }
    // Each half point-symmetric (its offsets sum to 0) and holding 4 taps of ring 2, 8 of ring 4.
    for (const auto* half : {shared::SFX_AO_CREASE_HALF_0, shared::SFX_AO_CREASE_HALF_1}) {
        int sx = 0, sy = 0, ring2 = 0;
        for (int j = 0; j < shared::SFX_AO_CREASE_HALF_TAPS; ++j)
            sx += half[j].x, sy += half[j].y, ring2 += std::abs(half[j].x) + std::abs(half[j].y) == 2;
        CHECK(sx == 0);
        CHECK(sy == 0);
        CHECK(ring2 == 4);
    }
    // The reference's taps: 24 on the high tier; 12 on the current tier, a pixel and its right
    // neighbour taking complementary halves (each tap of the diamond once between them).
    const auto rec = tools::facingPlaneScene(64, 48).reconstruction;
    const AoConfig high = configFor(AoTechnique::Crease, Tier::High, 1.0, true);
    const AoConfig current = configFor(AoTechnique::Crease, Tier::Current, 1.0, true);
    for (uint32_t y = 10; y < 13; ++y)
        for (uint32_t x = 10; x < 13; ++x) {
            const std::vector<reference::AoTap> all = reference::aoTaps(high, rec, 64, 48, x, y, 5.0);
            REQUIRE(all.size() == 24);
            for (size_t i = 0; i < all.size(); ++i) {
                CHECK(all[i].x == int(x) + diamond[i].x);
                CHECK(all[i].y == int(y) + diamond[i].y);
            }
            std::vector<int> taken(diamond.size(), 0);
            for (uint32_t px : {x, x + 1}) {
                const std::vector<reference::AoTap> mine = reference::aoTaps(current, rec, 64, 48, px, y, 5.0);
                REQUIRE(mine.size() == 12);
                for (const reference::AoTap& t : mine)
                    for (size_t i = 0; i < diamond.size(); ++i)
                        if (t.x - int(px) == diamond[i].x && t.y - int(y) == diamond[i].y) ++taken[i];
            }
            CHECK(std::all_of(taken.begin(), taken.end(), [](int n) { return n == 1; }));
        }
    // The rotation hash spreads neighbours over the circle.
    double sumCos = 0, sumSin = 0;
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x) {
            const shared::vec2 d = shared::aoDirection(shared::aoRotationIndex(x, y));
            sumCos += d.x;
            sumSin += d.y;
        }
    CHECK(std::abs(sumCos) / 1024 < 0.1);
    CHECK(std::abs(sumSin) / 1024 < 0.1);
}

TEST_CASE("ao tap directions: the table is the float of each angle's cosine and sine, turned by exact quarter turns", "[ao]") {
    for (int k = 0; k < 512; ++k) {
        const double angle = 2.0 * 3.14159265358979323846 * double(k % 256) / 256.0;
        const shared::vec2 d = shared::aoDirection(k);
        INFO("direction " << k);
        // Within 2^-24 of the exact value (an ulp of floats in [0.5, 1)): the literals round to nearest.
        CHECK(std::abs(double(d.x) - std::cos(angle)) <= 0x1p-24);
        CHECK(std::abs(double(d.y) - std::sin(angle)) <= 0x1p-24);
        if (k % 64 == 0) CHECK((d.x == 0.0f || d.y == 0.0f));  // axis directions are exact
    }
    // Alchemy: 64 taps at the golden angle take 64 different directions; Scalable's spiral of 9
    // taps over 7 turns lands where (i + 0.5) / 9 * 7 turns says, to the table's 1/256 turn.
    std::set<int> golden;
    for (int i = 0; i < 64; ++i) golden.insert(((shared::aoAlchemyTurnsQ16(i) + 128) >> 8) & 255);
    CHECK(golden.size() == 64);
    const int halfStep = shared::aoSpiralHalfStepQ16(7.0, 9, false);
    for (int i = 0; i < 9; ++i) {
        const double turns = (i + 0.5) / 9.0 * 7.0;
        const double table = double(shared::aoSpiralTurnsQ16(i, halfStep)) / 65536.0;
        const double diff = std::abs(table - (turns - std::floor(turns)));
        CHECK(std::min(diff, 1.0 - diff) < 1.0 / 65536.0 * 10);
    }
}

TEST_CASE("ao normals from depth: exact on planes, close on spheres, no differencing across edges", "[ao]") {
    for (const tools::AnalyticScene& s : {tools::tiltedPlaneScene(64, 48), tools::facingPlaneScene(64, 48)}) {
        const auto n = reference::normalsFromDepth(s.linearDepth, s.reconstruction);
        for (size_t i = 0; i < n.size(); ++i) REQUIRE(glm::dot(n[i], s.normals[i]) > 1.0 - 1e-9);
    }
    const tools::AnalyticScene s = tools::sphereOnPlaneScene(128, 96);
    const auto n = reference::normalsFromDepth(s.linearDepth, s.reconstruction);
    int bad = 0, edgePixels = 0;
    for (uint32_t y = 0; y < s.height; ++y)
        for (uint32_t x = 0; x < s.width; ++x) {
            const size_t i = size_t(y) * s.width + x;
            const glm::dvec3 view = -glm::normalize(s.positions[i]);
            if (glm::dot(s.normals[i], view) < 0.3) continue;  // grazing: finite differences are coarse there
            const double z = s.linearDepth.at(x, y);
            const bool atEdge = x > 0 && x + 1 < s.width && std::abs(s.linearDepth.at(x + 1, y) - s.linearDepth.at(x - 1, y)) > 0.2 * z;
            edgePixels += atEdge;
            if (glm::dot(n[i], s.normals[i]) < 0.95) ++bad;
        }
    CHECK(edgePixels > 10);  // the scene really has depth edges
    CHECK(bad == 0);
}

TEST_CASE("ao normals from depth: a non-finite or out-of-range neighbour is sky, by the shared rule", "[ao]") {
    // sfx_shared_ao.h: every depth is read through sfxLinearDepthOrFar, so NaN, +-inf, 0, a
    // negative value and one past the far plane all read as maxDepth, and the tangent goes to the
    // other neighbour. On a tilted plane the normals next to such pixels stay the plane's normal.
    tools::AnalyticScene s = tools::tiltedPlaneScene(32, 24);
    const double bad[] = {
        std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(), 0.0, -1.0, 1e30};
    std::vector<std::pair<uint32_t, uint32_t>> poked;
    for (size_t k = 0; k < std::size(bad); ++k) {
        const uint32_t x = 4 + uint32_t(k) * 4, y = 4 + uint32_t(k) * 3;  // isolated: no two share a neighbour
        s.linearDepth.at(x, y) = bad[k];
        poked.push_back({x, y});
    }
    const auto n = reference::normalsFromDepth(s.linearDepth, s.reconstruction);
    Grid asSky = s.linearDepth;
    for (auto [x, y] : poked) asSky.at(x, y) = s.reconstruction.maxDepth;
    const auto nSky = reference::normalsFromDepth(asSky, s.reconstruction);
    for (size_t i = 0; i < n.size(); ++i) {
        REQUIRE(std::isfinite(n[i].x));
        REQUIRE(std::isfinite(n[i].y));
        REQUIRE(std::isfinite(n[i].z));
        REQUIRE(glm::length(n[i]) == Approx(1.0).epsilon(1e-12));
        REQUIRE(n[i] == nSky[i]);  // exactly the sky rule, whatever the non-finite value
    }
    for (auto [px, py] : poked)
        for (auto [dx, dy] : {std::pair{-1, 0}, std::pair{1, 0}, std::pair{0, -1}, std::pair{0, 1}}) {
            const uint32_t x = uint32_t(int(px) + dx), y = uint32_t(int(py) + dy);
            const size_t i = size_t(y) * s.width + x;
            INFO("neighbour (" << x << ", " << y << ") of a depth " << s.linearDepth.at(px, py));
            CHECK(glm::dot(n[i], s.normals[i]) > 1.0 - 1e-9);
        }
    // The rule's pieces, as the shaders run them: ties take the lower index, borders the inside.
    CHECK_FALSE(shared::aoNormalUsesNext(3, 8, 9.0, 9.0, 1.0));
    // Differences a rounding apart are a tie (the lower index), a clear gap is not.
    CHECK_FALSE(shared::aoNormalUsesNext(3, 8, 3.0, 5.0 - 1e-12, 4.0));
    CHECK(shared::aoNormalUsesNext(3, 8, 3.0, 4.99, 4.0));
    CHECK(shared::aoNormalUsesNext(0, 8, 0.0, 50.0, 1.0));
    CHECK_FALSE(shared::aoNormalUsesNext(7, 8, 50.0, 0.0, 1.0));
    CHECK(shared::aoFacingNormal(glm::dvec3(1, 0, 0), glm::dvec3(2, 0, 0), glm::dvec3(0, 0, -1)) == glm::dvec3(0, 0, 1));
}

TEST_CASE("ao reference: an open plane is unoccluded", "[ao]") {
    for (AoTechnique t : kTechniques)
        for (Tier tier : kTiers)
            for (bool gbufferNormals : {false, true}) {
                INFO(name(t, tier) << (gbufferNormals ? " gbuffer normals" : " derived normals"));
                const tools::AnalyticScene facing = tools::facingPlaneScene(64, 48);
                const Grid v = reference::ambientVisibility(facing.aoInput(gbufferNormals), configFor(t, tier));
                requireValid(v);
                for (double x : v.values) REQUIRE(x > 1.0 - 1e-9);
                const tools::AnalyticScene tilted = tools::tiltedPlaneScene(64, 48);
                const Grid w = reference::ambientVisibility(tilted.aoInput(gbufferNormals), configFor(t, tier));
                requireValid(w);
                for (double x : w.values) REQUIRE(x > 0.999);
            }
}

TEST_CASE("ao reference: occlusion grows monotonically toward a crease and a contact point", "[ao]") {
    const std::vector<double> creaseEdges{0.0, 0.05, 0.1, 0.15, 0.2, 0.3, 0.4, 0.6, 0.9};
    const std::vector<double> contactEdges{0.35, 0.45, 0.55, 0.7, 0.85, 1.0, 1.3, 1.8};
    for (AoTechnique t : kTechniques)
        for (Tier tier : kTiers)
            for (bool blur : {false, true}) {
                INFO(name(t, tier) << (blur ? " blur" : " no blur"));
                // Bins average 100+ pixels; unblurred, the few rotated taps still leave ~0.03 of noise.
                const double tol = blur ? 0.02 : 0.04;
                const tools::AnalyticScene corner = tools::cornerScene(160, 120);
                const Grid vc = reference::ambientVisibility(corner.aoInput(false), configFor(t, tier, 1.0, blur));
                requireValid(vc);
                const auto bc = tools::occlusionBins(corner, vc, 1.0, creaseEdges, tools::onCornerPlaneA, tools::distanceToCrease);
                for (size_t i = 0; i + 1 < bc.size(); ++i) {
                    INFO("crease bin " << i << ": " << bc[i] << " then " << bc[i + 1]);
                    REQUIRE(bc[i] >= 0);
                    CHECK(bc[i] >= bc[i + 1] - tol);
                }
                CHECK(bc.front() > bc.back() + 0.01);
                const tools::AnalyticScene contact = tools::sphereOnPlaneScene(160, 120);
                const Grid vs = reference::ambientVisibility(contact.aoInput(false), configFor(t, tier, 1.0, blur, 1.0));
                requireValid(vs);
                const auto bs = tools::occlusionBins(contact, vs, 1.0, contactEdges, tools::onContactFloor, tools::distanceToContact);
                for (size_t i = 0; i + 1 < bs.size(); ++i) {
                    INFO("contact bin " << i << ": " << bs[i] << " then " << bs[i + 1]);
                    REQUIRE(bs[i] >= 0);
                    CHECK(bs[i] >= bs[i + 1] - tol);
                }
                CHECK(bs.front() > bs.back() + 0.01);
            }
}

TEST_CASE("ao reference: scaling scene and radius together leaves AO unchanged", "[ao]") {
    for (AoTechnique t : kTechniques)
        for (Tier tier : kTiers) {
            INFO(name(t, tier));
            const Grid a = reference::ambientVisibility(tools::cornerScene(96, 64).aoInput(false), configFor(t, tier, 1.0));
            const Grid b = reference::ambientVisibility(tools::cornerScene(96, 64, 10.0).aoInput(false), configFor(t, tier, 10.0));
            double maxDiff = 0;
            for (size_t i = 0; i < a.values.size(); ++i) maxDiff = std::max(maxDiff, std::abs(a.values[i] - b.values[i]));
            CHECK(maxDiff < 1e-6);
        }
}

TEST_CASE("ao reference: doubling resolution changes AO only within tolerance", "[ao]") {
    for (AoTechnique t : kTechniques)
        for (Tier tier : kTiers) {
            INFO(name(t, tier));
            for (auto make : {&tools::cornerScene, &tools::sphereOnPlaneScene}) {
                const Grid lo = reference::ambientVisibility(make(96, 64, 1.0).aoInput(false),
                                                             configFor(t, tier, 1.0, true, 0.5, AoResolution::Tier, 64));
                const Grid hi = tools::downsample2x(
                    reference::ambientVisibility(make(192, 128, 1.0).aoInput(false), configFor(t, tier, 1.0, true, 0.5, AoResolution::Tier, 128)));
                double meanAbs = 0, meanLo = 0, meanHi = 0;
                for (size_t i = 0; i < lo.values.size(); ++i) {
                    meanAbs += std::abs(lo.values[i] - hi.values[i]);
                    meanLo += lo.values[i];
                    meanHi += hi.values[i];
                }
                meanAbs /= double(lo.values.size());
                const double meanShift = std::abs(meanLo - meanHi) / double(lo.values.size());
                const double tol = 0.03;
                CHECK(meanAbs < tol);
                CHECK(meanShift < tol / 2);
            }
        }
}

TEST_CASE("ao reference: sky is unoccluded; tiny and huge radii and far depths stay finite", "[ao]") {
    const tools::AnalyticScene cols = tools::columnsScene(96, 64);
    for (AoTechnique t : kTechniques)
        for (Tier tier : kTiers)
            for (float radius : {1e-4f, 0.5f, 50.0f, 1000.0f}) {
                INFO(name(t, tier) << " radius " << radius);
                AoSettings s;
                s.technique = t;
                s.radius = radius;
                const AoConfig c = resolveAoConfig(s, tiers::profile(tier), 5, 64).value();
                const Grid v = reference::ambientVisibility(cols.aoInput(false), c);
                requireValid(v);
                for (uint32_t y = 0; y < v.height; ++y)
                    for (uint32_t x = 0; x < v.width; ++x)
                        if (cols.linearDepth.at(x, y) >= cols.reconstruction.maxDepth) REQUIRE(v.at(x, y) == 1.0);
                if (radius == 1e-4f && t != AoTechnique::Crease)
                    for (double x : v.values) REQUIRE(x > 0.999);  // a radius below a pixel finds no occluder
            }
}

TEST_CASE("ao reference: the bilateral blur does not carry occlusion across a depth edge", "[ao]") {
    Grid vis(16, 4, 1.0), depth(16, 4, 10.0);
    for (uint32_t y = 0; y < 4; ++y)
        for (uint32_t x = 0; x < 8; ++x) {
            vis.at(x, y) = 0.0;
            depth.at(x, y) = 2.0;
        }
    for (int r : {1, 2, 6, 8}) {
        const Grid h = reference::bilateralBlurPass(vis, depth, 100.0, r, 1, 0);
        for (uint32_t y = 0; y < 4; ++y)
            for (uint32_t x = 0; x < 16; ++x) REQUIRE(h.at(x, y) == (x < 8 ? 0.0 : 1.0));
    }
}

TEST_CASE("ao reference: the half-size depth takes depth MIP level 1's rotated-grid samples", "[ao][half-res]") {
    const tools::AnalyticScene scene = tools::columnsScene(97, 65);
    const Grid half = reference::halfSizeDepth(scene.linearDepth);
    REQUIRE(half.width == 48);
    REQUIRE(half.height == 32);
    const std::vector<Grid> pyramid = reference::depthPyramid(scene.linearDepth, 2);
    CHECK(half.values == pyramid[1].values);  // the high tier reuses MIP level 1 for it
    // Each texel is one full-size sample (never an average), so positions stay exact.
    for (uint32_t y = 0; y < half.height; ++y)
        for (uint32_t x = 0; x < half.width; ++x) {
            const shared::ivec2 s = shared::aoFullResPixel(shared::ivec2{int(x), int(y)}, shared::ivec2{97, 65});
            REQUIRE(half.at(x, y) == scene.linearDepth.at(uint32_t(s.x), uint32_t(s.y)));
        }
}

TEST_CASE("ao reference: the depth-aware upsample keeps edges and reproduces smooth input", "[ao][half-res]") {
    // A near square (depth 2, AO 0.2) on a far wall (depth 10, AO 0.9), edge at an odd pixel.
    const uint32_t w = 32, h = 16, edge = 13;
    Grid full(w, h, 10.0);
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < edge; ++x) full.at(x, y) = 2.0;
    const Grid half = reference::halfSizeDepth(full);
    Grid halfAo(half.width, half.height);
    for (size_t i = 0; i < halfAo.values.size(); ++i) halfAo.values[i] = half.values[i] < 5.0 ? 0.2 : 0.9;
    const Grid up = reference::depthAwareUpsample(halfAo, half, full, 100.0);
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) {
            INFO(x << ", " << y);
            // Every pixel gets only its own surface's AO, right up to the edge: no halo.
            CHECK(up.at(x, y) == Approx(x < edge ? 0.2 : 0.9).margin(1e-12));
        }
    // A smooth surface (depths within the tolerance) with AO linear in x: the blend is the
    // bilinear interpolation, exact for a linear ramp away from the clamped border but for the
    // nearest-depth texel's fixed weight (1e-3 of a total near 1: under 1e-4 on a 0.04 spread).
    Grid ramp(w, h, 5.0), rampHalf(w / 2, h / 2);
    for (uint32_t y = 0; y < h / 2; ++y)
        for (uint32_t x = 0; x < w / 2; ++x) rampHalf.at(x, y) = 0.02 * (2.0 * x + 0.5);
    const Grid rampUp = reference::depthAwareUpsample(rampHalf, reference::halfSizeDepth(ramp), ramp, 100.0);
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 1; x + 1 < w; ++x) CHECK(rampUp.at(x, y) == Approx(0.02 * x).margin(1e-4));
    // Sky at full size is unoccluded whatever the half-size texels hold.
    Grid withSky = full;
    withSky.at(20, 5) = 1e30;
    CHECK(reference::depthAwareUpsample(halfAo, half, withSky, 100.0).at(20, 5) == 1.0);
}

TEST_CASE("ao reference: Scalable's sum exponent raises the same normalised sum to its power", "[ao]") {
    // With contrast 1, occlusion = 1 - visibility = a^e for the same tap sum a at every pixel:
    // exponent 2 must be exponent 1 squared, and exponent 1 at least as dark wherever a < 1.
    for (Tier tier : kTiers) {
        INFO(toString(tier));
        const tools::AnalyticScene scene = tools::cornerScene(96, 64, 1.0);
        AoConfig linear = configFor(AoTechnique::Scalable, tier, 1.0, false, 0.5, AoResolution::Full), squared = linear;
        linear.sumExponent = 1.0;
        const Grid v1 = reference::ambientVisibility(scene.aoInput(false), linear);
        const Grid v2 = reference::ambientVisibility(scene.aoInput(false), squared);
        requireValid(v1);
        size_t occluded = 0;
        for (size_t i = 0; i < v1.values.size(); ++i) {
            const double a = 1.0 - v1.values[i];
            if (a > 0.0 && a < 1.0) ++occluded;
            CHECK(1.0 - v2.values[i] == Approx(a * a).margin(1e-12));
        }
        CHECK(occluded > v1.values.size() / 20);  // the corner is occluded, not a blank image
    }
}

TEST_CASE("ao reference: half resolution stays close to full resolution on analytic scenes", "[ao][half-res]") {
    for (AoTechnique t : {AoTechnique::Alchemy, AoTechnique::Scalable})
        for (Tier tier : kTiers) {
            INFO(name(t, tier));
            for (auto make : {&tools::cornerScene, &tools::sphereOnPlaneScene}) {
                const tools::AnalyticScene scene = make(192, 128, 1.0);
                const AoConfig full = configFor(t, tier, 1.0, true, 0.5, AoResolution::Full);
                const AoConfig half = configFor(t, tier, 1.0, true, 0.5, AoResolution::Half);
                const Grid a = reference::ambientVisibility(scene.aoInput(false), full);
                const Grid b = reference::ambientVisibility(scene.aoInput(false), half);
                requireValid(b);
                double meanAbs = 0;
                for (size_t i = 0; i < a.values.size(); ++i) meanAbs += std::abs(a.values[i] - b.values[i]);
                meanAbs /= double(a.values.size());
                INFO("mean |half - full| " << meanAbs);
                CHECK(meanAbs < 0.03);  // the same bound as doubling the resolution
            }
        }
}

// Not a check: writes the G-buffer files the `sfx ao` CTest entries read (fixture ao_cli_files).
TEST_CASE("ao cli fixture: write small G-buffer files", "[.ao-cli-fixture]") {
    const tools::AnalyticScene s = tools::cornerScene(64, 48);
    io::Image depth(s.width, s.height, 1), normals(s.width, s.height, 3);
    for (uint32_t y = 0; y < s.height; ++y)
        for (uint32_t x = 0; x < s.width; ++x) {
            depth.at(x, y) = float(s.linearDepth.at(x, y));
            const glm::dvec3 n = s.normals[size_t(y) * s.width + x];
            for (uint32_t c = 0; c < 3; ++c) normals.at(x, y, c) = float(n[int(c)]);
        }
    REQUIRE(io::writePfm("ao_cli_depth.pfm", depth).isOk());
    REQUIRE(io::writePfm("ao_cli_normals.pfm", normals).isOk());
    REQUIRE(io::writePfm("ao_cli_small.pfm", io::Image(32, 24, 1, 4.0f)).isOk());
    // Hostile values: a NaN normal is a named error; an infinite one and infinite or zero depth
    // follow the effect's rules (derived normal, sky).
    io::Image nanNormals = normals, hostileNormals = normals, hostileDepth = depth;
    nanNormals.at(9, 4, 2) = std::numeric_limits<float>::quiet_NaN();
    hostileNormals.at(9, 4, 0) = std::numeric_limits<float>::infinity();
    hostileDepth.at(10, 5) = std::numeric_limits<float>::infinity();
    hostileDepth.at(11, 5) = 0.0f;
    REQUIRE(io::writePfm("ao_cli_nan_normals.pfm", nanNormals).isOk());
    REQUIRE(io::writePfm("ao_cli_hostile_normals.pfm", hostileNormals).isOk());
    REQUIRE(io::writePfm("ao_cli_hostile_depth.pfm", hostileDepth).isOk());
    std::FILE* f = std::fopen("ao_cli_malformed.pfm", "wb");
    REQUIRE(f);
    std::fputs("Pf\n64 oops\n-1\n", f);
    std::fclose(f);
}

TEST_CASE("ao: an empty tier profile is a named error, not black output", "[ao][bad-input]") {
    TierProfile empty;  // value-initialised: every count 0
    Status s = validateAoSettings(AoSettings{}, empty);
    CHECK(s.code() == StatusCode::InvalidArgument);
    CHECK(s.message().find("AoDesc.profile") != std::string::npos);
    CHECK(resolveAoConfig(AoSettings{}, empty, 4, 64).status().code() == StatusCode::InvalidArgument);
}
