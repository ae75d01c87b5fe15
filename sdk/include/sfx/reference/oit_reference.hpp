// CPU references of order-independent transparency and of ambient occlusion through layers:
// double precision, written for clarity, built on the functions of
// shader_src/include/sfx_shared_oit.h exactly as the shaders use them.
//
//   compositing  every fragment sorted by (depth, id) and blended front to back over the opaque
//                colour; or the nearest K exact and the rest as one order-independent tail
//   compression  each list to M (normalised depth, opacity) nodes by the drop criterion
//                alpha * (1 - z'), quantised as the 24-byte texel stores them
//   AO           opacity-based AO of every fragment, occluders weighted by their opacity and the
//                two hemispheres blended by W, each sample keeping the largest occlusion over the
//                fragments at its pixel (brute force over the lists, or over the compressed
//                nodes), blended per pixel like colour; multilayer AO of opaque depth layers
//   WBOIT        weighted blended OIT, the current tier's approximation
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include <glm/glm.hpp>

#include "sfx/ao.hpp"
#include "sfx/reference/depth_reference.hpp"

namespace sfx::reference {

// One rasterised translucent fragment.
struct OitFragment {
    glm::dvec3 color{0.0};                    // straight (not premultiplied) linear RGB
    double alpha = 1.0;                       // coverage in [0, 1]
    double depth = 1.0;                       // positive linear view depth
    glm::dvec3 normal{0.0, 0.0, 1.0};         // the triangle's authored view-space unit normal (not flipped)
    bool frontFacing = true;                  // the authored normal faces the camera: dot(normal, position) < 0
    uint32_t drawIndex = 0, primitiveId = 0;  // orders fragments at equal depth
};

// What the opaque pass left at a pixel; depth at or beyond the reconstruction's maxDepth is sky
// (colour is then the background, and nothing occludes there).
struct OpaqueSurface {
    glm::dvec3 color{0.0};
    double depth = std::numeric_limits<double>::infinity();
    glm::dvec3 normal{0.0, 0.0, 1.0};  // view space, facing the camera
};

// A W x H picture of fragment lists (in any order) over the opaque surfaces, row 0 first.
struct FragmentImage {
    uint32_t width = 0, height = 0;
    std::vector<std::vector<OitFragment>> fragments;
    std::vector<OpaqueSurface> opaque;
    DepthReconstruction reconstruction;
    FragmentImage() = default;
    FragmentImage(uint32_t w, uint32_t h, const DepthReconstruction& rec)
        : width(w), height(h), fragments(size_t(w) * h), opaque(size_t(w) * h), reconstruction(rec) {}
    size_t index(uint32_t x, uint32_t y) const { return size_t(y) * width + x; }
};

// The fragments that pass the depth test against the opaque depth (depth < opaqueDepth; alpha
// clamped to [0, 1]), sorted by (depth, draw index, primitive id).
std::vector<OitFragment> sortedFragments(const std::vector<OitFragment>& fragments, double opaqueDepth);

// Every fragment composited front to back over the opaque colour.
glm::dvec3 compositeExact(const std::vector<OitFragment>& fragments, const OpaqueSurface& opaque);
// The nearest maxLayers exact, those behind folded into one tail layer (sfx_shared_oit.h);
// maxLayers 0 keeps every fragment.
glm::dvec3 compositeKept(const std::vector<OitFragment>& fragments, const OpaqueSurface& opaque, uint32_t maxLayers);
// The whole picture, maxLayers = 0: every fragment exact.
std::vector<glm::dvec3> compositeImage(const FragmentImage& image, uint32_t maxLayers = 0);

// One node of a compressed list: depth normalised to [0, 1] over [zNear, zFar], and opacity.
struct CompressedNode {
    double depth = 1.0;
    double opacity = 0.0;
};
struct CompressionConfig {
    uint32_t nodes = 4;        // M in [1, SFX_OIT_MAX_COMPRESSED_NODES]
    bool backHalfOnly = true;  // drop only from the back half: the front half is always kept
    double zNear = 0.1, zFar = 100.0;
};
// The pixel's sorted fragments, then its opaque surface (opacity 1, unless sky), inserted into
// M nodes; nodes beyond the count stay empty (depth 1, opacity 0). Exact, not quantised.
std::vector<CompressedNode> compressList(const std::vector<OitFragment>& fragments, const OpaqueSurface& opaque, double maxDepth,
                                         const CompressionConfig& config);
// The same nodes after the 24-byte texel's quantisation (16-bit depth, 8-bit opacity), as the
// AO pass reads them; M = 4 only, as the texel layout holds 4.
std::vector<CompressedNode> quantizeCompressed(const std::vector<CompressedNode>& nodes);

// Ambient occlusion through the layers. Technique Alchemy or Scalable (config.depthMipLevels
// is ignored: lists have no MIP); Crease, which has no opacity-based form, is InvalidArgument.
enum class OitAoOccluders {
    BruteForce,  // every stored fragment at a sample's pixel, and its opaque surface (alpha 1)
    Compressed,  // the sample pixel's M <= 4 quantised nodes (compressList + quantizeCompressed)
};
struct OitAoConfig {
    AoConfig ao;  // technique, radius, samples, intensity, ... as the opaque AO reference
    OitAoOccluders occluders = OitAoOccluders::BruteForce;
    CompressionConfig compression;  // for Compressed
};
struct OitAoResult {
    // Per pixel: each fragment's visibility (in sorted order) blended front to back with its
    // opacity, over the opaque surface's visibility; 1 where nothing is drawn.
    Grid blended;
    // The opaque surface's own visibility (it receives as a front face of opacity 1).
    Grid opaque;
    // Per pixel, the visibility of each sorted fragment.
    std::vector<std::vector<double>> perFragment;
};
Result<OitAoResult> opacityAmbientOcclusion(const FragmentImage& image, const OitAoConfig& config);

// Multilayer AO of opaque geometry: per pixel the linear depths of up to L opaque layers
// (nearest first; the first is the visible surface with its normal), each tap testing every
// layer and keeping the largest term. With one layer per pixel it is the single-layer
// reference's raw visibility (before blur); taps read full resolution (no depth MIP).
struct DepthLayers {
    uint32_t width = 0, height = 0;
    std::vector<std::vector<double>> depths;  // per pixel, nearest first; empty: sky
    std::vector<glm::dvec3> normals;          // the first layer's view-space normal
    DepthReconstruction reconstruction;
};
Grid multilayerVisibility(const DepthLayers& layers, const AoConfig& config);

// Weighted blended OIT of one pixel's fragments (in any order) over the opaque colour, through
// the two render targets' blend equations in double precision.
glm::dvec3 compositeWeightedBlended(const std::vector<OitFragment>& fragments, const OpaqueSurface& opaque);

}  // namespace sfx::reference
