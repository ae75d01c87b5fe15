// Reading the tier table: rows, presets, generated shader defines, and the choice of a tier.
#include "sfx/tiers.hpp"

#include <cctype>

namespace sfx::tiers {
namespace {

std::string join(const std::vector<std::string>& items) {
    std::string s;
    for (const auto& i : items) s += (s.empty() ? "" : ", ") + i;
    return s;
}

std::string quoted(Tier tier) { return std::string("'") + toString(tier) + "'"; }

}  // namespace

const TierRow& row(Tier tier) { return table()[size_t(tier)]; }

const std::vector<Requirement>& requirements(Tier tier) { return row(tier).requirements; }

std::vector<std::string> unmetRequirements(const DeviceCaps& caps, Tier tier) {
    std::vector<std::string> unmet;
    for (const Requirement& r : requirements(tier))
        if (!r.met(caps)) unmet.push_back(r.what);
    return unmet;
}

const TierProfile& profile(Tier tier) { return row(tier).presets.front().params; }

Result<TierProfile> preset(Tier tier, std::string_view name) {
    if (uint32_t(tier) >= kTierCount) return invalidArgument("tier", std::to_string(uint32_t(tier)), tierNameList());
    std::string names;
    for (const Preset& p : row(tier).presets) {
        if (p.name == name) return p.params;
        names += (names.empty() ? "" : ", ") + p.name;
    }
    return invalidArgument("preset", "'" + std::string(name) + "' for tier " + quoted(tier), names);
}

std::vector<ShaderDefine> shaderDefines(Tier tier) {
    std::string upper = toString(tier);
    for (char& c : upper) c = char(std::toupper(static_cast<unsigned char>(c)));
    const TierProfile& p = profile(tier);
    std::vector<ShaderDefine> defines = {{"SFX_TIER_" + upper, "1"}, {"SFX_TIER", std::to_string(uint32_t(tier))}};
    if (p.aoUsesDepthMip) defines.push_back({"SFX_AO_DEPTH_MIP", "1"});
    if (p.aoPackedDepthTarget) defines.push_back({"SFX_AO_PACKED_DEPTH_TARGET", "1"});
    if (p.aoMaxDepthLayers > 1) defines.push_back({"SFX_AO_MULTILAYER", "1"});
    return defines;
}

Result<TierChoice> choose(const DeviceCaps& caps, std::optional<Tier> requested) {
    const std::string device = std::string(toString(caps.backend)) + " (" + caps.apiName +
        (caps.ceiling != CapabilityCeiling::None ? ", capability ceiling " + std::string(toString(caps.ceiling)) : std::string()) + ")";
    if (requested) {
        if (uint32_t(*requested) >= kTierCount) return invalidArgument("requested tier", std::to_string(uint32_t(*requested)), tierNameList());
        std::vector<std::string> unmet = unmetRequirements(caps, *requested);
        if (!unmet.empty())
            return Status{StatusCode::UnsupportedTier, "tier " + quoted(*requested) + " was requested but " + device + " lacks: " + join(unmet)};
        TierChoice c{*requested, profile(*requested), "tier " + quoted(*requested) + " requested by the caller; " + device + " supports it"};
        for (uint32_t t = kTierCount; t-- > uint32_t(*requested) + 1;)
            if (unmetRequirements(caps, Tier(t)).empty()) {
                c.reason += std::string(" (") + toString(Tier(t)) + " is also available)";
                break;
            }
        return c;
    }
    // The highest tier whose rules all hold; the reason names what the next one up lacks.
    std::vector<std::string> unmetAbove;
    for (uint32_t t = kTierCount; t-- > 0;) {
        const Tier tier = Tier(t);
        std::vector<std::string> unmet = unmetRequirements(caps, tier);
        if (unmet.empty()) {
            const std::string why = t + 1 == kTierCount ? device + " has every " + toString(tier) + "-tier capability"
                                                        : device + " lacks for " + quoted(Tier(t + 1)) + ": " + join(unmetAbove);
            return TierChoice{tier, profile(tier), "tier " + quoted(tier) + ": " + why};
        }
        unmetAbove = std::move(unmet);
    }
    return Status{StatusCode::UnsupportedTier, device + " can run no tier; it lacks: " + join(unmetAbove)};
}

}  // namespace sfx::tiers
