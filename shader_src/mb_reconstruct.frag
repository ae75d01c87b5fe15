#version 450
#extension GL_EXT_control_flow_attributes : require
// Motion blur pass 4: gather reconstruction (docs/algorithms.md). Samples in mirrored pairs
// along the neighbourhood velocity v_N or the centre velocity v_C; each sample weighted by the
// soft depth comparison and the spread tests of sfx_shared_mb.h, the centre taking what the
// samples leave. Pixels with nothing moving near them return their colour untouched.
#define SFX_WANT_MB_RECONSTRUCT_PARAMS 1
#include "sfx_shared.h"
#include "sfx_shared_mb.h"

layout(set = 0, binding = 0) uniform sampler2D uColor;
layout(set = 0, binding = 1) uniform sampler2D uPacked;
layout(set = 0, binding = 2) uniform sampler2D uNeighborMax;
// params: the uniform block declared in sfx_shared_mb.h.

layout(location = 0) out vec4 outColor;
// Fixed per pipeline (sfx_shared_mb.h); MotionBlur gives both.
layout(constant_id = SFX_MB_SC_PAIRS) const int kPairs = 1;
layout(constant_id = SFX_MB_SC_JITTER_SIZE) const int kJitterSize = 2;

// Round half away from zero: the same on both sides of the centre, as the reference does.
vec2 roundAway(vec2 x) { return sign(x) * floor(abs(x) + 0.5); }

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec4 colorC = sfxColor(sfxTexel(uColor, p, 0));  // the colour rule of sfx_shared.h
    vec2 vN = sfxTexel(uNeighborMax, p / params.tileSize, 0).xy;
    if (length(vN) < SFX_MB_STILL_PX) {
        outColor = colorC;
        return;
    }
    ivec2 size = textureSize(uColor, 0);
    vec4 packedC = sfxTexel(uPacked, p, 0);
    vec2 vC = packedC.xy;
    float zC = packedC.z + packedC.w;
    float speedC = length(vC);
    float speedN = length(vN);
    float jitter = mbJitter(p.x, p.y, kJitterSize);
    int pairs = mbActivePairs(mbTexelSteps(vN), kPairs);
    // A pair follows v_C or v_N, so its ramp is one of two, computed once.
    float inverseWidthC = mbInverseRampWidth(speedC, pairs, params.radius);
    float inverseWidthN = mbInverseRampWidth(speedN, pairs, params.radius);

    vec4 sum = vec4(0.0);
    float total = 0.0;
    float window = 0.0;
    // The previous pair's texel offset on each side: a sample on the same texel is left out.
    ivec2 lastAhead = ivec2(0), lastBehind = ivec2(0);
    [[unroll]] for (int i = 0; i < kPairs; ++i) {
        if (i >= pairs) break;
        bool followsCentre = mbPairUsesCentre(i, speedC, speedN);
        vec2 v = followsCentre ? vC : vN;
        float speedV = followsCentre ? speedC : speedN;
        float inverseWidth = followsCentre ? inverseWidthC : inverseWidthN;
        [[unroll]] for (int s = 0; s < 2; ++s) {
            ivec2 off = ivec2(roundAway(mbSampleT(i, pairs, jitter, s == 0 ? 1.0 : -1.0, speedV) * v));
            // Repeated texels (sfx_shared_mb.h): weighed 0 rather than skipped, since a branch
            // here cost llvmpipe a third of the pass.
            ivec2 last = s == 0 ? lastAhead : lastBehind;
            float kept = mbRepeatsTexel(i, off.x, off.y, last.x, last.y) ? 0.0 : 1.0;
            if (s == 0)
                lastAhead = off;
            else
                lastBehind = off;
            // Clamped to the image: a sample never leaves it, however large the velocity.
            ivec2 q = clamp(p + off, ivec2(0), size - 1);
            float dist = length(vec2(q - p));
            vec4 packedS = sfxTexel(uPacked, q, 0);
            float speedS = length(packedS.xy);
            float zS = packedS.z + packedS.w;
            float w = kept * mbSampleWeight(zC, zS, speedC, speedS, dist, params.softExtent, inverseWidth);
            window += kept * mbSpread(dist, speedV, inverseWidth);
            vec4 colorS = sfxTexel(uColor, q, 0);
            if (!sfxColorIsFinite(colorS)) continue;  // a non-finite sample is left out (sfx_shared.h)
            sum += sfxColor(colorS) * w;
            total += w;
        }
    }
    float wC = mbCentreShare(params.centreWeight, total, window);
    sum += colorC * wC;
    total += wC;
    outColor = sum / total;
}
