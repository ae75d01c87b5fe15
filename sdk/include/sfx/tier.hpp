// The quality tiers of the SDK. Which tier a device gets, and what each tier's parameters
// are, is decided by the table in tiers/ (see sfx/tiers.hpp); this header only names them.
#pragma once

#include <cstdint>
#include <string>

#include "sfx/ao_technique.hpp"

namespace sfx {

// Every tier, lowest first: X(enumerator, name). Adding a tier is a line here plus its row in
// the tier table (tiers/src/tier_table.cpp), which holds what the tier is for (its summary,
// `sfx info --rules`, docs/tiers.md) and generates its shader defines.
// clang-format off
#define SFX_TIER_LIST(X) \
    X(Current, "current") \
    X(High, "high")
// clang-format on

enum class Tier : uint32_t {
#define SFX_TIER_ENUMERATOR(e, name) e,
    SFX_TIER_LIST(SFX_TIER_ENUMERATOR)
#undef SFX_TIER_ENUMERATOR
};

#define SFX_TIER_NAME(e, name) name,
inline constexpr const char* kTierNames[] = {SFX_TIER_LIST(SFX_TIER_NAME)};
#undef SFX_TIER_NAME
inline constexpr uint32_t kTierCount = uint32_t(sizeof(kTierNames) / sizeof(kTierNames[0]));

const char* toString(Tier tier);  // its name in SFX_TIER_LIST; "unknown" out of range
bool parseTier(const std::string& text, Tier* out);
// The tier names for a message's allowed values: "current or high".
std::string tierNameList();

// The default look of one AO technique on a tier: the values AoSettings' unset look fields
// resolve to, calibrated against ray-traced ground truth by tools/bench/fit_ao (docs/trade.md).
struct AoLook {
    float intensity = 1.0f;    // sigma
    float contrast = 1.0f;     // k
    float bias = 0.0f;         // Alchemy: beta; Scalable: the cosine bias; unused by crease
    float sumExponent = 2.0f;  // Scalable only: the exponent of the normalised tap sum (the course's 2)
    float creaseRange = 2.0f;  // crease only (in units of AoSettings.radius)
    float creaseBias = 0.25f;  // crease only
    // A: the intensity follows the radius, sigma * (r_m / kAoRadiusExponentReferenceMetres)^-A
    // with r_m the radius in metres (AoSettings.metresPerUnit). 0: one intensity at every radius.
    float radiusExponent = 0.0f;
};

// The parameters effects read: one quality preset of one tier. The values live in the tier
// table (tiers/src/tier_table.cpp); shaders get the structural ones (which passes and bindings
// exist) as defines generated from it, the rest through their uniform blocks.
struct TierProfile {
    Tier tier = Tier::Current;
    // Ambient obscurance
    // The technique an AoSettings without one runs: each preset's point of the measured front
    // (docs/trade.md).
    AoTechnique aoTechnique = AoTechnique::Scalable;
    uint32_t aoScalableTaps = 0;      // 4 (mirrored) or 9 (spiral)
    bool aoScalableMirrored = false;  // current tier: each offset also used negated
    // Scalable's screen-space clamp of the AO radius (0 = none), in output pixels at
    // SFX_AO_REFERENCE_ROWS (720) rows, scaled with the output's rows so the look does not
    // depend on the resolution.
    float aoScalableMaxRadiusPx = 0;
    bool aoUsesDepthMip = false;    // Scalable AO reads the depth MIP pyramid (SFX_AO_DEPTH_MIP)
    uint32_t aoDepthMipLevels = 0;  // levels of that pyramid (level 0 included)
    uint32_t aoAlchemySamples = 0;  // default Alchemy sample count
    uint32_t aoBlurRadiusPx = 0;    // bilateral blur half-width
    // Crease taps per pixel: 24 (the article's 11x11 stippled diamond) or 12 (its checkerboard
    // half, alternating between neighbours: the blur sees all 24 at half the fetches).
    uint32_t aoCreaseTaps = 24;
    // Horizon: slices per pixel, steps per side, the thickness heuristic and the edge falloff
    // (AoHorizonSettings); it reads the depth MIP where aoUsesDepthMip says, as Scalable does.
    uint32_t aoHorizonSlices = 2;
    uint32_t aoHorizonSteps = 4;
    float aoHorizonThickness = 1.0f;
    float aoHorizonFalloff = 0.2f;
    AoLook aoLook[4];  // per technique, indexed by AoTechnique (alchemy, scalable, crease, horizon)
    // Where the blur finds each pixel's depth: true (current tier), a 16-bit key packed in an
    // RGBA8 AO target; false (high), the linear depth in a float target (RG32F; RGBA32F for
    // crease). Either way one fetch per tap. Becomes SFX_AO_PACKED_DEPTH_TARGET.
    bool aoPackedDepthTarget = false;
    // AO at half resolution with a depth-aware upsample (AoResolution::Tier resolves to it).
    bool aoHalfResolution = false;
    // Opaque depth layers AO may test (AoSettings.depthLayers): 1 = single-layer AO only. Above 1
    // the table generates SFX_AO_MULTILAYER, which declares the obscurance passes' layer bindings.
    uint32_t aoMaxDepthLayers = 1;
    // Motion blur
    uint32_t mbTaps = 0;        // reconstruction taps including the centre
    float mbMaxRadiusPx = 0;    // maximum blur radius at the reference resolution
    float mbTilePx = 0;         // tile edge of tile max and neighbour max at the reference resolution
    uint32_t mbJitterSize = 0;  // 2 (checkerboard) or 4 (4x4 randomised)
    // Order-independent transparency
    bool abufferOit = false;
};

// A quality preset: a named set of a tier's parameters; every tier has kDefaultPreset. Presets of one tier may differ only in what reaches the shaders
// through uniforms (tap counts, radii, blur width); the structural parameters that become
// shader defines (shaderDefines) are the default preset's for every preset of the tier.
// What a preset buys, measured offline against ground truth by tools/bench/trade_presets
// (docs/trade.md): the settings-by-budget API (sfx/budget.hpp) picks the most accurate preset
// whose cost, measured on the device, fits. 0 = not measured.
struct PresetAccuracy {
    double aoPsnrDb[4] = {0, 0, 0, 0};  // per AO technique (AoTechnique order), held-out scene families
    double motionBlurPsnrDb = 0;        // against temporally supersampled truth
};

struct Preset {
    std::string name;
    TierProfile params;
    PresetAccuracy accuracy;
};
inline constexpr const char* kDefaultPreset = "default";

}  // namespace sfx
