// Motion blur reconstruction (McGuire et al.'s reconstruction filter, tiered as in the Scalable
// High Quality Motion Blur and Ambient Occlusion course; docs/algorithms.md): a gather blur along
// per-pixel velocity that blurs moving objects past their silhouettes and keeps still ones sharp.
// Same shape as every effect: create / dispatch / resize / destroy (RAII), status returns, a plan
// of passes and bytes.
//
// Velocity convention (inputs.velocity and the CLI's velocity files):
// - units: pixels of the output; x toward increasing column, y toward increasing memory row
//   (texel row y, as hal.hpp defines it; for images the SDK writes, row 0 is the top, so y
//   points toward the bottom of the picture);
// - time span: the displacement of the surface across the shutter interval (the time the
//   shutter is open) at exposure 1, with the frame rendered at mid-shutter. The blur therefore
//   reaches |v| / 2 to either side of a pixel; that half ("blur radius") is what maxRadiusPx
//   bounds. exposure scales the span (0.5 = the shutter open half as long).
// - sign: the direction of motion; the blur is symmetric, so the sign only matters to hosts
//   that also use the buffer for reprojection.
//
// Passes: linear depth (sfx::LinearDepth) -> pack (velocity clamped to the radius and encoded
// [-k, k] -> [0, 1], depth packed alongside, RGBA16F) -> tile max (N x N, N = radius, RG16F)
// -> neighbour max (the tiles within the radius, RG16F) -> reconstruction (the host colour's format).
#pragma once

#include <glm/glm.hpp>

#include <memory>
#include <optional>

#include "sfx/camera.hpp"
#include "sfx/depth.hpp"
#include "sfx/hal.hpp"
#include "sfx/plan.hpp"
#include "sfx/tier.hpp"

namespace sfx {

// Smallest MotionBlurSettings.softDepthExtent: well above FLT_MIN, so no GPU flushes it to 0.
inline constexpr float kMbMinSoftDepthExtent = 1e-6f;

// Ranges: docs/settings.md (sfx/settings_ranges.hpp); out of range is InvalidArgument naming the
// field, never a silent clamp. Unset (nullopt) fields take the tier's value.
struct MotionBlurSettings {
    // Maximum blur radius in pixels at referenceRows rows; the radius used is
    // round(maxRadiusPx * height / referenceRows), at least 1. Unset: the tier's
    // (TierProfile::mbMaxRadiusPx), capped at the shaders' 64 px (MotionBlurParams::radiusCapped
    // says so); a radius set here whose scaled value exceeds 64 px is InvalidArgument.
    std::optional<float> maxRadiusPx;
    uint32_t referenceRows = 720;  // rows maxRadiusPx is defined at; 0 = no scaling
    // Reconstruction taps, centre included, odd (mirrored pairs); unset: TierProfile::mbTaps.
    std::optional<uint32_t> samples;
    // Depth difference (linear depth units) over which a sample turns from "level with the
    // centre" to "in front of / behind it".
    float softDepthExtent = 0.1f;
    // Scales the centre's weight, the share of the shutter its samples leave (1 = exactly that):
    // larger keeps more of the pixel's own colour.
    float centreWeight = 1.0f;
    float exposure = 1.0f;  // scales the velocity's time span; 0 = no blur
};

// The parameters one dispatch runs with, after tier defaults and resolution scaling.
// Shared by the effect and the CPU reference so both run the same numbers.
struct MotionBlurParams {
    uint32_t taps = 0;        // centre included, odd
    uint32_t pairs = 0;       // (taps - 1) / 2 mirrored sample pairs
    uint32_t jitterSize = 0;  // 2 = checkerboard, 4 = 4x4 randomised
    uint32_t radiusPx = 0;    // k: clamp radius, output pixels, [1, 64]
    // N: tile edge of tile max and neighbour max, output pixels, [1, k] (TierProfile::mbTilePx
    // scaled as the radius is, made larger where the neighbourhood would reach past
    // SFX_MB_MAX_NEIGHBOR_REACH tiles).
    uint32_t tileSizePx = 0;
    // The tier-default radius scaled to the output height exceeded the 64 px limit and
    // radiusPx is that limit; scaledRadiusPx is the radius before the cap (0 when not capped).
    bool radiusCapped = false;
    double scaledRadiusPx = 0;
    double softDepthExtent = 0;
    double centreWeight = 0;
    double exposure = 0;
};

// Validates settings (InvalidArgument naming the field and its range; nothing is clamped
// silently) and resolves them with the tier parameters of `profile` (taps, radius, jitter) at an
// output of `height` rows. An empty or inconsistent profile is InvalidArgument naming
// "MotionBlurDesc.profile".
Result<MotionBlurParams> resolveMotionBlur(const TierProfile& profile, const MotionBlurSettings& settings, uint32_t height);

// Camera-only velocity: the host gives the camera's view-projection matrices (column-major,
// projection * view) for this frame and the previous one; each pixel's depth is reprojected.
// currentViewProjection's projection must be the DepthSource's camera projection.
struct CameraMotion {
    glm::dmat4 previousViewProjection{1.0};
    glm::dmat4 currentViewProjection{1.0};
};

struct MotionBlurInputs {
    TextureHandle color;  // the desc's colorFormat, output size, sampled
    DepthSource depth;    // output size
    // RG16F, RG32F, RGBA16F or RGBA32F (xy read), output size, pixels per shutter interval.
    // Null: camera-only velocity from depth and `camera`.
    TextureHandle velocity;
    CameraMotion camera;  // read only when velocity is null
    // Where the blurred colour goes. Null: the effect's own output() texture. Else a texture of
    // the host's (created, or imported with sfx::vulkan::importImage / sfx::gl::importTexture):
    // the MotionBlur size, the desc's colorFormat, usage including kTextureRenderTarget, and not
    // `color` itself (the last pass samples color while it writes here). Wrong size, format or
    // usage: InvalidArgument naming MotionBlurInputs.output and what is allowed.
    TextureHandle output;
};

struct MotionBlurDesc {
    uint32_t width = 0;  // [1, caps.limits.maxTextureSize]
    uint32_t height = 0;
    TierProfile profile;  // tiers::profile(tier) or tiers::choose(caps)->profile
    // Format of the host colour and of the output: RGBA8, RGBA16F or RGBA32F (renderable).
    Format colorFormat = Format::RGBA16F;
    // The MotionBlurInputs.depth.kind dispatch will get (LinearDepthDesc.input): with Linear the
    // host's texture is read directly and no linearisation pass runs.
    DepthKind depthInput = DepthKind::Hardware;
};

class MotionBlur {
public:
    // UnsupportedFormat when the device cannot render RGBA16F / RG16F (the packed velocity
    // and tile textures) or colorFormat.
    static Result<std::unique_ptr<MotionBlur>> create(Device& device, const MotionBlurDesc& desc);
    ~MotionBlur();
    MotionBlur(const MotionBlur&) = delete;
    MotionBlur& operator=(const MotionBlur&) = delete;

