// Ambient obscurance constants and sample patterns, shared by the ao_*.frag shaders and the
// CPU reference (sdk/src/reference/ao_reference.cpp): one definition, so they cannot drift.
// Same dialect rules as sfx_shared.h (the common subset of GLSL 450 and C++20).
#ifndef SFX_SHARED_AO_H
#define SFX_SHARED_AO_H

#include "sfx_shared.h"

#ifdef __cplusplus
#include <glm/glm.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
namespace sfx::shared {
using glm::cross;
using glm::dot;
using glm::length;
using std::abs;
using std::clamp;
using std::exp;
using std::floor;
using std::max;
using std::pow;
using std::sqrt;
#define SFX_AO_VEC3 glm::dvec3
#else
#define SFX_AO_VEC3 vec3
#endif

// ---- Tap directions ------------------------------------------------------------------------
// Every tap direction is one of 256 unit vectors, k / 256 of a turn, read from a table of the
// first quarter turn and turned by exact quarter turns: no sin or cos in any pass. Vulkan and
// GL ES bound sin and cos only to 2^-11 absolute inside [-pi, pi] and not at all outside it, and
// an angle such as i golden angles plus the pixel's rotation reaches 160 radians: drivers moved
// taps by hundredths of a pixel and across pixel edges. With the table a tap's offset is its
// radius times a constant, which the GPU and the reference round alike to within an ulp.
// Angles are integers in 1/65536 of a turn (Q16), so both languages compute the same index.
SFX_ARRAY_BEGIN(vec2, SFX_AO_QUARTER_TURN, 64)
    SFX_VEC2(1.0, 0.0), SFX_VEC2(0.999698818, 0.024541229), SFX_VEC2(0.99879545, 0.0490676761), SFX_VEC2(0.997290432, 0.0735645667),
    SFX_VEC2(0.99518472, 0.0980171412), SFX_VEC2(0.992479563, 0.122410677), SFX_VEC2(0.989176512, 0.146730468), SFX_VEC2(0.985277653, 0.170961887),
    SFX_VEC2(0.980785251, 0.195090324), SFX_VEC2(0.975702107, 0.219101235), SFX_VEC2(0.970031261, 0.242980182), SFX_VEC2(0.963776052, 0.266712755),
    SFX_VEC2(0.956940353, 0.290284663), SFX_VEC2(0.949528158, 0.313681751), SFX_VEC2(0.941544056, 0.336889863), SFX_VEC2(0.932992816, 0.359895051),
    SFX_VEC2(0.923879504, 0.382683426), SFX_VEC2(0.914209783, 0.405241311), SFX_VEC2(0.903989315, 0.427555084), SFX_VEC2(0.893224299, 0.449611336),
    SFX_VEC2(0.881921291, 0.471396744), SFX_VEC2(0.870086968, 0.492898196), SFX_VEC2(0.857728601, 0.514102757), SFX_VEC2(0.84485358, 0.534997642),
    SFX_VEC2(0.831469595, 0.555570245), SFX_VEC2(0.817584813, 0.575808167), SFX_VEC2(0.803207517, 0.59569931), SFX_VEC2(0.78834641, 0.615231574),
    SFX_VEC2(0.773010433, 0.634393275), SFX_VEC2(0.757208824, 0.653172851), SFX_VEC2(0.740951121, 0.671558976), SFX_VEC2(0.724247098, 0.689540565),
    SFX_VEC2(0.707106769, 0.707106769), SFX_VEC2(0.689540565, 0.724247098), SFX_VEC2(0.671558976, 0.740951121), SFX_VEC2(0.653172851, 0.757208824),
    SFX_VEC2(0.634393275, 0.773010433), SFX_VEC2(0.615231574, 0.78834641), SFX_VEC2(0.59569931, 0.803207517), SFX_VEC2(0.575808167, 0.817584813),
    SFX_VEC2(0.555570245, 0.831469595), SFX_VEC2(0.534997642, 0.84485358), SFX_VEC2(0.514102757, 0.857728601), SFX_VEC2(0.492898196, 0.870086968),
    SFX_VEC2(0.471396744, 0.881921291), SFX_VEC2(0.449611336, 0.893224299), SFX_VEC2(0.427555084, 0.903989315), SFX_VEC2(0.405241311, 0.914209783),
    SFX_VEC2(0.382683426, 0.923879504), SFX_VEC2(0.359895051, 0.932992816), SFX_VEC2(0.336889863, 0.941544056), SFX_VEC2(0.313681751, 0.949528158),
    SFX_VEC2(0.290284663, 0.956940353), SFX_VEC2(0.266712755, 0.963776052), SFX_VEC2(0.242980182, 0.970031261), SFX_VEC2(0.219101235, 0.975702107),
    SFX_VEC2(0.195090324, 0.980785251), SFX_VEC2(0.170961887, 0.985277653), SFX_VEC2(0.146730468, 0.989176512), SFX_VEC2(0.122410677, 0.992479563),
    SFX_VEC2(0.0980171412, 0.99518472), SFX_VEC2(0.0735645667, 0.997290432), SFX_VEC2(0.0490676761, 0.99879545), SFX_VEC2(0.024541229, 0.999698818)
SFX_ARRAY_END
// The unit vector at k / 256 of a turn (k taken modulo 256).
SFX_FN vec2 aoDirection(int k) {
    vec2 v = SFX_AO_QUARTER_TURN[k & 63];
    int quarter = (k >> 6) & 3;
    if ((quarter & 1) != 0) v = SFX_VEC2(-v.y, v.x);
    if ((quarter & 2) != 0) v = SFX_VEC2(-v.x, -v.y);
    return v;
}
// A tap at turnsQ16 (of 65536), turned by the pixel's rotation (of 256, aoRotationIndex).
SFX_FN vec2 aoTapDirection(int turnsQ16, int rotation) { return aoDirection(((turnsQ16 + 128) >> 8) + rotation); }

// ---- Where a tap lands -----------------------------------------------------------------------
// Which pixel a tap reads is a discrete decision, so the reference (aoTaps) makes it with the
// shader's own single-precision operations on the float values the shader receives. Vulkan
// rounds products and sums correctly, and `precise` keeps a driver from fusing them into one
// rounding; only the division by depth and the square root may differ by the few ulps the
// specification allows. The offset is floored on its own, then added to the integer pixel:
// floor(p + 0.5 + o) in float would round to the ulp of p (2^-10 px at 8192 pixels), while
// floor(0.5 + o) rounds to the ulp of o. The MIP level a Scalable tap reads is the highest set
// bit of its distance's integer part, exactly floor(log2(h)) without a log2 whose result a driver
// may round up across the integer just below a power of two.
// These are float in both languages (not SFX_REAL): the reference runs the shader's operations.
SFX_FN float aoScreenRadius(float radius, float pixelsPerUnit, float z) { return radius * pixelsPerUnit / z; }
// Alchemy's tap i of samples: sqrt((i + 0.5) / samples) of the screen radius.
SFX_FN float aoDiskTapRadius(int i, int samples, float screenRadius) { return sqrt((float(i) + 0.5f) / float(samples)) * screenRadius; }
// Scalable's tap i of offsets: (i + 0.5) / offsets of the screen radius.
SFX_FN float aoSpiralTapRadius(int i, int offsets, float screenRadius) { return (float(i) + 0.5f) / float(offsets) * screenRadius; }
// The tap's pixel relative to its centre's.
SFX_FN ivec2 aoTapStep(float rho, vec2 d) {
    SFX_PRECISE float ox = rho * d.x;
    SFX_PRECISE float oy = rho * d.y;
    SFX_PRECISE float tx = 0.5f + ox;
    SFX_PRECISE float ty = 0.5f + oy;
    return SFX_IVEC2(int(floor(tx)), int(floor(ty)));
}
// The pixel that tap lands on from pixel p, clamped to a size.x x size.y image (texelFetch
// outside the image is undefined): what every AO pass and the reference read.
SFX_FN ivec2 aoTap(ivec2 p, float rho, vec2 d, ivec2 size) {
    ivec2 s = aoTapStep(rho, d);
    return SFX_IVEC2(clamp(p.x + s.x, 0, size.x - 1), clamp(p.y + s.y, 0, size.y - 1));
}
// floor(log2(h)) for h >= 1 (distances past 65536 pixels count as 65536: no level is that deep).
#ifdef __cplusplus
inline int aoFloorLog2(float h) { return int(std::bit_width(uint32_t(std::min(h, 65536.0f)))) - 1; }
#else
int aoFloorLog2(float h) { return findMSB(int(min(h, 65536.0))); }
#endif

// ---- Spiral taps (Scalable AO) -----------------------------------------------------------
// Tap i of N: alpha = (i + 0.5) / N, screen radius alpha * R, angle alpha * turns (a turn being
// 2 pi) plus the pixel's rotation.
// 7 turns for 9 taps is the Scalable Ambient Obscurance reference's choice (a prime: no two
// taps line up). The current tier uses 2 offsets, each also negated (4 taps): with an integer
// number of turns both offsets would lie on one line through the centre; 1.5 turns puts them
// at 135 and 45 degrees, so the 4 taps form an X at two radii.
SFX_CONST(float, SFX_AO_SPIRAL_TURNS_SPIRAL, 7.0)
SFX_CONST(float, SFX_AO_SPIRAL_TURNS_MIRRORED, 1.5)
// A tap at screen distance h reads depth MIP level clamp(floor(log2(h)) - Q, 0, levels - 1).
SFX_CONST(int, SFX_AO_MIP_LEVEL_OFFSET, 3)
// Tap i's angle, (2i + 1) half steps of turns / N each: the half step, in Q16 modulo a turn, is
// what the host gives the shader (AoParams::spiralHalfStepQ16; aoSpiralHalfStepQ16 below).
SFX_FN int aoSpiralTurnsQ16(int i, int halfStepQ16) { return ((2 * i + 1) * halfStepQ16) & 0xFFFF; }
#ifdef __cplusplus
// samples taps, in mirrored pairs (N = samples / 2 offsets) or not (N = samples).
inline int32_t aoSpiralHalfStepQ16(double turns, uint32_t samples, bool mirrored) {
    const double offsets = double(mirrored ? samples / 2 : samples);
    return int32_t(std::llround(turns / (2.0 * offsets) * 65536.0) & 0xFFFF);
}
#endif

// ---- Alchemy disk pattern -----------------------------------------------------------------
// Sample i of s lies at radius sqrt((i + 0.5) / s) * R (uniform density in the projected disk)
// and angle i golden angles plus the pixel's rotation (a Vogel spiral: no two samples share a
// direction). The golden angle, 1 - 1 / golden ratio of a turn, is 25033 / 65536 (Q16).
SFX_CONST(int, SFX_AO_GOLDEN_ANGLE_Q16, 25033)
SFX_FN int aoAlchemyTurnsQ16(int i) { return (i * SFX_AO_GOLDEN_ANGLE_Q16) & 0xFFFF; }

// ---- Crease shading: the 24 taps of the 11x11 stippled diamond ------------------------------
// The pixels (dx, dy) with |dx| + |dy| in {2, 4}: every other pixel of the diamond of
// half-width 5 (a checkerboard stipple), the centre excluded. 8 taps on ring 2, 16 on ring 4.
// Held as two halves of 12, each point-symmetric (neither leans to one side): half 0 the axis
// taps of ring 2 and every other tap of ring 4 from (4, 0), half 1 the diagonals of ring 2 and the
// rest of ring 4. The whole diamond takes both (tap 2j from half 0, 2j + 1 from half 1: each ring
// in angular order). The current tier (TierProfile::aoCreaseTaps = 12) takes one half per pixel,
// chosen by the pixel's checkerboard parity, so neighbours take complementary halves and the
// blur that follows sees all 24 at half the fetches.
SFX_CONST(int, SFX_AO_CREASE_TAPS, 24)
SFX_CONST(int, SFX_AO_CREASE_HALF_TAPS, 12)
SFX_ARRAY_BEGIN(ivec2, SFX_AO_CREASE_HALF_0, 12)
    SFX_IVEC2(2, 0), SFX_IVEC2(0, 2), SFX_IVEC2(-2, 0), SFX_IVEC2(0, -2),
    SFX_IVEC2(4, 0), SFX_IVEC2(2, 2), SFX_IVEC2(0, 4), SFX_IVEC2(-2, 2),
    SFX_IVEC2(-4, 0), SFX_IVEC2(-2, -2), SFX_IVEC2(0, -4), SFX_IVEC2(2, -2)
SFX_ARRAY_END
SFX_ARRAY_BEGIN(ivec2, SFX_AO_CREASE_HALF_1, 12)
    SFX_IVEC2(1, 1), SFX_IVEC2(-1, 1), SFX_IVEC2(-1, -1), SFX_IVEC2(1, -1),
    SFX_IVEC2(3, 1), SFX_IVEC2(1, 3), SFX_IVEC2(-1, 3), SFX_IVEC2(-3, 1),
    SFX_IVEC2(-3, -1), SFX_IVEC2(-1, -3), SFX_IVEC2(1, -3), SFX_IVEC2(3, -1)
SFX_ARRAY_END
// The diamond's offsets are in units of a stride that follows the radius: its outer ring (4
// strides) lies at the pixel's screen radius, as Alchemy's disk reaches it, and no closer than
// one pass pixel per stride. A stride fixed in pixels would tie a crease's world extent to its
// distance from the camera instead of the radius the truth measures within (docs/ao_families.md).
// A tap lands where aoTap puts it, offset times stride.
SFX_FN float aoCreaseStride(float screenRadius) { return max(1.0f, screenRadius * 0.25f); }
// Scalable's radius clamp (TierProfile::aoScalableMaxRadiusPx) is output pixels at this many rows.
SFX_CONST(float, SFX_AO_REFERENCE_ROWS, 720.0)
// The half (0 or 1) a pixel takes when it takes 12 taps.
SFX_FN int aoCreaseParity(int x, int y) { return (x + y) & 1; }
// Whether a pixel of that parity takes half `which` (0 or 1) of the diamond with `taps` taps per pixel.
SFX_FN bool aoCreaseTakesHalf(int taps, int which, int parity) { return taps >= SFX_AO_CREASE_TAPS || which == parity; }
// Occlusion from the sum of a pixel's tap terms: the sum scaled to the full 24 taps (so the look
// means the same at 12), divided by the averager, faded with distance.
SFX_FN SFX_REAL aoCreaseOcclusion(SFX_REAL sum, int taps, SFX_REAL intensity, SFX_REAL averager, SFX_REAL fade) {
    return intensity * sum * (SFX_REAL(SFX_AO_CREASE_TAPS) / SFX_REAL(taps)) / averager * fade;
}
// The article's look: two blurs of the raw result, a wide one that lowers intensity and a
// moderate one (half the width) that raises it, averaged. Gains on occlusion.
SFX_CONST(float, SFX_AO_CREASE_WIDE_GAIN, 0.6)
SFX_CONST(float, SFX_AO_CREASE_MODERATE_GAIN, 1.4)

// ---- Bilateral blur ------------------------------------------------------------------------
// A neighbour's weight falls linearly to 0 as its depth differs from the centre's by this
// fraction of the centre's depth: occlusion is never carried across a depth discontinuity.
SFX_CONST(float, SFX_AO_BLUR_DEPTH_TOLERANCE, 0.05)
SFX_CONST(int, SFX_AO_MAX_BLUR_RADIUS, 8)
// Most taps a GPU pass takes (what settings validation allows); the CPU reference has no limit.
SFX_CONST(int, SFX_AO_MAX_SAMPLES, 64)
// Multilayer AO (AoSettings.depthLayers): opaque depth layers a tap tests, layer 0 included.
// Each tap keeps the largest per-tap term over the layers at its pixel (reference::multilayerVisibility).
SFX_CONST(int, SFX_AO_MAX_DEPTH_LAYERS, 4)

// ---- Per-tap terms (SFX_FN / SFX_REAL: double in the reference, float in the shaders) -------
// v is the tap's view position minus the centre's, n the centre's normal; vv = dot(v, v) and
// vn = dot(v, n). Every guard is written as "not inside", so NaN contributes nothing too.

// Alchemy (McGuire et al. 2011, eq. 10) for one sample: counted only inside the sphere of radius
// r (the Heaviside of eq. 9); z * bias is z_C * beta, a bias growing with distance. epsilon is
// relative to r^2, so the term is scale-invariant.
SFX_FN SFX_REAL aoAlchemyTerm(SFX_REAL vv, SFX_REAL vn, SFX_REAL z, SFX_REAL r, SFX_REAL bias, SFX_REAL epsilon) {
    if (!(vv < r * r)) return 0.0;
    return max(0.0, vn - z * bias) / (vv + epsilon * r * r);
}

// Scalable AO (Bukowski et al. 2012) for one tap: linear distance falloff times the biased
// cosine. A tap on the centre itself (vv within epsilon r^2, including 0) has no direction: 0.
SFX_FN SFX_REAL aoScalableTerm(SFX_REAL vv, SFX_REAL vn, SFX_REAL r, SFX_REAL bias, SFX_REAL epsilon) {
    if (!(vv > epsilon * r * r)) return 0.0;
    SFX_REAL len = sqrt(vv);
    return max(1.0 - len / r, 0.0) * max(vn / len - bias, 0.0);
}

// Scalable AO's occlusion from the sum of its per-tap terms over `samples` taps: the normalised
// sum raised to `exponent`. The course squares it (exponent 2), which makes weak occlusion
// quadratically fainter: against ray-traced truth that left creases and contacts too bright
// (docs/trade.md), so the exponent is part of the calibrated look (AoLook::sumExponent).
SFX_FN SFX_REAL aoScalableOcclusion(SFX_REAL sum, SFX_REAL intensity, int samples, SFX_REAL exponent) {
    SFX_REAL a = max(2.0 * intensity / SFX_REAL(samples) * sum, 0.0);
    return a > 0.0 ? pow(a, exponent) : 0.0;
}

// Crease shading (Fox & Compton 2007) for one tap: how far the normal faces the tap beyond the
// minimum crease, scaled by bias and saturated, attenuated linearly to 0 at `range`. A tap
// clamped onto the centre (dist^2 within epsilon range^2) adds nothing.
SFX_FN SFX_REAL aoCreaseTerm(SFX_REAL vv, SFX_REAL vn, SFX_REAL range, SFX_REAL minimumCrease, SFX_REAL bias, SFX_REAL epsilon) {
    if (!(vv > epsilon * range * range)) return 0.0;
    SFX_REAL dist = sqrt(vv);
    SFX_REAL contrib = clamp((vn / dist - minimumCrease) * bias, 0.0, 1.0);
    SFX_REAL atten = 1.0 - clamp(dist / range, 0.0, 1.0);
    return contrib * atten;
}

// Bilateral blur: a Gaussian of sigma (radius + 1) / 2 over the tap index k, times an edge
// weight falling linearly to 0 as the neighbour's depth zq departs from the centre's z0 by
// SFX_AO_BLUR_DEPTH_TOLERANCE of z0.
SFX_FN SFX_REAL aoBlurGaussian(int k, int radius) {
    SFX_REAL sigma = 0.5 * SFX_REAL(radius + 1);
    return exp(-SFX_REAL(k * k) / (2.0 * sigma * sigma));
}
SFX_FN SFX_REAL aoBlurEdgeWeight(SFX_REAL zq, SFX_REAL z0) {
    return max(0.0, 1.0 - abs(zq - z0) / (SFX_REAL(SFX_AO_BLUR_DEPTH_TOLERANCE) * z0));
}

// ---- AO at half resolution ---------------------------------------------------------------
// Half-size pixel q holds the depth of full-size pixel depthMipSource(q) (the rotated grid of
// depth MIP level 1, clamped to the full image): a real sample, not an average, so the view
// position the obscurance reconstructs there is exact (aoFullResPixel) and surfaces stay flat.
#ifdef __cplusplus
inline constexpr ivec2 aoFullResPixel(ivec2 q, ivec2 fullSize) {
    ivec2 s = depthMipSource(q);
    return ivec2{std::min(s.x, fullSize.x - 1), std::min(s.y, fullSize.y - 1)};
}
#else
ivec2 aoFullResPixel(ivec2 q, ivec2 fullSize) { return min(depthMipSource(q), fullSize - 1); }
#endif
// The depth-aware upsample to full size: each full-size pixel blends the 2x2 half-size texels
// around its centre (bilinear weights, x / 2 - 0.25 in half-size texels) times a depth weight
// falling linearly to 0 as a texel's depth zq departs from the full-size depth z0 by
// SFX_AO_UPSAMPLE_DEPTH_TOLERANCE of z0, so occlusion never bleeds across a silhouette. The
// texel of nearest depth is always added with weight SFX_AO_UPSAMPLE_NEAREST_WEIGHT: where every
// texel lies across an edge (thin features) it alone decides, and the blend stays continuous.
SFX_CONST(float, SFX_AO_UPSAMPLE_DEPTH_TOLERANCE, 0.1)
SFX_CONST(float, SFX_AO_UPSAMPLE_NEAREST_WEIGHT, 1.0e-3)
// The nearest-depth search starts above any gap (every depth it compares is finite, at most
// the far plane), so the first texel is taken and ties keep the first.
SFX_CONST(float, SFX_AO_UPSAMPLE_NO_GAP, 3.0e38)
// Along one axis, full-size index x: the lower half-size texel (may be -1: clamp it) and the
// bilinear weight of the upper one (the lower one gets 1 minus it).
SFX_FN int aoUpsampleBase(int x) { return (x + 1) / 2 - 1; }
SFX_FN SFX_REAL aoUpsampleUpperWeight(int x) { return (x % 2) == 1 ? 0.25 : 0.75; }
// The depth weight's scale, 1 / (tolerance * z0): once per pixel, so that each of the four taps
// multiplies instead of dividing.
SFX_FN SFX_REAL aoUpsampleInvTolerance(SFX_REAL z0) { return 1.0 / (SFX_REAL(SFX_AO_UPSAMPLE_DEPTH_TOLERANCE) * z0); }
SFX_FN SFX_REAL aoUpsampleWeight(SFX_REAL bilinear, SFX_REAL zq, SFX_REAL z0, SFX_REAL invTolerance) {
    return bilinear * max(0.0, 1.0 - abs(zq - z0) * invTolerance);
}
// The blend of the four taps: sum of w * ao, plus the nearest texel's ao at the fixed weight.
SFX_FN SFX_REAL aoUpsampleResolve(SFX_REAL weightedSum, SFX_REAL weightSum, SFX_REAL nearestAo) {
    SFX_REAL e = SFX_REAL(SFX_AO_UPSAMPLE_NEAREST_WEIGHT);
    return (weightedSum + e * nearestAo) / (weightSum + e);
}

// ---- Normal from depth (no host normals) --------------------------------------------------
// The one rule of the shaders (aoDerivedNormal below) and the reference (normalsFromDepth):
// - Every depth it reads, the centre's and each neighbour's, goes through sfxLinearDepthOrFar
//   first, so a non-finite (NaN, +-inf), non-positive or overflowing neighbour is sky: the far
//   plane, maxDepth. Positions, and so the normal, are then always finite.
// - On each axis the tangent runs to the neighbour whose depth is closer to the centre's; ties
//   take the lower index; at the image border the only in-bounds one. The next neighbour is
//   taken only when its difference is smaller by more than SFX_AO_NORMAL_TIE of the previous
//   one's; anything closer is a tie. The pixel on a crease, its two neighbours mirrored about
//   it, has differences equal in float and a rounding apart in double, and a strict comparison
//   let that rounding pick the side (and the normal).
//   A sky neighbour is thus used only when the other is as far from the centre or absent.
// - normal = normalize(cross(dx, dy)), facing the camera; a zero cross product gives +z.
// aoNormalUsesNext: along an axis of `size` pixels, at index i, whether the next neighbour
// (i + 1) is the one, given the (clamped) depths zPrev, zNext and the centre's z.
SFX_CONST(float, SFX_AO_NORMAL_TIE, 0.0009765625)  // 2^-10, far above float's 2^-24
SFX_FN bool aoNormalUsesNext(int i, int size, SFX_REAL zPrev, SFX_REAL zNext, SFX_REAL z) {
    return i == 0 || (i < size - 1 && abs(zNext - z) < abs(zPrev - z) * (1.0 - SFX_REAL(SFX_AO_NORMAL_TIE)));
}
// The unit normal of tangents dx, dy at view position C, turned to face the eye (C is the ray).
SFX_FN SFX_AO_VEC3 aoFacingNormal(SFX_AO_VEC3 dx, SFX_AO_VEC3 dy, SFX_AO_VEC3 C) {
    SFX_AO_VEC3 n = cross(dx, dy);
    SFX_REAL len = length(n);
    n = len > 0.0 ? n / len : SFX_AO_VEC3(0.0, 0.0, 1.0);
    return dot(n, C) > 0.0 ? -n : n;
}

// ---- Host normals ----------------------------------------------------------------------------
// A host normal is used when all its components are finite and its length is at least
// SFX_AO_MIN_NORMAL_LENGTH; it is then normalised. Otherwise (zero-length, NaN, +-infinity)
// the pixel falls back to the normal derived from depth (above). The length is taken of n
// divided by its largest component, so a huge finite normal neither overflows nor turns NaN.
// aoHostNormalOrZero returns the unit normal, or (0, 0, 0) for "derive it instead".
SFX_CONST(float, SFX_AO_MIN_NORMAL_LENGTH, 1.0e-3)
SFX_FN SFX_AO_VEC3 aoHostNormalOrZero(SFX_AO_VEC3 n) {
    if (!sfxIsFinite(n.x) || !sfxIsFinite(n.y) || !sfxIsFinite(n.z)) return SFX_AO_VEC3(0.0, 0.0, 0.0);
    SFX_REAL m = max(max(abs(n.x), abs(n.y)), abs(n.z));
    if (m == 0.0) return SFX_AO_VEC3(0.0, 0.0, 0.0);
    SFX_AO_VEC3 u = n / m;
    SFX_REAL len = length(u);
    if (len < SFX_REAL(SFX_AO_MIN_NORMAL_LENGTH) / m) return SFX_AO_VEC3(0.0, 0.0, 0.0);
    return u / len;
}

// ---- Per-pixel rotation --------------------------------------------------------------------
// An integer hash of the pixel turns its whole pattern by (hash & 255) / 256 of a turn, the same
// on the GPU and in the reference (aoTapDirection adds it to each tap's direction index).
#ifdef __cplusplus
inline constexpr uint32_t aoRotationHash(int x, int y) {
    uint32_t h = (uint32_t(x) * 73856093u) ^ (uint32_t(y) * 19349663u);
    h ^= h >> 13;
    h *= 0x5bd1e995u;
    h ^= h >> 15;
    return h;
}
inline constexpr int aoRotationIndex(int x, int y) { return int(aoRotationHash(x, y) & 0xFFu); }
#else
uint aoRotationHash(ivec2 p) {
    uint h = (uint(p.x) * 73856093u) ^ (uint(p.y) * 19349663u);
    h ^= h >> 13;
    h *= 0x5bd1e995u;
    h ^= h >> 15;
    return h;
}
int aoRotationIndex(ivec2 p) { return int(aoRotationHash(p) & 0xFFu); }
#endif

// ---- Depth packed in two 8-bit channels (current tier, RGBA8 AO target) --------------------
// A 16-bit float of the project's own, stored in b (high byte) and a (low): r = z / keyBase;
// r >= 1 keeps 5 exponent bits (2^0 to 2^30) and the top 11 mantissa bits, rounded, so the
// relative error is at most 2^-12 (2.4e-4); r < 1 is stored as round(r * 2048), an error of at
// most keyBase / 4096; code 0xFFFF is sky. keyBase is the near plane, raised where needed so that
// every depth short of SFX_SKY_DEPTH has a code (r < 2^31). Both ways are integer operations:
// the log2 key it replaces cost a log2 per pixel and an exp2 per tap, about 32 instructions per
// 8 pixels each on lavapipe (the blur and upsample read a key per tap; docs/trade.md).
SFX_CONST(float, SFX_AO_KEY_MAX_RATIO, 2147483648.0)  // 2^31: above the largest code's value
SFX_FN SFX_REAL aoDepthKeyBase(SFX_REAL nearDepth) {
    return max(nearDepth, SFX_REAL(SFX_SKY_DEPTH) / SFX_REAL(SFX_AO_KEY_MAX_RATIO));
}
#ifndef __cplusplus
// z: a surface's depth (below maxDepth, so below SFX_SKY_DEPTH).
// Signed integers throughout: x86 without AVX-512 converts floats to and from unsigned ones in
// several instructions each, to and from signed ones in one (codes fit either).
vec2 aoPackDepthKey(float z, float keyBase) {
    float r = z / keyBase;
    // Adding half of the dropped mantissa rounds; a carry moves into the exponent as it should.
    int code = r < 1.0 ? int(r * 2048.0 + 0.5) : ((floatBitsToInt(r) + 0x800) >> 12) - 0x3F000;
    code = min(code, 0xFFFE);
    return vec2(float(code >> 8), float(code & 0xFF)) / 255.0;
}
vec2 aoPackSkyKey() { return vec2(1.0); }
// The depth back (maxDepth for sky), as the passes compare it with their own.
float aoUnpackDepthKey(vec2 ba, float keyBase, float maxDepth) {
    ivec2 b = ivec2(ba * 255.0 + 0.5);  // non-negative: truncation rounds
    int code = (b.x << 8) | b.y;
    float r = code < 0x800 ? float(code) * (1.0 / 2048.0) : intBitsToFloat((code << 12) + 0x3F000000);
    return code == 0xFFFF ? maxDepth : r * keyBase;
}
#endif

// ---- Specialisation constants of the AO passes (layout(constant_id); the pipeline fixes them) --
// Every loop count and branch that is constant for an effect instance is one, never a uniform:
// lavapipe inlines uniforms that decide control flow and recompiles the shader each time they
// are bound (megabytes of resident memory per frame). Ids as plain macros, for both languages.
// The obscurance passes (ao_alchemy/ao_scalable/ao_crease/ao_horizon.frag):
#define SFX_AO_SC_SAMPLES 0        // taps (Alchemy, Scalable)
#define SFX_AO_SC_MIRRORED 1       // 1: Scalable taps come in mirrored pairs
#define SFX_AO_SC_MIP_LEVELS 2     // depth MIP levels Scalable reads (1: full resolution only)
#define SFX_AO_SC_NORMAL_SOURCE 3  // 0 derived from depth, 1 signed float, 2 unorm8
#define SFX_AO_SC_PACK_DEPTH 4     // where the depth for the blur and upsample goes (SFX_AO_DEPTH_IN_*)
#define SFX_AO_SC_CLAMP_RADIUS 5   // 1: the screen radius is clamped to maxRadiusPx
#define SFX_AO_SC_HALF_RES 6       // 1: half-size pass: positions and normals at aoFullResPixel
#define SFX_AO_SC_DEPTH_LAYERS 7   // opaque depth layers each tap tests (1: the first visible one only)
#define SFX_AO_SC_HORIZON_STEPS 8  // Horizon: depth samples per side of a slice (kAoSamples: its slices)
#define SFX_AO_SC_BENT_UNORM 9     // bent normal variants: 1 writes RGBA8 (xyz * 0.5 + 0.5), 0 signed float
// The bilateral blur (ao_blur.frag):
#define SFX_AO_SC_BLUR_RADIUS 0           // taps each side
#define SFX_AO_SC_BLUR_MODERATE_RADIUS 1  // Crease's second, moderate blur
#define SFX_AO_SC_BLUR_CREASE 2           // 1: also the moderate blur, blended in the final pass
#define SFX_AO_SC_BLUR_FINAL_PASS 3       // 0: horizontal into the intermediate, 1: vertical out
#define SFX_AO_SC_BLUR_KEEP_DEPTH 4       // 1: the vertical pass keeps the float depth (the upsample reads it)
#define SFX_AO_SC_BLUR_BENT_UNORM 5       // as SFX_AO_SC_BENT_UNORM, for the pass's bent normal target
// The upsample (ao_upsample.frag):
#define SFX_AO_SC_UPSAMPLE_DEPTH 0  // where the half-size depth comes from (SFX_AO_HALF_DEPTH_*)
#define SFX_AO_SC_UPSAMPLE_LINEARIZE 1  // 1: uDepth is the host's hardware depth: linearize on fetch
#define SFX_AO_SC_UPSAMPLE_BENT_UNORM 2  // as SFX_AO_SC_BENT_UNORM, for the host's bent normal target
// The half-size depth (ao_half_depth.frag):
#define SFX_AO_SC_HALF_DEPTH_LINEARIZE 0  // 1: uDepth is the host's hardware depth: linearize on fetch
// Where the obscurance pass puts the depth its readers need, when it writes the AO target (blur
// or half resolution). A depth in the target saves the blur and the upsample one fetch per tap,
// and fetches are what a fragment pass costs on CPU rasterisers (and bandwidth on GPUs).
#define SFX_AO_DEPTH_IN_NONE 0      // not written: the host's output (full resolution, no blur)
#define SFX_AO_DEPTH_IN_KEY_BA 1    // 16-bit log depth key in b and a (RGBA8 target, current tier)
#define SFX_AO_DEPTH_IN_FLOAT_G 2   // the linear depth itself in g (RG32F target, high tier)
#define SFX_AO_DEPTH_IN_FLOAT_B 3   // the linear depth in b (RGBA32F target, high tier crease: g
                                    // holds crease's moderate blur)
// The half-size depth the upsample weighs by (ao_upsample.frag). GL keeps one mip range per
// texture, so MIP level 1 is read through uDepth, not bound twice.
#define SFX_AO_HALF_DEPTH_TEXTURE 0  // uHalfDepth (the ao_half_depth pass, or level 0 of the half-size pyramid)
#define SFX_AO_HALF_DEPTH_SOURCE_G 2 // g of the half-size AO itself (SFX_AO_DEPTH_IN_FLOAT_G)
#define SFX_AO_HALF_DEPTH_SOURCE_B 3 // b of the half-size AO itself (SFX_AO_DEPTH_IN_FLOAT_B)
#define SFX_AO_HALF_DEPTH_SOURCE_KEY 4 // the key in b, a of the half-size AO (SFX_AO_DEPTH_IN_KEY_BA),
                                       // decoded as the blur decodes it

// ---- Uniform blocks of the AO passes (SFX_BLOCK: one declaration for GLSL and C++) ----------
// The obscurance passes (ao_alchemy/ao_scalable/ao_crease/ao_horizon.frag), filled by AmbientObscurance.
#if defined(__cplusplus) || defined(SFX_AO_PASS)
SFX_BLOCK(AoParams, 2)
    SFX_M_VEC4(projInfo)
    SFX_M_FLOAT(radius) SFX_M_FLOAT(intensity) SFX_M_FLOAT(contrast) SFX_M_FLOAT(bias)
    SFX_M_FLOAT(epsilon) SFX_M_FLOAT(pixelsPerUnit) SFX_M_FLOAT(maxRadiusPx) SFX_M_FLOAT(maxDepth)
    SFX_M_INT(fullWidth) SFX_M_INT(fullHeight)  // the full-size image (aoFullResPixel's clamp)
    SFX_M_INT(pad4) SFX_M_INT(pad5)  // counts: the constants above
    SFX_M_INT(spiralHalfStepQ16) SFX_M_FLOAT(keyBase) SFX_M_FLOAT(pad2) SFX_M_FLOAT(sumExponent)
    SFX_M_FLOAT(creaseRange) SFX_M_FLOAT(creaseBias) SFX_M_FLOAT(creaseAverager) SFX_M_FLOAT(creaseMinimum)
    SFX_M_FLOAT(fadeStart) SFX_M_FLOAT(invFadeRange) SFX_M_FLOAT(horizonThickness) SFX_M_FLOAT(horizonInvFalloffWidth)
SFX_BLOCK_END(params)
#endif
// The separable bilateral blur (ao_blur.frag, one direction per pass).
#if defined(__cplusplus) || defined(SFX_AO_BLUR_PASS)
SFX_BLOCK(BlurParams, 2)
    SFX_M_IVEC2(direction)
    SFX_M_INT(pad0) SFX_M_INT(pad1)  // radii and pass: the specialisation constants above
    SFX_M_INT(pad2) SFX_M_INT(pad3) SFX_M_INT(pad4) SFX_M_INT(pad5)
    SFX_M_FLOAT(maxDepth) SFX_M_FLOAT(keyBase) SFX_M_FLOAT(pad6) SFX_M_FLOAT(pad7)
SFX_BLOCK_END(params)
#endif
// The depth-aware upsample (ao_upsample.frag).
#if defined(__cplusplus) || defined(SFX_AO_UPSAMPLE_PASS)
SFX_BLOCK(UpsampleParams, 3)
    SFX_M_FLOAT(maxDepth) SFX_M_FLOAT(keyBase) SFX_M_FLOAT(pad0) SFX_M_FLOAT(pad2)  // key: as BlurParams
    SFX_M_FLOAT(ndcScale) SFX_M_FLOAT(denomOffset) SFX_M_FLOAT(numerator) SFX_M_FLOAT(pad1)  // LinearizeParams
SFX_BLOCK_END(params)
#endif
#ifdef __cplusplus
static_assert(sizeof(AoParams) == 112 && offsetof(AoParams, radius) == 16 && offsetof(AoParams, maxDepth) == 44 &&
              offsetof(AoParams, spiralHalfStepQ16) == 64 && offsetof(AoParams, fadeStart) == 96 && offsetof(AoParams, horizonThickness) == 104);
static_assert(sizeof(BlurParams) == 48 && offsetof(BlurParams, direction) == 0 && offsetof(BlurParams, maxDepth) == 32);
static_assert(sizeof(UpsampleParams) == 32);
#endif

#ifdef __cplusplus
}  // namespace sfx::shared
#endif

