#include "sfx/tiers.hpp"

#include "sfx_shared.h"

namespace sfx::tiers {
namespace {

bool apiAtLeast(const DeviceCaps& c, uint32_t major, uint32_t minor) {
    return c.apiMajor > major || (c.apiMajor == major && c.apiMinor >= minor);
}

// GL ES 3.0-class: fragment passes with float render targets for linear depth.
const std::vector<Requirement> kCurrentRules = {
    {"a rasterising device (not the null backend)", [](const DeviceCaps& c) { return c.backend != BackendKind::Null; }},
    {"API at least GL ES 3.0, GL 3.3 or Vulkan 1.0",
     [](const DeviceCaps& c) {
         switch (c.backend) {
         case BackendKind::GLES: return apiAtLeast(c, 3, 0);
         case BackendKind::GL: return apiAtLeast(c, 3, 3);
         case BackendKind::Vulkan: return apiAtLeast(c, 1, 0);
         default: return false;
         }
     }},
    // Linear depth (R32F), motion blur's packed velocity and tiles (RGBA16F, RG16F). On GL ES
    // one extension, EXT_color_buffer_float, makes all of them renderable.
    {"R32F, RGBA16F and RG16F render targets (EXT_color_buffer_float on GL ES)",
     [](const DeviceCaps& c) {
         return c.renderableFormat[size_t(Format::R32F)] && c.renderableFormat[size_t(Format::RGBA16F)] &&
                c.renderableFormat[size_t(Format::RG16F)];
     }},
    {"RGBA8 render targets", [](const DeviceCaps& c) { return c.renderableFormat[size_t(Format::RGBA8)]; }},
    {"sampling D32F or D24S8 depth", [](const DeviceCaps& c) {
         return c.sampledFormat[size_t(Format::D32F)] || c.sampledFormat[size_t(Format::D24S8)];
     }},
};

// Vulkan / D3D11-class: everything above, plus compute, storage buffers and atomics.
const std::vector<Requirement> kHighRules = [] {
    std::vector<Requirement> rules = kCurrentRules;
    rules.push_back({"API at least GL ES 3.1, GL 4.3 or Vulkan 1.1", [](const DeviceCaps& c) {
                         switch (c.backend) {
                         case BackendKind::GLES: return apiAtLeast(c, 3, 1);
                         case BackendKind::GL: return apiAtLeast(c, 4, 3);
                         case BackendKind::Vulkan: return apiAtLeast(c, 1, 1);
                         default: return false;
                         }
                     }});
    rules.push_back({"compute shaders", [](const DeviceCaps& c) { return c.computeShaders; }});
    rules.push_back({"storage buffers", [](const DeviceCaps& c) { return c.storageBuffers; }});
    rules.push_back({"atomics on storage buffers", [](const DeviceCaps& c) { return c.atomics; }});
    rules.push_back({"R32UI render targets", [](const DeviceCaps& c) { return c.renderableFormat[size_t(Format::R32UI)]; }});
    return rules;
}();

TierProfile makeProfile(Tier tier) {
    using namespace sfx::shared;
    TierProfile p;
    p.tier = tier;
    const bool high = tier == Tier::High;
    p.aoScalableTaps = uint32_t(high ? SFX_AO_SCALABLE_TAPS_HIGH : SFX_AO_SCALABLE_TAPS_CURRENT);
    p.aoScalableMirrored = !high;
    p.aoScalableMaxRadiusPx = high ? 0.0f : SFX_AO_RADIUS_CLAMP_PX_CURRENT;
    p.aoUsesDepthMip = high;
    p.aoDepthMipLevels = high ? uint32_t(SFX_DEPTH_MIP_MAX_LEVELS) : 1u;
    p.aoAlchemySamples = uint32_t(high ? SFX_AO_ALCHEMY_SAMPLES_HIGH : SFX_AO_ALCHEMY_SAMPLES_CURRENT);
    p.aoBlurRadiusPx = uint32_t(high ? SFX_AO_BLUR_RADIUS_HIGH : SFX_AO_BLUR_RADIUS_CURRENT);
    p.aoPackedDepthTarget = !high;  // ao_blur.frag's current-tier variant reads the packed key
    p.mbTaps = uint32_t(high ? SFX_MB_TAPS_HIGH : SFX_MB_TAPS_CURRENT);
    p.mbMaxRadiusPx = high ? SFX_MB_MAX_RADIUS_PX_HIGH : SFX_MB_MAX_RADIUS_PX_CURRENT;
    p.mbJitterSize = uint32_t(high ? SFX_MB_JITTER_SIZE_HIGH : SFX_MB_JITTER_SIZE_CURRENT);
    p.abufferOit = high;
    return p;
}

const TierProfile kProfiles[kTierCount] = {makeProfile(Tier::Current), makeProfile(Tier::High)};

std::string join(const std::vector<std::string>& items) {
    std::string s;
    for (const auto& i : items) s += (s.empty() ? "" : ", ") + i;
    return s;
}

}  // namespace

const std::vector<Requirement>& requirements(Tier tier) { return tier == Tier::High ? kHighRules : kCurrentRules; }

std::vector<std::string> unmetRequirements(const DeviceCaps& caps, Tier tier) {
    std::vector<std::string> unmet;
    for (const Requirement& r : requirements(tier))
        if (!r.met(caps)) unmet.push_back(r.what);
    return unmet;
}

const TierProfile& profile(Tier tier) { return kProfiles[tier == Tier::High ? 1 : 0]; }

Result<TierChoice> choose(const DeviceCaps& caps, std::optional<Tier> requested) {
    const std::string device = std::string(toString(caps.backend)) + " (" + caps.apiName +
                               (caps.ceiling != CapabilityCeiling::None
                                    ? ", capability ceiling " + std::string(toString(caps.ceiling))
                                    : std::string()) +
                               ")";
    if (requested) {
        std::vector<std::string> unmet = unmetRequirements(caps, *requested);
        if (!unmet.empty())
            return Status{StatusCode::UnsupportedTier, std::string("tier '") + toString(*requested) +
                                                           "' was requested but " + device + " lacks: " + join(unmet)};
        TierChoice c{*requested, profile(*requested), std::string("tier '") + toString(*requested) +
                                                          "' requested by the caller; " + device + " supports it"};
        if (*requested == Tier::Current && unmetRequirements(caps, Tier::High).empty())
            c.reason += " (high is also available)";
        return c;
    }
    std::vector<std::string> unmetHigh = unmetRequirements(caps, Tier::High);
    if (unmetHigh.empty())
        return TierChoice{Tier::High, profile(Tier::High), "tier 'high': " + device + " has every high-tier capability"};
    std::vector<std::string> unmetCurrent = unmetRequirements(caps, Tier::Current);
    if (unmetCurrent.empty())
        return TierChoice{Tier::Current, profile(Tier::Current),
                          "tier 'current': " + device + " lacks for 'high': " + join(unmetHigh)};
    return Status{StatusCode::UnsupportedTier, device + " can run no tier; it lacks: " + join(unmetCurrent)};
}

}  // namespace sfx::tiers
