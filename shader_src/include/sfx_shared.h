// Constants and sample patterns shared by the GLSL shaders in shader_src/ and the C++ CPU
// references: both include this one file, so they cannot drift apart.
//
// Written in the common subset of GLSL 450 and C++20. Arrays use SFX_ARRAY_* macros, which
// expand to `const T name[N] = T[N](...)` in GLSL and to a constexpr array in C++.
#ifndef SFX_SHARED_H
#define SFX_SHARED_H

#ifdef __cplusplus
#include <bit>
#include <cmath>
#include <cstddef>
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
// GLSL's bit casts; the double is rounded to float first, as the shader holds it.
inline uint32_t floatBitsToUint(double v) { return std::bit_cast<uint32_t>(float(v)); }
inline double uintBitsToFloat(uint32_t v) { return double(std::bit_cast<float>(v)); }
// Functions written once for both languages: double in C++ (the references), float in GLSL.
#define SFX_FN inline
#define SFX_REAL double
#define SFX_PRECISE  // C++: each float operation rounds on its own (x86-64 without -mfma has no FMA to contract into)
#else
#define SFX_FN
#define SFX_REAL float
#define SFX_PRECISE precise  // no fused multiply-add: each operation rounds as the C++ reference's does
#define SFX_CONST(type, name, value) const type name = value;
#define SFX_ARRAY_BEGIN(type, name, count) const type name[count] = type[count](
#define SFX_ARRAY_END );
#define SFX_VEC2(x, y) vec2(x, y)
#define SFX_IVEC2(x, y) ivec2(x, y)
#define SFX_UINT uint
#endif

// ---- Uniform blocks, written once for both languages --------------------------------------
// SFX_BLOCK(Name, binding) <members> SFX_BLOCK_END(instance) declares, in GLSL, the std140
// uniform block `Name` at (set 0, binding) named `instance` in the shader, and in C++ a struct
// `Name` of the same layout, which the effect fills and uploads (Name::kBinding is the binding).
// Members: SFX_M_MAT4 / SFX_M_VEC4 (16-byte aligned), SFX_M_IVEC2 (8-byte aligned), SFX_M_FLOAT
// and SFX_M_INT (4 bytes). C++ aligns each member as std140 does, and every block is padded to
// a multiple of 16 bytes by explicit members, so sizeof(Name) is the GLSL block's size; the
// static_asserts after each block check the offsets the shaders rely on. (No vec3 or arrays of
// scalars: std140 pads those differently from C++.) In GLSL a block is declared only by the
// shader that asks for it (SFX_WANT_<block>), so one header can hold the blocks of many passes.
#ifdef __cplusplus
#define SFX_BLOCK(name, b) struct name { static constexpr uint32_t kBinding = b;
#define SFX_BLOCK_END(instance) };
#define SFX_M_MAT4(n) alignas(16) float n[16];
#define SFX_M_VEC4(n) alignas(16) float n[4];
#define SFX_M_IVEC2(n) alignas(8) int32_t n[2];
#define SFX_M_FLOAT(n) float n;
#define SFX_M_INT(n) int32_t n;
#else
#define SFX_BLOCK(name, b) layout(set = 0, binding = b, std140) uniform name {
#define SFX_BLOCK_END(instance) } instance;
#define SFX_M_MAT4(n) mat4 n;
#define SFX_M_VEC4(n) vec4 n;
#define SFX_M_IVEC2(n) ivec2 n;
#define SFX_M_FLOAT(n) float n;
#define SFX_M_INT(n) int n;
#endif

// ---- Depth -------------------------------------------------------------------------------
// Linear depth is the positive eye-space distance along the view axis, in scene units.
// Pixels at or beyond SFX_SKY_DEPTH (the far plane of an infinite projection, or a cleared
// depth buffer) are sky: effects leave them unoccluded and unblurred.
SFX_CONST(float, SFX_SKY_DEPTH, 1.0e8)

// ---- Hostile values: the rules every effect applies to what it reads (docs/robustness_extremes.md)
// Finite: not NaN and not +-infinity. GLSL and C++ spell the test differently; the rule is one.
#ifdef __cplusplus
SFX_FN bool sfxIsFinite(SFX_REAL x) { return std::isfinite(x); }
#else
bool sfxIsFinite(float x) { return !isnan(x) && !isinf(x); }
#endif
// The smallest normal float. Linear depth below it (a denormal) is treated as zero, because a GPU
// may flush denormals to zero on fetch and the reference (double) must decide the same way.
SFX_CONST(float, SFX_FLOAT_MIN_NORMAL, 1.17549435e-38)

// Linear depth as every pass reads it: a non-positive, denormal, non-finite or overflowing value
// is a point at or beyond the far plane, so it becomes maxDepth (the far plane, or SFX_SKY_DEPTH
// for an infinite projection). The linearisation pass stores this; a pass that reads the host's
// linear depth directly (LinearDepth passing through) applies it on every fetch, which changes
// nothing for values already stored by that pass.
SFX_FN SFX_REAL sfxLinearDepthOrFar(SFX_REAL z, SFX_REAL maxDepth) {
    return (z >= SFX_REAL(SFX_FLOAT_MIN_NORMAL) && z < maxDepth) ? z : maxDepth;
}

