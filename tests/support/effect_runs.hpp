// One run of an effect on a given device and tier, read back as doubles: shared by the
// conformance tests (device under test vs CPU reference) and the cross-backend test (every
// backend vs every other), so both measure exactly the same thing.
#pragma once

#include "analytic_scenes.hpp"
#include "sfx/ao.hpp"
#include "sfx/hal.hpp"
#include "sfx/motion_blur.hpp"
#include "sfx/oit.hpp"
#include "sfx/reference/ao_reference.hpp"
#include "sfx/reference/motion_blur_reference.hpp"

namespace sfx::test {

// Horizon's slices take acos five times (the normal's angle, each side's horizon, each side of
// the open arc), which the Vulkan specification bounds to 4096 ulp (about 1e-3 radian for
// results up to pi); the visibility, a ratio of arcs, then moves by less than 2e-3 more than
// the tier's bound against the reference (docs/ao.md; test_ao_horizon_reference.cpp checks it).
inline constexpr double kAoHorizonTrigBound = 0.002;

// The bent normal (AoSettings.bentNormals) takes no acos of its own: cos H and sin H follow
// from the horizon's sine. Only the visible share that scales the open correction carries the
// visibility's acos allowance, times |2/3 n - open vector| <= 5/3.
inline constexpr double kBentTrigAllowance = kAoHorizonTrigBound * 5.0 / 3.0;

// One rounding of a bent-normal component in [-1, 1] stored as `format`, plus 1e-6 for the
// pass's float arithmetic. Both APIs let a conversion to a normalized 8-bit code return either of
// the two nearest codes, and a store to fp16 round to nearest or toward zero: one whole step,
// 2/255 of a component for RGBA8 (it holds xyz * 0.5 + 0.5) and 2^-11 for RGBA16F. Two backends
// storing nearly the same value land at most one step apart, so the same term bounds a pair.
double bentRounding(Format format);

// How many intermediate targets a bent normal passes through before the output: the raw
// target when a blur or upsample follows, and each blur pass that writes one.
int bentIntermediates(const AoConfig& config);

// The bound on one pixel's worst bent-normal component (docs/ao.md, "Bent normals"): the raw
// vector's direction moves by `directionAllowance` / its length, each intermediate rounding
// moves the vector by sqrt(3) roundings, the renormalisation divides both by the blurred
// vector's length, and the output rounds once more.
double bentComponentBound(double directionAllowance, double vectorLength, double resolveLength, Format intermediate, int intermediates,
                          Format output);

struct GpuAo {
    reference::Grid visibility;
    AoConfig config;
    EffectPlan plan;
    std::vector<glm::dvec3> bentNormals;  // when the settings ask for them
};

// The AO tests' settings for technique `t` at world scale `scale`: radius 0.5, Scalable at
// intensity 2, Crease's range and fade in world units.
AoSettings aoTestSettings(AoTechnique t, double scale = 1.0);

// A 96x54 motion blur scene: a checkered background moving (-6, 2) px, a disc moving (22, 6)
// px, and a still post in front of both.
reference::MotionScene movingAndStillLayersScene();

// The first of `wanted` the device renders to (or samples), else RGBA8.
Format pickFormat(Device& device, std::initializer_list<Format> wanted, bool renderable);

// AO of `scene` with `settings`. descInput: what the context is told it will get. The scenes'
// depth is linear, so Linear reads it where it lies (no linearisation pass unless a MIP is
// built); Hardware copies it first. With settings.bentNormals the bent normals are written to a
// `bentFormat` target and read back too.
GpuAo runAo(Device& device, const TierProfile& tier, const tools::AnalyticScene& scene, const AoSettings& settings,
            DepthKind descInput = DepthKind::Linear, Format bentFormat = Format::RGBA8);

// Depth layers of an analytic scene with foreground blocks: on a checker of 8-pixel blocks layer 0
// is a surface at 0.6 of the scene's depth (a foreground object) and layer 1 the scene itself, the
// occluder single-layer AO cannot see; every further layer lies 0.06 to 0.18 (a smooth ripple)
// behind the one before, within the AO radius, with holes (no layer: 0) on a pattern, so taps
// see every mix of layers present and absent. Linear depth, layer 0 first.
std::vector<std::vector<float>> syntheticDepthLayers(const tools::AnalyticScene& scene, uint32_t layers);

// Multilayer AO (AoSettings.depthLayers = layers.size()) of `layers` (R32F linear depth each)
// into an R32F target, raw (no blur), at full resolution.
struct GpuMultilayerAo {
    reference::Grid visibility;
    AoConfig config;
    DepthReconstruction reconstruction;
};
GpuMultilayerAo runMultilayerAo(Device& device, const TierProfile& tier, const tools::AnalyticScene& scene, AoTechnique technique,
                                const std::vector<std::vector<float>>& layers);

// The motion blur tests' camera for a w x h target.
CameraProjection motionBlurTestCamera(uint32_t w, uint32_t h);

// The motion blur inputs on a device: colour RGBA16F, linear depth R32F, velocity RG32F.
struct MotionBlurGpuInputs {
    Device& device;
    TextureHandle color, depth, velocity;
    MotionBlurGpuInputs(Device& d, const reference::ColorGrid& colorGrid, const reference::Grid& depthGrid,
                        const reference::VelocityGrid* velocityGrid);
    MotionBlurGpuInputs(const MotionBlurGpuInputs&) = delete;
    MotionBlurGpuInputs& operator=(const MotionBlurGpuInputs&) = delete;
    ~MotionBlurGpuInputs();
};

// One motion blur run read back: the RGBA16F output as doubles (sign kept: sfx/half.hpp), and
// pass 1's velocities (the packed texture's xy decoded to pixels at the dispatch's radius), to
// compare with the reference's MotionBlurReferenceResult::radiusPx.
struct GpuMotionBlur {
    reference::ColorGrid color;
    reference::VelocityGrid radiusPx;
};
GpuMotionBlur runMotionBlurPasses(Device& device, const TierProfile& tier, const reference::ColorGrid& color, const reference::Grid& depth,
                                  const reference::VelocityGrid* velocity, const MotionBlurSettings& s, const CameraMotion& camera = {},
                                  DepthKind descInput = DepthKind::Linear);

// Runs motion blur and reads the RGBA16F output back as doubles (runMotionBlurPasses' colour).
reference::ColorGrid runMotionBlur(Device& device, const TierProfile& tier, const reference::ColorGrid& color, const reference::Grid& depth,
                                   const reference::VelocityGrid* velocity, const MotionBlurSettings& s, const CameraMotion& camera = {},
                                   DepthKind descInput = DepthKind::Linear);

// The motion blur conformance rule (docs/motion_blur.md): every channel of `gpu` finite (a
// REQUIRE) and at most 3% of channels more than 2e-3 from `ref`. Returns how many are.
size_t checkMotionBlurConformance(const reference::ColorGrid& gpu, const reference::ColorGrid& ref);

// Three overlapping translucent square quads over an opaque depth at the far plane, the
// transparency setup of the precision and 8K size tests. Quad i (0..2) spans +-halfExtent
// around (step.x * (i - 1), step.y * i) at z = -2 - i, colour (0.9 - 0.3i, 0.35 + 0.2i,
// 0.2 + 0.3i), opacity 0.3 + 0.2i, id i. projection: orthographic along -z, near 0.5, far 20,
// in the device's clip depth convention.
struct TranslucentQuads {
    Device& device;
    BufferHandle vertices;
    TextureHandle opaqueDepth;  // D32F, w x h, every texel 1 (the far plane)
    std::vector<TransparentDraw> draws;
    glm::mat4 projection{1.0f};
    TranslucentQuads(Device& d, uint32_t w, uint32_t h, float halfExtent, glm::vec2 step);
    TranslucentQuads(const TranslucentQuads&) = delete;
    TranslucentQuads& operator=(const TranslucentQuads&) = delete;
    ~TranslucentQuads();
};

// sfx::Transparency with `desc` over an opaque picture of desc.width x desc.height (row 0 first):
// `opaqueColor` RGBA per pixel, held as RGBA16F, and `opaqueDepth` the D32F attachment's values.
// Two frames are rendered (the second's pool sized from the first's count, as a host's steady
// scene is) and the second read back as doubles: the RGBA16F composite, and the RG16F AO through
// the layers (blended, opaque per pixel) when the effect made one.
struct GpuTransparency {
    std::vector<double> color, ao;
    TransparencyStats stats;
};
GpuTransparency runTransparency(Device& device, const TransparencyDesc& desc, const std::vector<glm::dvec4>& opaqueColor,
                                const std::vector<float>& opaqueDepth, const glm::mat4& view, const glm::mat4& projection,
                                std::span<const TransparentDraw> draws);

}  // namespace sfx::test
