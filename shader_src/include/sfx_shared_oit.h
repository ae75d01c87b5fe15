// Order-independent transparency pieces shared by the OIT shaders and the C++ CPU reference
// (sfx/reference/oit_reference.hpp): the A-buffer node layout, the sort order, front-to-back
// compositing with a tail beyond K kept layers, the list compression, the opacity-based AO
// combination and the weighted blended weight. One definition, so the two cannot drift.
//
// Scalar code in the common subset of GLSL 450 and C++20 (same dialect as sfx_shared_mb.h):
// double and glm's double vectors in C++, float and GLSL vectors in shaders. Only built-ins that
// SPIRV-Cross can express in ESSL 300 are used (no packUnorm4x8), so current-tier programs may
// include this file too.
//
// Method (after Bauer, Knuth, Kuijper and Bender 2013, "Screen-space ambient occlusion using
// A-buffer techniques"):
// - Every translucent fragment that passes the depth test against the opaque depth is stored
//   in a per-pixel list. A fragment is premultiplied colour, positive linear view depth, the
//   authored view-space normal, whether the triangle was front-facing, and an id (draw index,
//   primitive id) that orders fragments at equal depth, so nothing depends on draw order.
// - The resolve sorts each list by (depth, id) and composites front to back over the opaque
//   colour, keeping the nearest K fragments exactly and folding the rest into a tail.
// - Ambient occlusion of a translucent fragment integrates two hemispheres: the exterior one
//   around its normal n and the interior one around -n, blended by W = alpha for a front face
//   and 1 - alpha for a back face (looking at a translucent hull from outside one mostly sees
//   its outside; looking at its inner wall through the hull, its inside). Each occluder counts
//   in proportion to its own opacity. A sample direction lands on a pixel that may hold many
//   fragments: the sample keeps the largest occlusion over them.
// - For speed the sorted list may be compressed to M (depth, opacity) nodes, dropping the node
//   that matters least for occlusion (lowest alpha * (1 - normalised depth)), so an AO sample
//   reads one texel instead of walking a list.
#ifndef SFX_SHARED_OIT_H
#define SFX_SHARED_OIT_H

#include "sfx_shared.h"
#include "sfx_shared_ao.h"

#ifdef __cplusplus
#include <glm/glm.hpp>
#include <glm/gtc/packing.hpp>

