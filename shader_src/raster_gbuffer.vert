#version 450
// Rasterises scene meshes into hardware depth, view-space normals, screen-space velocity and
// a textured albedo (the sample scenes' G-buffer).
#define SFX_WANT_RASTER_PARAMS 1
#include "sfx_shared_raster.h"  // RasterParams raster (binding 0)

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 0) out vec3 vNormal;
layout(location = 1) out vec3 vViewPosition;
layout(location = 2) out vec4 vOpenClip;
layout(location = 3) out vec4 vCloseClip;
layout(location = 4) out vec3 vObjectPosition;

void main() {
    vNormal = mat3(raster.normalMatrix) * inNormal;
    vec4 viewPosition = raster.modelView * vec4(inPosition, 1.0);
    vViewPosition = viewPosition.xyz;
    vOpenClip = raster.shutterOpenClip * vec4(inPosition, 1.0);
    vCloseClip = raster.shutterCloseClip * vec4(inPosition, 1.0);
    vObjectPosition = inPosition;
    gl_Position = raster.projection * viewPosition;
}
