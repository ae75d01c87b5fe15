#version 450
// HAL test: the integer-target twin of hal_test_pattern: R = x + 1000 y.
layout(location = 0) out uvec4 outValue;
void main() {
    uvec2 p = uvec2(gl_FragCoord.xy);
    outValue = uvec4(p.x + 1000u * p.y, p.y, p.x, 1u);
}
