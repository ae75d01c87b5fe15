#version 450
// HAL test: writes the colour of a uniform block, to see buffer contents and write ordering.
layout(set = 0, binding = 0, std140) uniform ColorParams {
    vec4 color;
} params;
layout(location = 0) out vec4 outColor;
void main() { outColor = params.color; }