// ---- GLSL of the obscurance passes (ao_alchemy/ao_scalable/ao_crease.frag define SFX_AO_PASS) ----
#if !defined(__cplusplus) && defined(SFX_AO_PASS)
layout(set = 0, binding = 0) uniform sampler2D uDepth;    // linear depth (+ MIP levels for Scalable, high tier)
layout(set = 0, binding = 1) uniform sampler2D uNormals;  // host normals; the depth again when derived
// AoParams (binding 2) is declared above, with the C++ side.
layout(location = 0) out vec4 outAo;
// Defaults are placeholders: AmbientObscurance gives every one.
layout(constant_id = SFX_AO_SC_SAMPLES) const int kAoSamples = 1;
layout(constant_id = SFX_AO_SC_MIRRORED) const int kAoMirrored = 0;
layout(constant_id = SFX_AO_SC_MIP_LEVELS) const int kAoMipLevels = 1;
layout(constant_id = SFX_AO_SC_NORMAL_SOURCE) const int kAoNormalSource = 0;
layout(constant_id = SFX_AO_SC_PACK_DEPTH) const int kAoPackDepth = 0;
layout(constant_id = SFX_AO_SC_CLAMP_RADIUS) const int kAoClampRadius = 0;
layout(constant_id = SFX_AO_SC_HALF_RES) const int kAoHalfRes = 0;
layout(constant_id = SFX_AO_SC_DEPTH_LAYERS) const int kAoDepthLayers = 1;
layout(constant_id = SFX_AO_SC_HORIZON_STEPS) const int kAoHorizonSteps = 1;

