// Ambient obscurance: Alchemy AO, Scalable AO, crease shading and horizon-based AO, with a depth-aware
// bilateral blur. Same shape as every effect: create / dispatch / resize / destroy (RAII),
// status returns, and a plan of the passes and bytes it holds.
//
// Output: ambient visibility in [0, 1] (1 = unoccluded) in the r channel of the host's output
// texture (every channel of an RGBA target holds it, alpha 1). Sky (linear depth at or past
// SFX_SKY_DEPTH, or the far plane) is 1. With AoSettings.bentNormals (horizon) also the bent
// normals, in AoInputs.bentNormals.
#pragma once

#include <memory>
#include <optional>

#include "sfx/ao_technique.hpp"
#include "sfx/depth.hpp"
#include "sfx/plan.hpp"
#include "sfx/tier.hpp"

namespace sfx {

enum class AoNormals : uint32_t {
    FromDepth,    // derived from linear depth (smaller-difference neighbour on each axis)
    FromTexture,  // AoInputs.normals: view-space unit normals, x right, y up, camera looking down -z.
    // Float formats (RGBA16F, RGBA32F) hold signed xyz; RGBA8 holds xyz * 0.5 + 0.5.
};

// Where obscurance and blur run. Half: on a half-size depth (each texel a real full-size
// sample, the depth MIP's rotated grid), then a depth-aware upsample to the output, weights
// from the full-size depth so silhouettes stay sharp: about a quarter of the obscurance and blur
// cost for one full-size pass (docs/ao.md). What most shipping AO does.
enum class AoResolution : uint32_t {
    Tier,  // the tier preset's (TierProfile::aoHalfResolution)
    Full,
    Half,
};
const char* toString(AoResolution resolution);  // "tier", "full", "half"
bool parseAoResolution(const std::string& text, AoResolution* out);

// Smallest AoSettings.radius: below it epsilon * r^2 (the centre-tap guard) is
// no longer a normal float, GPUs flush it to 0 and a centre tap would compute 0 / 0.
inline constexpr float kAoMinRadius = 1e-4f;

// The radius in metres at which a look that follows the radius (AoLook::radiusExponent) has its
// intensity: the radius the looks were fitted around (docs/trade.md).
inline constexpr double kAoRadiusExponentReferenceMetres = 0.5;

// Ranges: docs/settings.md (sfx/settings_ranges.hpp); out of range is InvalidArgument naming the
// field. An unset (nullopt) look field takes the tier preset's calibrated AoLook (docs/trade.md);
// an unset count takes the tier's.
struct AoCreaseSettings {
    std::optional<float> range;  // distance at which a tap's influence reaches 0, in units of AoSettings.radius
    std::optional<float> bias;   // scales (cos - minimumCrease) before saturating
    float averager = 10.0f;      // divisor of the tap sum (scaled to 24 taps when 12 are taken)
    float minimumCrease = 0.3f;  // cosine below which a tap adds nothing (stops radial banding)
    float fadeStart = 50.0f;     // [0, inf) linear depth where the distance fade begins
    float fadeEnd = 100.0f;      // (fadeStart, inf] linear depth where crease shading is gone
};

// The horizon technique's own settings; unset takes the tier's (TierProfile::aoHorizon*).
struct AoHorizonSettings {
    std::optional<uint32_t> slices;  // screen directions per pixel, each marched both ways
    std::optional<uint32_t> steps;   // depth samples per side of a slice
    // How far a lower sample seen past an occluder pulls the horizon back: 1 keeps the highest
    // (every occluder solid behind its face), lower values let thin occluders through.
    std::optional<float> thickness;
    std::optional<float> falloff;  // share of the radius, at its edge, over which a sample fades out
};

struct AoSettings {
    std::optional<AoTechnique> technique;  // unset: the tier preset's (TierProfile::aoTechnique)
    float radius = 0.5f;                   // world-space sampling radius (every technique)
    // The scene's scale: metres per world unit (0.01 for a world in centimetres). The
    // estimators are scale-free, but a look that follows the radius (radiusExponent) was fitted
    // on scenes of human scale, with the radius in metres.
    float metresPerUnit = 1.0f;
    std::optional<float> intensity;  // sigma, scales occlusion (all techniques)
    // A: the intensity used is intensity * (radius * metresPerUnit / 0.5 m)^-A, so a small radius
    // darkens as much as the truth does (docs/ao_families.md). 0 = the intensity as given.
    std::optional<float> radiusExponent;
    std::optional<float> contrast;  // k: visibility = max(0, 1 - occlusion)^k
    // Alchemy: beta, a distance per unit of depth (the paper's kAoAlchemyDefaultBias).
    // Scalable: subtracted from each tap's cosine (the paper's kAoScalableDefaultBias).
    std::optional<float> bias;
    // Scalable: occlusion = (2 sigma / N * sum)^e (the course's kAoScalableCourseSumExponent).
    std::optional<float> sumExponent;
    float epsilon = 1e-4f;  // guards divisions; in units of radius^2
    // Taps per pixel. Scalable on a mirrored tier: even. Crease: 12 (the diamond's checkerboard
    // half per pixel) or 24 (the whole diamond).
    std::optional<uint32_t> samples;
    bool blur = true;  // the separable depth-aware bilateral blur
    // Blur half-width in output pixels (TierProfile::aoBlurRadiusPx when unset); at half
    // resolution the blur takes (r + 1) / 2 half-size taps each side.
    std::optional<uint32_t> blurRadius;
    AoResolution resolution = AoResolution::Tier;
    AoNormals normals = AoNormals::FromDepth;
    AoCreaseSettings crease;
    AoHorizonSettings horizon;
    // Multilayer AO: opaque depth layers each tap tests, AoInputs.depth included; [1,
    // TierProfile::aoMaxDepthLayers]. Above 1 a tap keeps its largest term over the layers, so
    // surfaces behind the first visible one still occlude; runs at full resolution without a
    // depth MIP (resolution Tier resolves to Full; Half is an error).
    uint32_t depthLayers = 1;
    // Bent normals (Horizon only): the cosine-weighted mean unoccluded direction per pixel, into
    // AoInputs.bentNormals, blurred and upsampled with the visibility's weights (docs/ao.md).
    bool bentNormals = false;
};

// The papers' nominal values.
inline constexpr float kAoAlchemyDefaultBias = 1e-4f;
inline constexpr float kAoScalableDefaultBias = 0.02f;
inline constexpr float kAoScalableCourseSumExponent = 2.0f;

// Crease's resolved settings (AoCreaseSettings with the tier's look filled in).
struct AoCreaseConfig {
    // range in world units: AoCreaseSettings::range (or the look's) times the radius.
    float range = 1.0f, bias = 0.25f, averager = 10.0f, minimumCrease = 0.3f, fadeStart = 50.0f, fadeEnd = 100.0f;
};

// Horizon's resolved settings.
struct AoHorizonConfig {
    uint32_t slices = 2, steps = 4;
    double thickness = 1.0, falloff = 0.2;
};

// What a dispatch computes once settings and tier are resolved: the numbers the shaders get
// and the CPU reference (sfx/reference/ao_reference.hpp) consumes. Benchmarks may edit a
// resolved config (e.g. many samples, no MIP) to build a converged reference.
struct AoConfig {
    AoTechnique technique = AoTechnique::Scalable;
    double radius = 0.5, intensity = 1, contrast = 1, bias = 0.02, epsilon = 1e-4;
    double sumExponent = 2;  // Scalable: occlusion = (2 sigma / N * sum)^sumExponent
    // Every pixel count below is in the obscurance pass's pixels: at half resolution half-size ones.
    bool halfResolution = false;  // obscurance + blur at half size, then the depth-aware upsample
    uint32_t samples = 4;         // taps per pixel (Scalable mirrored: total, both signs); Horizon: its slices
    bool mirrored = false;        // Scalable: samples / 2 offsets, each also negated
    double spiralTurns = 7;       // Scalable spiral turns
    double maxRadiusPx = 0;       // Scalable: screen radius clamp, 0 = none
    uint32_t depthMipLevels = 1;  // Scalable, Horizon: depth MIP levels read, from the pass's size (1 = that size only)
    uint32_t depthLayers = 1;     // multilayer AO: layers each tap tests (AoSettings.depthLayers)
    uint32_t blurRadius = 0;      // 0 = no blur
    AoNormals normals = AoNormals::FromDepth;
    AoCreaseConfig crease;
    AoHorizonConfig horizon;
    bool bentNormals = false;  // AoSettings.bentNormals
};

// InvalidArgument naming the first field out of range.
Status validateAoSettings(const AoSettings& settings, const TierProfile& profile);
// Settings + tier -> config. mipLevelsAllowed: what the target size allows (maxMipLevels);
// outputRows: the output's height, which scales the tier's pixel extents defined at
// SFX_AO_REFERENCE_ROWS (Scalable's radius clamp).
Result<AoConfig> resolveAoConfig(const AoSettings& settings, const TierProfile& profile, uint32_t mipLevelsAllowed, uint32_t outputRows);

struct AoDesc {
    uint32_t width = 0;  // [1, caps.limits.maxTextureSize]
    uint32_t height = 0;
    TierProfile profile;  // tiers::profile(tier) or tiers::choose(caps)->profile
    AoSettings settings;
    // The AoInputs.depth.kind dispatch will get (LinearDepthDesc.input): with Linear, and no
    // depth MIP needed, the host's texture is read directly and no linearisation pass runs.
    DepthKind depthInput = DepthKind::Hardware;
};

// The host's inputs for one frame.
struct AoInputs {
    DepthSource depth;      // hardware or linear depth with its projection, the context's size
    TextureHandle normals;  // required when settings.normals == FromTexture (see AoNormals)
    // Where visibility goes: the context's size, kTextureRenderTarget, one of R8, RGBA8, R16F,
    // RG16F, RGBA16F, R32F, RGBA32F renderable on the device.
    TextureHandle output;
    // With AoSettings.depthLayers = L > 1: layers 1 .. L-1 in [0, L-2], each R32F positive linear
    // depth at the context's size, sampled: per pixel the nearest opaque surface strictly behind
    // the previous layer (0 or the far plane where there is none). Unused entries stay null.
    TextureHandle depthLayers[3] = {};
    // With AoSettings.bentNormals: the bent normals, view space (x right, y up, camera looking down
    // -z), unit length: the context's size, kTextureRenderTarget, RGBA8 (xyz * 0.5 + 0.5) or
    // RGBA16F / RGBA32F (signed xyz), alpha 1. Sky is (0, 0, 1), facing the eye.
    TextureHandle bentNormals;
};

class AmbientObscurance {
public:
    static Result<std::unique_ptr<AmbientObscurance>> create(Device& device, const AoDesc& desc);
    ~AmbientObscurance();
    AmbientObscurance(const AmbientObscurance&) = delete;
    AmbientObscurance& operator=(const AmbientObscurance&) = delete;