// Hardware depth d -> linear eye depth. For any perspective projection z = B / (ndc_z + A), with
// A = P[2][2] and B = P[3][2] of the column-major matrix; ndc_z = d * ndcScale + ndcOffset maps the
// stored depth to the API's clip range, and the host folds ndcOffset + A into denomOffset in
// double precision (makeDepthReconstruction), so this is one multiply-add and a divide. A zero
// or negative denominator (at or past the far plane) lands on maxDepth. A stored value outside
// [0, 1] (NaN, +-infinity, or any other value a float depth buffer can hold but no depth test
// writes) is outside the depth range: sky as well.
SFX_FN SFX_REAL sfxLinearizeDepth(SFX_REAL d, SFX_REAL ndcScale, SFX_REAL denomOffset, SFX_REAL numerator, SFX_REAL maxDepth) {
    if (!(d >= 0.0 && d <= 1.0)) return maxDepth;
    return sfxLinearDepthOrFar(numerator / (d * ndcScale + denomOffset), maxDepth);
}

// Colour as the gathering passes read it: a non-finite channel reads as 0, and a finite one is
// held within +-SFX_COLOR_MAX (the largest half float), so a weighted sum of colours can never
// overflow a float however bright the input, and the output is always finite. Samples whose
// colour has a non-finite channel are left out of a gather altogether (sfxColorIsFinite), so
// a NaN or infinite pixel never spreads to its neighbours; the pixel itself keeps its finite
// channels and reads 0 in the others.
SFX_CONST(float, SFX_COLOR_MAX, 65504.0)
SFX_FN SFX_REAL sfxColorChannel(SFX_REAL c) {
    return sfxIsFinite(c) ? (c > SFX_REAL(SFX_COLOR_MAX) ? SFX_REAL(SFX_COLOR_MAX) : (c < -SFX_REAL(SFX_COLOR_MAX) ? -SFX_REAL(SFX_COLOR_MAX) : c)) : 0.0;
}
#ifdef __cplusplus
template <class Rgba> bool sfxColorIsFinite(const Rgba& c) { return std::isfinite(c[0]) && std::isfinite(c[1]) && std::isfinite(c[2]) && std::isfinite(c[3]); }
template <class Rgba> Rgba sfxColor(Rgba c) {
    for (auto& v : c) v = sfxColorChannel(v);
    return c;
}
#else
bool sfxColorIsFinite(vec4 c) { return sfxIsFinite(c.r) && sfxIsFinite(c.g) && sfxIsFinite(c.b) && sfxIsFinite(c.a); }
vec4 sfxColor(vec4 c) { return vec4(sfxColorChannel(c.r), sfxColorChannel(c.g), sfxColorChannel(c.b), sfxColorChannel(c.a)); }
#endif

#ifndef __cplusplus
// One texel by its integer coordinates q in mip `lod`: the texel texelFetch(s, q, lod) reads, for
// q inside the level, taken through the nearest, clamp-to-edge sampler that the HAL binds when a
// binding names none (TextureBinding). Why not texelFetch: lavapipe compiles texelFetch into a
// call of about 125 instructions per 8 pixels, and a sample at the texel's centre into a
// fraction of that, inline; crease's obscurance pass fell from 115 to 57 million instructions
// at half of 1280x720 (docs/trade.md). The centre is (q + 0.5) times the reciprocal of the
// size, one divide that compilers share between the fetches of a texture where a divide per
// fetch was dearer on lavapipe (docs/trade.md). Three roundings of at most 2^-24 each (the
// reciprocal, the product, the sampler's scaling back) keep it within 0.003 of a texel of the
// exact centre up to 16384 texels, so the nearest texel is q.
vec4 sfxTexel(sampler2D s, ivec2 q, int lod) { return textureLod(s, (vec2(q) + 0.5) * (1.0 / vec2(textureSize(s, lod))), float(lod)); }
#endif

// Parameters of the linearisation pass (linearize_depth.frag), filled by LinearDepth. Whether
// the source is linear already is a specialisation constant (a branch, never a uniform: see
// sfx_shared_ao.h), its id this one.
#define SFX_DEPTH_SC_LINEAR_INPUT 0
#define SFX_DEPTH_SC_HALF_SIZE_BASE 1  // 1: the pass writes a half-size level 0 (LinearDepthDesc.halfSizeBase)
#if defined(__cplusplus) || defined(SFX_WANT_LINEARIZE_PARAMS)
SFX_BLOCK(LinearizeParams, 1)
    SFX_M_FLOAT(ndcScale)     // 1 for [0,1] clip depth, 2 for [-1,1]
    SFX_M_FLOAT(denomOffset)  // ndcOffset + A
    SFX_M_FLOAT(numerator)    // B
    SFX_M_FLOAT(maxDepth)     // far plane, or SFX_SKY_DEPTH for an infinite projection
    SFX_M_FLOAT(pad0) SFX_M_FLOAT(pad1) SFX_M_FLOAT(pad2) SFX_M_FLOAT(pad3)
SFX_BLOCK_END(params)
#endif
#ifdef __cplusplus
static_assert(sizeof(LinearizeParams) == 32 && offsetof(LinearizeParams, maxDepth) == 12);
#endif

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

// The per-tier parameters (tap counts, radii, jitter) are not here: they are rows of the tier
// table (tiers/src/tier_table.cpp), reaching the shaders as generated defines and uniforms.

#ifdef __cplusplus
}  // namespace sfx::shared
#endif

#endif  // SFX_SHARED_H
