// The horizon technique's per-pixel visibility for the AO reference (ao_reference.cpp), written
// from the shared header's terms exactly as ao_horizon.frag runs them. Internal: not installed.
#pragma once

#include <functional>
#include <vector>

#include <glm/glm.hpp>

#include "sfx/ao.hpp"
#include "sfx/reference/depth_reference.hpp"

namespace sfx::reference::detail {

// One obscurance pass's view of the depth: its pyramid (level 0 the pass's depth, through
// linearDepthOrFar), the view position of pass pixel (x, y) at a depth, and projInfo.
struct HorizonPass {
    const AoConfig& config;
    const std::vector<Grid>& pyramid;
    std::function<glm::dvec3(int, int, double)> position;
    const double* projInfo;
    float pixelsPerUnit;  // the float AoParams::pixelsPerUnit the shader gets (the pass's)
};

// Visibility (before intensity and contrast) of pass pixel (x, y) at depth z, position C,
// normal n: the mean over slices of the visible arc between the two horizons. With `bent`, also
// the pixel's bent vector (sfx_shared_ao_horizon.h, aoHorizonBentVector: not yet normalised).
double horizonVisibility(const HorizonPass& pass, int x, int y, double z, const glm::dvec3& C, const glm::dvec3& n, glm::dvec3* bent = nullptr);

}  // namespace sfx::reference::detail
