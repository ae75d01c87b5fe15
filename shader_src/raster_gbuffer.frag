#version 450
// Outputs: 0 = view-space unit normal (x right, y up, camera looking down -z), a = 1;
//          1 = velocity in pixels across the shutter interval (x toward increasing column,
//              y toward increasing memory row), the convention of sfx/motion_blur.hpp;
//          2 = albedo: the object's colour with its shading code in a (RasterParams.surface),
//              or, when surface.a is 0, a checker on the object's own coordinates, so motion shows.
#define SFX_WANT_RASTER_PARAMS 1
#include "sfx_shared_raster.h"  // RasterParams raster (binding 0)

layout(location = 0) in vec3 vNormal;
layout(location = 1) in vec3 vViewPosition;
layout(location = 2) in vec4 vOpenClip;
layout(location = 3) in vec4 vCloseClip;
layout(location = 4) in vec3 vObjectPosition;
layout(location = 0) out vec4 outNormal;
layout(location = 1) out vec2 outVelocity;
layout(location = 2) out vec4 outAlbedo;

void main() {
    vec3 n = normalize(vNormal);
    // Two-sided surfaces: turn the normal toward the viewer. Decided by the view vector, not
    // gl_FrontFacing, which a y-flipping projection (row 0 = top) inverts.
    if (dot(n, vViewPosition) > 0.0) n = -n;
    outNormal = vec4(n, 1.0);

    // NDC y = -1 is memory row 0 on every API, so pixel = (ndc * 0.5 + 0.5) * size.
    vec2 openPixel = (vOpenClip.xy / vOpenClip.w * 0.5 + 0.5) * raster.viewportSize.xy;
    vec2 closePixel = (vCloseClip.xy / vCloseClip.w * 0.5 + 0.5) * raster.viewportSize.xy;
    outVelocity = closePixel - openPixel;

    if (raster.surface.a > 0.0) {
        outAlbedo = raster.surface;
    } else {
        ivec3 cell = ivec3(floor(vObjectPosition * 4.0));
        float checker = ((cell.x + cell.y + cell.z) & 1) == 0 ? 1.0 : 0.55;
        outAlbedo = vec4(vec3(0.85, 0.8, 0.72) * checker, SFX_RASTER_SHADING_LAMBERT);
    }
}
