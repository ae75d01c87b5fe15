#version 450
// A-buffer fill (high tier): every transparent fragment in front of the opaque depth (early
// depth test, so hidden fragments store nothing) takes a node index from the pool's counter
// and swaps itself in as its pixel's list head. No locks and no waiting on other invocations:
// one atomicAdd and one imageAtomicExchange. A fragment whose index is past the pool's capacity
// is not stored; it still counted, so the host learns how many were dropped.
#define SFX_WANT_OIT_DRAW_PARAMS 1
#include "sfx_shared_oit_params.h"  // OitDrawParams draw (binding 0)
#include "sfx_shared_oit.h"

layout(early_fragment_tests) in;
layout(location = 0) in vec3 vViewPosition;
layout(location = 1) in vec3 vNormal;
layout(location = 2) flat in uint vPrimitive;

layout(set = 0, binding = 1, std430) buffer OitPool SFX_OIT_POOL_BODY
layout(set = 0, binding = 2, r32ui) uniform coherent uimage2D uHeads;

void main() {
    uint index = atomicAdd(pool.count, 1u);
    if (index >= pool.capacity) return;
    uint next = imageAtomicExchange(uHeads, ivec2(gl_FragCoord.xy), index);
    float alpha = clamp(draw.color.a, 0.0, 1.0);
    vec4 premultiplied = vec4(draw.color.rgb * alpha, alpha);
    uvec4 lo, hi;
    // Front-facing means the authored normal faces the camera (the paper's W(p)), whatever the
    // winding or the API's y direction: the same rule as the reference's.
    vec3 normal = normalize(vNormal);
    bool front = dot(normal, vViewPosition) < 0.0;
    oitPackNode(premultiplied, -vViewPosition.z, normal, front, uint(draw.drawId), vPrimitive, next, lo, hi);
    pool.nodes[2u * index] = lo;
    pool.nodes[2u * index + 1u] = hi;
}
