#version 450
// Hardware depth -> linear eye depth (positive distance along the view axis), by
// sfxLinearizeDepth in sfx_shared.h (the formula the CPU reference runs too).
#define SFX_WANT_LINEARIZE_PARAMS 1
#include "sfx_shared.h"

layout(set = 0, binding = 0) uniform sampler2D uHardwareDepth;

layout(location = 0) out float outLinearDepth;
// 1: the source already holds linear depth; only the clamp applies.
layout(constant_id = SFX_DEPTH_SC_LINEAR_INPUT) const int kLinearInput = 0;

void main() {
    float d = sfxTexel(uHardwareDepth, ivec2(gl_FragCoord.xy), 0).r;
    outLinearDepth = kLinearInput != 0 ? sfxLinearDepthOrFar(d, params.maxDepth)
                                               : sfxLinearizeDepth(d, params.ndcScale, params.denomOffset, params.numerator, params.maxDepth);
}
