#version 450
// The depth peel's vertex stage (raster_depth_peel.frag): the G-buffer raster pass's transform
// (raster_gbuffer.vert, same RasterParams), with only the view position the peel needs passed on.
#define SFX_WANT_RASTER_PARAMS 1
#include "sfx_shared_raster.h"  // RasterParams raster (binding 0)

layout(location = 0) in vec3 inPosition;
layout(location = 0) out vec3 vViewPosition;

void main() {
    vec4 viewPosition = raster.modelView * vec4(inPosition, 1.0);
    vViewPosition = viewPosition.xyz;
    gl_Position = raster.projection * viewPosition;
}
