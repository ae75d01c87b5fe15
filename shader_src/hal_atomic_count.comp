#version 450
// HAL contract test for compute, storage buffers and atomics: every invocation adds its
// index to a total and increments a counter.
layout(local_size_x = 64) in;
layout(set = 0, binding = 0, std430) buffer Counters {
    uint count;
    uint sum;
    uint values[];
} counters;
void main() {
    uint i = gl_GlobalInvocationID.x;
    atomicAdd(counters.count, 1u);
    atomicAdd(counters.sum, i);
    counters.values[i] = i * 3u;
}
