#include "sfx/reference/ao_reference.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "ao_horizon_reference.hpp"
#include "sfx_shared_ao_horizon.h"

namespace sfx::reference {
namespace {

using glm::dvec3;
namespace sh = sfx::shared;

double saturate(double v) { return std::clamp(v, 0.0, 1.0); }

bool isSky(double z, double maxDepth) { return !(z < maxDepth); }

// The pixel a tap at distance rho in direction d lands on, decided in float by the shaders' own
// sh::aoTap (sfx_shared_ao.h, "Where a tap lands"), with the MIP level it reads.
AoTap tapAt(uint32_t x, uint32_t y, float rho, sh::vec2 d, uint32_t w, uint32_t h, int level) {
    const sh::ivec2 q = sh::aoTap(sh::ivec2{int(x), int(y)}, rho, d, sh::ivec2{int(w), int(h)});
    return AoTap{q.x, q.y, level};
}

// Where the pixels of a pass lie in the full-size image: themselves, or at half size each
// texel's full-size source pixel (sh::aoFullResPixel), whose centre its position is.
struct PixelMap {
    bool half = false;
    int fullWidth = 0, fullHeight = 0;
    sh::ivec2 source(int x, int y) const { return half ? sh::aoFullResPixel(sh::ivec2{x, y}, sh::ivec2{fullWidth, fullHeight}) : sh::ivec2{x, y}; }
};

dvec3 positionAt(const DepthReconstruction& rec, const PixelMap& map, int x, int y, double z) {
    const sh::ivec2 q = map.source(x, y);
    sh::dvec3 p = sh::reconstructViewPosition(double(q.x) + 0.5, double(q.y) + 0.5, z, rec.projInfo);
    return dvec3(p.x, p.y, p.z);
}
dvec3 positionAt(const DepthReconstruction& rec, int x, int y, double z) { return positionAt(rec, PixelMap{}, x, y, z); }

}  // namespace

double aoFinishVisibility(double occlusion, double contrast) { return std::pow(std::max(0.0, 1.0 - occlusion), contrast); }

std::vector<AoTap> aoTaps(const AoConfig& c, const DepthReconstruction& rec, uint32_t w, uint32_t h, uint32_t x, uint32_t y, double z) {
    std::vector<AoTap> taps;
    const int rotation = sh::aoRotationIndex(int(x), int(y));
    // The float values the shader receives: AoParams' radius and pixels per unit, the depth texel.
    float screenRadius = sh::aoScreenRadius(float(c.radius), float(rec.pixelsPerUnitAtUnitDepth), float(z));
    switch (c.technique) {
        case AoTechnique::Alchemy:
            for (uint32_t i = 0; i < c.samples; ++i) {
                const float rho = sh::aoDiskTapRadius(int(i), int(c.samples), screenRadius);
                taps.push_back(tapAt(x, y, rho, sh::aoTapDirection(sh::aoAlchemyTurnsQ16(int(i)), rotation), w, h, 0));
            }
            break;
        case AoTechnique::Scalable: {
            if (c.maxRadiusPx > 0) screenRadius = std::min(screenRadius, float(c.maxRadiusPx));
            const uint32_t offsets = c.mirrored ? c.samples / 2 : c.samples;
            const int halfStep = sh::aoSpiralHalfStepQ16(c.spiralTurns, c.samples, c.mirrored);
            for (uint32_t i = 0; i < offsets; ++i) {
                const float hPx = sh::aoSpiralTapRadius(int(i), int(offsets), screenRadius);
                const sh::vec2 d = sh::aoTapDirection(sh::aoSpiralTurnsQ16(int(i), halfStep), rotation);
                int level = 0;
                if (c.depthMipLevels > 1 && hPx >= 1.0f)
                    level = std::clamp(sh::aoFloorLog2(hPx) - int(sh::SFX_AO_MIP_LEVEL_OFFSET), 0, int(c.depthMipLevels) - 1);
                taps.push_back(tapAt(x, y, hPx, d, w, h, level));
                if (c.mirrored) taps.push_back(tapAt(x, y, hPx, sh::vec2{-d.x, -d.y}, w, h, level));
            }
            break;
        }
        case AoTechnique::Crease: {
            const float stride = sh::aoCreaseStride(screenRadius);  // once per pixel, as ao_crease.frag
            for (int j = 0; j < sh::SFX_AO_CREASE_HALF_TAPS; ++j)
                for (int half = 0; half < 2; ++half) {
                    if (!sh::aoCreaseTakesHalf(int(c.samples), half, sh::aoCreaseParity(int(x), int(y)))) continue;
                    const auto o = half == 0 ? sh::SFX_AO_CREASE_HALF_0[j] : sh::SFX_AO_CREASE_HALF_1[j];
                    taps.push_back(tapAt(x, y, stride, sh::vec2{float(o.x), float(o.y)}, w, h, 0));
                }
            break;
        }
        case AoTechnique::Horizon: {
            // Per slice, per step, the + side's sample then the - side's (ao_horizon.frag's order).
            const int slices = int(c.horizon.slices), steps = int(c.horizon.steps);
            const uint32_t hash = sh::aoRotationHash(int(x), int(y));
            for (int i = 0; i < slices; ++i) {
                const sh::vec2 d = sh::aoTapDirection(sh::aoHorizonSliceTurnsQ16(i, slices), rotation);
                const int jitter = sh::aoHorizonJitterIndex(hash, i);
                for (int j = 0; j < steps; ++j) {
                    const float rho = sh::aoHorizonStepRadius(j, steps, jitter, screenRadius);
                    int level = 0;
                    if (c.depthMipLevels > 1)
                        level = std::clamp(sh::aoFloorLog2(rho) - int(sh::SFX_AO_MIP_LEVEL_OFFSET), 0, int(c.depthMipLevels) - 1);
                    taps.push_back(tapAt(x, y, rho, d, w, h, level));
                    taps.push_back(tapAt(x, y, rho, sh::vec2{-d.x, -d.y}, w, h, level));
                }
            }
            break;
        }
    }
    return taps;
}

double aoTapTerm(const AoConfig& c, double vv, double vn, double z) {
    switch (c.technique) {
        case AoTechnique::Alchemy: return sh::aoAlchemyTerm(vv, vn, z, c.radius, c.bias, c.epsilon);
        case AoTechnique::Scalable: return sh::aoScalableTerm(vv, vn, c.radius, c.bias, c.epsilon);
        case AoTechnique::Crease: {
            const AoCreaseConfig& k = c.crease;
            return sh::aoCreaseTerm(vv, vn, double(k.range), double(k.minimumCrease), double(k.bias), c.epsilon);
        }
        case AoTechnique::Horizon: return 0.0;  // horizons are not a sum of terms: reference::detail::horizonVisibility
    }
    return 0.0;
}

double aoOcclusionFromSum(const AoConfig& c, double sum, double z) {
    switch (c.technique) {
        // The falloff length u of the paper's g(t) is taken as r, so that the result is
        // scale-invariant (epsilon is relative to r^2 for the same reason).
        case AoTechnique::Alchemy: return 2.0 * c.intensity * c.radius / double(c.samples) * sum;
        case AoTechnique::Scalable: return sh::aoScalableOcclusion(sum, c.intensity, int(c.samples), c.sumExponent);
        case AoTechnique::Crease: {
            const AoCreaseConfig& k = c.crease;
            const double invFade = std::isinf(k.fadeEnd) ? 0.0 : 1.0 / (double(k.fadeEnd) - double(k.fadeStart));
            const double fade = 1.0 - saturate((z - double(k.fadeStart)) * invFade);
            return sh::aoCreaseOcclusion(sum, int(c.samples), c.intensity, double(k.averager), fade);
        }
        // The sum is the mean visibility over the slices.
        case AoTechnique::Horizon: return c.intensity * (1.0 - sum);
    }
    return 0.0;
}

glm::dvec3 viewPosition(const AoInput& in, uint32_t x, uint32_t y) { return positionAt(in.reconstruction, int(x), int(y), in.linearDepth.at(x, y)); }

namespace {

std::vector<dvec3> mappedNormalsFromDepth(const Grid& d, const DepthReconstruction& rec, const PixelMap& map) {
    std::vector<dvec3> out(size_t(d.width) * d.height, dvec3(0, 0, 1));
    // The rule of sfx_shared_ao.h: every depth read as sfxLinearDepthOrFar makes it.
    auto depth = [&](int x, int y) { return sh::sfxLinearDepthOrFar(d.at(uint32_t(x), uint32_t(y)), rec.maxDepth); };
    auto pos = [&](int x, int y) { return positionAt(rec, map, x, y, depth(x, y)); };
    const int w = int(d.width), h = int(d.height);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const double z = depth(x, y);
            const dvec3 C = pos(x, y);
            dvec3 dx(1, 0, 0), dy(0, 1, 0);
            if (w > 1) {
                const double zl = x > 0 ? depth(x - 1, y) : 0.0, zr = x < w - 1 ? depth(x + 1, y) : 0.0;
                dx = sh::aoNormalUsesNext(x, w, zl, zr, z) ? pos(x + 1, y) - C : C - pos(x - 1, y);
            }
            if (h > 1) {
                const double zd = y > 0 ? depth(x, y - 1) : 0.0, zu = y < h - 1 ? depth(x, y + 1) : 0.0;
                dy = sh::aoNormalUsesNext(y, h, zd, zu, z) ? pos(x, y + 1) - C : C - pos(x, y - 1);
            }
            out[size_t(y) * d.width + size_t(x)] = sh::aoFacingNormal(dx, dy, C);
        }
    }
    return out;
}

}  // namespace

