// A-buffer resolve (high tier): the pixel's list in (depth, draw id, primitive id) order
// composited front to back over the opaque colour (sfx_shared_oit.h). The nearest K fragments
// are kept in registers by insertion (the K nearest of a total order are one set, whatever the
// list order); those behind are folded into the tail in sorted order too, found by repeated
// selection of the next key, so no bit of the result depends on which fragment won a race.
// Every walk is bounded by the pool's capacity: a damaged list cannot hang the pass.
// With SFX_OIT_COMPRESS (oit_resolve_compress.frag) the same walk also compresses the pixel's
// list (the paper's section III-B): every fragment in sorted order, then the opaque surface at
// opacity 1, into M (normalised depth, opacity) nodes by sfx_shared_oit.h's oitCompressInsert,
// written to the OitCompressed buffer (SFX_OIT_COMPRESSED_WORDS words per pixel).
// With layer AO after it (kWriteTransmittance) it also stores in each node the transmittance in
// front of that fragment, in the same sorted order, for the AO pass's single walk.
// GLSL only: included by oit_resolve.frag and oit_resolve_compress.frag.
#ifndef SFX_SHARED_OIT_RESOLVE_H
#define SFX_SHARED_OIT_RESOLVE_H
#define SFX_WANT_OIT_RESOLVE_PARAMS 1
#include "sfx_shared_oit_params.h"  // OitResolveParams resolve (binding 4)
#include "sfx_shared_oit.h"

layout(set = 0, binding = 0) uniform sampler2D uOpaque;
layout(set = 0, binding = 1, std430) buffer OitPool SFX_OIT_POOL_BODY  // word 7 of each node written
layout(set = 0, binding = 2, r32ui) uniform readonly uimage2D uHeads;
layout(location = 0) out vec4 outColor;
layout(constant_id = SFX_OIT_SC_RESOLVE_TRANSMITTANCE) const int kWriteTransmittance = 0;
#ifdef SFX_OIT_COMPRESS
layout(set = 0, binding = 3, std430) writeonly buffer OitCompressed { uint words[]; } compressed;
layout(set = 0, binding = 5) uniform sampler2D uOpaqueDepth;  // the opaque pass's depth attachment
layout(constant_id = SFX_OIT_SC_COMPRESS_NODES) const int kCompressNodes = 4;
layout(constant_id = SFX_OIT_SC_COMPRESS_BACK_HALF) const int kCompressBackHalf = 1;
float compDepth[SFX_OIT_MAX_COMPRESSED_NODES + 1];
float compOpacity[SFX_OIT_MAX_COMPRESSED_NODES + 1];
int compCount = 0;
void compress(float z, float alpha) {
    oitCompressInsert(compDepth, compOpacity, compCount, kCompressNodes, kCompressBackHalf != 0,
                      oitNormalizedDepth(z, resolve.zNear, resolve.zFar), alpha);
}
#define SFX_OIT_COMPRESS_FRAGMENT(lo) compress(oitNodeDepth(lo), oitNodeColor(lo).a)
#else
#define SFX_OIT_COMPRESS_FRAGMENT(lo)
#endif

float keptDepth[SFX_OIT_MAX_KEPT_LAYERS];
uint keptDraw[SFX_OIT_MAX_KEPT_LAYERS];
uint keptPrimitive[SFX_OIT_MAX_KEPT_LAYERS];
uvec2 keptColor[SFX_OIT_MAX_KEPT_LAYERS];
uint keptNode[SFX_OIT_MAX_KEPT_LAYERS];

// The transmittance in front of the next fragment in sorted order, and its store into that node.
float gInFront = 1.0;
void passFragment(uint node, float alpha) {
    if (kWriteTransmittance != 0) pool.nodes[2u * node + 1u].w = floatBitsToUint(gInFront);
    gInFront *= 1.0 - alpha;
}

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec4 opaque = texelFetch(uOpaque, pixel, 0);
    uint head = imageLoad(uHeads, pixel).x;
    int k = resolve.maxLayers;
    // Walks are bounded by the pool header's capacity, not OitResolveParams.capacity: a loop bound
    // from a uniform block makes lavapipe inline the value and JIT-compile the pass again at every
    // draw (the resolve cost 535 ms at 320x180 on a scene of 0.3 fragments per pixel; 5.6 ms now).
    uint steps = pool.capacity;
    int kept = 0;
    uint total = 0u;
    for (uint node = head, s = 0u; node != SFX_OIT_NULL_INDEX && node < steps && s < steps; ++s) {
        uvec4 lo = pool.nodes[2u * node], hi = pool.nodes[2u * node + 1u];
        float depth = oitNodeDepth(lo);
        uint drawId = oitDrawIndex(hi.x), primitive = hi.y;
        total += 1u;
        uint self = node;
        node = hi.z;
        // Insert into the sorted kept set; when full, only if nearer than its last.
        int at = kept < k ? kept : k;
        if (at == k && !oitBefore(depth, drawId, primitive, keptDepth[k - 1], keptDraw[k - 1], keptPrimitive[k - 1])) continue;
        if (at == k) at = k - 1;  // the farthest kept one leaves
        while (at > 0 && oitBefore(depth, drawId, primitive, keptDepth[at - 1], keptDraw[at - 1], keptPrimitive[at - 1])) {
            keptDepth[at] = keptDepth[at - 1];
            keptDraw[at] = keptDraw[at - 1];
            keptPrimitive[at] = keptPrimitive[at - 1];
            keptColor[at] = keptColor[at - 1];
            keptNode[at] = keptNode[at - 1];
            at -= 1;
        }
        keptDepth[at] = depth;
        keptDraw[at] = drawId;
        keptPrimitive[at] = primitive;
        keptColor[at] = lo.xy;
        keptNode[at] = self;
        kept = min(kept + 1, k);
    }
