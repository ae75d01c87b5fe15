// A look that follows the radius: the intensity a dispatch (and the CPU reference, which reads
// the same AoConfig) uses is sigma * (radius * metresPerUnit / 0.5 m)^-A, and every way to make
// it meaningless is a named error.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "sfx/ao.hpp"
#include "sfx/tiers.hpp"

using namespace sfx;

namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

// The high tier's profile with Alchemy's look following the radius with exponent a.
TierProfile withExponent(float a) {
    TierProfile p = tiers::profile(Tier::High);
    p.aoLook[uint32_t(AoTechnique::Alchemy)].radiusExponent = a;
    return p;
}

double resolvedIntensity(const AoSettings& s, const TierProfile& p) {
    Result<AoConfig> c = resolveAoConfig(s, p, 5, 64);
    INFO(c.status().message());
    REQUIRE(c.isOk());
    return c->intensity;
}

AoSettings alchemy(float radius, float metresPerUnit = 1.0f) {
    AoSettings s;
    s.technique = AoTechnique::Alchemy;
    s.radius = radius;
    s.metresPerUnit = metresPerUnit;
    return s;
}

}  // namespace

TEST_CASE("a radius-following look scales its intensity by the radius in metres", "[ao]") {
    const TierProfile p = withExponent(0.2f);
    const double sigma = p.aoLook[uint32_t(AoTechnique::Alchemy)].intensity;
    CHECK(resolvedIntensity(alchemy(0.5f), p) == Approx(sigma));  // the reference radius keeps the look's
    CHECK(resolvedIntensity(alchemy(0.25f), p) == Approx(sigma * std::pow(2.0, 0.2)));
    CHECK(resolvedIntensity(alchemy(2.0f), p) == Approx(sigma * std::pow(4.0, -0.2)));
    // The same radius in centimetres resolves alike once the scale is stated, and not without it.
    CHECK(resolvedIntensity(alchemy(25.0f, 0.01f), p) == Approx(resolvedIntensity(alchemy(0.25f), p)));
    CHECK(resolvedIntensity(alchemy(25.0f), p) < resolvedIntensity(alchemy(0.25f), p) * 0.5);
    // A set exponent wins over the look's, and scales a set intensity too.
    AoSettings s = alchemy(0.25f);
    s.radiusExponent = 1.0f;
    s.intensity = 0.3f;
    CHECK(resolvedIntensity(s, p) == Approx(0.3 * 2.0));
    s.radiusExponent = 0.0f;
    CHECK(resolvedIntensity(s, p) == Approx(0.3));
}

TEST_CASE("an exponent of 0 leaves the intensity exactly as it is at any radius and scale", "[ao]") {
    const TierProfile p = tiers::profile(Tier::High);
    for (AoTechnique t : {AoTechnique::Alchemy, AoTechnique::Scalable, AoTechnique::Crease, AoTechnique::Horizon}) {
        if (p.aoLook[uint32_t(t)].radiusExponent != 0.0f) continue;
        for (float radius : {kAoMinRadius, 0.5f, 1000.0f})
            for (float scale : {1e-6f, 1.0f, 1e6f}) {
                AoSettings s;
                s.technique = t;
                s.radius = radius;
                s.metresPerUnit = scale;
                CHECK(resolvedIntensity(s, p) == double(p.aoLook[uint32_t(t)].intensity));
            }
    }
}

TEST_CASE("radius-following settings out of range are named errors", "[ao]") {
    const TierProfile p = withExponent(0.2f);
    for (float scale : {0.0f, -1.0f, 1e-7f, 2e6f, kNaN, kInf}) {
        const Status st = validateAoSettings(alchemy(0.5f, scale), p);
        CHECK(st.code() == StatusCode::InvalidArgument);
        CHECK(st.message().find("AoSettings.metresPerUnit") != std::string::npos);
        CHECK(st.message().find("[1e-6, 1e6]") != std::string::npos);
    }
    for (float a : {-0.1f, 2.5f, kNaN, kInf}) {
        AoSettings s = alchemy(0.5f);
        s.radiusExponent = a;
        const Status st = validateAoSettings(s, p);
        CHECK(st.message().find("AoSettings.radiusExponent") != std::string::npos);
        CHECK(st.message().find("[0, 2]") != std::string::npos);
    }
    // A hand-filled look out of range names the look's field; a value set does not read it.
    const Status badLook = validateAoSettings(alchemy(0.5f), withExponent(3.0f));
    CHECK(badLook.message().find("AoDesc.profile.aoLook.radiusExponent") != std::string::npos);
    AoSettings set = alchemy(0.5f);
    set.radiusExponent = 0.5f;
    CHECK(validateAoSettings(set, withExponent(3.0f)).isOk());
    // The smallest radius in micrometre units at the largest exponent would resolve an intensity
    // of about 1e17: refused, naming the radius and the scale, never clamped.
    AoSettings tiny = alchemy(kAoMinRadius, 1e-6f);
    tiny.radiusExponent = 2.0f;
    const Status st = validateAoSettings(tiny, p);
    CHECK(st.code() == StatusCode::InvalidArgument);
    CHECK(st.message().find("AoSettings.radius") != std::string::npos);
    CHECK(st.message().find("metresPerUnit") != std::string::npos);
    CHECK_FALSE(resolveAoConfig(tiny, p, 5, 64).isOk());
    // Within the intensity's range it resolves: 1 mm at A = 0.2 is 500^0.2, about 3.5 times the look's.
    tiny.radius = 1.0f, tiny.metresPerUnit = 1e-3f, tiny.radiusExponent = 0.2f;
    CHECK(validateAoSettings(tiny, p).isOk());
}
