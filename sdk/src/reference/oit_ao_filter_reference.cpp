// The layer AO's bilateral filter, double precision (sfx/reference/oit_ao_filter.hpp).
#include <algorithm>
#include <vector>

#include "sfx/reference/oit_ao_filter.hpp"
#include "sfx_shared_oit.h"

namespace sfx::reference {
namespace {

namespace sh = sfx::shared;

// One channel through one direction: values v keyed by `keys` (sky = at or past maxDepth).
Grid filterPass(const Grid& v, const std::vector<double>& keys, double maxDepth, int radius, bool vertical) {
    Grid out = v;
    const int w = int(v.width), h = int(v.height);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const double centre = keys[size_t(y) * size_t(w) + size_t(x)];
            if (!(centre < maxDepth)) continue;  // sky keeps its value
            double acc = 0, weight = 0;
            for (int k = -radius; k <= radius; ++k) {
                const int qx = vertical ? x : x + k, qy = vertical ? y + k : y;
                if (qx < 0 || qy < 0 || qx >= w || qy >= h) continue;
                const size_t q = size_t(qy) * size_t(w) + size_t(qx);
                const double wt = sh::oitFilterTapWeight(k, radius, keys[q], centre);
                acc += wt * v.values[q];
                weight += wt;
            }
            out.values[size_t(y) * size_t(w) + size_t(x)] = acc / weight;  // the centre's weight is 1
        }
    return out;
}

}  // namespace

OitAoResult filterLayerAo(const FragmentImage& image, const OitAoResult& raw, uint32_t radius) {
    if (radius == 0) return raw;
    const double maxDepth = image.reconstruction.maxDepth;
    const size_t n = size_t(image.width) * image.height;
    std::vector<double> front(n), opaque(n);
    for (size_t i = 0; i < n; ++i) {
        opaque[i] = std::min(image.opaque[i].depth, maxDepth);
        const std::vector<OitFragment> sorted = sortedFragments(image.fragments[i], image.opaque[i].depth);
        front[i] = sorted.empty() ? opaque[i] : std::min(sorted.front().depth, maxDepth);
    }
    OitAoResult out = raw;
    const int r = int(radius);
    out.blended = filterPass(filterPass(raw.blended, front, maxDepth, r, false), front, maxDepth, r, true);
    out.opaque = filterPass(filterPass(raw.opaque, opaque, maxDepth, r, false), opaque, maxDepth, r, true);
    return out;
}

}  // namespace sfx::reference