    // Records depth linearisation (+ MIP), at half resolution the half-size depth (unless MIP
    // level 1 is it), the obscurance pass, with blur two blur passes, at half resolution the upsample.
    Status dispatch(const AoInputs& inputs);
    Status resize(uint32_t width, uint32_t height);
    // Validates, then reallocates only what the new settings need (MIP levels, blur targets).
    Status setSettings(const AoSettings& settings);

    // Per-pass profiling, off by default: then dispatch creates and records no timers. On, each
    // pass of plan() (linearize, depth_mip levels, obscurance, blur h, blur v) is bracketed by
    // its own HAL timer, created here and kept across resize/setSettings until turned off.
    // On GL each timer waits for the GPU (glFinish) at both ends, so a profiled frame is
    // slower than an unprofiled one; Vulkan timestamps do not stall.
    Status setProfiling(bool enabled);
    bool profiling() const { return profiling_; }
    // The last profiled dispatch, read after the host's Device::flush(): one entry per plan()
    // pass, in its order. InvalidArgument when profiling is off or nothing was flushed yet.
    Result<std::vector<PassTiming>> passTimings();

    const AoDesc& desc() const { return desc_; }
    const AoConfig& config() const { return config_; }
    const LinearDepth& linearDepth() const { return *depth_; }
    EffectPlan plan() const;

private:
    AmbientObscurance(Device& device, const AoDesc& desc);
    Status allocate();
    Status allocateTargets();
    void releaseTargets();
    void release();
    Status createPassTimers();

