#version 450
// Half-size depth for AO at half resolution where no depth MIP exists (the current tier, and
// Alchemy / Crease on the high tier): each texel takes the full-size depth at aoFullResPixel,
// the same rotated-grid sample as depth MIP level 1, so both tiers see the same half-size depth.
#define SFX_WANT_LINEARIZE_PARAMS 1
#include "sfx_shared_ao.h"

layout(set = 0, binding = 0) uniform sampler2D uDepth;  // full-size linear depth, or the host's hardware depth
// LinearizeParams (binding 1): sfx_shared.h, LinearDepth's constants.
layout(constant_id = SFX_AO_SC_HALF_DEPTH_LINEARIZE) const int kLinearize = 0;

layout(location = 0) out float outDepth;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    float d = sfxTexel(uDepth, aoFullResPixel(p, textureSize(uDepth, 0)), 0).r;
    // Linear depth is copied as it is (every reader clamps on fetch, as for level 0); hardware
    // depth is linearized by the linearisation pass's own formula, which then never runs.
    outDepth = kLinearize != 0 ? sfxLinearizeDepth(d, params.ndcScale, params.denomOffset, params.numerator, params.maxDepth) : d;
}