// uDepth may be the host's linear depth itself (LinearDepth passing through): clamp on fetch.
// With a pyramid the level varies from pixel to pixel, and lavapipe samples at a per-pixel lod
// dearer than texelFetch fetches one (high-tier Scalable at 1280x720: 10 million instructions
// more); one level is read through sfxTexel.
float aoDepthAt(ivec2 q, int level) {
    float d = kAoMipLevels > 1 ? texelFetch(uDepth, q, level).r : sfxTexel(uDepth, q, 0).r;
    return sfxLinearDepthOrFar(d, params.maxDepth);
}
// The texel of MIP `level` under level-0 pixel q (in 0..size-1): the level's extent is size >>
// level, at least 1 (the Vulkan and GL rule), computed rather than queried: llvmpipe answers
// textureSize(uDepth, level) with another SIMD lane's level when the level varies per pixel.
ivec2 aoMipTexel(ivec2 q, int level, ivec2 size) { return min(q >> level, max(size >> level, ivec2(1)) - 1); }
float aoDepth(ivec2 q) { return sfxLinearDepthOrFar(sfxTexel(uDepth, q, 0).r, params.maxDepth); }
#ifdef SFX_AO_MULTILAYER  // generated from the tier table (TierProfile::aoMaxDepthLayers > 1)
// Opaque depth layers 1..3 (AoInputs.depthLayers): R32F linear depth at the AO size, full
// resolution only; a pixel without that layer holds 0 or the far plane (sky: its term is 0).
layout(set = 0, binding = 3) uniform sampler2D uDepthLayer1;
layout(set = 0, binding = 4) uniform sampler2D uDepthLayer2;
layout(set = 0, binding = 5) uniform sampler2D uDepthLayer3;
float aoLayerDepth(ivec2 q, int layer) {
    float d = layer == 1 ? sfxTexel(uDepthLayer1, q, 0).r : layer == 2 ? sfxTexel(uDepthLayer2, q, 0).r : sfxTexel(uDepthLayer3, q, 0).r;
    return sfxLinearDepthOrFar(d, params.maxDepth);
}
#endif
// At half size a texel's position is its full-size source pixel's (aoFullResPixel).
ivec2 aoSourcePixel(ivec2 q) { return kAoHalfRes != 0 ? aoFullResPixel(q, ivec2(params.fullWidth, params.fullHeight)) : q; }
vec3 aoPosition(ivec2 q, float z) { return reconstructViewPosition(vec2(aoSourcePixel(q)) + 0.5, z, params.projInfo); }

