#version 450
// View-space unit normal (x right, y up, camera looking down -z) in rgb, 1 in alpha.
layout(location = 0) in vec3 vNormal;
layout(location = 0) out vec4 outNormal;
void main() {
    vec3 n = normalize(vNormal);
    // Two-sided surfaces: the normal faces the viewer.
    outNormal = vec4(gl_FrontFacing ? n : -n, 1.0);
}
