// AoSettings: names, validation (named errors, never silent clamps) and resolution against a tier.
#include <algorithm>
#include <cmath>
#include <string>

#include "sfx/ao.hpp"
#include "sfx/settings_ranges.hpp"
#include "sfx_shared_ao.h"
#include "sfx_shared_ao_horizon.h"

namespace sfx {
namespace {

std::string num(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

// NaN fails every comparison, so each check is written as "inside the range" negated.
// Crease's other tap count: the checkerboard half of its diamond (shared::aoCreaseTapIndex).
constexpr uint32_t kCreaseHalfTaps = uint32_t(shared::SFX_AO_CREASE_TAPS) / 2;

// A look field's range (the table's row), for the value set or, unset, for the tier's look it
// resolves to (a hand-filled profile may hold any value there).
Status checkLookField(Setting id, const std::optional<float>& value, const char* lookField, float lookValue) {
    if (value) return checkSetting(id, *value);
    return checkSetting(id, lookValue, lookField);
}

// The intensity a dispatch uses: the set or looked-up sigma, times (r_m / 0.5 m)^-A when the
// look follows the radius. A = 0 leaves sigma exactly as it is.
double resolvedIntensity(const AoSettings& s, const AoLook& look) {
    const double sigma = s.intensity.value_or(look.intensity);
    const double exponent = s.radiusExponent.value_or(look.radiusExponent);
    if (exponent == 0.0) return sigma;
    return sigma * std::pow(double(s.radius) * double(s.metresPerUnit) / kAoRadiusExponentReferenceMetres, -exponent);
}

}  // namespace

const char* toString(AoTechnique technique) {
    switch (technique) {
        case AoTechnique::Alchemy: return "alchemy";
        case AoTechnique::Scalable: return "scalable";
        case AoTechnique::Crease: return "crease";
        case AoTechnique::Horizon: return "horizon";
    }
    return "unknown";
}

bool parseAoTechnique(const std::string& text, AoTechnique* out) {
    for (AoTechnique t : {AoTechnique::Alchemy, AoTechnique::Scalable, AoTechnique::Crease, AoTechnique::Horizon})
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
    if (uint32_t(profile.tier) >= kTierCount || profile.aoScalableTaps == 0 || profile.aoAlchemySamples == 0 || profile.aoBlurRadiusPx == 0 ||
        profile.aoDepthMipLevels == 0)
        return invalidArgument("AoDesc.profile", "an empty or unknown tier profile (tap counts 0)",
                               "tiers::profile(tier) or tiers::choose(caps)->profile");
    // A hand-filled profile must also stay inside what the shaders are built for: the resolved
    // config takes its counts from it unchecked.
    if (profile.aoScalableTaps > uint32_t(shared::SFX_AO_MAX_SAMPLES) || profile.aoAlchemySamples > uint32_t(shared::SFX_AO_MAX_SAMPLES) ||
        (profile.aoScalableMirrored && profile.aoScalableTaps % 2 != 0) || profile.aoBlurRadiusPx > uint32_t(shared::SFX_AO_MAX_BLUR_RADIUS) ||
        !(profile.aoScalableMaxRadiusPx >= 0.0f) ||
        (profile.aoCreaseTaps != kCreaseHalfTaps && profile.aoCreaseTaps != uint32_t(shared::SFX_AO_CREASE_TAPS)) ||
        std::isinf(profile.aoScalableMaxRadiusPx) || !inRange(settingRange(Setting::AoHorizonSlices), profile.aoHorizonSlices) ||
        !inRange(settingRange(Setting::AoHorizonSteps), profile.aoHorizonSteps) ||
        !inRange(settingRange(Setting::AoHorizonThickness), profile.aoHorizonThickness) ||
        !inRange(settingRange(Setting::AoHorizonFalloff), profile.aoHorizonFalloff))
        return invalidArgument("AoDesc.profile", "a tier profile with counts outside the shaders' limits",
                               "tiers::profile(tier) or tiers::choose(caps)->profile");
    if (uint32_t(profile.aoTechnique) >= kAoTechniqueCount)
        return invalidArgument("AoDesc.profile.aoTechnique", std::to_string(uint32_t(profile.aoTechnique)), "Alchemy, Scalable, Crease or Horizon");
    const AoTechnique technique = s.technique.value_or(profile.aoTechnique);
    if (uint32_t(technique) >= kAoTechniqueCount)
        return invalidArgument("AoSettings.technique", std::to_string(uint32_t(technique)), "Alchemy, Scalable, Crease or Horizon");
    SFX_TRY(checkSetting(Setting::AoRadius, s.radius));
    const AoLook& look = profile.aoLook[uint32_t(technique)];
    SFX_TRY(checkLookField(Setting::AoIntensity, s.intensity, "AoDesc.profile.aoLook.intensity", look.intensity));
    SFX_TRY(checkSetting(Setting::AoMetresPerUnit, s.metresPerUnit));
    SFX_TRY(checkLookField(Setting::AoRadiusExponent, s.radiusExponent, "AoDesc.profile.aoLook.radiusExponent", look.radiusExponent));
    // A small radius in metres raises a radius-following intensity without bound: refused, not clamped.
    if (const double sigma = resolvedIntensity(s, look); !inRange(settingRange(Setting::AoIntensity), sigma))
        return invalidArgument("AoSettings.radius", num(s.radius) + " at metresPerUnit " + num(s.metresPerUnit) + " (intensity " + num(sigma) + ")",
                               "a radius in metres for which intensity * (radius * metresPerUnit / 0.5)^-radiusExponent stays within " +
                                   rangeText(settingRange(Setting::AoIntensity)));
    SFX_TRY(checkLookField(Setting::AoContrast, s.contrast, "AoDesc.profile.aoLook.contrast", look.contrast));
    SFX_TRY(checkLookField(Setting::AoBias, s.bias, "AoDesc.profile.aoLook.bias", look.bias));
    SFX_TRY(checkLookField(Setting::AoSumExponent, s.sumExponent, "AoDesc.profile.aoLook.sumExponent", look.sumExponent));
    SFX_TRY(checkSetting(Setting::AoEpsilon, s.epsilon));
    if (s.samples && technique == AoTechnique::Horizon) {
        return invalidArgument("AoSettings.samples", std::to_string(*s.samples),
                               "unset for Horizon (its taps are AoSettings.horizon.slices and .steps)");
    } else if (s.samples && technique == AoTechnique::Crease) {
        if (*s.samples != kCreaseHalfTaps && *s.samples != uint32_t(shared::SFX_AO_CREASE_TAPS))
            return invalidArgument("AoSettings.samples", std::to_string(*s.samples),
                                   "12 (half the diamond per pixel) or 24 (the whole 11x11 stippled diamond) for Crease");
    } else if (s.samples) {
        SFX_TRY(checkSetting(Setting::AoSamples, *s.samples));
        if (technique == AoTechnique::Scalable && profile.aoScalableMirrored && *s.samples % 2 != 0)
            return invalidArgument(
                "AoSettings.samples", std::to_string(*s.samples),
                std::string("an even count on the ") + toString(profile.tier) + " tier (its Scalable taps come in mirrored pairs)");
    }
    if (s.blurRadius) SFX_TRY(checkSetting(Setting::AoBlurRadius, *s.blurRadius));
    if (uint32_t(s.resolution) > 2) return invalidArgument("AoSettings.resolution", std::to_string(uint32_t(s.resolution)), "Tier, Full or Half");
    if (uint32_t(s.normals) > 1) return invalidArgument("AoSettings.normals", std::to_string(uint32_t(s.normals)), "FromDepth or FromTexture");
    SFX_TRY(checkSetting(Setting::AoDepthLayers, s.depthLayers));
    const uint32_t maxLayers = std::clamp(profile.aoMaxDepthLayers, 1u, uint32_t(shared::SFX_AO_MAX_DEPTH_LAYERS));
    if (s.depthLayers > maxLayers)
        return invalidArgument(
            "AoSettings.depthLayers", std::to_string(s.depthLayers),
            maxLayers == 1 ? std::string("1 on the ") + toString(profile.tier) + " tier (multilayer AO needs a tier with aoMaxDepthLayers > 1: high)"
                           : "[1, " + std::to_string(maxLayers) + "] on the " + toString(profile.tier) + " tier");
    if (s.depthLayers > 1 && s.resolution == AoResolution::Half)
        return invalidArgument("AoSettings.resolution", "Half with depthLayers " + std::to_string(s.depthLayers),
                               "Full or Tier (multilayer AO runs at full resolution: the layers are full size)");
    if (s.depthLayers > 1 && technique == AoTechnique::Horizon)
        return invalidArgument("AoSettings.depthLayers", std::to_string(s.depthLayers),
                               s.technique ? "1 for Horizon (its horizons read the first visible layer)"
                                           : "1 for Horizon, the profile's technique when AoSettings.technique is unset (its horizons read the "
                                             "first visible layer); for multilayer AO set AoSettings.technique to Alchemy, Scalable or Crease");
    if (s.bentNormals && technique != AoTechnique::Horizon)
        return invalidArgument("AoSettings.bentNormals", std::string("true with technique ") + toString(technique),
                               "false, or true with technique horizon (the bent normals come from its horizons)");
    const AoHorizonSettings& hz = s.horizon;
    if (hz.slices) SFX_TRY(checkSetting(Setting::AoHorizonSlices, *hz.slices));
    if (hz.steps) SFX_TRY(checkSetting(Setting::AoHorizonSteps, *hz.steps));
    if (hz.thickness) SFX_TRY(checkSetting(Setting::AoHorizonThickness, *hz.thickness));
    if (hz.falloff) SFX_TRY(checkSetting(Setting::AoHorizonFalloff, *hz.falloff));
    const AoCreaseSettings& c = s.crease;
    if (c.range) SFX_TRY(checkSetting(Setting::AoCreaseRange, *c.range));
    if (c.bias) SFX_TRY(checkSetting(Setting::AoCreaseBias, *c.bias));
    SFX_TRY(checkSetting(Setting::AoCreaseAverager, c.averager));
    SFX_TRY(checkSetting(Setting::AoCreaseMinimumCrease, c.minimumCrease));
    if (!(c.fadeStart >= 0) || std::isinf(c.fadeStart)) return invalidArgument("AoSettings.crease.fadeStart", num(c.fadeStart), "[0, inf)");
    if (!(c.fadeEnd > c.fadeStart)) return invalidArgument("AoSettings.crease.fadeEnd", num(c.fadeEnd), "(fadeStart, inf]");
    return Status::ok();
}

Result<AoConfig> resolveAoConfig(const AoSettings& s, const TierProfile& profile, uint32_t mipLevelsAllowed, uint32_t outputRows) {
    SFX_TRY(validateAoSettings(s, profile));
    if (outputRows == 0) return invalidArgument("outputRows", "0", "the output's height, >= 1");
    AoConfig c;
    c.technique = s.technique.value_or(profile.aoTechnique);
    c.radius = s.radius;
    const AoLook& look = profile.aoLook[uint32_t(c.technique)];
    c.intensity = resolvedIntensity(s, look);
    c.contrast = s.contrast.value_or(look.contrast);
    c.epsilon = s.epsilon;
    c.normals = s.normals;
    const AoCreaseSettings& cs = s.crease;
    // Crease's range is in units of the radius, so the radius scales every technique alike.
    c.crease = {
        cs.range.value_or(look.creaseRange) * s.radius, cs.bias.value_or(look.creaseBias), cs.averager, cs.minimumCrease, cs.fadeStart, cs.fadeEnd};
    c.depthLayers = s.depthLayers;
    c.bentNormals = s.bentNormals;
    // Multilayer AO is full size (its layers are): the tier's half resolution does not apply.
    c.halfResolution = s.resolution == AoResolution::Half || (s.resolution == AoResolution::Tier && profile.aoHalfResolution && s.depthLayers == 1);
    // Pixel counts are the pass's: at half size the blur keeps its footprint in output pixels
    // with (r + 1) / 2 taps each side. Scalable's clamp, defined at the reference rows, scales
    // with the output's rows, then halves at half size: the look
    // the fit calibrated (docs/trade.md) then holds at every resolution.
    const double passPxPerReferencePx = double(outputRows) / double(shared::SFX_AO_REFERENCE_ROWS) * (c.halfResolution ? 0.5 : 1.0);
    const uint32_t blurPx = s.blurRadius.value_or(profile.aoBlurRadiusPx);
    c.blurRadius = s.blur ? (c.halfResolution ? std::max(1u, (blurPx + 1) / 2) : blurPx) : 0;
    switch (c.technique) {
        case AoTechnique::Alchemy:
            c.bias = s.bias.value_or(look.bias);
            c.samples = s.samples.value_or(profile.aoAlchemySamples);
            break;
        case AoTechnique::Scalable:
            c.bias = s.bias.value_or(look.bias);
            c.sumExponent = s.sumExponent.value_or(look.sumExponent);
            c.samples = s.samples.value_or(profile.aoScalableTaps);
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
            c.samples = s.samples.value_or(profile.aoCreaseTaps);
            break;
        case AoTechnique::Horizon: {
            c.bias = 0;
            const AoHorizonSettings& hs = s.horizon;
            c.horizon = {hs.slices.value_or(profile.aoHorizonSlices), hs.steps.value_or(profile.aoHorizonSteps),
                         double(hs.thickness.value_or(profile.aoHorizonThickness)), double(hs.falloff.value_or(profile.aoHorizonFalloff))};
            c.samples = c.horizon.slices;
            // Far steps read the depth MIP as Scalable's taps do (one level fewer at half size).
            c.depthMipLevels = profile.aoUsesDepthMip ? std::max(1u, std::min(profile.aoDepthMipLevels, mipLevelsAllowed)) : 1;
            if (c.halfResolution) c.depthMipLevels = std::max(1u, c.depthMipLevels - 1);
            break;
        }
    }
    return c;
}

}  // namespace sfx
