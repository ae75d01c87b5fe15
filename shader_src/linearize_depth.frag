#version 450
// Hardware depth -> linear eye depth (positive distance along the view axis), by
// sfxLinearizeDepth in sfx_shared.h (the formula the CPU reference runs too).
#include "sfx_shared.h"

layout(set = 0, binding = 0) uniform sampler2D uHardwareDepth;
layout(set = 0, binding = 1, std140) uniform LinearizeParams {
    float ndcScale;     // 1 for [0,1] clip depth, 2 for [-1,1]
    float denomOffset;  // ndcOffset + A
    float numerator;    // B
    float maxDepth;     // far plane, or SFX_SKY_DEPTH for an infinite projection
    float linearInput;  // 1: the source already holds linear depth; only the clamp applies
} params;

layout(location = 0) out float outLinearDepth;

void main() {
    float d = texelFetch(uHardwareDepth, ivec2(gl_FragCoord.xy), 0).r;
    outLinearDepth = params.linearInput != 0.0 ? sfxLinearDepthOrFar(d, params.maxDepth)
                                               : sfxLinearizeDepth(d, params.ndcScale, params.denomOffset, params.numerator, params.maxDepth);
}
