// Motion blur on rasterised scenes: a RasterScene rendered by the SDK's own raster pass
// (SceneRenderer) at instants of the shutter interval, shaded on the CPU, and its truth the
// average of many rendered instants. Shared by bench_motionblur's 3D sample scenes and the
// rasterised scene families (mb_raster_families.hpp).
#pragma once

#include <functional>
#include <vector>

#include "scene.hpp"
#include "sfx/reference/motion_blur_reference.hpp"

namespace sfx::tools {

// albedo * (0.35 + 0.65 * max(0, n.l)) with a fixed view-space light; sky where nothing was
// drawn. Colour is a simple lit shading: the effect is what is measured, not a lighting model.
reference::ColorGrid shadeGBuffer(const GBufferContents& g);

// One rendered instant as the effect sees it, read back and decoded.
struct ShadedFrame {
    reference::ColorGrid color;
    reference::Grid linearDepth;       // from the D32F depth, as sfx::LinearDepth computes it
    reference::VelocityGrid velocity;  // the G-buffer's RG16F, pixels across the shutter interval
    std::vector<bool> drawn;           // albedo a > 0
};
Result<ShadedFrame> readFrame(Device& device, const GBuffer& gbuffer);

// The truth: the shaded colour averaged over `instants` times spread evenly over [-0.5, 0.5].
// Its residual noise: the RMSE (RGB) between the average of the even-numbered instants (half
// as many, as evenly spread) and the average of all of them.
struct SceneTruth {
    reference::ColorGrid color;
    double residualRmse = 0;
};
// `observe`, when set, gets every instant (index, then the frame) in time order.
using InstantObserver = std::function<void(uint32_t, const ShadedFrame&)>;
Result<SceneTruth> sceneGroundTruth(Device& device, SceneRenderer& renderer, const RasterScene& scene, uint32_t w, uint32_t h, uint32_t instants,
                                    const InstantObserver& observe = {});

}  // namespace sfx::tools
