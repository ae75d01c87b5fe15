// Tier selection: the tier table (one row per tier: the capability rules a device must meet,
// the capability ceiling that holds a device to it, the GL dialects its shaders are built for,
// and its quality presets), the shader defines generated from it, and the choice of a tier for
// a device. Data and rules only; no effect code lives here.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "sfx/hal.hpp"
#include "sfx/shader_program.hpp"
#include "sfx/tier.hpp"

namespace sfx::tiers {

// One rule a device must meet for a tier, e.g. "compute shaders".
struct Requirement {
    const char* what;
    bool (*met)(const DeviceCaps&);
};

struct TierRow {
    Tier tier = Tier::Current;
    std::string summary;                    // one line: what class of device it is for
    std::vector<Requirement> requirements;  // all of them, in the order they are checked
    // The capability ceiling that holds a device that can do more to this tier (None for the
    // highest): how tests, samples and `--tier` run a lower tier on a capable device.
    CapabilityCeiling ceiling = CapabilityCeiling::None;
    // The GL dialects its programs are translated to (SPIR-V is always built): a device whose
    // dialect is not listed cannot run the tier anyway, its requirements say so.
    std::vector<ShaderDialect> glDialects;
    std::vector<Preset> presets;  // kDefaultPreset first
};

// Every tier, lowest first (row i is Tier(i)).
const std::vector<TierRow>& table();
// The row of `tier`; `tier` must be one of the enumerators of SFX_TIER_LIST.
const TierRow& row(Tier tier);

// The rules for `tier`, in the order they are checked.
const std::vector<Requirement>& requirements(Tier tier);

// Requirements of `tier` that `caps` fails, empty when the device can run it.
std::vector<std::string> unmetRequirements(const DeviceCaps& caps, Tier tier);

// The parameters of a tier's default preset (tap counts, radii, which passes exist).
const TierProfile& profile(Tier tier);
// A named preset of `tier`; InvalidArgument naming the presets the tier has when unknown.
Result<TierProfile> preset(Tier tier, std::string_view name);

// A preprocessor define for the shaders of one tier.
struct ShaderDefine {
    std::string name;
    std::string value;
};
// What sfxc defines when it compiles a program for `tier`, all generated from its row:
// SFX_TIER_<NAME> (e.g. SFX_TIER_HIGH) = 1, SFX_TIER = its index, and the structural
// parameters of its default preset: SFX_AO_DEPTH_MIP (Scalable AO reads the depth MIP) and
// SFX_AO_PACKED_DEPTH_TARGET (the AO target carries the blur's depth key), each 1 when set.
std::vector<ShaderDefine> shaderDefines(Tier tier);

struct TierChoice {
    Tier tier = Tier::Current;
    TierProfile profile;
    std::string reason;  // printable: why this tier, and why not a higher one
};

// The highest tier the device can run, or exactly `requested` when given. A requested tier the
// device cannot run is UnsupportedTier naming the unmet requirements. No tier possible at all
// is UnsupportedTier too.
Result<TierChoice> choose(const DeviceCaps& caps, std::optional<Tier> requested = std::nullopt);

}  // namespace sfx::tiers
