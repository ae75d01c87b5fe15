#version 450
#extension GL_EXT_control_flow_attributes : require
// Alchemy ambient obscurance (McGuire et al. 2011, eq. 10): samples uniform in the projected
// world-space disk, counted only inside the sphere of radius r. See docs/ao.md.
#define SFX_AO_PASS 1
#include "sfx_shared_ao.h"

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    ivec2 size = textureSize(uDepth, 0);
    float z = aoDepth(p);
    if (!(z < params.maxDepth)) { aoWrite(1.0, z, true); return; }
    vec3 C = aoPosition(p, z);
    vec3 n = aoNormal(p, C, z, size);
    float r = params.radius;
    float screenRadius = aoScreenRadius(r, params.pixelsPerUnit, z);
    int rotation = aoRotationIndex(p);
    float sum = 0.0;
    [[unroll]] for (int i = 0; i < kAoSamples; ++i) {
        ivec2 q = aoTap(p, aoDiskTapRadius(i, kAoSamples, screenRadius), aoTapDirection(aoAlchemyTurnsQ16(i), rotation), size);
        vec3 v = aoPosition(q, aoDepth(q)) - C;
        float term = aoAlchemyTerm(dot(v, v), dot(v, n), z, r, params.bias, params.epsilon);
#ifdef SFX_AO_MULTILAYER
        for (int l = 1; l < kAoDepthLayers; ++l) {  // multilayer AO: the largest term over the layers at q
            vec3 w = aoPosition(q, aoLayerDepth(q, l)) - C;
            term = max(term, aoAlchemyTerm(dot(w, w), dot(w, n), z, r, params.bias, params.epsilon));
        }
#endif
        sum += term;
    }
    aoWrite(aoFinish(2.0 * params.intensity * r / float(kAoSamples) * sum), z, false);
}
