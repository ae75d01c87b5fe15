#version 450
// HAL test for fragment stores and atomics: every fragment that passes the (early) depth test
// appends a node to its pixel's list: a counter hands out node indices (atomicAdd), the pixel's
// head swaps to the new node (imageAtomicExchange), the node keeps the old head and a value.
// No colour output: the pass's only effects are the storage writes.
layout(early_fragment_tests) in;
layout(location = 0) flat in vec4 vColor;
layout(set = 0, binding = 0, std430) buffer ListNodes {
    uint count;
    uint capacity;
    uint nodes[];  // per node: next, value
} lists;
layout(set = 0, binding = 1, r32ui) uniform coherent uimage2D uHeads;
void main() {
    uint index = atomicAdd(lists.count, 1u);
    if (index >= lists.capacity) return;  // full: counted, not stored
    uint previous = imageAtomicExchange(uHeads, ivec2(gl_FragCoord.xy), index);
    lists.nodes[2u * index] = previous;
    lists.nodes[2u * index + 1u] = uint(vColor.r * 255.0 + 0.5);
}