std::vector<glm::dvec3> normalsFromDepth(const Grid& d, const DepthReconstruction& rec) { return mappedNormalsFromDepth(d, rec, PixelMap{}); }

Grid linearDepthOrFar(const Grid& linearDepth, double maxDepth) {
    Grid out = linearDepth;
    for (double& z : out.values) z = sh::sfxLinearDepthOrFar(z, maxDepth);
    return out;
}

namespace {

// The obscurance of one pass over its depth d (already through linearDepthOrFar): at full size
// (map.half false) or half size, where positions come from each texel's full-size source pixel,
// host normals (full size, may be empty) are read there and screen radii are in half-size
// pixels (rec.pixelsPerUnitAtUnitDepth halved by the caller).
// With `bent` (Horizon), the pass's bent normals too (sky (0, 0, 1), its length infinite).
Grid rawVisibilityOfPass(const Grid& d, const std::vector<dvec3>& hostNormals, const DepthReconstruction& rec, const PixelMap& map, const AoConfig& c,
                         BentNormals* bent = nullptr) {
    // Host normals follow the rule of sfx_shared_ao.h: an unusable one (zero, NaN, infinite)
    // falls back to the derived normal of its pixel.
    std::vector<dvec3> normals = mappedNormalsFromDepth(d, rec, map);
    if (!hostNormals.empty())
        for (uint32_t y = 0; y < d.height; ++y)
            for (uint32_t x = 0; x < d.width; ++x) {
                const sh::ivec2 q = map.source(int(x), int(y));
                const uint32_t fullWidth = map.half ? uint32_t(map.fullWidth) : d.width;
                const dvec3 n = sh::aoHostNormalOrZero(hostNormals[size_t(q.y) * fullWidth + size_t(q.x)]);
                if (n != dvec3(0.0)) normals[size_t(y) * d.width + x] = n;
            }
    std::vector<Grid> pyramid;
    const bool readsMip = c.technique == AoTechnique::Scalable || c.technique == AoTechnique::Horizon;
    if (readsMip) pyramid = depthPyramid(d, std::max(c.depthMipLevels, 1u));
    const detail::HorizonPass horizonPass{c, pyramid, [&](int px, int py, double pz) { return positionAt(rec, map, px, py, pz); }, rec.projInfo,
                                          float(rec.pixelsPerUnitAtUnitDepth)};
    Grid out(d.width, d.height, 1.0);
    if (bent) {
        bent->normals.assign(size_t(d.width) * d.height, dvec3(0.0, 0.0, 1.0));
        bent->vectorLength.assign(size_t(d.width) * d.height, std::numeric_limits<double>::infinity());
        bent->resolveLength.assign(size_t(d.width) * d.height, 1.0);
    }
    for (uint32_t y = 0; y < d.height; ++y) {
        for (uint32_t x = 0; x < d.width; ++x) {
            const double z = d.at(x, y);
            if (isSky(z, rec.maxDepth)) continue;
            const dvec3 C = positionAt(rec, map, int(x), int(y), z);
            const dvec3 n = normals[size_t(y) * d.width + x];
            double sum = 0;
            if (c.technique == AoTechnique::Horizon) {
                dvec3 vector(0.0);
                sum = detail::horizonVisibility(horizonPass, int(x), int(y), z, C, n, bent ? &vector : nullptr);
                if (bent) {
                    const size_t i = size_t(y) * d.width + x;
                    bent->normals[i] = sh::aoHorizonBentNormal(vector, n);
                    bent->vectorLength[i] = glm::length(vector);
                }
                out.at(x, y) = saturate(aoFinishVisibility(aoOcclusionFromSum(c, sum, z), c.contrast));
                continue;
            }
            for (const AoTap& t : aoTaps(c, rec, d.width, d.height, x, y, z)) {
                // A Scalable tap may read a coarse level's depth; its position is its own pixel.
                const Grid& g = readsMip ? pyramid[size_t(t.level)] : d;
                const uint32_t mx = std::min(uint32_t(t.x) >> t.level, g.width - 1);
                const uint32_t my = std::min(uint32_t(t.y) >> t.level, g.height - 1);
                const dvec3 v = positionAt(rec, map, t.x, t.y, g.at(mx, my)) - C;
                sum += aoTapTerm(c, glm::dot(v, v), glm::dot(v, n), z);
            }
            const double v = aoFinishVisibility(aoOcclusionFromSum(c, sum, z), c.contrast);
            out.at(x, y) = saturate(v);
        }
    }
    return out;
}

// The pass's blur: the two separable passes, or Crease's two-blur look.
Grid blurOfPass(const Grid& raw, const Grid& d, double maxDepth, const AoConfig& c) {
    if (c.blurRadius == 0) return raw;
    const int r = int(c.blurRadius);
    Grid wide = bilateralBlurPass(bilateralBlurPass(raw, d, maxDepth, r, 1, 0), d, maxDepth, r, 0, 1);
    if (c.technique != AoTechnique::Crease) return wide;
    const int rm = std::max(1, r / 2);
    Grid moderate = bilateralBlurPass(bilateralBlurPass(raw, d, maxDepth, rm, 1, 0), d, maxDepth, rm, 0, 1);
    Grid out(raw.width, raw.height, 1.0);
    for (size_t i = 0; i < out.values.size(); ++i) {
        const double occ = 0.5 *
            (double(shared::SFX_AO_CREASE_WIDE_GAIN) * (1.0 - wide.values[i]) +
             double(shared::SFX_AO_CREASE_MODERATE_GAIN) * (1.0 - moderate.values[i]));
        out.values[i] = saturate(1.0 - occ);
    }
    return out;
}

}  // namespace

