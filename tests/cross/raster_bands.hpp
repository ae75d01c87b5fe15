// Where two conformant rasterisers may cover the scene renderer's picture differently: both
// specifications let a rasteriser snap vertices to a sub-pixel grid as coarse as 1/16 pixel
// (Vulkan subPixelPrecisionBits, GL ES GL_SUBPIXEL_BITS, at least 4), so a pixel whose centre
// lies within one grid step of a projected edge across which the picture changes may be
// covered by one and not the other. (Each snap moves a vertex by at most half a step on each
// axis, so an edge by at most sqrt(2) / 2 of the coarser step plus the finer one's.)
#pragma once

#include <cstdint>

#include "edge_bands.hpp"
#include "sfx/scene_render.hpp"

namespace sfx::test {

// The pixels of `scene`, drawn with the frame's camera (`frame`: a RenderResult's opaque
// inputs), whose centre lies within 2^-subPixelBits pixels of a silhouette or crease of any
// object, or of where the near plane cuts a triangle. Row 0 = top, as the renderer's images.
PixelMask sceneEdgeBand(const scene::Scene& scene, const render::RenderResult::OpaqueInputs& frame, uint32_t subPixelBits);

}  // namespace sfx::test
