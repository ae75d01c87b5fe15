// Ambient obscurance constants and sample patterns, shared by the ao_*.frag shaders and the
// CPU reference (sdk/src/reference/ao_reference.cpp): one definition, so they cannot drift.
// Same dialect rules as sfx_shared.h (the common subset of GLSL 450 and C++20).
#ifndef SFX_SHARED_AO_H
#define SFX_SHARED_AO_H

#include "sfx_shared.h"

#ifdef __cplusplus
#include <cmath>
namespace sfx::shared {
#endif

SFX_CONST(float, SFX_AO_TWO_PI, 6.28318530717958647692)

// ---- Spiral taps (Scalable AO) -----------------------------------------------------------
// Tap i of N: alpha = (i + 0.5) / N, screen radius alpha * R, angle 2 pi alpha turns + phi.
// 7 turns for 9 taps is the Scalable Ambient Obscurance reference's choice (a prime: no two
// taps line up). The current tier uses 2 offsets, each also negated (4 taps): with an integer
// number of turns both offsets would lie on one line through the centre; 1.5 turns puts them
// at 135 and 45 degrees, so the 4 taps form an X at two radii.
SFX_CONST(float, SFX_AO_SPIRAL_TURNS_HIGH, 7.0)
SFX_CONST(float, SFX_AO_SPIRAL_TURNS_MIRRORED, 1.5)
// A tap at screen distance h reads depth MIP level clamp(floor(log2(h)) - Q, 0, levels - 1).
SFX_CONST(int, SFX_AO_MIP_LEVEL_OFFSET, 3)

// ---- Alchemy disk pattern -----------------------------------------------------------------
// Sample i of s lies at radius sqrt((i + 0.5) / s) * R (uniform density in the projected disk)
// and angle i * golden angle + phi (a Vogel spiral: no two samples share a direction).
SFX_CONST(float, SFX_AO_GOLDEN_ANGLE, 2.39996322972865332)

// ---- Crease shading: the 24 taps of the 11x11 stippled diamond ------------------------------
// The pixels (dx, dy) with |dx| + |dy| in {2, 4}: every other pixel of the diamond of
// half-width 5 (a checkerboard stipple), the centre excluded. 8 taps on ring 2, 16 on ring 4.
SFX_CONST(int, SFX_AO_CREASE_TAPS, 24)
SFX_ARRAY_BEGIN(ivec2, SFX_AO_CREASE_OFFSETS, 24)
    SFX_IVEC2(2, 0), SFX_IVEC2(1, 1), SFX_IVEC2(0, 2), SFX_IVEC2(-1, 1),
    SFX_IVEC2(-2, 0), SFX_IVEC2(-1, -1), SFX_IVEC2(0, -2), SFX_IVEC2(1, -1),
    SFX_IVEC2(4, 0), SFX_IVEC2(3, 1), SFX_IVEC2(2, 2), SFX_IVEC2(1, 3),
    SFX_IVEC2(0, 4), SFX_IVEC2(-1, 3), SFX_IVEC2(-2, 2), SFX_IVEC2(-3, 1),
    SFX_IVEC2(-4, 0), SFX_IVEC2(-3, -1), SFX_IVEC2(-2, -2), SFX_IVEC2(-1, -3),
    SFX_IVEC2(0, -4), SFX_IVEC2(1, -3), SFX_IVEC2(2, -2), SFX_IVEC2(3, -1)
SFX_ARRAY_END
// The article's look: two blurs of the raw result, a wide one that lowers intensity and a
// moderate one (half the width) that raises it, averaged. Gains on occlusion.
SFX_CONST(float, SFX_AO_CREASE_WIDE_GAIN, 0.6)
SFX_CONST(float, SFX_AO_CREASE_MODERATE_GAIN, 1.4)

// ---- Bilateral blur ------------------------------------------------------------------------
// A neighbour's weight falls linearly to 0 as its depth differs from the centre's by this
// fraction of the centre's depth: occlusion is never carried across a depth discontinuity.
SFX_CONST(float, SFX_AO_BLUR_DEPTH_TOLERANCE, 0.05)
SFX_CONST(int, SFX_AO_MAX_BLUR_RADIUS, 8)
// Most taps a GPU pass takes (the uniform loop bound); the CPU reference has no limit.
SFX_CONST(int, SFX_AO_MAX_SAMPLES, 64)

// ---- Per-pixel rotation --------------------------------------------------------------------
// An integer hash of the pixel, so the GPU (32-bit float) and the reference (double) rotate
// each pixel's pattern by the same angle: phi = (hash & 0xFFFF) * 2 pi / 65536. The low 16 bits
// are exact in float, only the final multiply rounds.
#ifdef __cplusplus
inline constexpr uint32_t aoRotationHash(int x, int y) {
    uint32_t h = (uint32_t(x) * 73856093u) ^ (uint32_t(y) * 19349663u);
    h ^= h >> 13;
    h *= 0x5bd1e995u;
    h ^= h >> 15;
    return h;
}
inline double aoRotationAngle(int x, int y) { return double(aoRotationHash(x, y) & 0xFFFFu) * (6.28318530717958647692 / 65536.0); }
#else
uint aoRotationHash(ivec2 p) {
    uint h = (uint(p.x) * 73856093u) ^ (uint(p.y) * 19349663u);
    h ^= h >> 13;
    h *= 0x5bd1e995u;
    h ^= h >> 15;
    return h;
}
float aoRotationAngle(ivec2 p) { return float(aoRotationHash(p) & 0xFFFFu) * (SFX_AO_TWO_PI / 65536.0); }
#endif

// ---- Depth packed in two 8-bit channels (current tier, RGBA8 AO target) --------------------
// key = log2(z / zNear) / log2(SFX_SKY_DEPTH / zNear) in [0, 1], stored as 16 bits in b (high)
// and a (low). A log key gives the same relative precision at every distance (~3e-4 of z for
// zNear = 0.1), far finer than the blur's SFX_AO_BLUR_DEPTH_TOLERANCE.
#ifndef __cplusplus
vec2 aoPackDepthKey(float key) {
    float k = floor(clamp(key, 0.0, 1.0) * 65535.0 + 0.5);
    float hi = floor(k / 256.0);
    return vec2(hi, k - hi * 256.0) / 255.0;
}
float aoUnpackDepthKey(vec2 ba) {
    vec2 b = floor(ba * 255.0 + 0.5);
    return (b.x * 256.0 + b.y) / 65535.0;
}
#endif

#ifdef __cplusplus
}  // namespace sfx::shared
#endif

#endif  // SFX_SHARED_AO_H
