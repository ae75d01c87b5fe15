// The body of the depth-aware upsample of half-size AO to the host's full-size output
// (ao_upsample.frag; ao_upsample_bent.frag defines SFX_AO_BENT_NORMALS first and upsamples the
// bent normals with the same weights): the 2x2 half-size texels around each pixel, bilinear
// weights times a depth weight against the full-size depth, so edges stay as sharp as the
// full-size depth (sfx_shared_ao.h, "AO at half resolution").
#ifndef SFX_AO_UPSAMPLE_PASS_H
#define SFX_AO_UPSAMPLE_PASS_H
#define SFX_AO_UPSAMPLE_PASS 1
#include "sfx_shared_ao.h"
#ifdef SFX_AO_BENT_NORMALS
#include "sfx_shared_ao_horizon.h"
#endif

layout(set = 0, binding = 0) uniform sampler2D uDepth;      // the host's full-size depth, linear or hardware
layout(set = 0, binding = 1) uniform sampler2D uHalfDepth;  // the depth the half-size AO was computed on
layout(set = 0, binding = 2) uniform sampler2D uSource;     // half-size visibility in r (+ depth: SFX_AO_DEPTH_IN_*)
// UpsampleParams (binding 3): sfx_shared_ao.h.
layout(location = 0) out vec4 outAo;
layout(constant_id = SFX_AO_SC_UPSAMPLE_DEPTH) const int kHalfDepthSource = SFX_AO_HALF_DEPTH_TEXTURE;
layout(constant_id = SFX_AO_SC_UPSAMPLE_LINEARIZE) const int kLinearize = 0;

#ifdef SFX_AO_BENT_NORMALS
// The blurred half-size bent normals (unnormalised; RGBA8 xyz * 0.5 + 0.5 where the tier's AO
// target is RGBA8, else RGBA16F), renormalised here after the upsample's weights.
layout(set = 0, binding = 4) uniform sampler2D uBentSource;
layout(location = 1) out vec4 outBent;
layout(constant_id = SFX_AO_SC_UPSAMPLE_BENT_UNORM) const int kBentUnorm = 0;
vec3 bentAt(ivec2 q) { return aoBentDecode(sfxTexel(uBentSource, q, 0)); }
void writeBent(vec3 b) {
    b = aoBentNormalResolve(b);
    outBent = aoBentEncode(b, kBentUnorm != 0);
}
#endif

// A half-size texel's visibility (x) and depth (y): with the depth in the AO target one fetch
// gives both (stored clamped, as sfxLinearDepthOrFar returns it).
vec2 halfTexel(ivec2 q) {
    vec4 s = sfxTexel(uSource, q, 0);
    if (kHalfDepthSource == SFX_AO_HALF_DEPTH_SOURCE_G) return s.rg;
    if (kHalfDepthSource == SFX_AO_HALF_DEPTH_SOURCE_B) return s.rb;
    if (kHalfDepthSource == SFX_AO_HALF_DEPTH_SOURCE_KEY) {
        return vec2(s.r, aoUnpackDepthKey(s.ba, params.keyBase, params.maxDepth));
    }
    float d = sfxTexel(uHalfDepth, q, 0).r;
    return vec2(s.r, sfxLinearDepthOrFar(d, params.maxDepth));
}

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    // The host's full-size depth, linearized here where it is hardware depth (no pass makes a
    // full-size linear depth at half resolution).
    float d = sfxTexel(uDepth, p, 0).r;
    float z0 = kLinearize != 0 ? sfxLinearizeDepth(d, params.ndcScale, params.denomOffset, params.numerator, params.maxDepth)
                               : sfxLinearDepthOrFar(d, params.maxDepth);
    if (!(z0 < params.maxDepth)) {
        outAo = vec4(1.0);
#ifdef SFX_AO_BENT_NORMALS
        writeBent(vec3(0.0, 0.0, 1.0));
#endif
        return;
    }
    ivec2 halfSize = textureSize(uSource, 0);
    ivec2 base = ivec2(aoUpsampleBase(p.x), aoUpsampleBase(p.y));
    vec2 upper = vec2(aoUpsampleUpperWeight(p.x), aoUpsampleUpperWeight(p.y));
    float acc = 0.0, wsum = 0.0, nearestAo = 1.0, nearestGap = SFX_AO_UPSAMPLE_NO_GAP;
    float invTolerance = aoUpsampleInvTolerance(z0);
    vec4 gatheredAo = vec4(0.0), gatheredDepth = vec4(0.0);
    bool gathered = false;
