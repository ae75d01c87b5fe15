// Motion blur pieces shared by the mb_*.frag shaders and the C++ CPU reference
// (sfx/reference/motion_blur_reference.hpp): the stored velocity, the jitter patterns, where
// samples go and how they are weighted. Both sides include this one file so they cannot drift.
// "The course" below is Bukowski, Hennessy, McGuire, Osman, "Scalable High Quality Motion Blur
// and Ambient Occlusion" (SIGGRAPH 2012); docs/algorithms.md restates it.
//
// Scalar code only, in the common subset of GLSL 450 and C++20. In C++ the functions take
// double (SFX_MB_REAL); in GLSL float. Include sfx_shared.h first: its macros are used here.
//
// Conventions (docs/motion_blur.md says the same at length):
// - Velocities are in pixels; x toward increasing column, y toward increasing memory row.
// - Inside the effect a velocity is the blur *radius* vector: half the displacement across the
//   shutter interval (the scene is rendered at mid-shutter, so a point smears v/2 either way).
// - Linear depth z is positive and grows away from the camera. A sample S is "in front of" the
//   centre C when z_S < z_C.
#ifndef SFX_SHARED_MB_H
#define SFX_SHARED_MB_H

#include "sfx_shared.h"

#ifdef __cplusplus
#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
namespace sfx::shared {
using glm::length;
using std::abs;
using std::ceil;
using std::clamp;
using std::floor;
using std::isinf;
using std::isnan;
using std::max;
using std::min;
#define SFX_MB_FN inline
#define SFX_MB_REAL double
// Vectors and matrices: glm's double types in C++ (the same constructors and operators as GLSL
// for what is used here; no swizzles), GLSL's own in shaders.
#define SFX_MB_VEC2 glm::dvec2
#define SFX_MB_VEC4 glm::dvec4
#define SFX_MB_MAT4 glm::dmat4
#else
#define SFX_MB_FN
#define SFX_MB_REAL float
#define SFX_MB_VEC2 vec2
#define SFX_MB_VEC4 vec4
#define SFX_MB_MAT4 mat4
#endif

// A neighbourhood velocity shorter than this (pixels) means nothing moves near the pixel: the
// reconstruction returns the input colour unchanged (the course's "branch on velocity").
SFX_CONST(float, SFX_MB_STILL_PX, 0.5)
// Packed depth is stored as an fp16 hi/lo pair; fp16 ends at 65504, so depth is clamped here.
// Anything this far is "very far" for the soft comparisons; sky (SFX_SKY_DEPTH) lands here too.
SFX_CONST(float, SFX_MB_MAX_PACKED_DEPTH, 65000.0)
// Reference resolution of the tier radii: TierProfile::mbMaxRadiusPx is pixels at 720 rows.
SFX_CONST(float, SFX_MB_REFERENCE_ROWS, 720.0)
// Largest radius (output pixels, after resolution scaling) the shaders loop over; with the
// tile edge it bounds what tile max reads (N x N texels, N at most the radius).
SFX_CONST(int, SFX_MB_MAX_RADIUS_LIMIT_PX, 64)
// Most tiles neighbour max looks out on each side; the tile is made larger where the radius
// would need more (a user radius far beyond the tile).
SFX_CONST(int, SFX_MB_MAX_NEIGHBOR_REACH, 4)
// Largest tap count (centre included) the reconstruction loop allows.
SFX_CONST(int, SFX_MB_MAX_TAPS, 31)

// 4x4 randomised jitter (high tier): the 16 stratified offsets (k + 0.5) / 16 - 0.5 in a fixed
// shuffled order, indexed by (y & 3) * 4 + (x & 3). Every 4x4 block uses each offset once.
SFX_ARRAY_BEGIN(float, SFX_MB_JITTER_4X4, 16)
    0.15625, -0.40625, 0.28125, -0.03125,
    -0.21875, 0.40625, -0.46875, 0.09375,
    0.46875, -0.09375, 0.21875, -0.34375,
    -0.28125, 0.03125, -0.15625, 0.34375
SFX_ARRAY_END

// Jitter of the sample positions at pixel (x, y), in [-0.5, 0.5): size 2 is the current tier's
// checkerboard (+-0.25 alternating), size 4 the table above.
SFX_MB_FN SFX_MB_REAL mbJitter(int x, int y, int size) {
    if (size == 2) return ((x + y) & 1) == 0 ? -0.25 : 0.25;
    return SFX_MB_REAL(SFX_MB_JITTER_4X4[(y & 3) * 4 + (x & 3)]);
}

// Camera-only velocity of the pixel centred at `pc` (memory rows: NDC y = -1 at row 0, hal.hpp)
// with linear depth z, in pixels across the shutter interval. ndcScale = 2 / (W, H), target =
// (W, H); clipA = P[2][2], clipB = P[3][2] of the current projection (clip z of view depth -z;
// clip w = z for a perspective looking down -z); reprojection = previous view-projection *
// inverse(current view-projection). A point behind the previous camera has no previous pixel: 0.
SFX_MB_FN SFX_MB_VEC2 mbCameraVelocity(SFX_MB_VEC2 pc, SFX_MB_VEC2 ndcScale, SFX_MB_VEC2 target, SFX_MB_REAL z,
                                       SFX_MB_REAL clipA, SFX_MB_REAL clipB, SFX_MB_MAT4 reprojection) {
    SFX_MB_VEC2 ndc = pc * ndcScale - 1.0;
    SFX_MB_VEC4 clip = SFX_MB_VEC4(ndc * z, clipA * (-z) + clipB, z);
    SFX_MB_VEC4 prev = reprojection * clip;
    if (!(prev.w > 1.0e-6)) return SFX_MB_VEC2(0.0);
    return (ndc - SFX_MB_VEC2(prev.x, prev.y) / prev.w) * 0.5 * target;
}

// The velocity rule of pass 1: the blur radius vector v (pixels, as float: the reference rounds
// its double to float first, as the shader holds it) clamped to length k in its own direction.
// - A NaN component: the pixel is still (0), rather than poisoning the neighbourhood.
// - An infinite component: length k along the signs of the infinite components (a finite
//   component vanishes beside an infinite one); (+inf, -inf) is the diagonal.
// - Finite: longer than k is scaled to k. The length is taken of v divided by its largest
//   component, so no value up to the float maximum overflows and nothing becomes NaN.
SFX_MB_FN SFX_MB_VEC2 mbClampVelocity(SFX_MB_VEC2 v, SFX_MB_REAL k) {
    if (isnan(v.x) || isnan(v.y)) return SFX_MB_VEC2(0.0);
    SFX_MB_VEC2 dir;
    if (isinf(v.x) || isinf(v.y)) {
        dir = SFX_MB_VEC2(isinf(v.x) ? (v.x > 0.0 ? 1.0 : -1.0) : 0.0, isinf(v.y) ? (v.y > 0.0 ? 1.0 : -1.0) : 0.0);
    } else {
        SFX_MB_REAL m = max(abs(v.x), abs(v.y));
        if (m == 0.0) return SFX_MB_VEC2(0.0);
        dir = v / m;  // largest component +-1: its length is in [1, sqrt 2]
        if (length(dir) <= k / m) return v;
    }
    return dir * (k / length(dir));
}

// The packed velocity keeps pixels, each component on fp16's grid: rounded here to the nearest
// value with 11 significant bits (ties away from zero; integer operations on the float's bits,
// the same in both languages), and below fp16's least normal (2^-14 px, far under
// SFX_MB_STILL_PX) zero. Every such value is exact in the RGBA16F and RG16F targets whatever
// their float-to-half rounding, which the APIs let go to nearest or toward zero (llvmpipe and
// lavapipe truncate: left to the target, a clamped 64 px velocity was stored 1/16 px short on
// every pixel and moved whole rows of taps), so both sides read back what was written. The
// step is relative (k/1024 px or finer below k/2, whatever the radius): a velocity is stored
// the same on every tier, so a blur both tiers' radii contain is reconstructed the same way.
SFX_MB_FN SFX_MB_REAL mbQuantizeVelocity(SFX_MB_REAL v) {
    SFX_UINT bits = floatBitsToUint(v);
    if ((bits & 0x7FFFFFFFu) < 0x38800000u) return 0.0;  // |v| < 2^-14
    return uintBitsToFloat((bits + 0x1000u) & 0xFFFFE000u);
}

// The squared length by which tile max and neighbour max rank velocities, in float on both
// sides. The components are on the fp16 grid, so each square is exact in float (22 significant
// bits) and only the sum rounds, once (a fused multiply-add rounds it the same): the shader and
// the reference rank alike, ties included.
#ifdef __cplusplus
SFX_MB_FN SFX_MB_REAL mbRankKey(SFX_MB_VEC2 v) { return double(float(v.x * v.x) + float(v.y * v.y)); }
#else
SFX_MB_FN SFX_MB_REAL mbRankKey(SFX_MB_VEC2 v) { return v.x * v.x + v.y * v.y; }
#endif

// The reconstruction after Jimenez, "Next Generation Post Processing in Call of Duty: Advanced
// Warfare" (2014), and Guertin, McGuire, Nowrouzezahrai, "A Fast and Stable Feature-Aware Motion
// Blur Filter" (2014); docs/algorithms.md restates it. Each sample's weight is the fraction of
// the shutter it stands for (at most 1), the output their average over the pair count with the
// centre filling what the samples leave, so a uniformly moving area gets a box filter over its
// blur length, the shape of the truth, and a still pixel beside a moving edge keeps the share of
// the shutter in which it is not covered.

// Texel steps of a velocity along its major axis, max(|v.x|, |v.y|) (the Chebyshev length): a
// line of that velocity passes through this many texel rows or columns on each side of the centre,
// one per step, however it leans. Exact on the stored grid (no square root), so both languages
// count the same. The Euclidean length says how far a point's blur reaches (mbSpread); this says
// how many texels lie along it.
SFX_MB_FN SFX_MB_REAL mbTexelSteps(SFX_MB_VEC2 v) { return max(abs(v.x), abs(v.y)); }

// Sample pairs used at a pixel: one per texel the blur along the neighbourhood velocity v_N passes
// through on each side, its texel steps (mbTexelSteps) rounded half away from zero as the sample
// offsets are, at most the tier's; so the last pair's offset along v_N is that count, and no
// texel is read twice. More pairs than those texels would weight some double: rounding up did,
// for every length just past an integer, and so did counting by the Euclidean length along a
// leaning velocity (|v_N| = 3.5 px at 9 degrees off the column crosses 3 rows, not 4, and a fourth
// pair read row 3 a second time at 0.84 of a full weight), and so did a count stepping at
// k + 0.49 (texel steps of 3.49-3.5 took 4 pairs whose last offset rounded to 3). The steps are on
// the velocity grid, where steps + 0.5 is exact in float and double alike.
SFX_MB_FN int mbActivePairs(SFX_MB_REAL stepsN, int pairs) { return clamp(int(floor(stepsN + 0.5)), 1, pairs); }

// Pair i of `pairs` sits at +t and -t' along one velocity of length `speed`:
//   t = (i + 1 + jitter * s) / pairs,   t' = (i + 1 - jitter * s) / pairs,   both at most 1.
// Without jitter the samples end on the blur's ends (t = 1), so with one texel between samples
// they read every texel of the blur once and the box filter is exact. Jitter only hides the
// steps between texels the samples skip, so its share s grows from 0 at one texel per sample to
// 1 at two or more: s = clamp(speed / pairs - 1, 0, 1). `side` is +1 or -1; the offset is
// side * t times the velocity, rounded half away from zero to a texel. The share keeps the
// Euclidean length: measured against the texel steps instead, a leaning blur longer than the
// tier's pairs got less jitter, and the held-out rotating and approaching families lost up to
// 0.07 dB at 24-40 px, the training families within 0.01 dB (docs/motion_blur.md).
SFX_MB_FN SFX_MB_REAL mbSampleT(int i, int pairs, SFX_MB_REAL jitter, SFX_MB_REAL side, SFX_MB_REAL speed) {
    SFX_MB_REAL share = clamp(speed / SFX_MB_REAL(pairs) - 1.0, 0.0, 1.0);
    return side * min((SFX_MB_REAL(i) + 1.0 + side * jitter * share) / SFX_MB_REAL(pairs), 1.0);
}
// Repeated texels: a sample whose texel offset (before clamping to the image) equals the previous
// pair's on the same side weighs 0, in the weights and in the window, so one texel's colour counts
// once where two adjacent stretches of the blur round onto it. Along a uniform blur it never
// happens (pair i reads texel i + 1). It happens where the pairs follow v_C, shorter than the v_N
// their count comes from: on a slow surface beside a fast one every short offset rounds onto the
// same texel or two (the centre itself among them), and their colour outweighed the fast
// surface's blur over the pixel; and where a pair along v_N and the next along a slightly shorter
// v_C end on the same texel. Only the previous pair: leaving out every earlier repeat as well
// scored lower on the rasterised families (docs/motion_blur.md). Pair i's offset (x, y) against
// the previous pair's on its side (lastX, lastY); pair 0 has none.
SFX_MB_FN bool mbRepeatsTexel(int i, int x, int y, int lastX, int lastY) { return i > 0 && x == lastX && y == lastY; }

// Which velocity a pair follows. Odd pairs follow the centre's own velocity v_C, even ones the
// neighbourhood's v_N (the course's alternation, hiding tile edges), except that a centre moving
// at least half as fast as v_N sends every pair along v_C: sampling along only the dominant
// direction misses the centre's own blur where objects cross. A still centre uses v_N only.
SFX_MB_FN bool mbPairUsesCentre(int i, SFX_MB_REAL centreSpeed, SFX_MB_REAL neighbourSpeed) {
    if (centreSpeed < SFX_MB_REAL(SFX_MB_STILL_PX)) return false;
    return (i & 1) == 1 || centreSpeed >= 0.5 * neighbourSpeed;
}

// Soft depth comparison: the share of sample S that is background to centre C, 1/2 when level,
// 1 when S is farther by half the extent or more, 0 when nearer by as much; the foreground share
// is one minus it, so the two always sum to 1.
SFX_MB_FN SFX_MB_REAL mbBackgroundShare(SFX_MB_REAL zC, SFX_MB_REAL zS, SFX_MB_REAL extent) {
    return clamp(0.5 + (zS - zC) / extent, 0.0, 1.0);
}
// Spread: how much of the stretch of blur a sample stands for lies within the reach of a point
// moving at `speed` (blur radius): a linear ramp centred on speed == dist, 1 / inverseWidth
// pixels wide (mbInverseRampWidth).
SFX_MB_FN SFX_MB_REAL mbSpread(SFX_MB_REAL dist, SFX_MB_REAL speed, SFX_MB_REAL inverseWidth) {
    return clamp((speed - dist) * inverseWidth + 0.5, 0.0, 1.0);
}

// The inverse width of the spread ramps of a pair of samples along a velocity of length `speed`
// (the one the pair follows), with `pairs` pairs under a blur radius `radius` (pixels).
// - With samples a texel apart the ramp is 1 px wide: offsets are whole texels and a texel's
//   centre reaches the next texel's centre half a pixel before the edge between them does, so
//   the ramp is centred there; it also keeps the weight continuous in the last bit of the fp16
//   velocity.
// - With samples farther apart, each stands for that stretch of the blur (speed / pairs) and
//   the ramp is as wide: a sample just inside the reach of an object's end weighs the part of
//   its stretch the object covers, not a whole sample (a 1 px ramp gave a thin post 15 px away,
//   whose blur reaches 15.5 px, a full twelfth of a pixel it covers for 2 % of the shutter).
// - Over the last pixel below the radius the ramp narrows to 1 px again (the inverse width rises
//   linearly): a velocity at the radius was clamped there (mbClampVelocity) and the true blurs
//   around it reach farther, past the window's end (measured, the wide ramp there took 0.1-0.2
//   dB from blurs past the radius). Linear, so no float and double fall either side of a step.
// Per pair, not per sample: the samples' weights cost what they did with the 1 px ramp.
SFX_MB_FN SFX_MB_REAL mbInverseRampWidth(SFX_MB_REAL speed, int pairs, SFX_MB_REAL radius) {
    SFX_MB_REAL inverseStretch = 1.0 / max(speed / SFX_MB_REAL(pairs), 1.0);
    return inverseStretch + (1.0 - inverseStretch) * clamp(speed - radius + 1.0, 0.0, 1.0);
}

// Weight of sample S at distance `dist` from centre C, at most 1: as background (behind C) it
// shows where C's own blur reaches; as foreground (in front of C) where its own blur reaches.
// `inverseWidth` is the pair's (mbInverseRampWidth).
SFX_MB_FN SFX_MB_REAL mbSampleWeight(SFX_MB_REAL zC, SFX_MB_REAL zS, SFX_MB_REAL speedC, SFX_MB_REAL speedS, SFX_MB_REAL dist,
                                     SFX_MB_REAL softExtent, SFX_MB_REAL inverseWidth) {
    SFX_MB_REAL background = mbBackgroundShare(zC, zS, softExtent);
    return background * mbSpread(dist, speedC, inverseWidth) + (1.0 - background) * mbSpread(dist, speedS, inverseWidth);
}

// The centre's weight: what the samples leave of the blur window they stand for (never
// negative), times MotionBlurSettings.centreWeight (1 = exactly the remainder; larger keeps
// more of the pixel's own colour). Output = (sum of w * colour + this * centre colour) /
// (sum of w + this). The window is what the samples would weigh in an area moving uniformly
// with the velocities they follow (`windowWeights`: the sum of mbSpread at each sample's
// distance and followed speed, with the same ramp) plus one sample's worth for the centre
// (with samples a texel apart its own texel; with samples skipping texels, its share of the
// gaps, as each sample's).
// So a uniformly moving area gets the box filter over its blur length at any length: a window
// of 2 * pairs, as the 2012 course normalises, is right only when |v| is a whole number of
// texels, and gave the centre up to 1.6 (|v| = 2.7 px, 3 pairs) or 0.76 (3.12 px) of its share.
SFX_MB_FN SFX_MB_REAL mbCentreShare(SFX_MB_REAL centreWeight, SFX_MB_REAL sampleWeights, SFX_MB_REAL windowWeights) {
    return max(1.0 + windowWeights - sampleWeights, 0.0) * centreWeight;
}

// Tiles neighbour max looks out on each side: enough tiles of edge `tile` to cover `radius`
// (1, the 3 x 3 of the course, when the tile is the radius).
SFX_MB_FN int mbNeighborReachTiles(int radius, int tile) { return (radius + tile - 1) / tile; }

// Neighbour max keeps a tile at (dx, dy) tiles from the centre tile only if its velocity `v`
// (pixels) can carry its blur into the centre tile (after Guertin et al.): a tile in
// line with it along a side needs motion along that axis, one off both axes motion along the
// diagonal toward it; a tile beyond the adjacent ones also needs a radius that crosses the
// pixels between the two tiles (Chebyshev; the 0.5 px of a texel-wide mbSpread ramp). Keeps
// the dominant velocity from being one that never reaches the pixels.
SFX_MB_FN bool mbNeighborReaches(int dx, int dy, SFX_MB_VEC2 v, int tile) {
    if (dx == 0 && dy == 0) return true;
    int gap = (max(abs(dx), abs(dy)) - 1) * tile;
    if (gap > 0 && length(v) < SFX_MB_REAL(gap) + 0.5) return false;
    if (dx == 0) return v.y != 0.0;
    if (dy == 0) return v.x != 0.0;
    return SFX_MB_REAL(dx * dy) * v.x * v.y > 0.0;
}

// ---- Specialisation constants of the motion blur passes (branches and loop counts) -----------
// Never uniforms: lavapipe recompiles a shader whose control flow reads uniform values each
// time they are bound (see sfx_shared_ao.h). Ids as plain macros, for both languages.
#define SFX_MB_SC_CAMERA_ONLY 0  // mb_pack: 1 = velocity from depth and the camera motion
#define SFX_MB_SC_TILE_SIZE 0    // mb_tile_max and mb_neighbor_max: N, the tile edge in pixels
#define SFX_MB_SC_RADIUS 1       // mb_neighbor_max: k, the blur radius in pixels
#define SFX_MB_SC_PAIRS 0        // mb_reconstruct: sample pairs, (taps - 1) / 2
#define SFX_MB_SC_JITTER_SIZE 1  // mb_reconstruct: 2 = checkerboard, 4 = 4x4 randomised

// ---- Uniform blocks of the motion blur passes (SFX_BLOCK: one declaration for GLSL and C++) ----
// Pass 1, mb_pack.frag.
#if defined(__cplusplus) || defined(SFX_WANT_MB_PACK_PARAMS)
SFX_BLOCK(MbPackParams, 2)
    SFX_M_MAT4(reprojection)     // previous view-projection * inverse(current view-projection)
    SFX_M_VEC4(clipFromView)     // x = P[2][2], y = P[3][2]: clip z of view depth -z; zw = 2/W, 2/H
    SFX_M_VEC4(target)           // x = W, y = H
    SFX_M_FLOAT(radius)          // k: maximum blur radius in pixels at this size
    SFX_M_FLOAT(velocityScale)   // 0.5 * exposure: displacement across the shutter -> blur radius
    SFX_M_FLOAT(pad0)
    SFX_M_FLOAT(maxDepth)        // far plane, or SFX_SKY_DEPTH: out-of-range linear depth becomes this
SFX_BLOCK_END(params)
#endif
// Passes 2 and 3, mb_tile_max.frag and mb_neighbor_max.frag, have no uniforms (their tile size
// and radius are the constants above).
// Pass 4, mb_reconstruct.frag.
#if defined(__cplusplus) || defined(SFX_WANT_MB_RECONSTRUCT_PARAMS)
SFX_BLOCK(MbReconstructParams, 3)
    SFX_M_FLOAT(softExtent)    // soft depth comparison extent, scene units
    SFX_M_FLOAT(centreWeight)  // MotionBlurSettings.centreWeight
    SFX_M_FLOAT(radius)        // k: the blur radius in pixels (mbInverseRampWidth)
    SFX_M_FLOAT(pad1)
    SFX_M_INT(tileSize)        // N: pixel -> tile of the neighbour-max texture
    SFX_M_INT(pad2) SFX_M_INT(pad3) SFX_M_INT(pad4)  // pairs, jitter: constants above
SFX_BLOCK_END(params)
#endif
#ifdef __cplusplus
static_assert(sizeof(MbPackParams) == 112 && offsetof(MbPackParams, clipFromView) == 64 &&
              offsetof(MbPackParams, target) == 80 && offsetof(MbPackParams, radius) == 96);
static_assert(sizeof(MbReconstructParams) == 32 && offsetof(MbReconstructParams, tileSize) == 16);
#endif

#ifdef __cplusplus
}  // namespace sfx::shared
#endif

#endif  // SFX_SHARED_MB_H
