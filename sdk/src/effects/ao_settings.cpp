// AoSettings: names, validation (named errors, never silent clamps) and resolution against a tier.
#include <algorithm>
#include <cmath>
#include <string>

#include "sfx/ao.hpp"
#include "sfx_shared_ao.h"

namespace sfx {
namespace {

std::string num(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

// NaN fails every comparison, so each check is written as "inside the range" negated.
// The value of an AoSettings look field that means "the tier preset's AoLook".
constexpr float kTierValue = -1.0f;
float orTier(float value, float tierValue) { return value == kTierValue ? tierValue : value; }
// Crease's other tap count: the checkerboard half of its diamond (shared::aoCreaseTapIndex).
constexpr uint32_t kCreaseHalfTaps = uint32_t(shared::SFX_AO_CREASE_TAPS) / 2;
// A hand-filled profile's crease spacing beyond this (output pixels at the reference rows) would
// spread the 11x11 diamond over more than the image's height.
constexpr float kMaxCreaseSpacingPx = 64.0f;

Status checkRange(const char* field, double v, double lo, bool loOpen, double hi, bool hiOpen, const char* allowed) {
    const bool aboveLo = loOpen ? v > lo : v >= lo;
    const bool belowHi = hiOpen ? v < hi : v <= hi;
    if (!(aboveLo && belowHi)) return invalidArgument(field, num(v), allowed);
    return Status::ok();
}

// A look field's one closed range, for the value set or, at -1, for the tier's look that -1
// resolves to (a hand-filled profile may hold any value there).
Status checkLookField(const char* field, float value, const char* lookField, float lookValue, double lo, double hi, const std::string& range) {
    if (value != kTierValue) return checkRange(field, value, lo, false, hi, false, (range + ", or -1 for the tier's").c_str());
    return checkRange(lookField, lookValue, lo, false, hi, false, range.c_str());
}

}  // namespace

const char* toString(AoTechnique technique) {
    switch (technique) {
        case AoTechnique::Alchemy: return "alchemy";
        case AoTechnique::Scalable: return "scalable";
        case AoTechnique::Crease: return "crease";
    }
    return "unknown";
}

bool parseAoTechnique(const std::string& text, AoTechnique* out) {
    for (AoTechnique t : {AoTechnique::Alchemy, AoTechnique::Scalable, AoTechnique::Crease})
        if (text == toString(t)) {
            *out = t;
            return true;
        }
    return false;
}

const char* toString(AoResolution resolution) {
    switch (resolution) {
        case AoResolution::Tier: return "tier";
        case AoResolution::Full: return "full";
        case AoResolution::Half: return "half";
    }
    return "unknown";
}

bool parseAoResolution(const std::string& text, AoResolution* out) {
    for (AoResolution r : {AoResolution::Tier, AoResolution::Full, AoResolution::Half})
        if (text == toString(r)) {
            *out = r;
            return true;
        }
    return false;
}

Status validateAoSettings(const AoSettings& s, const TierProfile& profile) {
    // A value-initialised TierProfile has every count at 0 and would divide by zero in the
    // shaders; it must come from tiers::profile() or tiers::choose().
    if (uint32_t(profile.tier) >= kTierCount || profile.aoScalableTaps == 0 || profile.aoAlchemySamples == 0 ||
        profile.aoBlurRadiusPx == 0 || profile.aoDepthMipLevels == 0)
        return invalidArgument("AoDesc.profile", "an empty or unknown tier profile (tap counts 0)",
                               "tiers::profile(tier) or tiers::choose(caps)->profile");
    // A hand-filled profile must also stay inside what the shaders are built for: the resolved
    // config takes its counts from it unchecked.
    if (profile.aoScalableTaps > uint32_t(shared::SFX_AO_MAX_SAMPLES) || profile.aoAlchemySamples > uint32_t(shared::SFX_AO_MAX_SAMPLES) ||
        (profile.aoScalableMirrored && profile.aoScalableTaps % 2 != 0) ||
        profile.aoBlurRadiusPx > uint32_t(shared::SFX_AO_MAX_BLUR_RADIUS) || !(profile.aoScalableMaxRadiusPx >= 0.0f) ||
        (profile.aoCreaseTaps != kCreaseHalfTaps && profile.aoCreaseTaps != uint32_t(shared::SFX_AO_CREASE_TAPS)) ||
        std::isinf(profile.aoScalableMaxRadiusPx) || !(profile.aoCreaseSpacingPx > 0.0f && profile.aoCreaseSpacingPx <= kMaxCreaseSpacingPx))
        return invalidArgument("AoDesc.profile", "a tier profile with counts outside the shaders' limits",
                               "tiers::profile(tier) or tiers::choose(caps)->profile");
    if (uint32_t(s.technique) > 2) return invalidArgument("AoSettings.technique", std::to_string(uint32_t(s.technique)), "Alchemy, Scalable or Crease");
    // The lower bound keeps epsilon * r^2 a normal float (>= 1e-16 with epsilon >= 1e-8): smaller
    // radii underflow it to 0 on the GPU and a tap on the centre pixel would divide 0 by 0.
    SFX_TRY(checkRange("AoSettings.radius", s.radius, kAoMinRadius, false, 1000, false, "[1e-4, 1000]"));
    const AoLook& look = profile.aoLook[uint32_t(s.technique)];
    SFX_TRY(checkLookField("AoSettings.intensity", s.intensity, "AoDesc.profile.aoLook.intensity", look.intensity, 0, 100, "[0, 100]"));
    SFX_TRY(checkLookField("AoSettings.contrast", s.contrast, "AoDesc.profile.aoLook.contrast", look.contrast, 0.1, 10, "[0.1, 10]"));
    SFX_TRY(checkLookField("AoSettings.bias", s.bias, "AoDesc.profile.aoLook.bias", look.bias, 0, 1, "[0, 1]"));
    SFX_TRY(checkLookField("AoSettings.sumExponent", s.sumExponent, "AoDesc.profile.aoLook.sumExponent", look.sumExponent, 0.5, 4, "[0.5, 4]"));
    // The bound is the float nearest 1e-8 (just below it): the documented minimum must be settable.
    SFX_TRY(checkRange("AoSettings.epsilon", s.epsilon, double(1e-8f), false, 1, false, "[1e-8, 1]"));
    const uint32_t maxSamples = uint32_t(shared::SFX_AO_MAX_SAMPLES);
    if (s.technique == AoTechnique::Crease) {
        if (s.samples != 0 && s.samples != kCreaseHalfTaps && s.samples != uint32_t(shared::SFX_AO_CREASE_TAPS))
            return invalidArgument("AoSettings.samples", std::to_string(s.samples),
                                   "0 (the tier's), 12 (half the diamond per pixel) or 24 (the whole 11x11 stippled diamond) for Crease");
    } else if (s.samples > maxSamples) {
        return invalidArgument("AoSettings.samples", std::to_string(s.samples), "[0, " + std::to_string(maxSamples) + "] (0 = tier default)");
    } else if (s.technique == AoTechnique::Scalable && profile.aoScalableMirrored && s.samples % 2 != 0) {
        return invalidArgument("AoSettings.samples", std::to_string(s.samples),
                               std::string("an even count on the ") + toString(profile.tier) + " tier (its Scalable taps come in mirrored pairs), or 0");
    }
    if (s.blurRadius > uint32_t(shared::SFX_AO_MAX_BLUR_RADIUS))
        return invalidArgument("AoSettings.blurRadius", std::to_string(s.blurRadius),
                               "[0, " + std::to_string(shared::SFX_AO_MAX_BLUR_RADIUS) + "] (0 = tier default)");
    if (uint32_t(s.resolution) > 2)
        return invalidArgument("AoSettings.resolution", std::to_string(uint32_t(s.resolution)), "Tier, Full or Half");
    if (uint32_t(s.normals) > 1) return invalidArgument("AoSettings.normals", std::to_string(uint32_t(s.normals)), "FromDepth or FromTexture");
    const uint32_t maxLayers = std::clamp(profile.aoMaxDepthLayers, 1u, uint32_t(shared::SFX_AO_MAX_DEPTH_LAYERS));
    if (s.depthLayers < 1 || s.depthLayers > maxLayers)
        return invalidArgument("AoSettings.depthLayers", std::to_string(s.depthLayers),
                               maxLayers == 1 ? std::string("1 on the ") + toString(profile.tier) + " tier (multilayer AO needs a tier with aoMaxDepthLayers > 1: high)"
                                              : "[1, " + std::to_string(maxLayers) + "] on the " + toString(profile.tier) + " tier");
    if (s.depthLayers > 1 && s.resolution == AoResolution::Half)
        return invalidArgument("AoSettings.resolution", "Half with depthLayers " + std::to_string(s.depthLayers),
                               "Full or Tier (multilayer AO runs at full resolution: the layers are full size)");
    const AoCreaseSettings& c = s.crease;
    if (c.range != kTierValue) SFX_TRY(checkRange("AoSettings.crease.range", c.range, kAoMinRadius, false, 1000, false, "[1e-4, 1000], or -1 for the tier's"));
    if (c.bias != kTierValue) SFX_TRY(checkRange("AoSettings.crease.bias", c.bias, 0, true, 100, false, "(0, 100], or -1 for the tier's"));
    SFX_TRY(checkRange("AoSettings.crease.averager", c.averager, 0, true, 1000, false, "(0, 1000]"));
    SFX_TRY(checkRange("AoSettings.crease.minimumCrease", c.minimumCrease, -1, false, 1, true, "[-1, 1)"));
    if (!(c.fadeStart >= 0) || std::isinf(c.fadeStart)) return invalidArgument("AoSettings.crease.fadeStart", num(c.fadeStart), "[0, inf)");
    if (!(c.fadeEnd > c.fadeStart)) return invalidArgument("AoSettings.crease.fadeEnd", num(c.fadeEnd), "(fadeStart, inf]");
    return Status::ok();
}

Result<AoConfig> resolveAoConfig(const AoSettings& s, const TierProfile& profile, uint32_t mipLevelsAllowed, uint32_t outputRows) {
    SFX_TRY(validateAoSettings(s, profile));
    if (outputRows == 0) return invalidArgument("outputRows", "0", "the output's height, >= 1");
    AoConfig c;
    c.technique = s.technique;
    c.radius = s.radius;
    const AoLook& look = profile.aoLook[uint32_t(s.technique)];
    c.intensity = orTier(s.intensity, look.intensity);
    c.contrast = orTier(s.contrast, look.contrast);
    c.epsilon = s.epsilon;
    c.normals = s.normals;
    c.crease = s.crease;
    c.crease.range = orTier(s.crease.range, look.creaseRange);
    c.crease.bias = orTier(s.crease.bias, look.creaseBias);
    c.depthLayers = s.depthLayers;
    // Multilayer AO is full size (its layers are): the tier's half resolution does not apply.
    c.halfResolution = s.resolution == AoResolution::Half || (s.resolution == AoResolution::Tier && profile.aoHalfResolution && s.depthLayers == 1);
    // Pixel counts are the pass's: at half size the blur keeps its footprint in output pixels
    // with (r + 1) / 2 taps each side. The tier's extents defined at the reference rows (the
    // clamp, crease's spacing) scale with the output's rows, then halve at half size: the look
    // the fit calibrated (docs/trade.md) then holds at every resolution.
    const double passPxPerReferencePx = double(outputRows) / double(shared::SFX_AO_REFERENCE_ROWS) * (c.halfResolution ? 0.5 : 1.0);
    const uint32_t blurPx = s.blurRadius ? s.blurRadius : profile.aoBlurRadiusPx;
    c.blurRadius = s.blur ? (c.halfResolution ? std::max(1u, (blurPx + 1) / 2) : blurPx) : 0;
    switch (s.technique) {
        case AoTechnique::Alchemy:
            c.bias = orTier(s.bias, look.bias);
            c.samples = s.samples ? s.samples : profile.aoAlchemySamples;
            break;
        case AoTechnique::Scalable:
            c.bias = orTier(s.bias, look.bias);
            c.sumExponent = orTier(s.sumExponent, look.sumExponent);
            c.samples = s.samples ? s.samples : profile.aoScalableTaps;
            c.mirrored = profile.aoScalableMirrored;
            c.spiralTurns = c.mirrored ? shared::SFX_AO_SPIRAL_TURNS_MIRRORED : shared::SFX_AO_SPIRAL_TURNS_SPIRAL;
            // The clamp keeps the taps near the centre (the texture cache, the paper's reason). A
            // clamp fixed in texels cut the radius 4x more at 1280x720 than at 320x180, and the
            // current tier's Scalable lost 2.5 dB against the truth there (docs/trade.md): it is
            // a share of the image's height instead, at least one pass pixel.
            c.maxRadiusPx = profile.aoScalableMaxRadiusPx > 0.0f ? std::max(1.0, double(profile.aoScalableMaxRadiusPx) * passPxPerReferencePx) : 0.0;
            c.depthMipLevels = profile.aoUsesDepthMip ? std::max(1u, std::min(profile.aoDepthMipLevels, mipLevelsAllowed)) : 1;
            // At half size the pass reads the pyramid from level 1: one level fewer of its own.
            if (c.halfResolution) c.depthMipLevels = std::max(1u, c.depthMipLevels - 1);
            // Multilayer taps read every layer at full size, as reference::multilayerVisibility:
            // a MIP of layer 0 alone would mix coarse and fine depths in one tap's maximum.
            if (c.depthLayers > 1) c.depthMipLevels = 1;
            break;
        case AoTechnique::Crease:
            c.bias = 0;
            c.samples = s.samples ? s.samples : profile.aoCreaseTaps;
            c.creaseStride = uint32_t(std::max(1.0, std::round(double(profile.aoCreaseSpacingPx) * passPxPerReferencePx)));
            break;
    }
    return c;
}

}  // namespace sfx