#ifdef SFX_AO_BENT_NORMALS
    vec3 accBent = vec3(0.0), nearestBent = vec3(0.0, 0.0, 1.0);
#endif
#ifdef SFX_TIER_HIGH
    // With the depth in the AO target's G or B, the 2x2 footprint comes in two gathers (visibility,
    // depth) instead of four fetches: a pass on a CPU rasteriser costs about one copy pass per
    // fetch per pixel, and this full-size pass was the effect's dearest after the obscurance.
    // GL ES 3.0 has no textureGather, so the current tier fetches. Gathering at the footprint's
    // shared corner returns texels base + (0|1, 0|1), clamped to the edge by the null sampler,
    // exactly what the fetches read; the order is (i0 j1, i1 j1, i1 j0, i0 j0).
    if (kHalfDepthSource == SFX_AO_HALF_DEPTH_SOURCE_G || kHalfDepthSource == SFX_AO_HALF_DEPTH_SOURCE_B) {
        vec2 corner = (vec2(base) + 1.0) / vec2(halfSize);
        gatheredAo = textureGather(uSource, corner, 0);
        gatheredDepth = kHalfDepthSource == SFX_AO_HALF_DEPTH_SOURCE_G ? textureGather(uSource, corner, 1) : textureGather(uSource, corner, 2);
        gathered = true;
    }
#endif
    for (int j = 0; j < 2; ++j) {
        for (int i = 0; i < 2; ++i) {
            vec2 t;
            if (gathered) {
                int k = j == 1 ? (i == 1 ? 1 : 0) : (i == 1 ? 2 : 3);
                t = vec2(gatheredAo[k], gatheredDepth[k]);
            } else {
                // Off the edge (base is -1 at the first pixel) the clamp-to-edge sampler of
                // sfxTexel reads the edge texel, as the reference clamps.
                t = halfTexel(base + ivec2(i, j));
            }
            float a = t.x, zq = t.y;
            float bilinear = (i == 1 ? upper.x : 1.0 - upper.x) * (j == 1 ? upper.y : 1.0 - upper.y);
            float w = aoUpsampleWeight(bilinear, zq, z0, invTolerance);
            acc += w * a;
            wsum += w;
#ifdef SFX_AO_BENT_NORMALS
            // Off the edge the clamp-to-edge sampler reads the edge texel, as for the visibility.
            vec3 b = bentAt(base + ivec2(i, j));
            accBent += w * b;
#endif
            float gap = abs(zq - z0);
            if (gap < nearestGap) {
                nearestGap = gap;
                nearestAo = a;
#ifdef SFX_AO_BENT_NORMALS
                nearestBent = b;
#endif
            }
        }
    }
    float v = clamp(aoUpsampleResolve(acc, wsum, nearestAo), 0.0, 1.0);
    outAo = vec4(v, v, v, 1.0);
#ifdef SFX_AO_BENT_NORMALS
    writeBent(vec3(aoUpsampleResolve(accBent.x, wsum, nearestBent.x), aoUpsampleResolve(accBent.y, wsum, nearestBent.y),
                   aoUpsampleResolve(accBent.z, wsum, nearestBent.z)));
#endif
}

#endif  // SFX_AO_UPSAMPLE_PASS_H
