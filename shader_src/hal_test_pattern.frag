#version 450
// HAL test: a known value per texel from its integer coordinates, so readbacks can be exact.
// R = x + 16 y, G = y, B = x, A = 1, all times `scale` (1/255 for unorm targets).
layout(set = 0, binding = 0, std140) uniform PatternParams {
    vec4 scale;
} pattern;
layout(location = 0) out vec4 outColor;
void main() {
    vec2 p = floor(gl_FragCoord.xy);
    outColor = vec4(p.x + 16.0 * p.y, p.y, p.x, 1.0) * pattern.scale;
}
