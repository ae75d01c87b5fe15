// The tier table: one row per tier, lowest first. Everything that differs between tiers is a
// value here; effects, sfxc (the shader defines), `sfx info --rules` and docs/tiers.md read it.
// To add a tier: its line in SFX_TIER_LIST (sfx/tier.hpp) and its row below.
#include "sfx/tiers.hpp"

#include "sfx_shared.h"

namespace sfx::tiers {
namespace {

bool apiAtLeast(const DeviceCaps& c, uint32_t major, uint32_t minor) { return c.apiMajor > major || (c.apiMajor == major && c.apiMinor >= minor); }

// The current tier's requirements (what the tier is for is its row's summary, makeTable).
std::vector<Requirement> currentRules() {
    return {
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
        {"sampling D32F or D24S8 depth",
         [](const DeviceCaps& c) { return c.sampledFormat[size_t(Format::D32F)] || c.sampledFormat[size_t(Format::D24S8)]; }},
    };
}

// The high tier's requirements: the current tier's, plus compute, storage buffers and atomics.
std::vector<Requirement> highRules() {
    std::vector<Requirement> rules = currentRules();
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
}

TierProfile currentDefault() {
    TierProfile p;
    p.tier = Tier::Current;
    p.aoScalableTaps = 4;  // mirrored: 2 offsets, each also negated
    p.aoScalableMirrored = true;
    // 160 output pixels at 720 rows, scaled with the rows: the 20 half-size texels at 320x180
    // (a fifth of the height) that the look was fitted with, at every size.
    p.aoScalableMaxRadiusPx = 160.0f;
    p.aoUsesDepthMip = false;
    p.aoDepthMipLevels = 1;
    p.aoAlchemySamples = 6;
    p.aoBlurRadiusPx = 2;  // 5-tap separable bilateral
    // Crease's diamond halved by checkerboard (the blur completes it): its 24 fetches made the
    // current tier's crease the one default over the 12-copy-pass cost goal (docs/trade.md).
    p.aoCreaseTaps = 12;
    // The look fitted against ray-traced truth (tools/bench/fit_ao, docs/trade.md); before the
    // calibration every tier had the papers' 1, 1, 1e-4 / 0.02, range 1, bias 0.25.
    p.aoLook[0] = {.intensity = 0.472871f, .contrast = 1.38237f, .bias = 1.59371e-7f};  // alchemy
    // Scalable fitted at half resolution with the 20 px clamp in half-size texels, its sum
    // exponent fitted too (tools/bench/fit_ao --start tier): below 1 where the course squares.
    p.aoLook[1] = {.intensity = 0.0654423f, .contrast = 7.23394f, .bias = 0.0f, .sumExponent = 0.569394f};  // scalable
    // Crease with its diamond reaching the radius, fitted at half resolution: the better training
    // score of the searches from the tier's previous look and from the article's (tools/bench/fit_ao
    // --start both; docs/ao_families.md has the held-out scores).
    p.aoLook[2] = {.intensity = 1.48865f, .contrast = 10.0f, .bias = 0, .creaseRange = 2.324f, .creaseBias = 0.165467f};  // crease
    // Crease at the default preset: at the cost of the 4-tap Scalable default it replaced
    // (1.00-1.06 times, inside the runs' spread), the configuration most accurate on the training
    // families that lowers no held-out family (tools/bench/ao_front, docs/trade.md): 2.4 dB over
    // Scalable on the training families, 2.3 dB held out; horizon 1 x 6 costs 1.18-1.19 times as
    // much for less.
    p.aoTechnique = AoTechnique::Crease;
    // Horizon: 1 slice of 6 steps a side at half size (12 fetches), its look the geometry's own,
    // as the high tier's default; on the front, where 2 x 4 is not, and where the truth is
    // occluded too bright by 0.030 held out against 2 x 4's 0.053 (docs/trade.md).
    p.aoHorizonSlices = 1;
    p.aoHorizonSteps = 6;
    p.aoHorizonThickness = 1.0f;
    p.aoHorizonFalloff = 0.02f;
    p.aoLook[3] = {};              // horizon: intensity 1, contrast 1 (the visibility as estimated)
    p.aoPackedDepthTarget = true;  // ao_blur.frag reads the key packed in the RGBA8 AO target
    // Obscurance and blur at half size, a depth-aware upsample last, for the cost goal
    // (docs/trade.md); the blur's 2 px become 1 half-size tap each side.
    p.aoHalfResolution = true;
    p.aoMaxDepthLayers = 1;  // multilayer AO is a high-tier feature
    p.mbTaps = 7;            // 6 samples + centre
    // 14 px: on the training motion families at 720 rows, 0.8 dB above the course's 10 px at the
    // same cost (fit_mb; the radius costs nothing measurable on lavapipe), and still below the
    // high tier's default on every held-out family and speed (docs/motion_blur.md).
    p.mbMaxRadiusPx = 14.0f;
    // 10 px on both tiers: a tier promise needs the same tiles (with the 2012 filter's N = k the
    // high tier's longer radius took its sampling direction from farther features), and from 5 to
    // 18 px the training families' PSNR moves by 0.05 dB at most (fit_mb --tiles,
    // docs/motion_blur.md), so the tile is no preset's dimension.
    p.mbTilePx = 10.0f;
    p.mbJitterSize = 2;  // checkerboard
    p.abufferOit = false;
    return p;
}

TierProfile highDefault() {
    TierProfile p;
    p.tier = Tier::High;
    p.aoScalableTaps = 9;  // spiral taps reading the depth MIP
    p.aoScalableMirrored = false;
    p.aoScalableMaxRadiusPx = 0.0f;  // no clamp
    p.aoUsesDepthMip = true;
    p.aoDepthMipLevels = uint32_t(shared::SFX_DEPTH_MIP_MAX_LEVELS);
    p.aoAlchemySamples = 12;  // the paper's 12 samples per pixel
    p.aoBlurRadiusPx = 6;     // 13-tap, as Alchemy's filter
    p.aoCreaseTaps = 24;      // the article's whole diamond
    // Alchemy's intensity follows the radius, times (r / 0.5 m)^-0.2: one intensity fits the
    // families' radii only on average, too bright where occluded at small ones. 0.2 has the best
    // training objective of 0, 0.1, 0.2 and 0.3; the look refitted with it raises every held-out
    // family and is too bright by 0.047 where occluded (fit_ao --start both, docs/ao_families.md).
    // The current tier's refit lowers `thin`, so it keeps one intensity.
    p.aoLook[0] = {.intensity = 0.269649f, .contrast = 3.16228f, .bias = 1e-7f, .radiusExponent = 0.2f};  // alchemy
    // Scalable with its sum exponent fitted (tools/bench/fit_ao --start tier, at half resolution).
    p.aoLook[1] = {.intensity = 0.187609f, .contrast = 7.36525f, .bias = 0.0468752f, .sumExponent = 0.707107f};  // scalable
    // Crease as on the current tier, the search from the article's look the better (fit_ao --start both).
    p.aoLook[2] = {.intensity = 4.47214f, .contrast = 1.77828f, .bias = 0, .creaseRange = 2.78512f, .creaseBias = 0.25f};  // crease
    // Horizon at the default preset (tools/bench/ao_front, docs/trade.md): at the cost of the
    // 9-tap Scalable default it replaced (0.95-1.09 times over six runs, inside the runs'
    // spread), the configuration most accurate on the training families that lowers no held-out
    // family (the adoption rule of the fits): 1 slice of 6 steps a side with the 6 px blur; too
    // bright by 0.035 where the truth is occluded held out, against 0.061.
    p.aoTechnique = AoTechnique::Horizon;
    p.aoHorizonSlices = 1;
    p.aoHorizonSteps = 6;
    p.aoHorizonThickness = 1.0f;
    p.aoHorizonFalloff = 0.02f;
    p.aoLook[3] = {};               // horizon: intensity 1, contrast 1
    p.aoPackedDepthTarget = false;  // float AO target carrying the linear depth (RG32F; RGBA32F crease)
    p.aoHalfResolution = true;      // as the current tier; the blur's 6 px become 3 half-size taps each side
    p.aoMaxDepthLayers = 4;         // multilayer AO: the first visible layer and 3 peeled ones (SFX_AO_MAX_DEPTH_LAYERS)
    // 12 samples + centre: its samples no farther apart than the current tier's (18 px / 6 pairs
    // against 14 px / 3 pairs), so a thin feature is missed and a hidden background guessed from
    // afar no more often on the tier with the longer blur (docs/motion_blur.md, scene families).
    p.mbTaps = 13;
    p.mbMaxRadiusPx = 18.0f;
    p.mbTilePx = 10.0f;  // the current tier's tile (above)
    // The current tier's checkerboard: with the velocity stored alike on both tiers, a blur both
    // radii contain is then reconstructed exactly as on the current tier (the 4x4 pattern lost
    // up to 0.03 dB there on the held-out families and gained nothing at longer blurs).
    p.mbJitterSize = 2;
    p.abufferOit = true;
    return p;
}

// A preset of a tier: its default with another AO technique (its point of the measured front,
// docs/trade.md), other tap counts (horizon's as slices x steps), blur width (output pixels), AO
// at full or half resolution and motion blur radius (uniforms and specialisation constants only:
// the tier's shader defines, and so its programs, stay the default's).
enum class AoRes { Full, Half };
struct HorizonCounts {
    uint32_t slices, steps;
};
Preset variant(const char* name, TierProfile p, AoTechnique technique, AoRes res, uint32_t alchemy, uint32_t scalable, HorizonCounts horizon,
               uint32_t blur, uint32_t mbTaps, float mbRadius, PresetAccuracy accuracy) {
    p.aoTechnique = technique;
    p.aoHalfResolution = res == AoRes::Half;
    p.aoAlchemySamples = alchemy, p.aoScalableTaps = scalable, p.aoBlurRadiusPx = blur;
    p.aoHorizonSlices = horizon.slices, p.aoHorizonSteps = horizon.steps;
    p.mbTaps = mbTaps, p.mbMaxRadiusPx = mbRadius;
    return {name, p, accuracy};
}

// Each preset's technique, counts, blur and resolution are a point of the measured front
// (tools/bench/ao_front, docs/trade.md: PSNR on the training families against the geometric
// mean of the Vulkan and GL ES milliseconds), from the cheapest useful AO to the most accurate
// point at half size; full size costs 2.8 times that for 0.35 dB on the current tier and is on
// the high tier's front nowhere.
// Accuracy: PSNR in dB of alchemy, scalable, crease and horizon AO on the held-out scene families
// and of motion blur on the held-out motion families at 720 rows, measured by tools/bench/trade_presets
// (tools/run_trade.sh) on llvmpipe; the figures of docs/trade.md (motion blur's also fit_mb's, the
// same measure on the CPU reference: docs/mb_fit.csv).
std::vector<Preset> currentPresets() {
    const TierProfile d = currentDefault();
    return {{kDefaultPreset, d, {{28.95, 28.41, 30.70, 29.03}, 26.62}},
            variant("low", d, AoTechnique::Scalable, AoRes::Half, 3, 2, {1, 3}, 2, 3, 8.0f, {{27.67, 27.37, 30.70, 28.52}, 23.03}),
            variant("medium", d, AoTechnique::Scalable, AoRes::Half, 4, 6, {1, 4}, 2, 5, 14.0f, {{28.21, 28.85, 30.70, 28.95}, 25.56}),
            variant("high", d, AoTechnique::Horizon, AoRes::Half, 10, 12, {2, 8}, 2, 9, 24.0f, {{29.33, 30.35, 30.70, 31.35}, 27.95}),
            variant("ultra", d, AoTechnique::Horizon, AoRes::Half, 16, 16, {3, 12}, 2, 13, 24.0f, {{29.61, 30.48, 30.70, 32.03}, 28.38})};
}

std::vector<Preset> highPresets() {
    const TierProfile d = highDefault();
    return {{kDefaultPreset, d, {{29.69, 29.95, 30.52, 30.62}, 27.82}},
            variant("low", d, AoTechnique::Scalable, AoRes::Half, 4, 4, {1, 3}, 2, 5, 14.0f, {{28.26, 27.75, 30.42, 28.52}, 25.56}),
            variant("medium", d, AoTechnique::Scalable, AoRes::Half, 8, 6, {1, 4}, 4, 7, 24.0f, {{29.56, 28.99, 30.47, 29.84}, 27.56}),
            variant("high", d, AoTechnique::Horizon, AoRes::Half, 16, 12, {2, 8}, 2, 13, 24.0f, {{29.79, 29.82, 30.42, 31.35}, 28.38}),
            variant("ultra", d, AoTechnique::Horizon, AoRes::Half, 24, 16, {3, 12}, 2, 17, 24.0f, {{29.95, 30.14, 30.42, 32.03}, 28.58})};
}

std::vector<TierRow> makeTable() {
    std::vector<TierRow> rows;
    rows.push_back({Tier::Current,
                    "GL ES 3.0-class: fragment passes only, no storage buffers or atomics",
                    currentRules(),
                    CapabilityCeiling::GLES30,
                    {ShaderDialect::Essl300, ShaderDialect::Essl310, ShaderDialect::Glsl330, ShaderDialect::Glsl450},
                    currentPresets()});
    rows.push_back({Tier::High,
                    "Vulkan / GL ES 3.1+ / GL 4.3+: storage buffers, atomics, compute",
                    highRules(),
                    CapabilityCeiling::None,
                    {ShaderDialect::Essl310, ShaderDialect::Glsl450},
                    highPresets()});
    return rows;
}

}  // namespace

const std::vector<TierRow>& table() {
    static const std::vector<TierRow> rows = makeTable();
    return rows;
}

}  // namespace sfx::tiers
