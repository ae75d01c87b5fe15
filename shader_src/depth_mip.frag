#version 450
// One level of the depth MIP pyramid: the binding shows level i as lod 0; we write level i+1.
#include "sfx_shared.h"

layout(set = 0, binding = 0) uniform sampler2D uPreviousLevel;

layout(location = 0) out float outDepth;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    ivec2 src = min(depthMipSource(p), textureSize(uPreviousLevel, 0) - 1);
    outDepth = sfxTexel(uPreviousLevel, src, 0).r;
}
