#version 450
// One depth-peeling pass for multilayer AO (sfx render --ao-layers N, tools/render/
// scene_depth_peel.cpp): with the pass's own depth test (less), each pixel keeps the nearest
// opaque fragment strictly behind the previous layer and writes its linear depth. The vertex
// stage (raster_depth_peel.vert) transforms as the G-buffer raster pass does.
#define SFX_WANT_RASTER_PARAMS 1
#include "sfx_shared_raster.h"  // RasterParams raster (binding 0)

layout(location = 0) in vec3 vViewPosition;
layout(set = 0, binding = 1) uniform sampler2D uPreviousLayer;  // R32F linear depth of the layer in front; 0: none
layout(location = 0) out vec4 outLayer;                          // R32F: this layer's linear depth; cleared to 0 (none)

// "Strictly behind": farther than the previous layer by this fraction of its depth. The
// previous layer 0 comes from linearising 32-bit hardware depth, not from this interpolation,
// so the surface itself must not pass again; 1e-3 is well above either's rounding and thin
// enough (1 mm at 1 m) for any surface pair the scenes hold.
const float kPeelRelativeGap = 1.0e-3;

void main() {
    float z = -vViewPosition.z;
    float previous = texelFetch(uPreviousLayer, ivec2(gl_FragCoord.xy), 0).r;
    // No layer in front (0): nothing behind it either. Past the previous layer only.
    if (!(previous > 0.0) || !(z > previous * (1.0 + kPeelRelativeGap))) discard;
    outLayer = vec4(z, 0.0, 0.0, 1.0);
}
