#version 450
// The GL backend's depth readback on GL ES, where glReadPixels cannot read depth: a full-screen
// pass copies the bound level of a depth texture into an R32F target that can be read back.
// Built for the current tier, so it has every GL dialect (ESSL 300 under the GL ES 3.0 ceiling).
layout(set = 0, binding = 0) uniform sampler2D uDepth;
layout(location = 0) out vec4 outDepth;
void main() { outDepth = vec4(texelFetch(uDepth, ivec2(gl_FragCoord.xy), 0).x, 0.0, 0.0, 1.0); }
