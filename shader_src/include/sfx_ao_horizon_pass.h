// The body of the horizon obscurance pass (ao_horizon.frag; ao_horizon_bent.frag defines
// SFX_AO_BENT_NORMALS first and also writes the bent normal to a second attachment, which only
// its pipelines have). Horizon-based AO (Jimenez et al. 2016, GTAO) as a fragment pass:
// kAoSamples slices per pixel, each marched both ways in kAoHorizonSteps steps evenly spread over
// the radius, the highest horizon above the tangent plane per side kept (thickness heuristic,
// falloff at the radius's edge), then the cosine-weighted visible arc in closed form
// (sfx_shared_ao_horizon.h). High tier: far steps read the depth MIP level their distance calls
// for, as Scalable's taps do.
#ifndef SFX_AO_HORIZON_PASS_H
#define SFX_AO_HORIZON_PASS_H
#define SFX_AO_PASS 1
#include "sfx_shared_ao_horizon.h"

#ifdef SFX_AO_BENT_NORMALS
layout(location = 1) out vec4 outBent;
// 1: the bent normal's target is RGBA8 (xyz * 0.5 + 0.5), else float (signed xyz).
layout(constant_id = SFX_AO_SC_BENT_UNORM) const int kAoBentUnorm = 0;
#endif

float horizonSampleSin(ivec2 p, float rho, vec2 d, int level, ivec2 size, vec3 C, vec3 n, float invProjectedLength) {
    ivec2 q = aoTap(p, rho, d, size);
    ivec2 m = aoMipTexel(q, level, size);
    vec3 v = aoPosition(q, aoDepthAt(m, level)) - C;
    return aoHorizonSampleSin(v, n, invProjectedLength, params.radius, params.horizonInvFalloffWidth, params.epsilon);
}

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    ivec2 size = textureSize(uDepth, 0);
    float z = aoDepth(p);
    // Sky runs the loop too and discards it (ao_scalable.frag says why: per-pixel MIP levels).
    bool sky = !(z < params.maxDepth);
    vec3 C = aoPosition(p, z);
    vec3 n = aoNormal(p, C, z, size);
    vec3 V = aoHorizonViewVector(C);
    float screenRadius = aoScreenRadius(params.radius, params.pixelsPerUnit, z);
    uint hash = aoRotationHash(p);
    int rotation = int(hash & 0xFFu);
    float visibleSum = 0.0, openSum = 0.0;
#ifdef SFX_AO_BENT_NORMALS
    vec3 bentSum = vec3(0.0), openBentSum = vec3(0.0);
#endif
    [[unroll]] for (int i = 0; i < kAoSamples; ++i) {
        vec2 d = aoTapDirection(aoHorizonSliceTurnsQ16(i, kAoSamples), rotation);
        vec3 u = aoHorizonSliceDirection(d.x, d.y, params.projInfo.x, params.projInfo.y, V);
        vec3 t = aoHorizonSliceTangent(u);
        float weight = aoHorizonSliceWeight(u);
        vec3 projected = aoHorizonProjectedNormal(n, V, t);
        int jitter = aoHorizonJitterIndex(hash, i);
        float invProjectedLength = 1.0 / projected.x;
        float plusSin = 0.0, minusSin = 0.0;  // both sides start at the tangent plane
        [[unroll]] for (int j = 0; j < kAoHorizonSteps; ++j) {
            float rho = aoHorizonStepRadius(j, kAoHorizonSteps, jitter, screenRadius);
            int level = 0;
#ifdef SFX_AO_DEPTH_MIP  // generated from the tier table (TierProfile::aoUsesDepthMip)
            if (kAoMipLevels > 1) level = clamp(aoFloorLog2(rho) - SFX_AO_MIP_LEVEL_OFFSET, 0, kAoMipLevels - 1);
#endif
            plusSin = aoHorizonUpdate(plusSin, horizonSampleSin(p, rho, d, level, size, C, n, invProjectedLength), params.horizonThickness);
            minusSin = aoHorizonUpdate(minusSin, horizonSampleSin(p, rho, -d, level, size, C, n, invProjectedLength), params.horizonThickness);
        }
        float nAngle = aoHorizonNormalAngle(projected);
        visibleSum += weight * aoHorizonSliceVisibility(plusSin, minusSin, projected, nAngle);
        openSum += weight * aoHorizonSliceVisibility(0.0, 0.0, projected, nAngle);
#ifdef SFX_AO_BENT_NORMALS
        bentSum += weight * aoHorizonSliceBent(plusSin, minusSin, projected, nAngle, V, t);
        openBentSum += weight * aoHorizonSliceBent(0.0, 0.0, projected, nAngle, V, t);
#endif
    }
    float visibility = aoHorizonRatio(visibleSum, openSum);
    aoWrite(sky ? 1.0 : aoFinish(params.intensity * (1.0 - visibility)), z, sky);
#ifdef SFX_AO_BENT_NORMALS
    vec3 bent = sky ? vec3(0.0, 0.0, 1.0) : aoHorizonBentNormal(aoHorizonBentVector(bentSum, openBentSum, visibleSum, openSum, n), n);
    outBent = aoBentEncode(bent, kAoBentUnorm != 0);
#endif
}

#endif  // SFX_AO_HORIZON_PASS_H

