#version 450
// A-buffer clear (high tier): every head to the end-of-list index and the pool's counter to 0,
// one dispatch before the fill.
#include "sfx_shared_oit.h"

layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 1, std430) buffer OitPool SFX_OIT_POOL_BODY
layout(set = 0, binding = 2, r32ui) uniform writeonly uimage2D uHeads;

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (pixel == ivec2(0)) pool.count = 0u;
    if (all(lessThan(pixel, imageSize(uHeads)))) imageStore(uHeads, pixel, uvec4(SFX_OIT_NULL_INDEX));
}