Grid rawVisibility(const AoInput& in, const AoConfig& c) {
    const Grid d = linearDepthOrFar(in.linearDepth, in.reconstruction.maxDepth);
    return rawVisibilityOfPass(d, in.normals, in.reconstruction, PixelMap{}, c);
}

Grid halfSizeDepth(const Grid& linearDepth) {
    Grid out(std::max(1u, linearDepth.width / 2), std::max(1u, linearDepth.height / 2));
    const sh::ivec2 fullSize{int(linearDepth.width), int(linearDepth.height)};
    for (uint32_t y = 0; y < out.height; ++y)
        for (uint32_t x = 0; x < out.width; ++x) {
            const sh::ivec2 s = sh::aoFullResPixel(sh::ivec2{int(x), int(y)}, fullSize);
            out.at(x, y) = linearDepth.at(uint32_t(s.x), uint32_t(s.y));
        }
    return out;
}

namespace {

// The upsample's weights applied to one channel: visibility (saturated, sky 1) or a bent
// normal's component (sky `skyValue`, not saturated).
Grid upsampleChannel(const Grid& halfValues, const Grid& halfDepth, const Grid& fullDepth, double maxDepth, double skyValue, bool saturated) {
    Grid out(fullDepth.width, fullDepth.height, skyValue);
    const int hw = int(halfValues.width), hh = int(halfValues.height);
    for (uint32_t y = 0; y < out.height; ++y) {
        for (uint32_t x = 0; x < out.width; ++x) {
            const double z0 = sh::sfxLinearDepthOrFar(fullDepth.at(x, y), maxDepth);
            if (isSky(z0, maxDepth)) continue;
            const int bx = sh::aoUpsampleBase(int(x)), by = sh::aoUpsampleBase(int(y));
            const double ux = sh::aoUpsampleUpperWeight(int(x)), uy = sh::aoUpsampleUpperWeight(int(y));
            double acc = 0, wsum = 0, nearestAo = 1, nearestGap = sh::SFX_AO_UPSAMPLE_NO_GAP;
            const double invTolerance = sh::aoUpsampleInvTolerance(z0);
            for (int j = 0; j < 2; ++j)
                for (int i = 0; i < 2; ++i) {  // the shader's order: ties keep the first
                    const uint32_t qx = uint32_t(std::clamp(bx + i, 0, hw - 1)), qy = uint32_t(std::clamp(by + j, 0, hh - 1));
                    const double zq = sh::sfxLinearDepthOrFar(halfDepth.at(qx, qy), maxDepth);
                    const double a = halfValues.at(qx, qy);
                    const double bilinear = (i == 1 ? ux : 1.0 - ux) * (j == 1 ? uy : 1.0 - uy);
                    const double w = sh::aoUpsampleWeight(bilinear, zq, z0, invTolerance);
                    acc += w * a;
                    wsum += w;
                    const double gap = std::abs(zq - z0);
                    if (gap < nearestGap) {
                        nearestGap = gap;
                        nearestAo = a;
                    }
                }
            const double v = sh::aoUpsampleResolve(acc, wsum, nearestAo);
            out.at(x, y) = saturated ? saturate(v) : v;
        }
    }
    return out;
}

}  // namespace

