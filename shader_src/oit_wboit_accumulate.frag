#version 450
// Weighted blended OIT accumulation (current tier; McGuire and Bavoil 2013): each transparent
// fragment in front of the opaque depth adds its weighted premultiplied colour to target 0's
// rgb and its weighted alpha to target 1's r, and multiplies target 0's a (the revealage) by
// 1 - alpha, all through one blend state (sfx_shared_oit.h: colour ONE, ONE; alpha ZERO,
// ONE_MINUS_SRC_ALPHA), which GL ES 3.0 can express.
#define SFX_WANT_OIT_DRAW_PARAMS 1
#include "sfx_shared_oit_params.h"  // OitDrawParams draw (binding 0)
#include "sfx_shared_oit.h"

layout(location = 0) in vec3 vViewPosition;
layout(location = 1) in vec3 vNormal;
layout(location = 2) flat in uint vPrimitive;
layout(location = 0) out vec4 outAccum;
layout(location = 1) out vec4 outWeight;

void main() {
    float alpha = clamp(draw.color.a, 0.0, 1.0);
    oitWeightedBlendedOutputs(vec4(draw.color.rgb * alpha, alpha), -vViewPosition.z, outAccum, outWeight);
}