    // Records the passes; the result is in inputs.output, or output() when that is null, once
    // the device flushes.
    Status dispatch(const MotionBlurInputs& inputs, const MotionBlurSettings& settings = {});
    Status resize(uint32_t width, uint32_t height);

    // The effect's own output: colorFormat, width x height; written by dispatches without inputs.output.
    TextureHandle output() const { return output_; }
    TextureHandle packedVelocity() const { return packed_; }  // RGBA16F, for debugging views
    TextureHandle neighborMax() const { return neighborMax_; }
    const MotionBlurDesc& desc() const { return desc_; }
    // Passes and bytes for the given settings (the tile textures depend on the radius).
    EffectPlan plan(const MotionBlurSettings& settings = {}) const;

    // Per-pass profiling, off by default (as AmbientObscurance::setProfiling): on, each pass of
    // plan(settings) is bracketed by its own HAL timer and every dispatch records its passes
    // anew (a recording with timers is single-use). passTimings() reads the last profiled
    // dispatch after the host's Device::flush(), in plan() order; InvalidArgument when
    // profiling is off or nothing was timed yet. On GL each timer waits for the GPU at both ends.
    Status setProfiling(bool enabled);
    bool profiling() const { return profiling_; }
    Result<std::vector<PassTiming>> passTimings();

private:
    MotionBlur(Device& device, const MotionBlurDesc& desc);
    Status allocate();
    Status allocateTargets();
    Status allocateTiles(uint32_t tileSizePx);
    // Every pass of a dispatch whose inputs were checked, into `target`.
    Status recordPasses(const MotionBlurInputs& in, const MotionBlurParams& p, TextureHandle target);
    void release();
    void releaseTargets();
    void releaseTiles();

    Device& device_;
    MotionBlurDesc desc_;
    std::unique_ptr<LinearDepth> depth_;
    TextureHandle packed_, tileMax_, neighborMax_, output_;
    uint32_t tileSize_ = 0;  // the tile edge the tile textures were sized for
    BufferHandle packParams_, reconstructParams_;
    ProgramHandle packProgram_, tileProgram_, neighborProgram_, reconstructProgram_;
    // Pipelines by specialisation constants (camera-only, tile size, taps); kept across resize.
    std::unique_ptr<detail::PipelineCache> pipelines_;
    std::unique_ptr<detail::UniformWrites> uniforms_;  // every write of the uniform buffers above
    // The passes as a recording replayed in steady frames (Vulkan), unless profiling.
    std::unique_ptr<detail::RecordedPasses> recorded_;
    bool profiling_ = false;
    MotionBlurSettings profiledSettings_;             // the last profiled dispatch's, for its plan's pass names
    std::unique_ptr<detail::PassTimers> passTimers_;  // one per plan() pass while profiling, else empty
};

}  // namespace sfx
