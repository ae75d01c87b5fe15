#version 450
// HAL test: positions straight to clip space with a per-vertex colour, for depth, index,
// culling and blending checks.
layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec4 inColor;
layout(location = 0) flat out vec4 vColor;
void main() {
    vColor = inColor;
    gl_Position = vec4(inPosition, 1.0);
}