// Normal from depth by the rule above (aoDepth applies sfxLinearDepthOrFar to every fetch).
vec3 aoDerivedNormal(ivec2 p, vec3 C, float z, ivec2 size) {
    vec3 dx = vec3(1.0, 0.0, 0.0), dy = vec3(0.0, 1.0, 0.0);
    if (size.x > 1) {
        float zl = p.x > 0 ? aoDepth(p - ivec2(1, 0)) : 0.0, zr = p.x < size.x - 1 ? aoDepth(p + ivec2(1, 0)) : 0.0;
        dx = aoNormalUsesNext(p.x, size.x, zl, zr, z) ? aoPosition(p + ivec2(1, 0), zr) - C : C - aoPosition(p - ivec2(1, 0), zl);
    }
    if (size.y > 1) {
        float zd = p.y > 0 ? aoDepth(p - ivec2(0, 1)) : 0.0, zu = p.y < size.y - 1 ? aoDepth(p + ivec2(0, 1)) : 0.0;
        dy = aoNormalUsesNext(p.y, size.y, zd, zu, z) ? aoPosition(p + ivec2(0, 1), zu) - C : C - aoPosition(p - ivec2(0, 1), zd);
    }
    return aoFacingNormal(dx, dy, C);
}

vec3 aoNormal(ivec2 p, vec3 C, float z, ivec2 size) {
    if (kAoNormalSource != 0) {
        vec3 n = sfxTexel(uNormals, aoSourcePixel(p), 0).xyz;  // host normals are full size
        if (kAoNormalSource == 2) n = n * 2.0 - 1.0;
        n = aoHostNormalOrZero(n);  // the host-normal rule above
        if (n != vec3(0.0)) return n;
    }
    return aoDerivedNormal(p, C, z, size);
}

// Visibility out, with the depth where kAoPackDepth says (SFX_AO_DEPTH_IN_*). The packed key
// of sky is 1 exactly (surfaces stay below it), so the blur can tell sky apart; a float depth is
// z as every reader clamps it (sfxLinearDepthOrFar: sky is maxDepth), so it reads the same value
// it would fetch from the depth texture.
void aoWrite(float visibility, float z, bool sky) {
    float v = clamp(visibility, 0.0, 1.0);
    if (kAoPackDepth == SFX_AO_DEPTH_IN_KEY_BA) {
        outAo = vec4(v, v, sky ? aoPackSkyKey() : aoPackDepthKey(z, params.keyBase));
    } else if (kAoPackDepth == SFX_AO_DEPTH_IN_FLOAT_G) {
        outAo = vec4(v, z, 0.0, 1.0);
    } else if (kAoPackDepth == SFX_AO_DEPTH_IN_FLOAT_B) {
        outAo = vec4(v, v, z, 1.0);
    } else {
        outAo = vec4(v, v, v, 1.0);
    }
}
float aoFinish(float occlusion) { return pow(max(0.0, 1.0 - occlusion), params.contrast); }
#endif

#endif  // SFX_SHARED_AO_H
