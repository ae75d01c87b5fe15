#version 450
// GL backend test: a texel-exact pattern from gl_FragCoord (values k/256 are exact in
// half and float, and round predictably to unorm8).
layout(location = 0) out vec4 outColor;
void main() {
    vec2 p = floor(gl_FragCoord.xy);
    outColor = vec4(p.x, p.y, p.x + 2.0 * p.y, 128.0) / 256.0;
}
