// Opacity-based ambient occlusion through the A-buffer's layers (the paper's eq. 1-4 and
// Algorithm 1), one full-screen pass after the resolve. GLSL only: included by oit_ao.frag
// (brute force: every tap walks the list at its pixel) and oit_ao_compressed.frag
// (SFX_OIT_AO_COMPRESSED: every tap reads the M compressed nodes the resolve wrote).
//
// Per pixel, the receivers are the opaque surface (a front face of opacity 1, its normal derived
// from the opaque depth by sfx_shared_ao.h's rule) and every stored fragment (its authored normal,
// the exterior and interior hemispheres blended by W). Each tap of the technique's pattern
// (sfx_shared_ao.h: the same taps as the opaque AO passes, without the depth MIP) keeps the
// largest occlusion over the occluders at its pixel, each weighted by its own opacity; the opaque
// surface there is an occluder of opacity 1. The receivers' visibilities are then blended front
// to back with the fragments' opacities, like colour but separately from it:
//   out.r = sum_i T_i alpha_i v_i + T v_opaque (T_i the transmittance in front of fragment i)
//   out.g = v_opaque
//   out.b = the front depth (the nearest fragment's, else the opaque surface's), out.a = the opaque
//           depth: the bilateral filter's keys (oit_ao_filter.frag), kept only by its RGBA32F target
// The CPU reference is sfx::reference::opacityAmbientOcclusion.
#ifndef SFX_SHARED_OIT_AO_H
#define SFX_SHARED_OIT_AO_H
#define SFX_WANT_OIT_AO_PARAMS 1
#include "sfx_shared_oit_params.h"  // OitAoParams ao (binding 4)
#include "sfx_shared_oit.h"

layout(set = 0, binding = 0) uniform sampler2D uOpaqueDepth;  // the opaque pass's depth attachment
layout(set = 0, binding = 1, std430) readonly buffer OitPool SFX_OIT_POOL_BODY
layout(set = 0, binding = 2, r32ui) uniform readonly uimage2D uHeads;
#ifdef SFX_OIT_AO_COMPRESSED
layout(set = 0, binding = 3, std430) readonly buffer OitCompressed { uint words[]; } compressed;
#endif
layout(location = 0) out vec4 outAo;
layout(constant_id = SFX_OIT_SC_AO_TECHNIQUE) const int kTechnique = 1;  // 0 Alchemy, 1 Scalable
layout(constant_id = SFX_OIT_SC_AO_SAMPLES) const int kSamples = 1;
layout(constant_id = SFX_OIT_SC_AO_MIRRORED) const int kMirrored = 0;

ivec2 gSize;
const float SFX_OIT_AO_SUM_SCALE = 16777216.0;  // 2^24: the fixed-point step of the blended sum

float opaqueDepthAt(ivec2 q) {
    return sfxLinearizeDepth(texelFetch(uOpaqueDepth, q, 0).r, ao.ndcScale, ao.denomOffset, ao.numerator, ao.maxDepth);
}
vec3 positionAt(ivec2 q, float z) { return reconstructViewPosition(vec2(q) + 0.5, z, ao.projInfo); }

// The opaque surface's normal from its depth (sfx_shared_ao.h's rule, as normalsFromDepth).
vec3 opaqueNormal(ivec2 p, vec3 C, float z) {
    vec3 dx = vec3(1.0, 0.0, 0.0), dy = vec3(0.0, 1.0, 0.0);
    if (gSize.x > 1) {
        float zl = p.x > 0 ? opaqueDepthAt(p - ivec2(1, 0)) : 0.0, zr = p.x < gSize.x - 1 ? opaqueDepthAt(p + ivec2(1, 0)) : 0.0;
        dx = aoNormalUsesNext(p.x, gSize.x, zl, zr, z) ? positionAt(p + ivec2(1, 0), zr) - C : C - positionAt(p - ivec2(1, 0), zl);
    }
    if (gSize.y > 1) {
        float zd = p.y > 0 ? opaqueDepthAt(p - ivec2(0, 1)) : 0.0, zu = p.y < gSize.y - 1 ? opaqueDepthAt(p + ivec2(0, 1)) : 0.0;
        dy = aoNormalUsesNext(p.y, gSize.y, zd, zu, z) ? positionAt(p + ivec2(0, 1), zu) - C : C - positionAt(p - ivec2(0, 1), zd);
    }
    return aoFacingNormal(dx, dy, C);
}