Grid depthAwareUpsample(const Grid& halfVisibility, const Grid& halfDepth, const Grid& fullDepth, double maxDepth) {
    return upsampleChannel(halfVisibility, halfDepth, fullDepth, maxDepth, 1.0, true);
}

Grid bilateralBlurPass(const Grid& vis, const Grid& d, double maxDepth, int radius, int dx, int dy) {
    Grid out(vis.width, vis.height, 1.0);
    for (uint32_t y = 0; y < vis.height; ++y) {
        for (uint32_t x = 0; x < vis.width; ++x) {
            const double z0 = d.at(x, y);
            if (isSky(z0, maxDepth)) {
                out.at(x, y) = vis.at(x, y);
                continue;
            }
            double acc = 0, wsum = 0;
            for (int k = -radius; k <= radius; ++k) {
                const int qx = int(x) + k * dx, qy = int(y) + k * dy;
                if (qx < 0 || qy < 0 || qx >= int(vis.width) || qy >= int(vis.height)) continue;
                const double zq = d.at(uint32_t(qx), uint32_t(qy));
                const double w = sh::aoBlurGaussian(k, radius) * sh::aoBlurEdgeWeight(zq, z0);
                acc += w * vis.at(uint32_t(qx), uint32_t(qy));
                wsum += w;
            }
            out.at(x, y) = acc / wsum;  // the centre's own weight is 1: wsum > 0
        }
    }
    return out;
}

