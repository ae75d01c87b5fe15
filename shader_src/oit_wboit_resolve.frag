#version 450
// Weighted blended OIT resolve (current tier): the weighted average colour covers
// 1 - revealage of the opaque colour (sfx_shared_oit.h).
#include "sfx_shared_oit.h"

layout(set = 0, binding = 0) uniform sampler2D uOpaque;
layout(set = 0, binding = 1) uniform sampler2D uAccum;
layout(set = 0, binding = 2) uniform sampler2D uWeight;
layout(location = 0) out vec4 outColor;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec4 opaque = texelFetch(uOpaque, pixel, 0);
    vec3 rgb = oitWeightedBlendedResolve(texelFetch(uAccum, pixel, 0), texelFetch(uWeight, pixel, 0), opaque.rgb);
    outColor = vec4(rgb, opaque.a);
}
