#version 450
// GL backend test: max of a 2x2 footprint of the previous mip, bound as the shader's lod 0.
layout(set = 0, binding = 1) uniform sampler2D uPrevious;
layout(location = 0) out float outValue;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy) * 2;
    ivec2 last = textureSize(uPrevious, 0) - 1;
    float m = texelFetch(uPrevious, min(p, last), 0).x;
    m = max(m, texelFetch(uPrevious, min(p + ivec2(1, 0), last), 0).x);
    m = max(m, texelFetch(uPrevious, min(p + ivec2(0, 1), last), 0).x);
    m = max(m, texelFetch(uPrevious, min(p + ivec2(1, 1), last), 0).x);
    outValue = m;
}