#ifdef SFX_OIT_COMPRESS
    for (int i = 0; i <= SFX_OIT_MAX_COMPRESSED_NODES; ++i) {
        compDepth[i] = 1.0;
        compOpacity[i] = 0.0;
    }
#endif
    vec4 acc = vec4(0.0, 0.0, 0.0, 1.0);
    for (int i = 0; i < kept; ++i) {
        vec4 color = oitNodeColor(uvec4(keptColor[i], 0u, 0u));
        oitCompositeFront(acc, color);
        passFragment(keptNode[i], color.a);
        SFX_OIT_COMPRESS_FRAGMENT(uvec4(keptColor[i], floatBitsToUint(keptDepth[i]), 0u));
    }
    if (total > uint(kept)) {
        // The tail: the fragments after the K-th key, in sorted order.
        vec4 tail = vec4(0.0);
        float tailTransmittance = 1.0;
        float lastDepth = keptDepth[kept - 1];
        uint lastDraw = keptDraw[kept - 1], lastPrimitive = keptPrimitive[kept - 1];
        for (uint t = uint(kept); t < total; ++t) {
            bool found = false;
            float bestDepth = 0.0;
            uint bestDraw = 0u, bestPrimitive = 0u;
            uvec2 bestColor = uvec2(0u);
            uint bestNode = 0u;
            for (uint node = head, s = 0u; node != SFX_OIT_NULL_INDEX && node < steps && s < steps; ++s) {
                uvec4 lo = pool.nodes[2u * node], hi = pool.nodes[2u * node + 1u];
                uint self = node;
                node = hi.z;
                float depth = oitNodeDepth(lo);
                uint drawId = oitDrawIndex(hi.x), primitive = hi.y;
                if (!oitBefore(lastDepth, lastDraw, lastPrimitive, depth, drawId, primitive)) continue;
                if (found && !oitBefore(depth, drawId, primitive, bestDepth, bestDraw, bestPrimitive)) continue;
                found = true;
                bestDepth = depth;
                bestDraw = drawId;
                bestPrimitive = primitive;
                bestColor = lo.xy;
                bestNode = self;
            }
            if (!found) break;
            vec4 color = oitNodeColor(uvec4(bestColor, 0u, 0u));
            oitTailAccumulate(tail, tailTransmittance, color);
            passFragment(bestNode, color.a);
            SFX_OIT_COMPRESS_FRAGMENT(uvec4(bestColor, floatBitsToUint(bestDepth), 0u));
            lastDepth = bestDepth;
            lastDraw = bestDraw;
            lastPrimitive = bestPrimitive;
        }
        oitCompositeFront(acc, oitTailLayer(tail, tailTransmittance));
    }
    outColor = vec4(oitCompositeFinish(acc, opaque.rgb), opaque.a);
#ifdef SFX_OIT_COMPRESS
    // Opaque geometry enters last, at opacity 1 (sky enters not at all).
    float opaqueZ = sfxLinearizeDepth(texelFetch(uOpaqueDepth, pixel, 0).r, resolve.ndcScale, resolve.denomOffset,
                                      resolve.numerator, resolve.maxDepth);
    if (opaqueZ < resolve.maxDepth) compress(opaqueZ, 1.0);
    // Entries at and past M hold what the last insertion shifted out: empty nodes instead.
    for (int i = kCompressNodes; i < SFX_OIT_COMPRESSED_NODES; ++i) {
        compDepth[i] = 1.0;
        compOpacity[i] = 0.0;
    }
    uvec4 texel = uvec4(oitPackCompressedDepths(compDepth[0], compDepth[1]), oitPackCompressedDepths(compDepth[2], compDepth[3]),
                        oitPackCompressedOpacities(compOpacity[0], compOpacity[1], compOpacity[2], compOpacity[3]), 0u);
    uint base = (uint(pixel.y) * uint(imageSize(uHeads).x) + uint(pixel.x)) * uint(SFX_OIT_COMPRESSED_WORDS);
    compressed.words[base] = texel.x;
    compressed.words[base + 1u] = texel.y;
    compressed.words[base + 2u] = texel.z;
#endif
}

#endif  // SFX_SHARED_OIT_RESOLVE_H
