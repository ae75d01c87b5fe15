// Tier selection: the capability rules that turn a device's caps into a tier, and the
// per-tier parameter table effects read. Data and rules only; no effect code lives here.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "sfx/hal.hpp"
#include "sfx/tier.hpp"

namespace sfx::tiers {

// One rule a device must meet for a tier, e.g. "compute shaders".
struct Requirement {
    const char* what;
    bool (*met)(const DeviceCaps&);
};

// The rules for `tier`, in the order they are checked.
const std::vector<Requirement>& requirements(Tier tier);

// Requirements of `tier` that `caps` fails, empty when the device can run it.
std::vector<std::string> unmetRequirements(const DeviceCaps& caps, Tier tier);

// The parameters of a tier (tap counts, radii, which passes exist).
const TierProfile& profile(Tier tier);

struct TierChoice {
    Tier tier = Tier::Current;
    TierProfile profile;
    std::string reason;  // printable: why this tier, and why not a higher one
};

// The highest tier the device can run, or exactly `requested` when given. A requested tier the
// device cannot run is UnsupportedTier naming the unmet requirements. Current when neither
// tier is possible is UnsupportedTier too.
Result<TierChoice> choose(const DeviceCaps& caps, std::optional<Tier> requested = std::nullopt);

}  // namespace sfx::tiers
