#version 450
// Half-size depth for AO at half resolution where no depth MIP exists (the current tier, and
// Alchemy / Crease on the high tier): each texel takes the full-size depth at aoFullResPixel,
// the same rotated-grid sample as depth MIP level 1, so both tiers see the same half-size depth.
#include "sfx_shared_ao.h"

layout(set = 0, binding = 0) uniform sampler2D uDepth;  // full-size linear depth (maybe the host's)

layout(location = 0) out float outDepth;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    // Copied as it is: every reader clamps on fetch (sfxLinearDepthOrFar), as for level 0.
    outDepth = texelFetch(uDepth, aoFullResPixel(p, textureSize(uDepth, 0)), 0).r;
}
