// One run of an effect on a given device and tier, read back as doubles: shared by the
// conformance tests (device under test vs CPU reference) and the cross-backend test (every
// backend vs every other), so both measure exactly the same thing.
#pragma once

#include "analytic_scenes.hpp"
#include "sfx/ao.hpp"
#include "sfx/hal.hpp"
#include "sfx/motion_blur.hpp"
#include "sfx/reference/ao_reference.hpp"
#include "sfx/reference/motion_blur_reference.hpp"

namespace sfx::test {

struct GpuAo {
    reference::Grid visibility;
    AoConfig config;
    Plan plan;
};

// The AO tests' settings for technique `t` at world scale `scale`: radius 0.5, Scalable at
// intensity 2, Crease's range and fade in world units.
AoSettings aoTestSettings(AoTechnique t, double scale = 1.0);

// A 96x54 motion blur scene: a checkered background moving (-6, 2) px, a disc moving (22, 6)
// px, and a still post in front of both.
reference::Scene movingAndStillLayersScene();

// The first of `wanted` the device renders to (or samples), else RGBA8.
Format pickFormat(Device& device, std::initializer_list<Format> wanted, bool renderable);

// AO of `scene` with `settings`. descInput: what the context is told it will get. The scenes'
// depth is linear, so Linear reads it where it lies (no linearisation pass unless a MIP is
// built); Hardware copies it first.
GpuAo runAo(Device& device, const TierProfile& tier, const samples::AnalyticScene& scene, const AoSettings& settings,
            DepthKind descInput = DepthKind::Linear);

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

// Runs motion blur and reads the RGBA16F output back as doubles (sign kept: sfx/half.hpp).
reference::ColorGrid runMotionBlur(Device& device, const TierProfile& tier, const reference::ColorGrid& color,
                                   const reference::Grid& depth, const reference::VelocityGrid* velocity,
                                   const MotionBlurSettings& s, const CameraMotion& camera = {},
                                   DepthKind descInput = DepthKind::Linear);

}  // namespace sfx::test
