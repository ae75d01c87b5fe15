// The tier table and what is generated from it (shader defines, dialects, names). The uniform
// blocks are checked in test_uniform_blocks.cpp.
#include <catch2/catch.hpp>

#include <algorithm>
#include <string>
#include <tuple>

#include "sfx/ao.hpp"
#include "sfx/tiers.hpp"
#include "sfx_shaders.hpp"
#include "sfx_shared.h"
#include "sfx_shared_ao.h"
#include "sfx_shared_mb.h"
#include "sfx_shared_raster.h"

using namespace sfx;

namespace {

// Every parameter of a profile, for comparing whole profiles.
auto fields(const TierProfile& p) {
    return std::make_tuple(p.tier, p.aoScalableTaps, p.aoScalableMirrored, p.aoScalableMaxRadiusPx, p.aoUsesDepthMip, p.aoDepthMipLevels,
                           p.aoAlchemySamples, p.aoBlurRadiusPx, p.aoCreaseTaps, p.aoPackedDepthTarget, p.mbTaps, p.mbMaxRadiusPx, p.mbTilePx,
                           p.mbJitterSize, p.abufferOit);
}

bool sameStructure(const TierProfile& a, const TierProfile& b) {
    return a.tier == b.tier && a.aoUsesDepthMip == b.aoUsesDepthMip && a.aoPackedDepthTarget == b.aoPackedDepthTarget;
}

}  // namespace

TEST_CASE("tier table: a row per tier, in order, each with its default preset first", "[tiers]") {
    const std::vector<tiers::TierRow>& table = tiers::table();
    REQUIRE(table.size() == kTierCount);
    for (uint32_t i = 0; i < kTierCount; ++i) {
        const tiers::TierRow& row = table[i];
        INFO(toString(row.tier));
        CHECK(row.tier == Tier(i));
        CHECK(&tiers::row(Tier(i)) == &row);
        CHECK_FALSE(row.summary.empty());
        CHECK_FALSE(row.requirements.empty());
        CHECK_FALSE(row.glDialects.empty());
        REQUIRE_FALSE(row.presets.empty());
        CHECK(row.presets.front().name == kDefaultPreset);
        for (const Preset& p : row.presets) {
            INFO(p.name);
            CHECK(p.params.tier == row.tier);
            // Presets differ only in uniforms: the structural parameters are the default's.
            CHECK(sameStructure(p.params, row.presets.front().params));
        }
        Result<TierProfile> byName = tiers::preset(row.tier, kDefaultPreset);
        REQUIRE(byName.isOk());
        CHECK(byName->aoScalableTaps == tiers::profile(row.tier).aoScalableTaps);
        // Only the highest tier runs without a ceiling; a lower one is reachable on any device.
        CHECK((row.ceiling == CapabilityCeiling::None) == (i + 1 == kTierCount));
        // A higher tier asks for everything a lower one does.
        if (i > 0)
            for (const tiers::Requirement& lower : table[i - 1].requirements)
                CHECK(std::any_of(row.requirements.begin(), row.requirements.end(),
                                  [&](const tiers::Requirement& r) { return std::string(r.what) == lower.what; }));
    }
    Result<TierProfile> unknown = tiers::preset(Tier::Current, "no-such-preset");
    CHECK(unknown.status().code() == StatusCode::InvalidArgument);
    CHECK(unknown.status().message().find(kDefaultPreset) != std::string::npos);
}

TEST_CASE("tier table: each preset names its AO technique, and no two presets of a tier are alike", "[tiers][ao]") {
    for (Tier tier : {Tier::Current, Tier::High}) {
        const std::vector<Preset>& presets = tiers::row(tier).presets;
        // The default runs the most accurate configuration at the tier's default cost that lowers
        // no held-out family: crease on the current tier, horizon on the high tier; the presets
        // above it buy horizon's accuracy (docs/trade.md).
        CHECK(presets.front().params.aoTechnique == (tier == Tier::High ? AoTechnique::Horizon : AoTechnique::Crease));
        for (const char* name : {"high", "ultra"}) CHECK(tiers::preset(tier, name)->aoTechnique == AoTechnique::Horizon);
        for (const Preset& p : presets) {
            INFO(toString(tier) << "/" << p.name);
            CHECK(uint32_t(p.params.aoTechnique) < kAoTechniqueCount);
            CHECK(p.accuracy.aoPsnrDb[uint32_t(p.params.aoTechnique)] > 0);
            // An AoSettings without a technique runs the preset's.
            Result<AoConfig> c = resolveAoConfig(AoSettings{}, p.params, 1, 720);
            REQUIRE(c.isOk());
            CHECK(c->technique == p.params.aoTechnique);
            AoSettings explicitAlchemy;
            explicitAlchemy.technique = AoTechnique::Alchemy;
            CHECK(resolveAoConfig(explicitAlchemy, p.params, 1, 720)->technique == AoTechnique::Alchemy);
        }
        // No two presets alike: each differs from every other in technique or in a count.
        for (size_t i = 0; i < presets.size(); ++i)
            for (size_t j = i + 1; j < presets.size(); ++j) {
                const TierProfile &a = presets[i].params, &b = presets[j].params;
                INFO(presets[i].name << " vs " << presets[j].name);
                CHECK((a.aoTechnique != b.aoTechnique || a.aoAlchemySamples != b.aoAlchemySamples || a.aoScalableTaps != b.aoScalableTaps ||
                       a.aoHorizonSlices != b.aoHorizonSlices || a.aoHorizonSteps != b.aoHorizonSteps || a.aoBlurRadiusPx != b.aoBlurRadiusPx ||
                       a.aoHalfResolution != b.aoHalfResolution));
            }
    }
    TierProfile bad = tiers::profile(Tier::High);
    bad.aoTechnique = AoTechnique(9);
    Status st = resolveAoConfig(AoSettings{}, bad, 1, 720).status();
    CHECK(st.code() == StatusCode::InvalidArgument);
    CHECK(st.message().find("AoDesc.profile.aoTechnique") != std::string::npos);
}

