// The scene renderer (sfx_render) run once in a test: the tier chosen on the device, the
// renderer created and one frame rendered, each step REQUIREd with its status in the report.
#pragma once

#include "sfx/scene_render.hpp"
#include "sfx/tiers.hpp"

namespace sfx::test {

// The tier `tier` on `device` (tiers::choose), REQUIREd.
tiers::TierChoice chooseTier(const Device& device, Tier tier);

// One frame of `scene` with `options` at `tier`; `plan`, when given, receives the renderer's plan.
render::RenderResult renderScene(Device& device, Tier tier, const scene::Scene& scene, const render::RenderOptions& options,
                                 render::FramePlan* plan = nullptr);

}  // namespace sfx::test
