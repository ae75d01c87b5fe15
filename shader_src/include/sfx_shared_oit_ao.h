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

float opaqueDepthAt(ivec2 q) {
    return sfxLinearizeDepth(texelFetch(uOpaqueDepth, q, 0).r, ao.ndcScale, ao.denomOffset, ao.numerator, ao.maxDepth);
}
vec3 positionAt(ivec2 q, float z) { return reconstructViewPosition(vec2(q) + 0.5, z, ao.projInfo); }
ivec2 tapPixel(ivec2 p, vec2 offset) { return clamp(ivec2(floor(vec2(p) + 0.5 + offset)), ivec2(0), gSize - 1); }

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
    uint steps = uint(ao.capacity);
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
    float screenRadius = ao.radius * ao.pixelsPerUnit / z;
    float phi = aoRotationAngle(p);
    float sum = 0.0;
    if (kTechnique == 0) {
        for (int i = 0; i < kSamples; ++i) {
            float rho = sqrt((float(i) + 0.5) / float(kSamples)) * screenRadius;
            float theta = float(i) * SFX_AO_GOLDEN_ANGLE + phi;
            sum += tapOcclusion(tapPixel(p, rho * vec2(cos(theta), sin(theta))), C, n, z, exteriorWeight);
        }
        return clamp(finishOcclusion(2.0 * ao.intensity * ao.radius / float(kSamples) * sum), 0.0, 1.0);
    }
    if (ao.maxRadiusPx > 0.0) screenRadius = min(screenRadius, ao.maxRadiusPx);
    const int offsets = kMirrored != 0 ? kSamples / 2 : kSamples;
    for (int i = 0; i < offsets; ++i) {
        float alpha = (float(i) + 0.5) / float(offsets);
        float h = alpha * screenRadius;
        float theta = SFX_AO_TWO_PI * alpha * ao.spiralTurns + phi;
        vec2 offset = h * vec2(cos(theta), sin(theta));
        sum += tapOcclusion(tapPixel(p, offset), C, n, z, exteriorWeight);
        if (kMirrored != 0) sum += tapOcclusion(tapPixel(p, -offset), C, n, z, exteriorWeight);
    }
    return clamp(finishOcclusion(aoScalableOcclusion(sum, ao.intensity, kSamples, ao.sumExponent)), 0.0, 1.0);
}

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    gSize = imageSize(uHeads);
    float zo = opaqueDepthAt(p);
    float opaqueVisibility = 1.0;
    if (zo < ao.maxDepth) opaqueVisibility = receiverVisibility(p, zo, opaqueNormal(p, positionAt(p, zo), zo), 1.0);
    // The pixel's fragments in (depth, draw id, primitive id) order, by repeated selection of the
    // next key (no registers per layer, and bounded by the pool's capacity like the resolve).
    uint head = imageLoad(uHeads, p).x;
    uint steps = uint(ao.capacity);
    float acc = 0.0, transmittance = 1.0, frontDepth = zo;
    bool any = false;
    float lastDepth = 0.0;
    uint lastDraw = 0u, lastPrimitive = 0u;
    bool more = true;
    for (uint t = 0u; more && t < steps; ++t) {
        bool found = false;
        float bestDepth = 0.0;
        uint bestDraw = 0u, bestPrimitive = 0u;
        uvec4 bestLo = uvec4(0u), bestHi = uvec4(0u);
        for (uint node = head, s = 0u; node != SFX_OIT_NULL_INDEX && node < steps && s < steps; ++s) {
            uvec4 lo = pool.nodes[2u * node], hi = pool.nodes[2u * node + 1u];
            node = hi.z;
            float depth = oitNodeDepth(lo);
            uint drawId = oitDrawIndex(hi.x), primitive = hi.y;
            if (any && !oitBefore(lastDepth, lastDraw, lastPrimitive, depth, drawId, primitive)) continue;
            if (found && !oitBefore(depth, drawId, primitive, bestDepth, bestDraw, bestPrimitive)) continue;
            found = true;
            bestDepth = depth;
            bestDraw = drawId;
            bestPrimitive = primitive;
            bestLo = lo;
            bestHi = hi;
        }
        more = found;
        if (!found) continue;
        if (!any) frontDepth = bestDepth;
        any = true;
        lastDepth = bestDepth;
        lastDraw = bestDraw;
        lastPrimitive = bestPrimitive;
        float alpha = oitNodeColor(bestLo).a;
        float v = receiverVisibility(p, bestDepth, oitNodeNormal(bestLo), oitExteriorWeight(alpha, oitFrontFacing(bestHi.x)));
        acc += transmittance * alpha * v;
        transmittance *= 1.0 - alpha;
    }
    outAo = vec4(acc + transmittance * opaqueVisibility, opaqueVisibility, frontDepth, zo);
}

#endif  // SFX_SHARED_OIT_AO_H
