#include "mb_sequence.hpp"

#include <algorithm>
#include <cmath>

namespace sfx::tools {

using namespace sfx::reference;

namespace {

// x folded into [lo, hi] as a ball bouncing between two walls; dir is +1 on the way out, -1 on
// the way back. Left as it is when there is no room to bounce in.
double fold(double x, double lo, double hi, double& dir) {
    dir = 1;
    if (!(hi > lo) || (x >= lo && x <= hi)) return x;
    const double span = hi - lo;
    double u = std::fmod(x - lo, 2 * span);
    if (u < 0) u += 2 * span;
    if (u <= span) return lo + u;
    dir = -1;
    return lo + 2 * span - u;
}

// Half of the object's extent along each axis at `scale` (any angle when it turns).
std::array<double, 2> reach(const FamilyObject& o, double scale) {
    const double hx = o.halfSize[0], hy = o.shape == FamilyObject::Shape::Disc ? o.halfSize[0] : o.halfSize[1];
    if (o.spinRad != 0 || o.angleRad != 0) {
        const double r = o.shape == FamilyObject::Shape::Disc ? hx : std::hypot(hx, hy);
        return {r * scale, r * scale};
    }
    return {hx * scale, hy * scale};
}

}  // namespace

FamilyScene sequenceScene(const FamilyScene& scene, double centreTime, std::array<double, 2> panPx) {
    const double kFold = std::log(2.0);  // a growing object stays within half to twice its size
    FamilyScene out = scene;
    for (FamilyObject& o : out.objects) {
        const double maxScale = o.growth != 0 ? o.scale * 2 : o.scale;
        const std::array<double, 2> r = reach(o, maxScale);
        const double size[2] = {double(scene.width), double(scene.height)};
        for (int a = 0; a < 2; ++a) {
            const double v = o.velocityPx[a] + panPx[a];
            const double x = o.centre[a] + v * centreTime;
            double dir = 1;
            // The background plane has no edges to keep in view: it only pans.
            o.centre[a] = o.shape == FamilyObject::Shape::Plane ? x
                                                                : fold(x, std::min(r[a], o.centre[a]), std::max(size[a] - r[a], o.centre[a]), dir);
            o.velocityPx[a] = v * dir;
        }
        o.angleRad += o.spinRad * centreTime;
        if (o.growth != 0) {
            // In log scale, where growth is a constant rate; the offset from the laid-out size
            // is folded so that a frame within the band keeps its scale exactly.
            double dir = 1;
            o.scale *= std::exp(fold(o.growth * centreTime, -kFold, kFold, dir));
            o.growth *= dir;
        }
    }
    return out;
}

SequenceFrame sequenceFrame(const FamilyScene& frameScene, uint32_t instants) {
    const uint32_t w = frameScene.width, h = frameScene.height;
    const size_t n = size_t(w) * h;
    SequenceFrame f{frameScene.render(0), ColorGrid(w, h), ColorGrid(w, h), std::vector<bool>(n, false)};
    // The truth as shutterAverage computes it, and the mask and the half truth from the same
    // instants (one render each).
    const uint32_t halfCount = (instants + 1) / 2;
    for (uint32_t i = 0; i < instants; ++i) {
        const SceneFrame s = frameScene.render((i + 0.5) / instants - 0.5);
        for (size_t p = 0; p < n; ++p) {
            for (int c = 0; c < 4; ++c) f.truth.values[p][c] += s.color.values[p][c] / instants;
            if (i % 2 == 0)
                for (int c = 0; c < 4; ++c) f.truthHalf.values[p][c] += s.color.values[p][c] / halfCount;
            const int l = s.layer[p];
            if (l >= 0 && frameScene.objects[size_t(l)].shape != FamilyObject::Shape::Plane) f.objects[p] = true;
        }
    }
    return f;
}

}  // namespace sfx::tools
