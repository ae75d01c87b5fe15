// The body of the separable depth-aware bilateral blur of the obscurance (one direction per pass;
// ao_blur.frag, and ao_blur_bent.frag, which defines SFX_AO_BENT_NORMALS first and blurs the
// bent normal beside it with the same weights). A neighbour's weight falls to 0 as its depth
// departs from the centre's by SFX_AO_BLUR_DEPTH_TOLERANCE of it, so occlusion never crosses a
// depth discontinuity. Crease keeps a second, moderate-width blur in g and the final pass blends
// both (the article's two-blur look).
#ifndef SFX_AO_BLUR_PASS_H
#define SFX_AO_BLUR_PASS_H
#define SFX_AO_BLUR_PASS 1
#include "sfx_shared_ao.h"
#ifdef SFX_AO_BENT_NORMALS
#include "sfx_shared_ao_horizon.h"
#endif

// SFX_AO_PACKED_DEPTH_TARGET comes from the tier table (TierProfile::aoPackedDepthTarget): the
// depth key packed in b and a of the RGBA8 target. Otherwise the float target carries the linear
// depth itself, in g (RG32F), or in b for crease (RGBA32F: g holds the moderate blur).
layout(set = 0, binding = 1) uniform sampler2D uSource;
// BlurParams (binding 2): sfx_shared_ao.h.
layout(location = 0) out vec4 outAo;
// Fixed per pipeline (sfx_shared_ao.h); AmbientObscurance gives every one.
layout(constant_id = SFX_AO_SC_BLUR_RADIUS) const int kRadius = 1;
layout(constant_id = SFX_AO_SC_BLUR_MODERATE_RADIUS) const int kModerateRadius = 1;
layout(constant_id = SFX_AO_SC_BLUR_CREASE) const int kCrease = 0;
layout(constant_id = SFX_AO_SC_BLUR_FINAL_PASS) const int kFinalPass = 0;
layout(constant_id = SFX_AO_SC_BLUR_KEEP_DEPTH) const int kKeepDepth = 0;

#ifdef SFX_AO_BENT_NORMALS
// The obscurance pass's bent normals beside uSource: RGBA8 (xyz * 0.5 + 0.5) where the tier's
// AO target is (SFX_AO_PACKED_DEPTH_TARGET), else RGBA16F. Blurred as weighted sums of unit
// vectors (inside the unit ball, so RGBA8 holds them too); the final pass into the host's
// target renormalises, a pass into another intermediate (the first; at half resolution the
// second too) does not.
layout(set = 0, binding = 3) uniform sampler2D uBentSource;
layout(location = 1) out vec4 outBent;
layout(constant_id = SFX_AO_SC_BLUR_BENT_UNORM) const int kBentUnorm = 0;
vec3 bentAt(ivec2 q) { return aoBentDecode(sfxTexel(uBentSource, q, 0)); }
void writeBent(vec3 b) {
    if (kFinalPass != 0 && kKeepDepth == 0) b = aoBentNormalResolve(b);
    outBent = aoBentEncode(b, kBentUnorm != 0);
}
#endif

float blurDepth(vec4 s) {
#ifndef SFX_AO_PACKED_DEPTH_TARGET
    // Already clamped by the obscurance pass (sfxLinearDepthOrFar), as a fetch would be.
    return kCrease != 0 ? s.b : s.g;
#else
    return aoUnpackDepthKey(s.ba, params.keyBase, params.maxDepth);
#endif
}

// The first pass keeps the centre's depth for the second; the second writes visibility, and at
// half resolution (kKeepDepth) the depth again, float or key, for the upsample.
vec4 blurOut(float wide, float moderate, vec4 c) {
#ifndef SFX_AO_PACKED_DEPTH_TARGET
    if (kFinalPass == 0 || kKeepDepth != 0) return kCrease != 0 ? vec4(wide, moderate, c.b, 1.0) : vec4(wide, c.g, 0.0, 1.0);
    return vec4(wide, wide, wide, 1.0);
#else
    if (kFinalPass == 0) return vec4(wide, moderate, c.b, c.a);
    return kKeepDepth != 0 ? vec4(wide, wide, c.b, c.a) : vec4(wide, wide, wide, 1.0);
#endif
}

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    ivec2 size = textureSize(uSource, 0);
    vec4 c = sfxTexel(uSource, p, 0);
    float z0 = blurDepth(c);
    if (!(z0 < params.maxDepth)) {
        outAo = kFinalPass != 0 ? blurOut(1.0, 1.0, c) : c;
#ifdef SFX_AO_BENT_NORMALS
        writeBent(bentAt(p));
#endif
        return;
    }
    float accWide = 0.0, wWide = 0.0, accModerate = 0.0, wModerate = 0.0;
#ifdef SFX_AO_BENT_NORMALS
    vec3 accBent = vec3(0.0);
#endif
    for (int k = -kRadius; k <= kRadius; ++k) {
        ivec2 q = p + k * params.direction;
        if (q.x < 0 || q.y < 0 || q.x >= size.x || q.y >= size.y) continue;
        vec4 s = sfxTexel(uSource, q, 0);
        float edge = aoBlurEdgeWeight(blurDepth(s), z0);
        float w = aoBlurGaussian(k, kRadius) * edge;
        accWide += w * s.r;
        wWide += w;
#ifdef SFX_AO_BENT_NORMALS
        accBent += w * bentAt(q);
#endif
        if (kCrease != 0 && abs(k) <= kModerateRadius) {
            float wm = aoBlurGaussian(k, kModerateRadius) * edge;
            // The first pass blurs the raw result (r) twice; the second blurs each in its channel.
            accModerate += wm * (kFinalPass != 0 ? s.g : s.r);
            wModerate += wm;
        }
    }
    float wide = accWide / wWide;
    float moderate = kCrease != 0 ? accModerate / wModerate : wide;
#ifdef SFX_AO_BENT_NORMALS
    writeBent(accBent / wWide);
#endif
    if (kFinalPass == 0) {
        outAo = blurOut(wide, moderate, c);
        return;
    }
    float v = wide;
    if (kCrease != 0) {
        float occ = 0.5 * (SFX_AO_CREASE_WIDE_GAIN * (1.0 - wide) + SFX_AO_CREASE_MODERATE_GAIN * (1.0 - moderate));
        v = clamp(1.0 - occ, 0.0, 1.0);
    }
    outAo = blurOut(v, v, c);
}

#endif  // SFX_AO_BLUR_PASS_H
