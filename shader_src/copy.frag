#version 450
// A full-screen copy: the baseline that effect costs are reported against. It reads through
// sfxTexel as the effects do, the cheaper of the two ways to read a texel on lavapipe (a
// texelFetch copy costs about 1.5 times the instructions), so no effect's ratio is flattered by
// a slow unit.
#include "sfx_shared.h"
layout(set = 0, binding = 0) uniform sampler2D uSource;
layout(location = 0) out vec4 outColor;
void main() { outColor = sfxTexel(uSource, ivec2(gl_FragCoord.xy), 0); }
