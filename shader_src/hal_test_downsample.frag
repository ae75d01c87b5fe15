#version 450
// HAL test: the maximum of each 2x2 block of the bound level (lod 0 = the binding's baseMip),
// rendered into the next mip of the same texture.
layout(set = 0, binding = 0) uniform sampler2D uSource;
layout(location = 0) out vec4 outColor;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy) * 2;
    vec4 a = texelFetch(uSource, p, 0), b = texelFetch(uSource, p + ivec2(1, 0), 0);
    vec4 c = texelFetch(uSource, p + ivec2(0, 1), 0), d = texelFetch(uSource, p + ivec2(1, 1), 0);
    outColor = max(max(a, b), max(c, d));
}
