// Constants and sample patterns shared by the GLSL shaders in shader_src/ and the C++ CPU
// references: both include this one file, so they cannot drift apart.
//
// Written in the common subset of GLSL 450 and C++20. Arrays use SFX_ARRAY_* macros, which
// expand to `const T name[N] = T[N](...)` in GLSL and to a constexpr array in C++.
#ifndef SFX_SHARED_H
#define SFX_SHARED_H

#ifdef __cplusplus
#include <cstdint>
namespace sfx::shared {
struct vec2 { float x, y; };
struct ivec2 { int x, y; };
#define SFX_CONST(type, name, value) inline constexpr type name = value;
#define SFX_ARRAY_BEGIN(type, name, count) inline constexpr type name[count] = {
#define SFX_ARRAY_END };
#define SFX_VEC2(x, y) vec2{x, y}
#define SFX_IVEC2(x, y) ivec2{x, y}
#define SFX_UINT uint32_t
// Functions written once for both languages: double in C++ (the references), float in GLSL.
#define SFX_FN inline
#define SFX_REAL double
#else
#define SFX_FN
#define SFX_REAL float
#define SFX_CONST(type, name, value) const type name = value;
#define SFX_ARRAY_BEGIN(type, name, count) const type name[count] = type[count](
#define SFX_ARRAY_END );
#define SFX_VEC2(x, y) vec2(x, y)
#define SFX_IVEC2(x, y) ivec2(x, y)
#define SFX_UINT uint
#endif

// ---- Depth -------------------------------------------------------------------------------
// Linear depth is the positive eye-space distance along the view axis, in scene units.
// Pixels at or beyond SFX_SKY_DEPTH (the far plane of an infinite projection, or a cleared
// depth buffer) are sky: effects leave them unoccluded and unblurred.
SFX_CONST(float, SFX_SKY_DEPTH, 1.0e8)

// Linear depth as every pass reads it: a non-positive, non-finite or overflowing value is a point
// at or beyond the far plane, so it becomes maxDepth (the far plane, or SFX_SKY_DEPTH for an
// infinite projection). The linearisation pass stores this; a pass that reads the host's linear
// depth directly (LinearDepth passing through) applies it on every fetch, which changes nothing
// for values already stored by that pass.
SFX_FN SFX_REAL sfxLinearDepthOrFar(SFX_REAL z, SFX_REAL maxDepth) { return (z > 0.0 && z < maxDepth) ? z : maxDepth; }

// Hardware depth d -> linear eye depth. For any perspective projection z = B / (ndc_z + A), with
// A = P[2][2] and B = P[3][2] of the column-major matrix; ndc_z = d * ndcScale + ndcOffset maps the
// stored depth to the API's clip range, and the host folds ndcOffset + A into denomOffset in
// double precision (makeDepthReconstruction), so this is one multiply-add and a divide. A zero
// or negative denominator (at or past the far plane) lands on maxDepth.
SFX_FN SFX_REAL sfxLinearizeDepth(SFX_REAL d, SFX_REAL ndcScale, SFX_REAL denomOffset, SFX_REAL numerator, SFX_REAL maxDepth) {
    return sfxLinearDepthOrFar(numerator / (d * ndcScale + denomOffset), maxDepth);
}

// The depth MIP pyramid of the high tier holds at most this many levels (level 0 included).
SFX_CONST(int, SFX_DEPTH_MIP_MAX_LEVELS, 5)

// Rotated-grid subsample (Scalable Ambient Obscurance): texel p of level i+1 takes texel
// 2p + (p.y & 1, p.x & 1) of level i. Averaging depths would invent surfaces.
#ifdef __cplusplus
inline constexpr ivec2 depthMipSource(ivec2 p) { return ivec2{2 * p.x + (p.y & 1), 2 * p.y + (p.x & 1)}; }
#else
ivec2 depthMipSource(ivec2 p) { return ivec2(2 * p.x + (p.y & 1), 2 * p.y + (p.x & 1)); }
#endif


// ---- Position reconstruction -------------------------------------------------------------
// From a pixel centre (px + 0.5, py + 0.5), in memory rows (row 0 = NDC y -1 on every API),
// and linear depth z > 0, the view-space position (x right, y up, camera looking down -z):
//     x = z * (pc.x * projInfo.x + projInfo.z),  y = z * (pc.y * projInfo.y + projInfo.w),  -z
// with projInfo = (2 / (W * P00), 2 / (H * P11), (P20 - 1) / P00, (P21 - 1) / P11) from the
// column-major projection P (P20 = P[2][0]). Off-centre (jittered) projections work too.
#ifdef __cplusplus
struct dvec3 { double x, y, z; };
inline dvec3 reconstructViewPosition(double pcx, double pcy, double z, const double projInfo[4]) {
    return dvec3{z * (pcx * projInfo[0] + projInfo[2]), z * (pcy * projInfo[1] + projInfo[3]), -z};
}
#else
vec3 reconstructViewPosition(vec2 pixelCentre, float z, vec4 projInfo) {
    return vec3(z * (pixelCentre * projInfo.xy + projInfo.zw), -z);
}
#endif

// ---- Tier parameters (docs/tiers.md's parameter table; tiers/ selects among them) ---------
SFX_CONST(int, SFX_AO_SCALABLE_TAPS_CURRENT, 4)      // mirrored: 2 offsets, each also negated
SFX_CONST(int, SFX_AO_SCALABLE_TAPS_HIGH, 9)         // spiral taps reading the depth MIP
SFX_CONST(float, SFX_AO_RADIUS_CLAMP_PX_CURRENT, 20.0)
SFX_CONST(int, SFX_AO_ALCHEMY_SAMPLES_CURRENT, 6)
SFX_CONST(int, SFX_AO_ALCHEMY_SAMPLES_HIGH, 12)      // the paper's 12 samples per pixel
SFX_CONST(int, SFX_AO_BLUR_RADIUS_CURRENT, 2)        // 5-tap separable bilateral
SFX_CONST(int, SFX_AO_BLUR_RADIUS_HIGH, 6)           // 13-tap, as Alchemy's filter
SFX_CONST(int, SFX_MB_TAPS_CURRENT, 7)               // 6 samples + centre
SFX_CONST(int, SFX_MB_TAPS_HIGH, 9)                  // 8 samples + centre
SFX_CONST(float, SFX_MB_MAX_RADIUS_PX_CURRENT, 10.0)
SFX_CONST(float, SFX_MB_MAX_RADIUS_PX_HIGH, 18.0)
SFX_CONST(int, SFX_MB_JITTER_SIZE_CURRENT, 2)        // checkerboard
SFX_CONST(int, SFX_MB_JITTER_SIZE_HIGH, 4)           // 4x4 randomised

#ifdef __cplusplus
}  // namespace sfx::shared
#endif

#endif  // SFX_SHARED_H