Grid ambientVisibility(const AoInput& in, const AoConfig& c) {
    const double maxDepth = in.reconstruction.maxDepth;
    const Grid d = linearDepthOrFar(in.linearDepth, maxDepth);
    if (!c.halfResolution) return blurOfPass(rawVisibilityOfPass(d, in.normals, in.reconstruction, PixelMap{}, c), d, maxDepth, c);
    // Half resolution: the same passes on the half-size depth, then the upsample.
    const Grid dh = halfSizeDepth(d);
    DepthReconstruction halfRec = in.reconstruction;
    halfRec.pixelsPerUnitAtUnitDepth *= 0.5;
    const PixelMap map{true, int(d.width), int(d.height)};
    const Grid half = blurOfPass(rawVisibilityOfPass(dh, in.normals, halfRec, map, c), dh, maxDepth, c);
    return depthAwareUpsample(half, dh, d, maxDepth);
}

namespace {

Grid component(const std::vector<dvec3>& v, uint32_t w, uint32_t h, int axis) {
    Grid g(w, h);
    for (size_t i = 0; i < v.size(); ++i) g.values[i] = v[i][axis];
    return g;
}

// The smallest of `g` over the (2r + 1)-wide box around each texel (the blur's footprint).
Grid boxMin(const Grid& g, int r) {
    Grid out = g;
    for (uint32_t y = 0; y < g.height; ++y)
        for (uint32_t x = 0; x < g.width; ++x)
            for (int j = -r; j <= r; ++j)
                for (int i = -r; i <= r; ++i) {
                    const int qx = int(x) + i, qy = int(y) + j;
                    if (qx >= 0 && qy >= 0 && qx < int(g.width) && qy < int(g.height))
                        out.at(x, y) = std::min(out.at(x, y), g.at(uint32_t(qx), uint32_t(qy)));
                }
    return out;
}

// The smallest of half-size `g` over the 2x2 texels the upsample reads for each full-size pixel.
Grid upsampleMin(const Grid& g, uint32_t w, uint32_t h) {
    Grid out(w, h);
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) {
            double m = std::numeric_limits<double>::infinity();
            for (int j = 0; j < 2; ++j)
                for (int i = 0; i < 2; ++i) {
                    const int qx = std::clamp(sh::aoUpsampleBase(int(x)) + i, 0, int(g.width) - 1);
                    const int qy = std::clamp(sh::aoUpsampleBase(int(y)) + j, 0, int(g.height) - 1);
                    m = std::min(m, g.at(uint32_t(qx), uint32_t(qy)));
                }
            out.at(x, y) = m;
        }
    return out;
}

}  // namespace