float finishOcclusion(float occlusion) { return pow(max(0.0, 1.0 - occlusion), ao.contrast); }

// getAO of Algorithm 1: one occluder at tap pixel q, depth zq and opacity alpha.
float occluderTerm(ivec2 q, float zq, float alpha, vec3 C, vec3 n, float z, float exteriorWeight) {
    vec3 v = positionAt(q, zq) - C;
    float vv = dot(v, v), vn = dot(v, n);
    if (kTechnique == 0) return oitAlchemyOcclusion(vv, vn, z, ao.radius, ao.bias, ao.epsilon, exteriorWeight, alpha);
    return oitScalableOcclusion(vv, vn, ao.radius, ao.bias, ao.epsilon, exteriorWeight, alpha);
}

// The largest occlusion over everything at tap pixel q.
float tapOcclusion(ivec2 q, vec3 C, vec3 n, float z, float exteriorWeight) {
    float occlusion = 0.0;
#ifdef SFX_OIT_AO_COMPRESSED
    uint base = (uint(q.y) * uint(gSize.x) + uint(q.x)) * uint(SFX_OIT_COMPRESSED_WORDS);
    uvec4 texel = uvec4(compressed.words[base], compressed.words[base + 1u], compressed.words[base + 2u], 0u);
    for (int i = 0; i < SFX_OIT_COMPRESSED_NODES; ++i) {
        float alpha = oitCompressedOpacity(texel, i);
        if (!(alpha > 0.0)) continue;  // an empty node
        float zq = ao.zNear + oitCompressedDepth(texel, i) * (ao.zFar - ao.zNear);
        occlusion = max(occlusion, occluderTerm(q, zq, alpha, C, n, z, exteriorWeight));
    }
#else
    // The walk's bound from the pool's own header, not the uniform block: loop bounds read from
    // a uniform block make lavapipe inline their values and JIT-compile the pass again at every
    // draw (100 to 500 ms a frame at 320x180; docs/oit.md).
    uint steps = pool.capacity;
    // A fixed trip count (the most layers the resolve keeps), the same in every lane: llvmpipe and
    // lavapipe read wrong list nodes for whole 4x4 blocks when lanes left this nested walk at
    // different iterations (docs/oit.md).
    uint node = imageLoad(uHeads, q).x;
    for (int s = 0; s < SFX_OIT_MAX_KEPT_LAYERS; ++s) {
        bool live = node != SFX_OIT_NULL_INDEX && node < steps;
        uint at = live ? node : 0u;
        uvec4 lo = pool.nodes[2u * at];
        uint next = pool.nodes[2u * at + 1u].z;
        float term = occluderTerm(q, oitNodeDepth(lo), oitNodeColor(lo).a, C, n, z, exteriorWeight);
        occlusion = live ? max(occlusion, term) : occlusion;
        node = live ? next : SFX_OIT_NULL_INDEX;
    }
    float zo = opaqueDepthAt(q);
    if (zo < ao.maxDepth) occlusion = max(occlusion, occluderTerm(q, zo, 1.0, C, n, z, exteriorWeight));
#endif
    return occlusion;
}

