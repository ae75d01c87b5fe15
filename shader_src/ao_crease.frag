#version 450
// Crease shading (Fox & Compton 2007): 24 taps on the 11x11 stippled diamond; a tap occludes by
// how far the centre's normal faces it beyond the minimum crease, attenuated by distance.
#define SFX_AO_PASS 1
#include "sfx_shared_ao.h"

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    ivec2 size = textureSize(uDepth, 0);
    float z = aoDepth(p);
    if (!(z < params.maxDepth)) { aoWrite(1.0, z, true); return; }
    vec3 C = aoPosition(p, z);
    vec3 n = aoNormal(p, C, z, size);
    float total = 0.0;
    for (int i = 0; i < SFX_AO_CREASE_TAPS; ++i) {
        ivec2 q = clamp(p + SFX_AO_CREASE_OFFSETS[i], ivec2(0), size - 1);
        vec3 v = aoPosition(q, aoDepth(q)) - C;
        float term = aoCreaseTerm(dot(v, v), dot(v, n), params.creaseRange, params.creaseMinimum, params.creaseBias, params.epsilon);
#ifdef SFX_AO_MULTILAYER
        for (int l = 1; l < kAoDepthLayers; ++l) {  // multilayer AO: the largest term over the layers at q
            vec3 w = aoPosition(q, aoLayerDepth(q, l)) - C;
            term = max(term, aoCreaseTerm(dot(w, w), dot(w, n), params.creaseRange, params.creaseMinimum, params.creaseBias, params.epsilon));
        }
#endif
        total += term;
    }
    float fade = 1.0 - clamp((z - params.fadeStart) * params.invFadeRange, 0.0, 1.0);
    aoWrite(aoFinish(params.intensity * total / params.creaseAverager * fade), z, false);
}
