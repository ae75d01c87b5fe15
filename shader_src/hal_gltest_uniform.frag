#version 450
// GL backend test: a uniform block (bound by name where the dialect drops binding=).
layout(set = 0, binding = 2, std140) uniform GlTestParams {
    vec4 base;
    vec4 step;
} params;
layout(location = 0) out vec4 outColor;
void main() {
    vec2 p = floor(gl_FragCoord.xy);
    outColor = params.base + params.step * vec4(p.x, p.y, 0.0, 0.0);
}
