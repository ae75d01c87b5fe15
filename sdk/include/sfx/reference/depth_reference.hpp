// CPU references of the depth passes, in double precision and written for clarity.
#pragma once

#include <vector>

#include "sfx/camera.hpp"

namespace sfx::reference {

// A W x H grid of values, row 0 first (memory rows), in double precision.
struct Grid {
    uint32_t width = 0, height = 0;
    std::vector<double> values;
    Grid() = default;
    Grid(uint32_t w, uint32_t h, double fill = 0.0) : width(w), height(h), values(size_t(w) * h, fill) {}
    double& at(uint32_t x, uint32_t y) { return values[size_t(y) * width + x]; }
    double at(uint32_t x, uint32_t y) const { return values[size_t(y) * width + x]; }
};

// Stored hardware depth -> linear eye depth, as the linearize_depth shader computes it:
// z = B / (ndc_z + A), clamped to reconstruction.maxDepth where the point is at or past the far plane.
Grid linearizeDepth(const Grid& storedDepth, const DepthReconstruction& reconstruction);

// The rotated-grid pyramid: levels[0] = linear depth, levels[i+1] texel p = levels[i] texel
// 2p + (p.y & 1, p.x & 1), clamped to the level's last texel.
std::vector<Grid> depthPyramid(const Grid& linearDepth, uint32_t levels);

}  // namespace sfx::reference
