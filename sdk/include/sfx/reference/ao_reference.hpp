// CPU references of ambient obscurance (Alchemy, Scalable, Crease), normals from depth and the
// bilateral blur: double precision, written for clarity, using the sample patterns of
// shader_src/include/sfx_shared_ao.h exactly as the shaders do.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "sfx/ao.hpp"
#include "sfx/reference/depth_reference.hpp"

namespace sfx::reference {

struct AoInput {
    Grid linearDepth;                 // positive eye depth; >= reconstruction.maxDepth is sky
    std::vector<glm::dvec3> normals;  // view-space unit normals, row 0 first; empty: derive from depth
    DepthReconstruction reconstruction;
};

// View-space position of pixel (x, y)'s centre at its linear depth.
glm::dvec3 viewPosition(const AoInput& in, uint32_t x, uint32_t y);

// Normals from depth, robust at edges: on each axis, the difference to the neighbour whose
// depth is closer to the centre's (the only in-bounds one at the border), so a normal never
// differences across a discontinuity; oriented toward the camera. The rule is sfx_shared_ao.h's
// (aoNormalUsesNext, aoFacingNormal), the shaders' too: a non-finite or out-of-range depth
// reads as the far plane, so its neighbours take their tangent from the other side.
std::vector<glm::dvec3> normalsFromDepth(const Grid& linearDepth, const DepthReconstruction& reconstruction);

// One tap of a technique's pattern around a pixel: the pixel it lands on (clamped to the image)
// and the depth MIP level it reads (Scalable on the high tier; 0 otherwise).
struct AoTap {
    int x = 0, y = 0;
    int level = 0;
};
// The taps of config's pattern (Alchemy disk, Scalable spiral, Crease diamond) around pixel
// (x, y) of a w x h image whose centre is at linear depth z, in the shaders' order.
std::vector<AoTap> aoTaps(const AoConfig& config, const DepthReconstruction& reconstruction, uint32_t w, uint32_t h, uint32_t x, uint32_t y,
                          double z);
// The technique's per-tap term (sfx_shared_ao.h) for v = tap - centre: vv = dot(v, v), vn = dot(v, n).
double aoTapTerm(const AoConfig& config, double vv, double vn, double z);
// The summed per-tap terms of one pixel as occlusion (the technique's normalisation), and the
// visibility it leaves with contrast applied (before saturation).
double aoOcclusionFromSum(const AoConfig& config, double sum, double z);
double aoFinishVisibility(double occlusion, double contrast);

// Visibility of every pixel before any blur (1 = unoccluded, sky = 1).
Grid rawVisibility(const AoInput& in, const AoConfig& config);

// Every depth the AO reference reads goes through sfxLinearDepthOrFar first, as every fetch of
// the shaders does: a non-positive, non-finite or overflowing depth is the far plane (sky).
Grid linearDepthOrFar(const Grid& linearDepth, double maxDepth);

// One separable bilateral pass along (dx, dy) with half-width radius; depth weights relative
// to the centre's depth (SFX_AO_BLUR_DEPTH_TOLERANCE). Sky pixels pass through.
Grid bilateralBlurPass(const Grid& visibility, const Grid& linearDepth, double maxDepth, int radius, int dx, int dy);

// AO at half resolution (sfx_shared_ao.h): the half-size depth, texel (x, y) holding the depth
// of full-size pixel aoFullResPixel(x, y) (depth MIP level 1's rotated grid), size max(1, w / 2).
Grid halfSizeDepth(const Grid& linearDepth);
// The depth-aware upsample of half-size visibility to fullDepth's size: per pixel the 2x2
// half-size texels around it, bilinear times depth weights against the full-size depth, plus
// the nearest-depth texel at SFX_AO_UPSAMPLE_NEAREST_WEIGHT. Sky (full-size) is 1.
Grid depthAwareUpsample(const Grid& halfVisibility, const Grid& halfDepth, const Grid& fullDepth, double maxDepth);

// The whole effect: raw visibility, then (blurRadius > 0) the two blur passes, or for Crease
// its two-blur look (a wide and a moderate blur, blended with SFX_AO_CREASE_*_GAIN). With
// config.halfResolution all of it on halfSizeDepth (positions at each texel's full-size source
// pixel, screen radii in half-size pixels), then depthAwareUpsample.
Grid ambientVisibility(const AoInput& in, const AoConfig& config);

// Bent normals (AoSettings.bentNormals, Horizon): per pixel the unit view-space mean unoccluded
// direction of shared::aoHorizonBentNormal, sky (0, 0, 1), row 0 first, with what conditions
// them (docs/ao.md, "Bent normals": the conformance bound divides by both lengths).
struct BentNormals {
    std::vector<glm::dvec3> normals;
    // The bent vector's length per unit of open arc (shared::aoHorizonBentVector; 2/3 unoccluded,
    // infinite for sky): raw, the pixel's own; ambient, the smallest over the raw pixels the blur
    // and the upsample weigh in.
    std::vector<double> vectorLength;
    // The blurred (and upsampled) vector's length before the last renormalisation (1 raw).
    std::vector<double> resolveLength;
};
// Raw: the obscurance pass's. Ambient: each component through the blur's and the upsample's
// visibility weights, then renormalised (shared::aoBentNormalResolve), as the last pass writes.
BentNormals rawBentNormals(const AoInput& in, const AoConfig& config);
BentNormals ambientBentNormals(const AoInput& in, const AoConfig& config);

}  // namespace sfx::reference
