// Pixels two conformant rasterisers may cover differently: those whose centre lies within a
// band of a projected mesh edge across which the picture changes. Shared by the tests that
// compare a rasterised picture with a CPU rasteriser (test_render_oit.cpp) or with another
// driver (test_cross_render.cpp).
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "sfx/mesh_primitives.hpp"

namespace sfx::test {

// One flag per pixel of a width x height picture, row-major.
struct PixelMask {
    uint32_t width = 0, height = 0;
    std::vector<uint8_t> set;
    PixelMask(uint32_t w, uint32_t h) : width(w), height(h), set(size_t(w) * h, 0) {}
    bool at(int x, int y) const { return set[size_t(y) * width + size_t(x)] != 0; }
    size_t count() const;
};

// Marks every pixel whose centre (x + 0.5, y + 0.5) lies within `band` pixels of the segment
// a-b (window pixels).
void markSegmentBand(PixelMask& mask, glm::dvec2 a, glm::dvec2 b, double band);

// A mesh's edges (object-space end points) across which the picture may change: used by one
// triangle, or by two facing different ways (`facing`: +1, -1, or 0 for edge-on, per triangle),
// which are silhouettes; with `creases`, also by two in different planes (a face's shading
// changes there). Edges are keyed by their end points' positions: meshes repeat vertices.
std::vector<std::pair<glm::vec3, glm::vec3>> changingEdges(const scene::TriangleMesh& mesh, const std::vector<int>& facing, bool creases);

}  // namespace sfx::test
