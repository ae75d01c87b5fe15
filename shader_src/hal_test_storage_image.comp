#version 450
// HAL test for storage images (high tier): every texel of mip `uImage` gets x + 16 y.
layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 0, r32f) uniform writeonly image2D uImage;
void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    imageStore(uImage, p, vec4(float(p.x + 16 * p.y), 0.0, 0.0, 1.0));
}
