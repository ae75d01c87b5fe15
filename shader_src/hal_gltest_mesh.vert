#version 450
// GL backend test: positions already in clip space, a colour per vertex.
layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec4 inColor;
layout(location = 0) out vec4 vColor;
void main() {
    vColor = inColor;
    gl_Position = vec4(inPosition, 1.0);
}