TEST_CASE("tier table: the default presets hold the parameters the tiers always had", "[tiers]") {
    // Written out here, apart from the table, so that moving the values into it changed none.
    // Scalable's clamp is output pixels at 720 rows: 20 half-size texels at 320x180, where the
    // looks were fitted (docs/trade.md).
    TierProfile expected[kTierCount];
    expected[0] = {.tier = Tier::Current,
                   .aoScalableTaps = 4,
                   .aoScalableMirrored = true,
                   .aoScalableMaxRadiusPx = 160.0f,
                   .aoUsesDepthMip = false,
                   .aoDepthMipLevels = 1,
                   .aoAlchemySamples = 6,
                   .aoBlurRadiusPx = 2,
                   .aoCreaseTaps = 12,
                   .aoPackedDepthTarget = true,
                   .mbTaps = 7,
                   .mbMaxRadiusPx = 14.0f,
                   .mbTilePx = 10.0f,
                   .mbJitterSize = 2,
                   .abufferOit = false};
    expected[1] = {.tier = Tier::High,
                   .aoScalableTaps = 9,
                   .aoScalableMirrored = false,
                   .aoScalableMaxRadiusPx = 0.0f,
                   .aoUsesDepthMip = true,
                   .aoDepthMipLevels = uint32_t(shared::SFX_DEPTH_MIP_MAX_LEVELS),
                   .aoAlchemySamples = 12,
                   .aoBlurRadiusPx = 6,
                   .aoCreaseTaps = 24,
                   .aoPackedDepthTarget = false,
                   .mbTaps = 13,
                   .mbMaxRadiusPx = 18.0f,
                   .mbTilePx = 10.0f,
                   .mbJitterSize = 2,
                   .abufferOit = true};
    for (uint32_t i = 0; i < kTierCount; ++i) {
        INFO(toString(Tier(i)));
        CHECK(fields(tiers::profile(Tier(i))) == fields(expected[i]));
    }
}

TEST_CASE("tier table: names, shader defines and dialects are generated from it", "[tiers][shaders]") {
    CHECK(tierNameList() == "current or high");
    for (uint32_t i = 0; i < kTierCount; ++i) {
        Tier parsed;
        REQUIRE(parseTier(kTierNames[i], &parsed));
        CHECK(parsed == Tier(i));
        CHECK(std::string(toString(Tier(i))) == kTierNames[i]);
    }
    Tier t;
    CHECK_FALSE(parseTier("ultra", &t));
    CHECK(std::string(toString(Tier(kTierCount))) == "unknown");

    auto has = [](Tier tier, const std::string& name, const std::string& value) {
        for (const tiers::ShaderDefine& d : tiers::shaderDefines(tier))
            if (d.name == name) return d.value == value;
        return false;
    };
    CHECK(has(Tier::Current, "SFX_TIER_CURRENT", "1"));
    CHECK(has(Tier::Current, "SFX_TIER", "0"));
    CHECK(has(Tier::Current, "SFX_AO_PACKED_DEPTH_TARGET", "1"));
    CHECK_FALSE(has(Tier::Current, "SFX_AO_DEPTH_MIP", "1"));
    CHECK(has(Tier::High, "SFX_TIER_HIGH", "1"));
    CHECK(has(Tier::High, "SFX_TIER", "1"));
    CHECK(has(Tier::High, "SFX_AO_DEPTH_MIP", "1"));
    CHECK_FALSE(has(Tier::High, "SFX_AO_PACKED_DEPTH_TARGET", "1"));

    // The embedded programs carry exactly their tier's GL dialects.
    for (const CompiledProgram& p : shaders::all()) {
        const std::vector<ShaderDialect>& dialects = tiers::row(p.tier).glDialects;
        for (const StageCode& s : p.stages)
            for (uint32_t d = uint32_t(ShaderDialect::Essl300); d < uint32_t(ShaderDialect::Count); ++d) {
                INFO(p.name << " " << toString(p.tier) << " " << toString(ShaderDialect(d)));
                const bool listed = std::find(dialects.begin(), dialects.end(), ShaderDialect(d)) != dialects.end();
                CHECK(s.glsl[d].empty() == !listed);
            }
    }
}
