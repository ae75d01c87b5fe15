#include "sfx/reference/depth_reference.hpp"

#include <algorithm>
#include <cmath>

#include "sfx_shared.h"

namespace sfx::reference {

Grid linearizeDepth(const Grid& stored, const DepthReconstruction& r) {
    Grid out(stored.width, stored.height);
    for (uint32_t y = 0; y < stored.height; ++y) {
        for (uint32_t x = 0; x < stored.width; ++x) {
            out.at(x, y) = shared::sfxLinearizeDepth(stored.at(x, y), r.ndcScale, r.denomOffset, r.numerator, r.maxDepth);
        }
    }
    return out;
}

std::vector<Grid> depthPyramid(const Grid& linearDepth, uint32_t levels) {
    std::vector<Grid> pyramid{linearDepth};
    for (uint32_t i = 1; i < levels; ++i) {
        const Grid& prev = pyramid.back();
        Grid next(std::max(1u, prev.width / 2), std::max(1u, prev.height / 2));
        for (uint32_t y = 0; y < next.height; ++y) {
            for (uint32_t x = 0; x < next.width; ++x) {
                const shared::ivec2 s = shared::depthMipSource(shared::ivec2{int(x), int(y)});
                const uint32_t sx = std::min(uint32_t(s.x), prev.width - 1), sy = std::min(uint32_t(s.y), prev.height - 1);
                next.at(x, y) = prev.at(sx, sy);
            }
        }
        pyramid.push_back(std::move(next));
    }
    return pyramid;
}

}  // namespace sfx::reference
