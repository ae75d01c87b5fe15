// The uniform blocks and storage layout of the transparency passes (shader_src/oit_*.{vert,frag}),
// declared once for GLSL and for the C++ that fills them (sdk/src/effects/oit*.cpp), with the
// SFX_BLOCK macros of sfx_shared.h. The node layout itself is sfx_shared_oit.h's.
#ifndef SFX_SHARED_OIT_PARAMS_H
#define SFX_SHARED_OIT_PARAMS_H

#include "sfx_shared.h"

#ifdef __cplusplus
namespace sfx::shared {
#endif

// One transparent draw: its transforms, straight colour and opacity, and the id that orders
// its fragments against other draws' at equal depth.
#if defined(__cplusplus) || defined(SFX_WANT_OIT_DRAW_PARAMS)
SFX_BLOCK(OitDrawParams, 0)
    SFX_M_MAT4(modelView)
    SFX_M_MAT4(projection)
    SFX_M_MAT4(normalMatrix)  // inverse transpose of modelView (upper 3x3 used)
    SFX_M_VEC4(color)         // straight linear rgb, opacity in a
    SFX_M_INT(drawId)         // [0, 2^31)
SFX_BLOCK_END(draw)
#endif

// The A-buffer resolve.
#if defined(__cplusplus) || defined(SFX_WANT_OIT_RESOLVE_PARAMS)
SFX_BLOCK(OitResolveParams, 4)
    SFX_M_INT(maxLayers)  // K: fragments kept exactly per pixel, [1, SFX_OIT_MAX_KEPT_LAYERS]
    SFX_M_INT(capacity)   // nodes in the pool: no list walk takes more steps than this
SFX_BLOCK_END(resolve)
#endif

// The node pool's fixed header (storage buffer OitPool, before the nodes):
//   count     nodes handed out by the fill's atomicAdd this frame, stored or not (> capacity:
//             count - capacity fragments were dropped)
//   capacity  nodes the pool holds; a fragment whose index is at or past it is not stored
SFX_CONST(int, SFX_OIT_POOL_HEADER_BYTES, 16)

#ifdef __cplusplus
static_assert(sizeof(OitDrawParams) == 224 && offsetof(OitDrawParams, drawId) == 208);
}  // namespace sfx::shared
#endif

#endif  // SFX_SHARED_OIT_PARAMS_H
