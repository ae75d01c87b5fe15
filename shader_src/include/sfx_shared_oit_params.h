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
    SFX_M_INT(pad0) SFX_M_INT(pad1) SFX_M_INT(pad2)  // to 16 bytes, so the block is sizeof's 224
SFX_BLOCK_END(draw)
#endif

// The A-buffer resolve.
#if defined(__cplusplus) || defined(SFX_WANT_OIT_RESOLVE_PARAMS)
SFX_BLOCK(OitResolveParams, 4)
    SFX_M_INT(maxLayers)  // K: fragments kept exactly per pixel, [1, SFX_OIT_MAX_KEPT_LAYERS]
    // No list walk takes more steps than the pool header's capacity, read from the pool itself:
    // a loop bound from this block would make lavapipe recompile the pass at every draw.
    SFX_M_INT(pad0) SFX_M_INT(pad1) SFX_M_INT(pad4)
    // The compressing resolve (oit_resolve_compress.frag) only: the opaque depth's linearisation
    // (sfxLinearizeDepth) and the range [zNear, zFar] depths are normalised over.
    SFX_M_FLOAT(ndcScale) SFX_M_FLOAT(denomOffset) SFX_M_FLOAT(numerator) SFX_M_FLOAT(maxDepth)
    SFX_M_FLOAT(zNear) SFX_M_FLOAT(zFar) SFX_M_FLOAT(pad2) SFX_M_FLOAT(pad3)
SFX_BLOCK_END(resolve)
#endif

// Specialisation constants of the compressing resolve: M, and whether only the back half is
// searched for the node to drop (SFX_OIT_SC_* ids, plain macros for both languages).
#define SFX_OIT_SC_COMPRESS_NODES 0
#define SFX_OIT_SC_COMPRESS_BACK_HALF 1
// Both resolves: 1 when layer AO follows, so the resolve writes each node's transmittance in
// front of it (word 7 of the node, sfx_shared_oit.h) while it has the list sorted.
#define SFX_OIT_SC_RESOLVE_TRANSMITTANCE 2

// The compressed lists (storage buffer OitCompressed): SFX_OIT_COMPRESSED_WORDS words per pixel,
// pixel (x, y) at word (y * width + x) * SFX_OIT_COMPRESSED_WORDS: the x, y and z of the packed
// texel of sfx_shared_oit.h (16-bit depths of nodes 0-3, 8-bit opacities). 12 bytes per pixel.
SFX_CONST(int, SFX_OIT_COMPRESSED_WORDS, 3)

// Opacity-based AO through the layers (oit_ao.frag, oit_ao_compressed.frag).
#if defined(__cplusplus) || defined(SFX_WANT_OIT_AO_PARAMS)
SFX_BLOCK(OitAoParams, 4)
    SFX_M_VEC4(projInfo)
    SFX_M_FLOAT(radius) SFX_M_FLOAT(intensity) SFX_M_FLOAT(contrast) SFX_M_FLOAT(bias)
    SFX_M_FLOAT(epsilon) SFX_M_FLOAT(pixelsPerUnit) SFX_M_FLOAT(maxRadiusPx) SFX_M_FLOAT(maxDepth)
    SFX_M_INT(spiralHalfStepQ16) SFX_M_FLOAT(ndcScale) SFX_M_FLOAT(denomOffset) SFX_M_FLOAT(numerator)
    SFX_M_FLOAT(zNear) SFX_M_FLOAT(zFar) SFX_M_INT(pad0) SFX_M_FLOAT(sumExponent)  // walks: the pool header's capacity
SFX_BLOCK_END(ao)
#endif
// Its specialisation constants: the technique (0 Alchemy, 1 Scalable), taps, mirrored pairs.
#define SFX_OIT_SC_AO_TECHNIQUE 0
#define SFX_OIT_SC_AO_SAMPLES 1
#define SFX_OIT_SC_AO_MIRRORED 2
// The layer AO's bilateral filter (oit_ao_filter.frag, OitAoParams at binding 4 for maxDepth):
// taps each side, [1, SFX_AO_MAX_BLUR_RADIUS], and the direction (0 horizontal, 1 vertical).
#define SFX_OIT_SC_FILTER_RADIUS 0
#define SFX_OIT_SC_FILTER_VERTICAL 1

// The node pool's fixed header (storage buffer OitPool, before the nodes):
//   count     nodes handed out by the fill's atomicAdd this frame, stored or not (> capacity:
//             count - capacity fragments were dropped)
//   capacity  nodes the pool holds; a fragment whose index is at or past it is not stored
SFX_CONST(int, SFX_OIT_POOL_HEADER_BYTES, 16)

#ifdef __cplusplus
static_assert(sizeof(OitDrawParams) == 224 && offsetof(OitDrawParams, drawId) == 208);
static_assert(sizeof(OitResolveParams) == 48 && offsetof(OitResolveParams, ndcScale) == 16);
static_assert(sizeof(OitAoParams) == 80 && offsetof(OitAoParams, radius) == 16 && offsetof(OitAoParams, sumExponent) == 76);
}  // namespace sfx::shared
#endif

#endif  // SFX_SHARED_OIT_PARAMS_H
