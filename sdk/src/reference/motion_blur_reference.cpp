#include "sfx/reference/motion_blur_reference.hpp"

#include <algorithm>
#include <cmath>

#include "sfx_shared.h"
#include "sfx_shared_mb.h"

namespace sfx::reference {
namespace {

using shared::mbActivePairs;
using shared::mbCentreShare;
using shared::mbJitter;
using shared::mbPairUsesCentre;
using shared::mbSampleT;
using shared::mbSampleWeight;

double length2(const std::array<double, 2>& v) { return v[0] * v[0] + v[1] * v[1]; }
double rankKey(const std::array<double, 2>& v) { return shared::mbRankKey(glm::dvec2(v[0], v[1])); }
double roundAway(double x) { return x < 0 ? -std::floor(-x + 0.5) : std::floor(x + 0.5); }

// Largest by magnitude over a set of texels, ranked as the shaders rank (mbRankKey); strict '>'
// so the first in scan order wins ties.
struct MaxTracker {
    std::array<double, 2> best{0, 0};
    double bestLen2 = -1;
    void offer(const std::array<double, 2>& v) {
        const double l = rankKey(v);
        if (l > bestLen2) {
            bestLen2 = l;
            best = v;
        }
    }
};

}  // namespace

static_assert(kSkyDepth == double(shared::SFX_SKY_DEPTH));

double roundToHalf(double value) {
    if (!std::isfinite(value) || value == 0.0) return value;
    int exponent = 0;
    std::frexp(value, &exponent);  // value = m * 2^exponent, |m| in [0.5, 1)
    // fp16 keeps 11 significant bits for normals; subnormals (below 2^-14) keep a fixed step 2^-24.
    const int step = std::max(exponent - 11, -24);
    const double scaled = std::ldexp(value, -step);
    const double rounded = std::nearbyint(scaled);  // default rounding: to nearest, ties to even
    const double out = std::ldexp(rounded, step);
    return std::fabs(out) > 65504.0 ? std::copysign(INFINITY, value) : out;
}

MotionBlurReferenceResult motionBlur(const ColorGrid& color, const Grid& linearDepth, const VelocityGrid& velocityPx, const MotionBlurParams& p,
                                     double maxDepth, const MotionBlurCandidate& candidate) {
    const uint32_t w = color.width, h = color.height;
    const double k = double(p.radiusPx);
    MotionBlurReferenceResult r;

    // Pass 1: scale to a radius, clamp the magnitude to k, and round to the fp16 grid the RGBA16F
    // target holds exactly (sfx_shared_mb.h): what the later passes read.
    r.radiusPx = VelocityGrid(w, h);
    Grid depth(w, h);
    for (uint32_t y = 0; y < h; ++y) {
        for (uint32_t x = 0; x < w; ++x) {
            // The scaled velocity as the shader holds it (a float), then the rule of sfx_shared_mb.h.
            const std::array<double, 2>& in = velocityPx.at(x, y);
            const float scale = float(0.5 * p.exposure);
            const glm::dvec2 v = shared::mbClampVelocity(glm::dvec2(double(float(in[0]) * scale), double(float(in[1]) * scale)), k);
            for (int c = 0; c < 2; ++c) r.radiusPx.at(x, y)[c] = shared::mbQuantizeVelocity(v[c]);
            depth.at(x, y) = std::min(shared::sfxLinearDepthOrFar(linearDepth.at(x, y), maxDepth), double(shared::SFX_MB_MAX_PACKED_DEPTH));
        }
    }

    // Pass 2: tile max over N x N, N = the tile edge.
    const uint32_t n = p.tileSizePx;
    const uint32_t tw = (w + n - 1) / n, th = (h + n - 1) / n;
    r.tileMax = VelocityGrid(tw, th);
    for (uint32_t ty = 0; ty < th; ++ty) {
        for (uint32_t tx = 0; tx < tw; ++tx) {
            MaxTracker m;
            for (uint32_t y = ty * n; y < std::min(h, (ty + 1) * n); ++y)
                for (uint32_t x = tx * n; x < std::min(w, (tx + 1) * n); ++x) m.offer(r.radiusPx.at(x, y));
            r.tileMax.at(tx, ty) = m.best;
        }
    }

    // Pass 3: neighbour max over the tiles within the radius whose velocity reaches the centre
    // tile (clipped at the grid's edge).
    r.neighborMax = VelocityGrid(tw, th);
    const int reach = shared::mbNeighborReachTiles(int(p.radiusPx), int(n));
    for (int ty = 0; ty < int(th); ++ty) {
        for (int tx = 0; tx < int(tw); ++tx) {
            MaxTracker m;
            for (int dy = -reach; dy <= reach; ++dy)
                for (int dx = -reach; dx <= reach; ++dx) {
                    const int qx = tx + dx, qy = ty + dy;
                    if (qx < 0 || qy < 0 || qx >= int(tw) || qy >= int(th)) continue;
                    const std::array<double, 2>& v = r.tileMax.at(uint32_t(qx), uint32_t(qy));
                    if (shared::mbNeighborReaches(dx, dy, glm::dvec2(v[0], v[1]), int(n))) m.offer(v);
                }
            r.neighborMax.at(uint32_t(tx), uint32_t(ty)) = m.best;
        }
    }

    // Pass 4: reconstruction.
    r.color = ColorGrid(w, h);
    for (int y = 0; y < int(h); ++y) {
        for (int x = 0; x < int(w); ++x) {
            const std::array<double, 4> colorC = shared::sfxColor(color.at(uint32_t(x), uint32_t(y)));  // sfx_shared.h
            const std::array<double, 2> vN = r.neighborMax.at(uint32_t(x) / n, uint32_t(y) / n);
            if (std::sqrt(length2(vN)) < double(shared::SFX_MB_STILL_PX)) {
                r.color.at(uint32_t(x), uint32_t(y)) = colorC;
                ++r.stillPixels;
                continue;
            }
            const std::array<double, 2> vC = r.radiusPx.at(uint32_t(x), uint32_t(y));
            const double zC = depth.at(uint32_t(x), uint32_t(y));
            const double speedC = std::sqrt(length2(vC));
            const double speedN = std::sqrt(length2(vN));
            const bool table = candidate.ditherPairs || candidate.jitterAlways;
            const double jitter = mbJitter(x, y, table ? 4 : int(p.jitterSize));
            const double stepsN = shared::mbTexelSteps(glm::dvec2(vN[0], vN[1]));
            const int pairs = candidate.ditherPairs ? std::clamp(int(std::floor(stepsN + 0.5 + jitter)), 1, int(p.pairs))
                                                    : mbActivePairs(stepsN, int(p.pairs));
            std::array<double, 4> sum{}, hiddenSum{};
            double total = 0, window = 0, hiddenWeight = 0, hiddenNear = 0;
            int lastOffset[2][2] = {{0, 0}, {0, 0}};  // per side, the previous pair's texel offset (repeated texels, sfx_shared_mb.h)
            for (int i = 0; i < pairs; ++i) {
                const std::array<double, 2> v = mbPairUsesCentre(i, speedC, speedN) ? vC : vN;
                const double speedV = std::sqrt(length2(v));
                const double inverseWidth = shared::mbInverseRampWidth(speedV, pairs, double(p.radiusPx));
                for (double side : {1.0, -1.0}) {
                    const double t = candidate.jitterAlways ? side * std::min((i + 1.0 + side * jitter) / pairs, 1.0)
                                                            : mbSampleT(i, pairs, jitter, side, speedV);
                    const int ox = int(roundAway(t * v[0])), oy = int(roundAway(t * v[1]));
                    int* last = lastOffset[side > 0 ? 0 : 1];
                    const bool repeat = shared::mbRepeatsTexel(i, ox, oy, last[0], last[1]);
                    last[0] = ox, last[1] = oy;
                    if (repeat) {
                        ++r.repeatedSamples;
                        continue;
                    }
                    const int qx = std::clamp(x + ox, 0, int(w) - 1), qy = std::clamp(y + oy, 0, int(h) - 1);
                    if (qx != x + ox || qy != y + oy) ++r.samplesOutside;
                    const double dist = std::hypot(double(qx - x), double(qy - y));
                    r.maxSampleOffsetPx = std::max(r.maxSampleOffsetPx, dist);
                    const double speedS = std::sqrt(length2(r.radiusPx.at(uint32_t(qx), uint32_t(qy))));
                    const double zS = depth.at(uint32_t(qx), uint32_t(qy));
                    const double wS = mbSampleWeight(zC, zS, speedC, speedS, dist, p.softDepthExtent, inverseWidth);
                    window += shared::mbSpread(dist, speedV, inverseWidth);
                    const std::array<double, 4>& rawS = color.at(uint32_t(qx), uint32_t(qy));
                    if (!shared::sfxColorIsFinite(rawS)) continue;  // never spread (sfx_shared.h)
                    const std::array<double, 4> colorS = shared::sfxColor(rawS);
                    double wShown = wS;
                    if (candidate.hiddenNearExponent > 0) {
                        const double hidden = std::clamp(2.0 * (zS - zC) / p.softDepthExtent, 0.0, 1.0) *
                            shared::mbBackgroundShare(zC, zS, p.softDepthExtent) * shared::mbSpread(dist, speedC, inverseWidth);
                        const double near = hidden * std::pow(std::max(dist, 1.0), -candidate.hiddenNearExponent);
                        for (int c = 0; c < 4; ++c) hiddenSum[c] += colorS[c] * near;
                        hiddenWeight += hidden, hiddenNear += near, wShown -= hidden;
                    }
                    for (int c = 0; c < 4; ++c) sum[c] += colorS[c] * wShown;
                    total += wS;
                }
            }
            if (hiddenNear > 0)
                for (int c = 0; c < 4; ++c) sum[c] += hiddenSum[c] * (hiddenWeight / hiddenNear);
            const double wC = mbCentreShare(p.centreWeight, total, window);
            for (int c = 0; c < 4; ++c) sum[c] += colorC[c] * wC;
            total += wC;
            std::array<double, 4>& out = r.color.at(uint32_t(x), uint32_t(y));
            for (int c = 0; c < 4; ++c) out[c] = sum[c] / total;
        }
    }
    return r;
}

VelocityGrid cameraVelocity(const Grid& linearDepth, const glm::dmat4& projection, const CameraMotion& camera) {
    const uint32_t w = linearDepth.width, h = linearDepth.height;
    const glm::dmat4 reprojection = camera.previousViewProjection * glm::inverse(camera.currentViewProjection);
    VelocityGrid out(w, h);
    for (uint32_t y = 0; y < h; ++y) {
        for (uint32_t x = 0; x < w; ++x) {
            const glm::dvec2 v = shared::mbCameraVelocity(glm::dvec2(x + 0.5, y + 0.5), 2.0 / glm::dvec2(w, h), glm::dvec2(w, h),
                                                          linearDepth.at(x, y), projection[2][2], projection[3][2], reprojection);
            out.at(x, y) = {v.x, v.y};
        }
    }
    return out;
}

SceneFrame MotionScene::render(double t) const {
    SceneFrame f;
    f.color = ColorGrid(width, height, {0, 0, 0, 1});
    f.depth = Grid(width, height, double(shared::SFX_SKY_DEPTH));
    f.velocity = VelocityGrid(width, height);
    f.layer.assign(size_t(width) * height, -1);
    for (uint32_t y = 0; y < height; ++y) {
        for (uint32_t x = 0; x < width; ++x) {
            for (size_t i = 0; i < layers.size(); ++i) {
                const SceneLayer& L = layers[i];
                if (L.depth >= f.depth.at(x, y)) continue;
                // Layer-local coordinates of this pixel centre at time t.
                const double lx = x + 0.5 - (L.centre[0] + L.velocityPx[0] * t);
                const double ly = y + 0.5 - (L.centre[1] + L.velocityPx[1] * t);
                bool inside = true;
                if (L.shape == SceneLayer::Shape::Rect) inside = std::fabs(lx) < L.halfSize[0] && std::fabs(ly) < L.halfSize[1];
                if (L.shape == SceneLayer::Shape::Disc) inside = lx * lx + ly * ly < L.halfSize[0] * L.halfSize[0];
                if (!inside) continue;
                bool useB = false;
                if (L.cell > 0) {
                    const long cx = long(std::floor(lx / L.cell)), cy = long(std::floor(ly / L.cell));
                    useB = ((cx + cy) & 1) != 0;
                }
                f.color.at(x, y) = useB ? L.colorB : L.colorA;
                f.depth.at(x, y) = L.depth;
                f.velocity.at(x, y) = L.velocityPx;
                f.layer[size_t(y) * width + x] = int(i);
            }
        }
    }
    return f;
}

ColorGrid shutterAverage(uint32_t width, uint32_t height, uint32_t instants, const std::function<SceneFrame(double)>& render) {
    ColorGrid sum(width, height);
    for (uint32_t i = 0; i < instants; ++i) {
        const SceneFrame f = render((i + 0.5) / instants - 0.5);
        for (size_t p = 0; p < sum.values.size(); ++p)
            for (int c = 0; c < 4; ++c) sum.values[p][c] += f.color.values[p][c] / instants;
    }
    return sum;
}

ColorGrid MotionScene::groundTruth(uint32_t instants) const {
    return shutterAverage(width, height, instants, [this](double t) { return render(t); });
}

std::vector<bool> movingSilhouetteMask(const SceneFrame& frame, const MotionScene& scene, uint32_t radius) {
    const uint32_t w = scene.width, h = scene.height;
    auto moving = [&](int layer) {
        return layer >= 0 && (scene.layers[size_t(layer)].velocityPx[0] != 0 || scene.layers[size_t(layer)].velocityPx[1] != 0);
    };
    std::vector<bool> edge(size_t(w) * h, false), mask(size_t(w) * h, false);
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) {
            const int a = frame.layer[size_t(y) * w + x];
            const int right = x + 1 < w ? frame.layer[size_t(y) * w + x + 1] : a;
            const int down = y + 1 < h ? frame.layer[size_t(y + 1) * w + x] : a;
            if ((a != right && (moving(a) || moving(right))) || (a != down && (moving(a) || moving(down)))) edge[size_t(y) * w + x] = true;
        }
    const int r = int(radius);
    for (int y = 0; y < int(h); ++y)
        for (int x = 0; x < int(w); ++x) {
            if (!edge[size_t(y) * w + size_t(x)]) continue;
            for (int dy = -r; dy <= r; ++dy)
                for (int dx = -r; dx <= r; ++dx) {
                    const int qx = x + dx, qy = y + dy;
                    if (qx >= 0 && qy >= 0 && qx < int(w) && qy < int(h)) mask[size_t(qy) * w + size_t(qx)] = true;
                }
        }
    return mask;
}

}  // namespace sfx::reference
