#version 450
// HAL test: a later pass walks the lists the fragment-store pass built and writes
// length * 65536 + the sum of the values, so the fill's writes must be visible to it.
layout(location = 0) out uint outValue;
layout(set = 0, binding = 0, std430) readonly buffer ListNodes {
    uint count;
    uint capacity;
    uint nodes[];
} lists;
layout(set = 0, binding = 1, r32ui) uniform readonly uimage2D uHeads;
void main() {
    uint node = imageLoad(uHeads, ivec2(gl_FragCoord.xy)).x;
    uint steps = 0u, sum = 0u;
    while (node != 0xFFFFFFFFu && steps < 64u) {
        sum += lists.nodes[2u * node + 1u];
        node = lists.nodes[2u * node];
        steps += 1u;
    }
    outValue = steps * 65536u + sum;
}