// Visibility of a receiver at pixel p, linear depth z, normal n (Algorithm 1 over the taps).
float receiverVisibility(ivec2 p, float z, vec3 n, float exteriorWeight) {
    vec3 C = positionAt(p, z);
    float screenRadius = aoScreenRadius(ao.radius, ao.pixelsPerUnit, z);
    int rotation = aoRotationIndex(p);
    float sum = 0.0;
    if (kTechnique == 0) {
        for (int i = 0; i < kSamples; ++i) {
            ivec2 q = aoTap(p, aoDiskTapRadius(i, kSamples, screenRadius), aoTapDirection(aoAlchemyTurnsQ16(i), rotation), gSize);
            sum += tapOcclusion(q, C, n, z, exteriorWeight);
        }
        return clamp(finishOcclusion(2.0 * ao.intensity * ao.radius / float(kSamples) * sum), 0.0, 1.0);
    }
    // A select, not a branch: a branch on uniform values alone lets lavapipe inline them and
    // JIT-compile the shader again at every draw (see the pool's capacity below).
    screenRadius = ao.maxRadiusPx > 0.0 ? min(screenRadius, ao.maxRadiusPx) : screenRadius;
    const int offsets = kMirrored != 0 ? kSamples / 2 : kSamples;
    for (int i = 0; i < offsets; ++i) {
        float h = aoSpiralTapRadius(i, offsets, screenRadius);
        vec2 d = aoTapDirection(aoSpiralTurnsQ16(i, ao.spiralHalfStepQ16), rotation);
        sum += tapOcclusion(aoTap(p, h, d, gSize), C, n, z, exteriorWeight);
        if (kMirrored != 0) sum += tapOcclusion(aoTap(p, h, -d, gSize), C, n, z, exteriorWeight);
    }
    return clamp(finishOcclusion(aoScalableOcclusion(sum, ao.intensity, kSamples, ao.sumExponent)), 0.0, 1.0);
}

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    gSize = imageSize(uHeads);
    float zo = opaqueDepthAt(p);
    float opaqueVisibility = 1.0;
    if (zo < ao.maxDepth) opaqueVisibility = receiverVisibility(p, zo, opaqueNormal(p, positionAt(p, zo), zo), 1.0);
    // One walk over the pixel's list: the resolve stored in each node the transmittance in front of
    // it (word 7, in sorted order), so no second sort. The sum of T_i alpha_i v_i is taken in fixed
    // point (2^-24 steps; the terms sum to at most 1) so that it is exact whatever the list order,
    // and the output stays bit-identical when the draw order changes. The front fragment (for the
    // filter's key) and the back one (whose T (1 - alpha) is what reaches the opaque surface) are
    // the least and greatest (depth, draw, primitive) keys.
    uint head = imageLoad(uHeads, p).x;
    uint steps = pool.capacity;
    uint sum = 0u;
    bool any = false;
    float frontDepth = zo, backDepth = 0.0, transmittance = 1.0;
    uint frontDraw = 0u, frontPrimitive = 0u, backDraw = 0u, backPrimitive = 0u;
    for (uint node = head, s = 0u; node != SFX_OIT_NULL_INDEX && node < steps && s < steps; ++s) {
        uvec4 lo = pool.nodes[2u * node], hi = pool.nodes[2u * node + 1u];
        node = hi.z;
        float depth = oitNodeDepth(lo);
        uint drawId = oitDrawIndex(hi.x), primitive = hi.y;
        float alpha = oitNodeColor(lo).a;
        float stored = uintBitsToFloat(hi.w);
        float inFront = stored >= 0.0 ? min(stored, 1.0) : 0.0;  // a NaN stays out
        if (!any || oitBefore(depth, drawId, primitive, frontDepth, frontDraw, frontPrimitive)) {
            frontDepth = depth;
            frontDraw = drawId;
            frontPrimitive = primitive;
        }
        if (!any || oitBefore(backDepth, backDraw, backPrimitive, depth, drawId, primitive)) {
            backDepth = depth;
            backDraw = drawId;
            backPrimitive = primitive;
            transmittance = inFront * (1.0 - alpha);
        }
        // Only the weight and the receiver's own terms stay live across the taps.
        float weight = inFront * alpha;
        float v = receiverVisibility(p, depth, oitNodeNormal(lo), oitExteriorWeight(alpha, oitFrontFacing(hi.x)));
        sum += uint(clamp(weight * v, 0.0, 1.0) * SFX_OIT_AO_SUM_SCALE + 0.5);
        any = true;
    }
    float acc = float(sum) / SFX_OIT_AO_SUM_SCALE;
    outAo = vec4(acc + transmittance * opaqueVisibility, opaqueVisibility, frontDepth, zo);
}

#endif  // SFX_SHARED_OIT_AO_H
