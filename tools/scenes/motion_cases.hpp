// The motion blur cases the benchmarks share: the procedural 2.5D scenes with their temporally
// supersampled truth, and running the effect on them (or on any inputs) with a tier preset,
// timed and read back.
#pragma once

#include <string>
#include <vector>

#include "sfx/motion_blur.hpp"
#include "sfx/reference/motion_blur_reference.hpp"

namespace sfx::tools {

struct NamedMotionScene {
    std::string name;
    reference::MotionScene scene;
};
// "ball", "pan", "crossing", laid out in fractions of a w x h picture.
std::vector<NamedMotionScene> makeMotionScenes(uint32_t w, uint32_t h);

// RMSE over the RGB of every pixel and of the masked pixels (0 when none).
struct ColorErrors {
    double rmse = 0, rmseSilhouette = 0;
};
ColorErrors colorErrors(const reference::ColorGrid& a, const reference::ColorGrid& truth, const std::vector<bool>& mask);

struct MotionBlurRun {
    reference::ColorGrid output;
    double medianMs = 0;
    TimingSource source = TimingSource::GpuTimestamps;
};

// Uploads a colour grid as RGBA32F (no rounding before the effect).
Result<TextureHandle> uploadColor(Device& device, const reference::ColorGrid& color, const char* name);
// Dispatches the effect with `profile` (a tier preset) and `settings` `runs` times after one
// warm-up and reads the last output back.
Result<MotionBlurRun> timeMotionBlur(Device& device, const TierProfile& profile, const MotionBlurSettings& settings, uint32_t w, uint32_t h,
                                     const MotionBlurInputs& in, uint32_t runs);
// A 2.5D frame: colour, linear depth and velocity uploaded exactly as rendered, then timeMotionBlur.
Result<MotionBlurRun> runMotionBlur(Device& device, const TierProfile& profile, const MotionBlurSettings& settings,
                                    const reference::SceneFrame& frame, const CameraProjection& camera, uint32_t runs);

}  // namespace sfx::tools
