#version 450
// The layer AO's bilateral filter, one direction per pass (sfx_shared_oit.h, oitFilterTapWeight):
// r (visibility blended through the layers) keyed by the front depth, g (the opaque surface's)
// by the opaque depth; the keys are the raw AO target's b and a (sfx_shared_oit_ao.h).
#define SFX_WANT_OIT_AO_PARAMS 1
#include "sfx_shared_oit_params.h"  // OitAoParams ao (binding 4): maxDepth
#include "sfx_shared_oit.h"

layout(set = 0, binding = 0) uniform sampler2D uSource;  // r, g: the visibilities to filter
layout(set = 0, binding = 1) uniform sampler2D uKeys;    // b, a: front and opaque depth (RGBA32F)
layout(location = 0) out vec4 outAo;
layout(constant_id = SFX_OIT_SC_FILTER_RADIUS) const int kRadius = 2;
layout(constant_id = SFX_OIT_SC_FILTER_VERTICAL) const int kVertical = 0;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    ivec2 size = textureSize(uSource, 0);
    ivec2 direction = kVertical != 0 ? ivec2(0, 1) : ivec2(1, 0);
    vec2 centre = texelFetch(uKeys, p, 0).ba;
    vec2 own = texelFetch(uSource, p, 0).rg;
    vec2 acc = vec2(0.0), weight = vec2(0.0);
    for (int k = -kRadius; k <= kRadius; ++k) {
        ivec2 q = p + k * direction;
        if (q.x < 0 || q.y < 0 || q.x >= size.x || q.y >= size.y) continue;
        vec2 keys = texelFetch(uKeys, q, 0).ba;
        vec2 v = texelFetch(uSource, q, 0).rg;
        vec2 w = vec2(oitFilterTapWeight(k, kRadius, keys.x, centre.x), oitFilterTapWeight(k, kRadius, keys.y, centre.y));
        acc += w * v;
        weight += w;
    }
    // The centre's own weight is 1 (its key equals itself), so neither sum is 0.
    float r = centre.x < ao.maxDepth ? acc.x / weight.x : own.x;
    float g = centre.y < ao.maxDepth ? acc.y / weight.y : own.y;
    outAo = vec4(r, g, 0.0, 1.0);
}
