// The uniform block of the sample scenes' G-buffer raster pass (raster_gbuffer.vert/.frag),
// declared once for GLSL and for the C++ that fills it (tools/scenes/scene.cpp), with the
// SFX_BLOCK macros of sfx_shared.h. Samples and tests only; no effect uses it.
#ifndef SFX_SHARED_RASTER_H
#define SFX_SHARED_RASTER_H

#include "sfx_shared.h"

#ifdef __cplusplus
namespace sfx::shared {
#endif

// The albedo target's alpha says how a composite shades the pixel: 0 = nothing drawn, else one
// of these codes (an RGBA8 target stores 0.5 as 128/255, so readers compare against 0.75).
SFX_CONST(float, SFX_RASTER_SHADING_LAMBERT, 1.0)  // colour * (ambient * AO + light * n.l)
SFX_CONST(float, SFX_RASTER_SHADING_UNLIT, 0.5)    // the colour exactly

#if defined(__cplusplus) || defined(SFX_WANT_RASTER_PARAMS)
SFX_BLOCK(RasterParams, 0)
    SFX_M_MAT4(modelView)
    SFX_M_MAT4(projection)
    SFX_M_MAT4(normalMatrix)      // inverse transpose of modelView (upper 3x3 used)
    SFX_M_MAT4(shutterOpenClip)   // projection * view * model at the start of the shutter interval
    SFX_M_MAT4(shutterCloseClip)  // ... and at its end; the frame itself is mid-shutter
    SFX_M_VEC4(viewportSize)      // width, height in pixels
    SFX_M_VEC4(surface)           // rgb: linear colour; a: shading code (below), 0 = the samples' checker
SFX_BLOCK_END(raster)
#endif
#ifdef __cplusplus
static_assert(sizeof(RasterParams) == 352 && offsetof(RasterParams, viewportSize) == 320 && offsetof(RasterParams, surface) == 336);
}  // namespace sfx::shared
#endif

#endif  // SFX_SHARED_RASTER_H
