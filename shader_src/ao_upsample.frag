#version 450
// Depth-aware upsample of half-size AO to the host's full-size output: the 2x2 half-size texels
// around each pixel, bilinear weights times a depth weight against the full-size depth, so
// edges stay as sharp as the full-size depth (sfx_shared_ao.h, "AO at half resolution").
#define SFX_AO_UPSAMPLE_PASS 1
#include "sfx_shared_ao.h"

layout(set = 0, binding = 0) uniform sampler2D uDepth;      // full-size linear depth (maybe the host's), + MIP
layout(set = 0, binding = 1) uniform sampler2D uHalfDepth;  // the depth the half-size AO was computed on,
                                                            // or uDepth again when it is its level 1
layout(set = 0, binding = 2) uniform sampler2D uSource;     // half-size visibility in r
// UpsampleParams (binding 3): sfx_shared_ao.h.
layout(location = 0) out vec4 outAo;
layout(constant_id = SFX_AO_SC_UPSAMPLE_DEPTH_MIP) const int kHalfDepthIsMip = 0;

float halfDepth(ivec2 q) { return kHalfDepthIsMip != 0 ? texelFetch(uDepth, q, 1).r : texelFetch(uHalfDepth, q, 0).r; }

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    float z0 = sfxLinearDepthOrFar(texelFetch(uDepth, p, 0).r, params.maxDepth);
    if (!(z0 < params.maxDepth)) {
        outAo = vec4(1.0);
        return;
    }
    ivec2 halfSize = textureSize(uSource, 0);
    ivec2 base = ivec2(aoUpsampleBase(p.x), aoUpsampleBase(p.y));
    vec2 upper = vec2(aoUpsampleUpperWeight(p.x), aoUpsampleUpperWeight(p.y));
    float acc = 0.0, wsum = 0.0, nearestAo = 1.0, nearestGap = -1.0;
    for (int j = 0; j < 2; ++j) {
        for (int i = 0; i < 2; ++i) {
            ivec2 q = clamp(base + ivec2(i, j), ivec2(0), halfSize - 1);
            float zq = sfxLinearDepthOrFar(halfDepth(q), params.maxDepth);
            float a = texelFetch(uSource, q, 0).r;
            float bilinear = (i == 1 ? upper.x : 1.0 - upper.x) * (j == 1 ? upper.y : 1.0 - upper.y);
            float w = aoUpsampleWeight(bilinear, zq, z0);
            acc += w * a;
            wsum += w;
            float gap = abs(zq - z0);
            if (nearestGap < 0.0 || gap < nearestGap) {
                nearestGap = gap;
                nearestAo = a;
            }
        }
    }
    float v = clamp(aoUpsampleResolve(acc, wsum, nearestAo), 0.0, 1.0);
    outAo = vec4(v, v, v, 1.0);
}
