#version 450
// Crease shading (Fox & Compton 2007): the 24 taps of the 11x11 stippled diamond, or on the
// current tier one checkerboard half of it per pixel (kAoSamples 12), its offsets times the
// stride that keeps its share of the image at every size; a tap occludes by how far the
// centre's normal faces it beyond the minimum crease, attenuated by distance.
#define SFX_AO_PASS 1
#include "sfx_shared_ao.h"

float creaseTap(ivec2 p, ivec2 offset, float stride, vec3 C, vec3 n, ivec2 size) {
    ivec2 q = aoTap(p, stride, vec2(offset), size);
    vec3 v = aoPosition(q, aoDepth(q)) - C;
    float term = aoCreaseTerm(dot(v, v), dot(v, n), params.creaseRange, params.creaseMinimum, params.creaseBias, params.epsilon);
#ifdef SFX_AO_MULTILAYER
    for (int l = 1; l < kAoDepthLayers; ++l) {  // multilayer AO: the largest term over the layers at q
        vec3 w = aoPosition(q, aoLayerDepth(q, l)) - C;
        term = max(term, aoCreaseTerm(dot(w, w), dot(w, n), params.creaseRange, params.creaseMinimum, params.creaseBias, params.epsilon));
    }
#endif
    return term;
}

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    ivec2 size = textureSize(uDepth, 0);
    float z = aoDepth(p);
    if (!(z < params.maxDepth)) { aoWrite(1.0, z, true); return; }
    vec3 C = aoPosition(p, z);
    vec3 n = aoNormal(p, C, z, size);
    float stride = aoCreaseStride(aoScreenRadius(params.radius, params.pixelsPerUnit, z));
    int parity = aoCreaseParity(p.x, p.y);
    float total = 0.0;
    // The loop runs over the halves' length so that compilers unroll it and every offset is a
    // constant (Mesa's NIR unrolls a loop indexing an array by its counter up to the array's
    // length): a loop of 12 over the 24-entry table stayed a loop on lavapipe and read the table
    // from memory, 26-46 ms for the 12 taps at half of 1280x720 against 16 ms for 24 unrolled.
    for (int j = 0; j < SFX_AO_CREASE_HALF_TAPS; ++j) {
        if (kAoSamples >= SFX_AO_CREASE_TAPS) {
            total += creaseTap(p, SFX_AO_CREASE_HALF_0[j], stride, C, n, size) + creaseTap(p, SFX_AO_CREASE_HALF_1[j], stride, C, n, size);
        } else {
            // The pixel selects between two constants: no per-pixel index into a table.
            total += creaseTap(p, parity == 0 ? SFX_AO_CREASE_HALF_0[j] : SFX_AO_CREASE_HALF_1[j], stride, C, n, size);
        }
    }
    float fade = 1.0 - clamp((z - params.fadeStart) * params.invFadeRange, 0.0, 1.0);
    aoWrite(aoFinish(aoCreaseOcclusion(total, kAoSamples, params.intensity, params.creaseAverager, fade)), z, false);
}