    Device& device_;
    AoDesc desc_;
    AoConfig config_;
    std::unique_ptr<LinearDepth> depth_;
    // Records one pass, bracketed by its plan() timer while profiling (ao_half_res.cpp has the
    // half-resolution passes). A template defined in ao_internal.hpp, next to its only callers:
    // each pass's lambda is called directly, with no std::function to allocate per pass.
    template <class Record>
    Status timed(size_t passIndex, Record&& record);
    Status allocateHalfRes();
    // Every pass of a dispatch whose inputs were checked; `out` is the output's description,
    // `normalSource` the shaders' normal source (0 derived, 1 signed float, 2 RGBA8), `bentFormat`
    // the host's bent normal target's format (Undefined without bent normals).
    Status recordPasses(const AoInputs& in, const TextureDesc& out, int32_t normalSource, Format bentFormat);
    Status recordHalfDepth(size_t passIndex);
    Status recordUpsample(const AoInputs& in, Format outFormat, Format bentFormat, TextureHandle source, size_t passIndex);
    // Half resolution: whether the half-size depth is depth MIP level 1 (high-tier Scalable),
    // else halfDepth_ made by the ao_half_depth pass. The pass's size.
    bool halfDepthFromMip() const;
    uint32_t passWidth() const;
    uint32_t passHeight() const;
    TextureHandle halfDepthTexture() const;

    TextureHandle aoTarget_, blurTarget_;
    // With bent normals: the obscurance pass's and the blur intermediate's (bentTargetFormat()).
    TextureHandle bentTarget_, bentBlurTarget_;
    TextureHandle halfDepth_;  // half resolution without a depth MIP: R32F, half size
    Format targetFormat_ = Format::Undefined;
    BufferHandle aoParams_, blurParamsH_, blurParamsV_, upsampleParams_;
    ProgramHandle aoProgram_, blurProgram_, halfDepthProgram_, upsampleProgram_;
    // Pipelines by program, format and specialisation constants; kept across resize.
    std::unique_ptr<detail::PipelineCache> pipelines_;
    std::unique_ptr<detail::UniformWrites> uniforms_;  // every write of the uniform buffers above
    // The passes as a recording replayed in steady frames (Vulkan), unless profiling.
    std::unique_ptr<detail::RecordedPasses> recorded_;
    bool profiling_ = false;
    std::unique_ptr<detail::PassTimers> passTimers_;  // one per plan() pass while profiling, else empty
};

}  // namespace sfx
