#version 450
// View-space unit normal (x right, y up, camera looking down -z) in rgb, 1 in alpha.
layout(location = 0) in vec3 vNormal;
layout(location = 1) in vec3 vViewPosition;
layout(location = 0) out vec4 outNormal;
void main() {
    vec3 n = normalize(vNormal);
    // Two-sided surfaces: turn the normal toward the viewer. Decided by the view vector, not
    // gl_FrontFacing, which a y-flipping projection (row 0 = top) inverts.
    if (dot(n, vViewPosition) > 0.0) n = -n;
    outNormal = vec4(n, 1.0);
}
