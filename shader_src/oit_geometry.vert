#version 450
// Transparent geometry (both OIT paths): object-space positions and normals of a non-indexed
// triangle list to view space. The primitive id is the vertex index / 3, the same for the three
// vertices of a triangle, so it reaches the fragment stage flat on every API without
// gl_PrimitiveID (which ESSL 3.1 lacks in fragment shaders).
#define SFX_WANT_OIT_DRAW_PARAMS 1
#include "sfx_shared_oit_params.h"  // OitDrawParams draw (binding 0)

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 0) out vec3 vViewPosition;
layout(location = 1) out vec3 vNormal;
layout(location = 2) flat out uint vPrimitive;

void main() {
    vec4 viewPosition = draw.modelView * vec4(inPosition, 1.0);
    vViewPosition = viewPosition.xyz;
    vNormal = mat3(draw.normalMatrix) * inNormal;
    vPrimitive = uint(gl_VertexIndex) / 3u;
    gl_Position = draw.projection * viewPosition;
}
