#version 450
// Hardware depth -> linear eye depth (positive distance along the view axis), by
// sfxLinearizeDepth in sfx_shared.h (the formula the CPU reference runs too).
#define SFX_WANT_LINEARIZE_PARAMS 1
#include "sfx_shared.h"

layout(set = 0, binding = 0) uniform sampler2D uHardwareDepth;

layout(location = 0) out float outLinearDepth;
// 1: the source already holds linear depth; only the clamp applies.
layout(constant_id = SFX_DEPTH_SC_LINEAR_INPUT) const int kLinearInput = 0;
// 1: a half-size level 0, each texel the source's depth at depthMipSource (MIP level 1's sample).
layout(constant_id = SFX_DEPTH_SC_HALF_SIZE_BASE) const int kHalfSizeBase = 0;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    ivec2 q = kHalfSizeBase != 0 ? min(depthMipSource(p), textureSize(uHardwareDepth, 0) - 1) : p;
    float d = sfxTexel(uHardwareDepth, q, 0).r;
    outLinearDepth = kLinearInput != 0 ? sfxLinearDepthOrFar(d, params.maxDepth)
                                               : sfxLinearizeDepth(d, params.ndcScale, params.denomOffset, params.numerator, params.maxDepth);
}
