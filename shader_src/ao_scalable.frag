#version 450
#extension GL_EXT_control_flow_attributes : require
// Scalable AO (Bukowski et al. 2012): spiral taps with a linear distance falloff and a biased
// cosine; the normalised sum raised to the look's exponent (the course squares it). Current
// tier: mirrored pairs, radius clamp, full-resolution depth. High tier: 9 spiral taps, each
// reading the depth MIP level its distance calls for.
#define SFX_AO_PASS 1
#include "sfx_shared_ao.h"

float scalableTap(ivec2 p, float h, vec2 d, int level, ivec2 size, vec3 C, vec3 n) {
    ivec2 q = aoTap(p, h, d, size);
    ivec2 m = aoMipTexel(q, level, size);
    vec3 v = aoPosition(q, aoDepthAt(m, level)) - C;
    float term = aoScalableTerm(dot(v, v), dot(v, n), params.radius, params.bias, params.epsilon);
#ifdef SFX_AO_MULTILAYER
    // Multilayer AO (level is 0 then: no depth MIP): the largest term over the layers at q.
    for (int l = 1; l < kAoDepthLayers; ++l) {
        vec3 w = aoPosition(q, aoLayerDepth(q, l)) - C;
        term = max(term, aoScalableTerm(dot(w, w), dot(w, n), params.radius, params.bias, params.epsilon));
    }
#endif
    return term;
}

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    ivec2 size = textureSize(uDepth, 0);
    float z = aoDepth(p);
    // Sky is unoccluded. Its pixels still run the loop below (and discard the sum) rather than
    // returning here: with the depth MIP each tap's level varies per pixel, and lavapipe fetched
    // wrong texels for the other pixels of a SIMD block when one of its lanes had left early.
    bool sky = !(z < params.maxDepth);
    vec3 C = aoPosition(p, z);
    vec3 n = aoNormal(p, C, z, size);
    float screenRadius = aoScreenRadius(params.radius, params.pixelsPerUnit, z);
    if (kAoClampRadius != 0) screenRadius = min(screenRadius, params.maxRadiusPx);
    int rotation = aoRotationIndex(p);
    const int offsets = kAoMirrored != 0 ? kAoSamples / 2 : kAoSamples;
    float sum = 0.0;
    [[unroll]] for (int i = 0; i < offsets; ++i) {
        float h = aoSpiralTapRadius(i, offsets, screenRadius);
        vec2 d = aoTapDirection(aoSpiralTurnsQ16(i, params.spiralHalfStepQ16), rotation);
        int level = 0;
#ifdef SFX_AO_DEPTH_MIP  // generated from the tier table (TierProfile::aoUsesDepthMip)
        if (kAoMipLevels > 1 && h >= 1.0)
            level = clamp(aoFloorLog2(h) - SFX_AO_MIP_LEVEL_OFFSET, 0, kAoMipLevels - 1);
#endif
        sum += scalableTap(p, h, d, level, size, C, n);
        if (kAoMirrored != 0) sum += scalableTap(p, h, -d, level, size, C, n);
    }
    float occlusion = aoScalableOcclusion(sum, params.intensity, kAoSamples, params.sumExponent);
    aoWrite(sky ? 1.0 : aoFinish(occlusion), z, sky);
}
