// Rasterised scene families for scoring motion blur on geometry it was never tuned on, drawn by
// the SDK's own raster pass (mb_raster.hpp): "models", glmark2's horse and cat moving in front of
// a still checkered wall and floor (object motion, still camera), and "camera", a still scene of
// a sphere, a thin post, the bunny, a box and a wall at depths from 2.5 to 12 seen by a camera
// that pans right while it dollies in (every pixel moves, faster the nearer it is), and
// "turning", a two-bladed cross spinning in the picture plane and the horse turning on the spot
// (still camera). Each is scaled to a chosen speed; the truth is the average of many rendered instants.
#pragma once

#include <string>
#include <vector>

#include "mb_families.hpp"
#include "scene.hpp"

namespace sfx::tools {

std::vector<std::string> rasterFamilyNames();

// The family's scene with its motion scaled so that its fastest visible point moves `speedPx`
// across the shutter in a w x h frame (the velocity buffer's largest length at t = 0, set by
// rendering, as the motion is not quite linear in the speed once it has a depth component).
// Layout 1 is the family as designed; other layouts move, turn and tilt its objects and motion
// (drawn from the layout number). InvalidArgument for an unknown family; FileError when a
// glmark2 model is missing.
Result<RasterScene> rasterFamilyScene(Device& device, SceneRenderer& renderer, const std::string& family, double speedPx, uint32_t w, uint32_t h,
                                      uint32_t layout = 1);

struct RasterFamilyCase {
    std::string family;
    double speedPx = 0;          // asked for
    double measuredSpeedPx = 0;  // the t = 0 velocity buffer's largest length
    reference::ColorGrid truth;  // average of the rendered instants
    double residualRmse = 0;     // the truth's residual noise (mb_raster.hpp)
    // As FamilyMasks for the 2D families, from the rendered instants: moving = a drawn surface
    // moves at some instant or the surface seen changes (coverage, or linear depth by more than
    // 10%); leading / trailing = at the last instant a nearer / farther surface than at the first.
    FamilyMasks masks;
    reference::SceneFrame frame;  // the t = 0 frame: colour, linear depth, the rasteriser's velocity
};
// `renderer` is loaded with the family's scene (replacing what it held).
Result<RasterFamilyCase> makeRasterFamilyCase(Device& device, SceneRenderer& renderer, const std::string& family, double speedPx, uint32_t w,
                                              uint32_t h, uint32_t instants, uint32_t layout = 1);

}  // namespace sfx::tools