BentNormals rawBentNormals(const AoInput& in, const AoConfig& c) {
    const Grid d = linearDepthOrFar(in.linearDepth, in.reconstruction.maxDepth);
    BentNormals bent;
    (void)rawVisibilityOfPass(d, in.normals, in.reconstruction, PixelMap{}, c, &bent);
    return bent;
}

BentNormals ambientBentNormals(const AoInput& in, const AoConfig& c) {
    const double maxDepth = in.reconstruction.maxDepth;
    const Grid d = linearDepthOrFar(in.linearDepth, maxDepth);
    const Grid dh = c.halfResolution ? halfSizeDepth(d) : d;
    DepthReconstruction rec = in.reconstruction;
    if (c.halfResolution) rec.pixelsPerUnitAtUnitDepth *= 0.5;
    const PixelMap map{c.halfResolution, int(d.width), int(d.height)};
    BentNormals raw;
    (void)rawVisibilityOfPass(dh, in.normals, rec, map, c, &raw);
    // Each component through the visibility's blur weights (the blur's sky passes (0, 0, 1)
    // through) and upsample weights, then renormalised once, as the last pass does.
    Grid channels[3];
    const int r = int(c.blurRadius);
    for (int a = 0; a < 3; ++a) {
        channels[a] = component(raw.normals, dh.width, dh.height, a);
        if (r > 0) channels[a] = bilateralBlurPass(bilateralBlurPass(channels[a], dh, maxDepth, r, 1, 0), dh, maxDepth, r, 0, 1);
        if (c.halfResolution) channels[a] = upsampleChannel(channels[a], dh, d, maxDepth, a == 2 ? 1.0 : 0.0, false);
    }
    Grid lengths(dh.width, dh.height);
    lengths.values = raw.vectorLength;
    if (r > 0) lengths = boxMin(lengths, r);
    if (c.halfResolution) lengths = upsampleMin(lengths, d.width, d.height);
    BentNormals out;
    out.normals.resize(size_t(d.width) * d.height);
    out.resolveLength.resize(out.normals.size());
    out.vectorLength = lengths.values;
    for (size_t i = 0; i < out.normals.size(); ++i) {
        const dvec3 v(channels[0].values[i], channels[1].values[i], channels[2].values[i]);
        out.normals[i] = sh::aoBentNormalResolve(v);
        out.resolveLength[i] = glm::length(v);
    }
    return out;
}

}  // namespace sfx::reference
