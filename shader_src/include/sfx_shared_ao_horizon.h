// Horizon-based ambient occlusion (after Jimenez, Wu, Pesce and Jarabo, "Practical Realtime
// Strategies for Accurate Indirect Occlusion"): what ao_horizon.frag and the CPU reference
// (sdk/src/reference/ao_horizon_reference.cpp) share. Same dialect rules as sfx_shared.h.
//
// Per pixel, `slices` screen directions spread over half a turn. Along each, both ways, `steps`
// depth samples find the highest horizon (the largest elevation above the tangent plane of a
// sample within the world radius). The cosine-weighted visible arc between the
// two horizons, about the normal projected into the slice's plane, has a closed form; its mean
// over the slices is the visibility, the quantity the ray-traced truth measures (docs/trade.md).
// Which pixel a step reads is decided with the float operations of "Where a tap lands"
// (sfx_shared_ao.h); acos, the one transcendental, appears only in the continuous arc
// (docs/ao.md derives the conformance bound from its specified precision).
#ifndef SFX_SHARED_AO_HORIZON_H
#define SFX_SHARED_AO_HORIZON_H

#include "sfx_shared_ao.h"

#ifdef __cplusplus
namespace sfx::shared {
using std::acos;
#define SFX_AO_VEC2 glm::dvec2
#else
#define SFX_AO_VEC2 vec2
#endif

// Most slices and steps per side the shader is built for (what settings validation allows).
SFX_CONST(int, SFX_AO_HORIZON_MAX_SLICES, 16)
SFX_CONST(int, SFX_AO_HORIZON_MAX_STEPS, 32)
// The nearest step lies at least a pixel away: aoTapStep then never lands on the centre.
SFX_CONST(float, SFX_AO_HORIZON_MIN_STEP_PX, 1.0)
// Each slice's step jitter is the pixel's, advanced by this many 256ths of a step (0.617, near
// the golden ratio's fraction) per slice, so the slices of one pixel sample different distances.
SFX_CONST(int, SFX_AO_HORIZON_JITTER_PER_SLICE, 158)

// Slice i of `slices`: (2i + 1) / (4 slices) of a turn in Q16, so the slices split half a turn
// evenly (each is marched both ways); the pixel's rotation turns them all (aoTapDirection).
SFX_FN int aoHorizonSliceTurnsQ16(int i, int slices) { return ((2 * i + 1) * 16384) / slices; }
// The step jitter of slice i, in 256ths of a step, from the pixel's hash bits 8..15 (bits 0..7
// are its rotation, aoRotationIndex).
SFX_FN int aoHorizonJitterIndex(SFX_UINT hash, int slice) {
    return (int((hash >> 8u) & 255u) + slice * SFX_AO_HORIZON_JITTER_PER_SLICE) & 255;
}
// Step j of `steps` lies at (j + jitter) / steps of the screen radius, jitter = (k + 0.5) / 256:
// evenly spread, so no gap between two steps is wider than 1 / steps of the radius, inside which
// the truth counts every occluder (docs/ao_families.md measures other spreads). Float in both
// languages (a discrete decision follows: the pixel it reads).
SFX_FN float aoHorizonStepRadius(int j, int steps, int jitterIndex, float screenRadius) {
    SFX_PRECISE float jitter = (float(jitterIndex) + 0.5f) * 0.00390625f;
    SFX_PRECISE float t = (float(j) + jitter) / float(steps);
    SFX_PRECISE float rho = t * screenRadius;
    return max(rho, SFX_AO_HORIZON_MIN_STEP_PX);
}

// The unit vector from view position C toward the eye.
SFX_FN SFX_AO_VEC3 aoHorizonViewVector(SFX_AO_VEC3 C) {
    SFX_REAL len = length(C);
    return len > 0.0 ? -C / len : SFX_AO_VEC3(0.0, 0.0, 1.0);
}

// The slice's in-plane direction u: the view-space direction of screen direction (dx, dy) (a
// screen step of (dx, dy) moves a point at depth z by z * (dx * projInfo.x, dy * projInfo.y, 0))
// made orthogonal to the view vector V. Its unit vector is the slice's tangent t, + side.
SFX_FN SFX_AO_VEC3 aoHorizonSliceDirection(SFX_REAL dx, SFX_REAL dy, SFX_REAL projX, SFX_REAL projY, SFX_AO_VEC3 V) {
    SFX_AO_VEC3 d = SFX_AO_VEC3(dx * projX, dy * projY, 0.0);
    return d - V * dot(d, V);
}
SFX_FN SFX_AO_VEC3 aoHorizonSliceTangent(SFX_AO_VEC3 u) {
    SFX_REAL len = length(u);
    return len > 0.0 ? u / len : SFX_AO_VEC3(1.0, 0.0, 0.0);
}
// The slice's weight in the mean: the visibility integral runs over slice planes evenly spread
// in azimuth about V, but the slices are spread evenly in screen angle, and off the image's
// centre the two differ (up to 10% of the visibility at a 60-degree field of view's corner).
// The azimuth's rate of turn per screen angle is |projX projY V.z| / |u|^2 for unit (dx, dy);
// the factor common to a pixel's slices cancels in the weighted mean, leaving 1 / |u|^2.
SFX_FN SFX_REAL aoHorizonSliceWeight(SFX_AO_VEC3 u) {
    SFX_REAL uu = dot(u, u);
    return uu > 0.0 ? 1.0 / uu : 0.0;
}
// The normal n projected into the plane of V and t: (its length, cos and sin of its angle from
// V, positive toward t). A normal along the slice's axis projects to length 0, and the slice
// then adds nothing (the cosine weight of every direction in it is 0).
SFX_FN SFX_AO_VEC3 aoHorizonProjectedNormal(SFX_AO_VEC3 n, SFX_AO_VEC3 V, SFX_AO_VEC3 t) {
    SFX_REAL c = dot(n, V);
    SFX_REAL s = dot(n, t);
    SFX_REAL len = sqrt(c * c + s * s);
    if (!(len > 1.0e-6)) return SFX_AO_VEC3(0.0, 1.0, 0.0);
    return SFX_AO_VEC3(len, c / len, s / len);
}
// One sample's horizon, as the sine of its elevation above the tangent plane within the slice:
// dot(v, n) / |v| over the projected normal's length (invProjectedLength), so that a sample in
// the slice's plane gives exactly the sine of its angle above the plane's trace there. Measured
// from the tangent plane, a tap that lands off the slice's line (taps read pixel centres) still
// reads 0 on a plane of any tilt; measured from the view vector it would read a horizon above
// the plane. Inside the radius a sample counts fully up to the last `falloff` share of it, then
// fades linearly to 0 at the radius (invFalloffWidth = 1 / (falloff * radius)). A sample on the
// centre (|v|^2 within epsilon r^2) has no direction and reads 0.
SFX_FN SFX_REAL aoHorizonSampleSin(SFX_AO_VEC3 v, SFX_AO_VEC3 n, SFX_REAL invProjectedLength, SFX_REAL radius, SFX_REAL invFalloffWidth,
                                   SFX_REAL epsilon) {
    SFX_REAL vv = dot(v, v);
    if (!(vv > epsilon * radius * radius)) return 0.0;
    SFX_REAL len = sqrt(vv);
    SFX_REAL w = clamp((radius - len) * invFalloffWidth, 0.0, 1.0);
    return clamp(dot(v, n) / len * invProjectedLength, -1.0, 1.0) * w;
}
// The thickness heuristic: a higher sample raises the horizon; a lower one, seen past an
// occluder, means the occluder may be thin, and pulls the horizon (1 - thickness) of the way
// down to it (thickness 1: every occluder is solid behind its visible face).
SFX_FN SFX_REAL aoHorizonUpdate(SFX_REAL horizonSin, SFX_REAL sampleSin, SFX_REAL thickness) {
    return sampleSin > horizonSin ? sampleSin : sampleSin + (horizonSin - sampleSin) * thickness;
}

// The cosine-weighted visible arc from the view vector to the horizon on one side (side +1 or
// -1), about the normal at angle nAngle (cosN, sinN) from the view vector in the slice. The
// horizon lies at h = nAngle + side * alpha, alpha = acos(s) for elevation sine s; the arc is
// 1/4 (cos n + 2 h sin n - cos(2 h - n)), with cos(2 h - n) expanded in s (cos 2 alpha =
// 2 s^2 - 1), so acos is the only transcendental. A horizon past the view vector (h on the other
// side: possible only for a tap off the slice's line) leaves that side nothing.
SFX_FN SFX_REAL aoHorizonArc(SFX_REAL s, SFX_REAL side, SFX_REAL nAngle, SFX_REAL cosN, SFX_REAL sinN) {
    SFX_REAL e = clamp(s, 0.0, 1.0);
    SFX_REAL h = nAngle + side * acos(e);
    if (!(side * h > 0.0)) return 0.0;
    SFX_REAL cos2a = 2.0 * e * e - 1.0;
    SFX_REAL sin2a = side * 2.0 * e * sqrt(max(1.0 - e * e, 0.0));
    SFX_REAL cos2hn = cos2a * cosN - sin2a * sinN;
    return 0.25 * (cosN + 2.0 * h * sinN - cos2hn);
}
// The projected normal's signed angle from the view vector in the slice, positive toward t.
SFX_FN SFX_REAL aoHorizonNormalAngle(SFX_AO_VEC3 projected) {
    SFX_REAL nAngle = acos(clamp(projected.y, -1.0, 1.0));
    return projected.z < 0.0 ? -nAngle : nAngle;
}
// One slice's visibility from the two sides' horizons (elevation sines, the + side toward t),
// its projected normal (length, cos, sin) and that normal's angle: the arcs of both sides times
// the projected length. With both horizons on the tangent plane (0, 0) it is the slice's open
// arc, (cos n + n sin n) times the length, whose mean over slices evenly spread is exactly 1.
SFX_FN SFX_REAL aoHorizonSliceVisibility(SFX_REAL plusSin, SFX_REAL minusSin, SFX_AO_VEC3 projected, SFX_REAL nAngle) {
    SFX_REAL cosN = projected.y, sinN = projected.z;
    return projected.x * (aoHorizonArc(plusSin, 1.0, nAngle, cosN, sinN) + aoHorizonArc(minusSin, -1.0, nAngle, cosN, sinN));
}
// The pixel's visibility: its slices' weighted visible arcs over their weighted open arcs. Both
// sums converge to the same integral's numerator and denominator (the denominator's limit is 1),
// but with a few slices the open arcs of a normal tilted from the view vector scatter around 1
// by up to 20% with the pixel's rotation; dividing by them leaves an unoccluded pixel exactly 1
// at any slice count and removes that scatter from occluded ones.
SFX_FN SFX_REAL aoHorizonRatio(SFX_REAL visibleSum, SFX_REAL openSum) { return openSum > 0.0 ? visibleSum / openSum : 1.0; }

// ---- Bent normal: the cosine-weighted mean unoccluded direction (AoSettings.bentNormals) ----
// One side's arc from the view vector to its horizon, weighted and measured as the visibility's
// (cos(th - n) |sin th| dth), integrated against the direction (cos th, sin th) itself: the
// arc's vector along V (x) and along t (y). With H = side * h >= 0 and the normal's sine turned
// to the side (sin n -> side sin n) both are cubics in cos H and sin H (docs/algorithms.md):
//   along V: (cos n (1 - cos^3 H) + side sin n sin^3 H) / 3
//   along t: side (cos n sin^3 H + side sin n (2 - 3 cos H + cos^3 H)) / 3
// H = side n + acos e, so cos H and sin H follow from e, cos n and sin n without another
// transcendental; a horizon past the view vector leaves nothing, decided as aoHorizonArc does.
SFX_FN SFX_AO_VEC2 aoHorizonArcDirection(SFX_REAL s, SFX_REAL side, SFX_REAL nAngle, SFX_REAL cosN, SFX_REAL sinN) {
    SFX_REAL e = clamp(s, 0.0, 1.0);
    SFX_REAL h = nAngle + side * acos(e);
    if (!(side * h > 0.0)) return SFX_AO_VEC2(0.0, 0.0);
    SFX_REAL sinNs = side * sinN;
    SFX_REAL cosA = sqrt(max(1.0 - e * e, 0.0));
    SFX_REAL cosH = cosN * e - sinNs * cosA;
    SFX_REAL sinH = sinNs * e + cosN * cosA;
    SFX_REAL cosH3 = cosH * cosH * cosH, sinH3 = sinH * sinH * sinH;
    SFX_REAL alongV = (cosN * (1.0 - cosH3) + sinNs * sinH3) / 3.0;
    SFX_REAL alongT = side * (cosN * sinH3 + sinNs * (2.0 - 3.0 * cosH + cosH3)) / 3.0;
    return SFX_AO_VEC2(alongV, alongT);
}
// One slice's bent vector in view space: both sides' arc vectors on V and t, times the projected
// normal's length as the slice's visibility is.
SFX_FN SFX_AO_VEC3 aoHorizonSliceBent(SFX_REAL plusSin, SFX_REAL minusSin, SFX_AO_VEC3 projected, SFX_REAL nAngle, SFX_AO_VEC3 V,
                                      SFX_AO_VEC3 t) {
    SFX_REAL cosN = projected.y, sinN = projected.z;
    SFX_AO_VEC2 b = aoHorizonArcDirection(plusSin, 1.0, nAngle, cosN, sinN) + aoHorizonArcDirection(minusSin, -1.0, nAngle, cosN, sinN);
    return projected.x * (b.x * V + b.y * t);
}
// The pixel's bent vector from its slices' weighted sums (visible and open bent vectors, visible
// and open arcs), per unit of the open arcs. A few slices' open vectors scatter around the open
// hemisphere's exact vector (over the hemisphere the weighted direction integrates to 2/3 n per
// unit of the cosine's integral) as their open arcs scatter around 1; the visible vector is
// corrected by that scatter times the visible share (the ratio that corrects the visibility),
// so an unoccluded pixel's vector is exactly 2/3 n at any slice count.
SFX_FN SFX_AO_VEC3 aoHorizonBentVector(SFX_AO_VEC3 bentSum, SFX_AO_VEC3 openBentSum, SFX_REAL visibleSum, SFX_REAL openSum, SFX_AO_VEC3 n) {
    if (!(openSum > 0.0)) return (2.0 / 3.0) * n;
    SFX_REAL ratio = visibleSum / openSum;
    return (bentSum + ratio * ((2.0 / 3.0) * openSum * n - openBentSum)) / openSum;
}
// Below this length of the bent vector nothing is seen and the normal stands in.
SFX_CONST(float, SFX_AO_HORIZON_MIN_BENT_LENGTH, 0.001)
// The bent normal: the bent vector's direction, unit length; n where nothing is visible.
SFX_FN SFX_AO_VEC3 aoHorizonBentNormal(SFX_AO_VEC3 bentVector, SFX_AO_VEC3 n) {
    SFX_REAL len = length(bentVector);
    return len > SFX_REAL(SFX_AO_HORIZON_MIN_BENT_LENGTH) ? bentVector / len : n;
}

// The last pass's renormalisation of blurred and upsampled bent normals (sky's (0, 0, 1) stays);
// a vector blurred to nothing (opposite normals cancelling) faces the eye.
SFX_FN SFX_AO_VEC3 aoBentNormalResolve(SFX_AO_VEC3 v) {
    SFX_REAL len = length(v);
    return len > 0.0 ? v / len : SFX_AO_VEC3(0.0, 0.0, 1.0);
}

#ifdef __cplusplus
}  // namespace sfx::shared
#endif

// ---- GLSL of the bent-normal programs (the _bent variants define SFX_AO_BENT_NORMALS) ----
#if !defined(__cplusplus) && defined(SFX_AO_BENT_NORMALS)
// A bent vector as a target stores it: RGBA8 (unorm) holds xyz * 0.5 + 0.5, float targets signed xyz.
vec4 aoBentEncode(vec3 b, bool unorm) { return vec4(unorm ? b * 0.5 + 0.5 : b, 1.0); }
// A bent vector read from an intermediate target: RGBA8 where the tier's AO target is
// (SFX_AO_PACKED_DEPTH_TARGET, from the tier table), else RGBA16F.
vec3 aoBentDecode(vec4 texel) {
#ifdef SFX_AO_PACKED_DEPTH_TARGET
    return texel.xyz * 2.0 - 1.0;
#else
    return texel.xyz;
#endif
}
#endif

#endif  // SFX_SHARED_AO_HORIZON_H
