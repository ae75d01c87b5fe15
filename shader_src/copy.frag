#version 450
// A full-screen copy: the baseline that effect costs are reported against.
layout(set = 0, binding = 0) uniform sampler2D uSource;
layout(location = 0) out vec4 outColor;
void main() { outColor = texelFetch(uSource, ivec2(gl_FragCoord.xy), 0); }