#include <cmath>
namespace sfx::shared {
using std::abs;
using std::floor;
using std::max;
using std::min;
using std::pow;
using glm::normalize;
#define SFX_OIT_VEC2 glm::dvec2
#define SFX_OIT_VEC3 glm::dvec3
#define SFX_OIT_VEC4 glm::dvec4
#define SFX_OIT_UVEC2 glm::uvec2
#define SFX_OIT_UVEC4 glm::uvec4
// Parameters written to (GLSL out / inout): references in C++.
#define SFX_OIT_OUT(type) type&
#define SFX_OIT_INOUT(type) type&
#define SFX_OIT_INOUT_ARRAY(type, name, count) type (&name)[count]
// GLSL's half/snorm packing, for the node layout (the bit casts are sfx_shared.h's).
inline uint32_t packHalf2x16(glm::dvec2 v) { return glm::packHalf2x16(glm::vec2(v)); }
inline glm::dvec2 unpackHalf2x16(uint32_t v) { return glm::dvec2(glm::unpackHalf2x16(v)); }
inline uint32_t packSnorm2x16(glm::dvec2 v) { return glm::packSnorm2x16(glm::vec2(v)); }
inline glm::dvec2 unpackSnorm2x16(uint32_t v) { return glm::dvec2(glm::unpackSnorm2x16(v)); }
inline double sfxOitRound(double v) { return std::floor(v + 0.5); }
#else
#define SFX_OIT_VEC2 vec2
#define SFX_OIT_VEC3 vec3
#define SFX_OIT_VEC4 vec4
#define SFX_OIT_UVEC2 uvec2
#define SFX_OIT_UVEC4 uvec4
#define SFX_OIT_OUT(type) out type
#define SFX_OIT_INOUT(type) inout type
#define SFX_OIT_INOUT_ARRAY(type, name, count) inout type name[count]
float sfxOitRound(float v) { return floor(v + 0.5); }
// The node pool every A-buffer pass binds (std430 storage buffer): the fixed header of
// SFX_OIT_POOL_HEADER_BYTES (sfx_shared_oit_params.h), then node i as nodes[2i] (colour, depth,
// normal) and nodes[2i + 1] (ids, next). Each pass declares it with its own access qualifier:
//   layout(set = 0, binding = 1, std430) readonly buffer OitPool SFX_OIT_POOL_BODY
#define SFX_OIT_POOL_BODY { uint count; uint capacity; uint reserved0; uint reserved1; uvec4 nodes[]; } pool;
#endif

// ---- The A-buffer node (a storage-buffer array of uint, SFX_OIT_NODE_WORDS per node) ------------
//   word 0, 1  premultiplied colour r, g | b, a as two packHalf2x16 (linear HDR colour stays
//              exact to fp16; 8-bit unorm would lose the front layers of deep stacks)
//   word 2     positive linear view depth, floatBitsToUint (positive floats order as uints)
//   word 3     authored view-space unit normal, octahedral, packSnorm2x16
//   word 4     bit 31: front-facing; bits 0..30: draw index
//   word 5     primitive id (gl_PrimitiveID of the draw)
//   word 6     index of the next node of the pixel's list, SFX_OIT_NULL_INDEX at the end
//   word 7     the transmittance in front of the fragment (floatBitsToUint): the product of
//              (1 - opacity) over the fragments before it in (depth, draw, primitive) order,
//              written by the resolve when layer AO follows it (SFX_OIT_SC_RESOLVE_TRANSMITTANCE),
//              so the AO pass walks each list once instead of sorting it again; 0 from the fill
SFX_CONST(int, SFX_OIT_NODE_WORDS, 8)
SFX_CONST(SFX_UINT, SFX_OIT_NULL_INDEX, 0xFFFFFFFFu)
SFX_CONST(SFX_UINT, SFX_OIT_FRONT_FACING_BIT, 0x80000000u)
SFX_CONST(SFX_UINT, SFX_OIT_DRAW_INDEX_MASK, 0x7FFFFFFFu)
// Most fragments the resolve keeps per pixel in registers (the quality settings choose K up to it).
SFX_CONST(int, SFX_OIT_MAX_KEPT_LAYERS, 32)

// Octahedral normal encoding: the unit sphere folded onto the square [-1, 1]^2. A zero or
// non-finite vector encodes as +z (the guard is "not positive", so NaN takes it too).
SFX_FN SFX_REAL oitSignNotZero(SFX_REAL v) { return v >= 0.0 ? 1.0 : -1.0; }
SFX_FN SFX_OIT_VEC2 oitOctEncode(SFX_OIT_VEC3 n) {
    SFX_REAL l1 = abs(n.x) + abs(n.y) + abs(n.z);
    if (!(l1 > 0.0)) return SFX_OIT_VEC2(0.0, 0.0);
    SFX_OIT_VEC2 p = SFX_OIT_VEC2(n.x / l1, n.y / l1);
    if (n.z < 0.0) p = SFX_OIT_VEC2((1.0 - abs(p.y)) * oitSignNotZero(p.x), (1.0 - abs(p.x)) * oitSignNotZero(p.y));
    return p;
}
SFX_FN SFX_OIT_VEC3 oitOctDecode(SFX_OIT_VEC2 e) {
    SFX_OIT_VEC3 n = SFX_OIT_VEC3(e.x, e.y, 1.0 - abs(e.x) - abs(e.y));
    if (n.z < 0.0) n = SFX_OIT_VEC3((1.0 - abs(e.y)) * oitSignNotZero(e.x), (1.0 - abs(e.x)) * oitSignNotZero(e.y), n.z);
    return normalize(n);
}

SFX_FN SFX_UINT oitPackIdWord(SFX_UINT drawIndex, bool frontFacing) {
    return (drawIndex & SFX_OIT_DRAW_INDEX_MASK) | (frontFacing ? SFX_OIT_FRONT_FACING_BIT : 0u);
}
SFX_FN SFX_UINT oitDrawIndex(SFX_UINT idWord) { return idWord & SFX_OIT_DRAW_INDEX_MASK; }
SFX_FN bool oitFrontFacing(SFX_UINT idWord) { return (idWord & SFX_OIT_FRONT_FACING_BIT) != 0u; }

// The node as two uvec4 (words 0-3 and 4-7).
SFX_FN void oitPackNode(SFX_OIT_VEC4 premultiplied, SFX_REAL depth, SFX_OIT_VEC3 normal, bool frontFacing,
                        SFX_UINT drawIndex, SFX_UINT primitiveId, SFX_UINT next,
                        SFX_OIT_OUT(SFX_OIT_UVEC4) lo, SFX_OIT_OUT(SFX_OIT_UVEC4) hi) {
    lo = SFX_OIT_UVEC4(packHalf2x16(SFX_OIT_VEC2(premultiplied.x, premultiplied.y)),
                       packHalf2x16(SFX_OIT_VEC2(premultiplied.z, premultiplied.w)), floatBitsToUint(depth),
                       packSnorm2x16(oitOctEncode(normal)));
    hi = SFX_OIT_UVEC4(oitPackIdWord(drawIndex, frontFacing), primitiveId, next, 0u);
}
SFX_FN SFX_OIT_VEC4 oitNodeColor(SFX_OIT_UVEC4 lo) {
    SFX_OIT_VEC2 rg = unpackHalf2x16(lo.x), ba = unpackHalf2x16(lo.y);
    return SFX_OIT_VEC4(rg.x, rg.y, ba.x, ba.y);
}
SFX_FN SFX_REAL oitNodeDepth(SFX_OIT_UVEC4 lo) { return SFX_REAL(uintBitsToFloat(lo.z)); }
SFX_FN SFX_OIT_VEC3 oitNodeNormal(SFX_OIT_UVEC4 lo) { return oitOctDecode(unpackSnorm2x16(lo.w)); }

// ---- Sort order -------------------------------------------------------------------------------
// Fragment a comes before b when nearer; at equal depth the lower draw index, then the lower
// primitive id. (A primitive covers a pixel centre once, so no two fragments of a pixel share
// all three: the order is total and the resolve's result is the same for any list order.)
SFX_FN bool oitBefore(SFX_REAL depthA, SFX_UINT drawA, SFX_UINT primitiveA, SFX_REAL depthB, SFX_UINT drawB, SFX_UINT primitiveB) {
    if (depthA != depthB) return depthA < depthB;
    if (drawA != drawB) return drawA < drawB;
    return primitiveA < primitiveB;
}

// ---- Front-to-back compositing ---------------------------------------------------------------
// acc.rgb is the colour gathered so far, acc.a the transmittance left (start at (0, 0, 0, 1)).
// Each premultiplied fragment (c, alpha) in sorted order: acc.rgb += acc.a * c, acc.a *= 1 - alpha.
// The opaque colour behind everything is added last with the remaining transmittance.
SFX_FN void oitCompositeFront(SFX_OIT_INOUT(SFX_OIT_VEC4) acc, SFX_OIT_VEC4 premultiplied) {
    acc = SFX_OIT_VEC4(acc.x + acc.w * premultiplied.x, acc.y + acc.w * premultiplied.y,
                       acc.z + acc.w * premultiplied.z, acc.w * (1.0 - premultiplied.w));
}
SFX_FN SFX_OIT_VEC3 oitCompositeFinish(SFX_OIT_VEC4 acc, SFX_OIT_VEC3 opaque) {
    return SFX_OIT_VEC3(acc.x + acc.w * opaque.x, acc.y + acc.w * opaque.y, acc.z + acc.w * opaque.z);
}

// Tail beyond the K kept layers: the fragments behind the K-th are blended as one layer whose
// transmittance is their exact product of (1 - alpha) and whose colour is their alpha-weighted
// average (the weighted average of Bavoil and Myers 2008). Both are sums and products, so the
// tail does not depend on order; it is exact when the tail layers share one colour, and its
// error is bounded by the transmittance left in front of it, so the front K stay exact.
//   tail.rgb = sum of premultiplied colours, tail.a = sum of alphas; tailTransmittance starts at 1.
SFX_FN void oitTailAccumulate(SFX_OIT_INOUT(SFX_OIT_VEC4) tail, SFX_OIT_INOUT(SFX_REAL) tailTransmittance,
                              SFX_OIT_VEC4 premultiplied) {
    tail = SFX_OIT_VEC4(tail.x + premultiplied.x, tail.y + premultiplied.y, tail.z + premultiplied.z, tail.w + premultiplied.w);
    tailTransmittance *= 1.0 - premultiplied.w;
}
// The tail as one premultiplied layer, to be composited after the kept ones.
SFX_FN SFX_OIT_VEC4 oitTailLayer(SFX_OIT_VEC4 tail, SFX_REAL tailTransmittance) {
    if (!(tail.w > 0.0)) return SFX_OIT_VEC4(0.0, 0.0, 0.0, 0.0);
    SFX_REAL coverage = 1.0 - tailTransmittance;
    return SFX_OIT_VEC4(tail.x / tail.w * coverage, tail.y / tail.w * coverage, tail.z / tail.w * coverage, coverage);
}

// ---- List compression (M nodes of normalised depth and opacity) ------------------------------
// Normalised depth z' = (z - near) / (far - near) in [0, 1]. The array starts with every node
// at z' = 1, opacity 0 (empty). Fragments are inserted in sorted (depth, id) order, opaque
// geometry last with opacity 1; each insertion keeps the nodes sorted, and once the array holds
// M + 1 nodes the one with the smallest alpha * (1 - z') is dropped: faint and far nodes go
// first, opaque and near ones stay. With backHalfOnly the search covers only indices
// [(M + 1) / 2, M], so the front half is never dropped. Ties drop the farther node.
SFX_CONST(int, SFX_OIT_COMPRESSED_NODES, 4)
SFX_CONST(int, SFX_OIT_MAX_COMPRESSED_NODES, 8)
SFX_FN SFX_REAL oitNormalizedDepth(SFX_REAL z, SFX_REAL zNear, SFX_REAL zFar) {
    return clamp((z - zNear) / (zFar - zNear), 0.0, 1.0);
}
SFX_FN SFX_REAL oitCompressionKeep(SFX_REAL alpha, SFX_REAL normalizedDepth) { return alpha * (1.0 - normalizedDepth); }

// Inserts (z', alpha) into the first `count` nodes (arrays of capacity SFX_OIT_MAX_COMPRESSED_NODES
// + 1, m <= SFX_OIT_MAX_COMPRESSED_NODES); count grows to at most m.
SFX_FN void oitCompressInsert(SFX_OIT_INOUT_ARRAY(SFX_REAL, depth, SFX_OIT_MAX_COMPRESSED_NODES + 1),
                              SFX_OIT_INOUT_ARRAY(SFX_REAL, opacity, SFX_OIT_MAX_COMPRESSED_NODES + 1),
                              SFX_OIT_INOUT(int) count, int m, bool backHalfOnly, SFX_REAL z, SFX_REAL alpha) {
    int at = count;
    while (at > 0 && depth[at - 1] > z) {
        depth[at] = depth[at - 1];
        opacity[at] = opacity[at - 1];
        at -= 1;
    }
    depth[at] = z;
    opacity[at] = alpha;
    count += 1;
    if (count <= m) return;
    int drop = m;
    SFX_REAL lowest = oitCompressionKeep(opacity[m], depth[m]);
    for (int j = m - 1; j >= (backHalfOnly ? (m + 1) / 2 : 0); --j) {
        SFX_REAL keep = oitCompressionKeep(opacity[j], depth[j]);
        if (keep < lowest) {
            lowest = keep;
            drop = j;
        }
    }
    for (int j = drop; j < m; ++j) {
        depth[j] = depth[j + 1];
        opacity[j] = opacity[j + 1];
    }
    count = m;
}

// The paper's 24 bytes per pixel for 4 nodes with 16-bit depth, as an RGBA32UI texel (nodes)
// and an RG32UI texel (their normals):
//   nodes.x = d0 | d1 << 16, nodes.y = d2 | d3 << 16     (16-bit unorm normalised depth)
//   nodes.z = a0 | a1 << 8 | a2 << 16 | a3 << 24          (8-bit unorm opacity)
//   nodes.w = node count (bits 0..3) | front-facing bit of node i at bit 8 + i
//   normals.x, .y: the nodes' octahedral normals, 8 + 8 bits each, nodes 0, 1 and 2, 3
// Empty nodes hold depth 1 (65535) and opacity 0, so a reader may ignore the count.
SFX_FN SFX_UINT oitUnorm(SFX_REAL v, SFX_REAL scale) { return SFX_UINT(sfxOitRound(clamp(v, 0.0, 1.0) * scale)); }
SFX_FN SFX_UINT oitPackCompressedDepths(SFX_REAL a, SFX_REAL b) { return oitUnorm(a, 65535.0) | (oitUnorm(b, 65535.0) << 16u); }
SFX_FN SFX_UINT oitPackCompressedOpacities(SFX_REAL a0, SFX_REAL a1, SFX_REAL a2, SFX_REAL a3) {
    return oitUnorm(a0, 255.0) | (oitUnorm(a1, 255.0) << 8u) | (oitUnorm(a2, 255.0) << 16u) | (oitUnorm(a3, 255.0) << 24u);
}
SFX_FN SFX_UINT oitPackCompressedNormal(SFX_OIT_VEC3 n) {
    SFX_OIT_VEC2 e = oitOctEncode(n);
    return oitUnorm(e.x * 0.5 + 0.5, 255.0) | (oitUnorm(e.y * 0.5 + 0.5, 255.0) << 8u);
}
// Node i (0..3) of a packed texel.
SFX_FN SFX_REAL oitCompressedDepth(SFX_OIT_UVEC4 nodes, int i) {
    SFX_UINT word = i < 2 ? nodes.x : nodes.y;
    return SFX_REAL((word >> SFX_UINT(16 * (i & 1))) & 0xFFFFu) / 65535.0;
}
SFX_FN SFX_REAL oitCompressedOpacity(SFX_OIT_UVEC4 nodes, int i) { return SFX_REAL((nodes.z >> SFX_UINT(8 * i)) & 0xFFu) / 255.0; }
SFX_FN int oitCompressedCount(SFX_OIT_UVEC4 nodes) { return int(nodes.w & 0xFu); }
SFX_FN bool oitCompressedFrontFacing(SFX_OIT_UVEC4 nodes, int i) { return ((nodes.w >> SFX_UINT(8 + i)) & 1u) != 0u; }
SFX_FN SFX_OIT_VEC3 oitCompressedNormal(SFX_OIT_UVEC2 normals, int i) {
    SFX_UINT word = ((i < 2 ? normals.x : normals.y) >> SFX_UINT(16 * (i & 1))) & 0xFFFFu;
    SFX_OIT_VEC2 e = SFX_OIT_VEC2(SFX_REAL(word & 0xFFu), SFX_REAL(word >> 8u)) / 255.0 * 2.0 - 1.0;
    return oitOctDecode(e);
}

// ---- Opacity-based ambient occlusion ---------------------------------------------------------
// W(p): the weight of the exterior hemisphere (around the authored normal n) of a fragment of
// opacity alpha; 1 - W weighs the interior one (around -n).
SFX_FN SFX_REAL oitExteriorWeight(SFX_REAL alpha, bool frontFacing) { return frontFacing ? alpha : 1.0 - alpha; }
// One occluder fragment's occlusion of the receiver (getAO of Algorithm 1): the technique's per-tap
// term toward it in the exterior hemisphere (vn = dot(v, n)) and in the interior one
// (dot(v, -n) = -vn), blended by W and scaled by the occluder's own opacity.
SFX_FN SFX_REAL oitOpacityOcclusion(SFX_REAL exteriorTerm, SFX_REAL interiorTerm, SFX_REAL exteriorWeight, SFX_REAL occluderAlpha) {
    return occluderAlpha * (exteriorWeight * exteriorTerm + (1.0 - exteriorWeight) * interiorTerm);
}
// The per-tap terms of sfx_shared_ao.h through the two hemispheres.
SFX_FN SFX_REAL oitAlchemyOcclusion(SFX_REAL vv, SFX_REAL vn, SFX_REAL z, SFX_REAL r, SFX_REAL bias, SFX_REAL epsilon,
                                    SFX_REAL exteriorWeight, SFX_REAL occluderAlpha) {
    return oitOpacityOcclusion(aoAlchemyTerm(vv, vn, z, r, bias, epsilon), aoAlchemyTerm(vv, -vn, z, r, bias, epsilon),
                               exteriorWeight, occluderAlpha);
}
SFX_FN SFX_REAL oitScalableOcclusion(SFX_REAL vv, SFX_REAL vn, SFX_REAL r, SFX_REAL bias, SFX_REAL epsilon,
                                     SFX_REAL exteriorWeight, SFX_REAL occluderAlpha) {
    return oitOpacityOcclusion(aoScalableTerm(vv, vn, r, bias, epsilon), aoScalableTerm(vv, -vn, r, bias, epsilon),
                               exteriorWeight, occluderAlpha);
}

// ---- Bilateral filter of the layer AO ----------------------------------------------------------
// The AO through the layers is blended after the sort separately from colour so that it can be
// filtered: a separable depth-aware blur (horizontal, then vertical) with the opaque AO blur's
// weights (sfx_shared_ao.h: a Gaussian over the tap index times an edge weight that falls to 0
// as the tap's key depth departs from the centre's by SFX_AO_BLUR_DEPTH_TOLERANCE of it). The
// blended visibility is keyed by the pixel's front depth (its nearest stored fragment, or its
// opaque surface), the opaque visibility by the opaque depth; a centre whose key is sky (at or
// past maxDepth) keeps its value.
SFX_FN SFX_REAL oitFilterTapWeight(int k, int radius, SFX_REAL tapKey, SFX_REAL centreKey) {
    return aoBlurGaussian(k, radius) * aoBlurEdgeWeight(tapKey, centreKey);
}

// ---- Weighted blended OIT (McGuire and Bavoil 2013), the current tier's fallback -------------
// Weight of a fragment at linear depth z with coverage alpha (their eq. 7):
//     w = alpha * clamp(10 / (1e-5 + (z / 5)^2 + (z / 200)^6), 1e-2, 3e3)
// It is tuned for view depths of about SFX_OIT_WBOIT_DEPTH_MIN to SFX_OIT_WBOIT_DEPTH_MAX scene
// units: nearer than that the weight saturates at 3e3, farther it sits at 1e-2, so layers
// there are no longer told apart by depth. Weights stay below fp16's 65504 at alpha = 1.
SFX_CONST(float, SFX_OIT_WBOIT_DEPTH_MIN, 0.1)
SFX_CONST(float, SFX_OIT_WBOIT_DEPTH_MAX, 500.0)
SFX_CONST(float, SFX_OIT_WBOIT_NEAR_SCALE, 5.0)
SFX_CONST(float, SFX_OIT_WBOIT_FAR_SCALE, 200.0)
SFX_CONST(float, SFX_OIT_WBOIT_MIN_WEIGHT, 0.01)
SFX_CONST(float, SFX_OIT_WBOIT_MAX_WEIGHT, 3000.0)
SFX_FN SFX_REAL oitWeightedBlendedWeight(SFX_REAL z, SFX_REAL alpha) {
    SFX_REAL a = abs(z) / SFX_REAL(SFX_OIT_WBOIT_NEAR_SCALE), b = abs(z) / SFX_REAL(SFX_OIT_WBOIT_FAR_SCALE);
    SFX_REAL b3 = b * b * b;
    return alpha * clamp(10.0 / (1.0e-5 + a * a + b3 * b3), SFX_REAL(SFX_OIT_WBOIT_MIN_WEIGHT), SFX_REAL(SFX_OIT_WBOIT_MAX_WEIGHT));
}
// The two targets' outputs, blended with ONE state for both (so ES 3.0 without per-target blend
// state works): colour factors (ONE, ONE), alpha factors (ZERO, ONE_MINUS_SRC_ALPHA), both
// targets cleared to (0, 0, 0, 1).
//   target 0: rgb sums the premultiplied colour times w, a multiplies down to the revealage prod(1 - alpha)
//   target 1: r sums alpha * w (its a output is 0, so its alpha stays 1)
SFX_FN void oitWeightedBlendedOutputs(SFX_OIT_VEC4 premultiplied, SFX_REAL z, SFX_OIT_OUT(SFX_OIT_VEC4) target0,
                                      SFX_OIT_OUT(SFX_OIT_VEC4) target1) {
    SFX_REAL w = oitWeightedBlendedWeight(z, premultiplied.w);
    target0 = SFX_OIT_VEC4(premultiplied.x * w, premultiplied.y * w, premultiplied.z * w, premultiplied.w);
    target1 = SFX_OIT_VEC4(premultiplied.w * w, 0.0, 0.0, 0.0);
}
// Resolve: the weighted average colour covers (1 - revealage) of the opaque colour. A single
// layer comes out exact; two layers of equal weight (same depth, same alpha a) and straight
// colours s1 in front of s2 come out as (s1 + s2) / 2 * a * (2 - a) instead of
// a * s1 + (1 - a) * a * s2: an error of a^2 / 2 * (s2 - s1), growing with opacity, and layers
// far apart in depth are told apart only by the weight's depth falloff.
SFX_FN SFX_OIT_VEC3 oitWeightedBlendedResolve(SFX_OIT_VEC4 target0, SFX_OIT_VEC4 target1, SFX_OIT_VEC3 opaque) {
    SFX_REAL revealage = target0.w;
    SFX_REAL norm = max(target1.x, 1.0e-5);
    SFX_REAL coverage = 1.0 - revealage;
    return SFX_OIT_VEC3(target0.x / norm * coverage + revealage * opaque.x, target0.y / norm * coverage + revealage * opaque.y,
                        target0.z / norm * coverage + revealage * opaque.z);
}

#ifdef __cplusplus
}  // namespace sfx::shared
#endif

#endif  // SFX_SHARED_OIT_H
