#include "sfx/reference/oit_reference.hpp"

#include <algorithm>
#include <cmath>

#include "sfx/reference/ao_reference.hpp"
#include "sfx_shared_oit.h"

namespace sfx::reference {
namespace {

using glm::dvec3;
using glm::dvec4;
namespace sh = sfx::shared;

constexpr int kCompressedArray = sh::SFX_OIT_MAX_COMPRESSED_NODES + 1;

dvec4 premultiplied(const OitFragment& f) { return dvec4(f.color * f.alpha, f.alpha); }

bool isSky(double z, double maxDepth) { return !(z < maxDepth); }

dvec3 positionAt(const DepthReconstruction& rec, int x, int y, double z) {
    const sh::dvec3 p = sh::reconstructViewPosition(double(x) + 0.5, double(y) + 0.5, z, rec.projInfo);
    return dvec3(p.x, p.y, p.z);
}

// One occluder as an AO sample sees it: its linear depth and its opacity.
struct Occluder {
    double depth, alpha;
};

// getAO of Algorithm 1 for the technique (Alchemy or Scalable), from the shared header.
double occlusionOf(const AoConfig& c, double vv, double vn, double z, double exteriorWeight, double occluderAlpha) {
    if (c.technique == AoTechnique::Alchemy) return sh::oitAlchemyOcclusion(vv, vn, z, c.radius, c.bias, c.epsilon, exteriorWeight, occluderAlpha);
    return sh::oitScalableOcclusion(vv, vn, c.radius, c.bias, c.epsilon, exteriorWeight, occluderAlpha);
}

}  // namespace

std::vector<OitFragment> sortedFragments(const std::vector<OitFragment>& fragments, double opaqueDepth) {
    std::vector<OitFragment> out;
    for (OitFragment f : fragments) {
        if (!(f.depth < opaqueDepth)) continue;  // the geometry pass depth-tests against the opaque depth
        f.alpha = std::clamp(f.alpha, 0.0, 1.0);
        out.push_back(f);
    }
    std::sort(out.begin(), out.end(), [](const OitFragment& a, const OitFragment& b) {
        return sh::oitBefore(a.depth, a.drawIndex, a.primitiveId, b.depth, b.drawIndex, b.primitiveId);
    });
    return out;
}

glm::dvec3 compositeExact(const std::vector<OitFragment>& fragments, const OpaqueSurface& opaque) { return compositeKept(fragments, opaque, 0); }

glm::dvec3 compositeKept(const std::vector<OitFragment>& fragments, const OpaqueSurface& opaque, uint32_t maxLayers) {
    const std::vector<OitFragment> sorted = sortedFragments(fragments, opaque.depth);
    const size_t kept = maxLayers == 0 ? sorted.size() : std::min<size_t>(maxLayers, sorted.size());
    dvec4 acc(0.0, 0.0, 0.0, 1.0);
    for (size_t i = 0; i < kept; ++i) sh::oitCompositeFront(acc, premultiplied(sorted[i]));
    dvec4 tail(0.0);
    double tailTransmittance = 1.0;
    for (size_t i = kept; i < sorted.size(); ++i) sh::oitTailAccumulate(tail, tailTransmittance, premultiplied(sorted[i]));
    if (kept < sorted.size()) sh::oitCompositeFront(acc, sh::oitTailLayer(tail, tailTransmittance));
    return sh::oitCompositeFinish(acc, opaque.color);
}

std::vector<glm::dvec3> compositeImage(const FragmentImage& image, uint32_t maxLayers) {
    std::vector<dvec3> out(image.fragments.size());
    for (size_t i = 0; i < out.size(); ++i) out[i] = compositeKept(image.fragments[i], image.opaque[i], maxLayers);
    return out;
}

std::vector<CompressedNode> compressList(const std::vector<OitFragment>& fragments, const OpaqueSurface& opaque, double maxDepth,
                                         const CompressionConfig& config) {
    const int m = std::clamp(int(config.nodes), 1, int(sh::SFX_OIT_MAX_COMPRESSED_NODES));
    double depth[kCompressedArray], opacity[kCompressedArray];
    std::fill(depth, depth + kCompressedArray, 1.0);
    std::fill(opacity, opacity + kCompressedArray, 0.0);
    int count = 0;
    auto insert = [&](double z, double alpha) {
        sh::oitCompressInsert(depth, opacity, count, m, config.backHalfOnly, sh::oitNormalizedDepth(z, config.zNear, config.zFar), alpha);
    };
    for (const OitFragment& f : sortedFragments(fragments, opaque.depth)) insert(f.depth, f.alpha);
    if (!isSky(opaque.depth, maxDepth)) insert(opaque.depth, 1.0);  // opaque geometry enters at alpha 1
    std::vector<CompressedNode> nodes(static_cast<size_t>(m));
    for (int i = 0; i < count; ++i) nodes[size_t(i)] = {depth[i], opacity[i]};
    return nodes;
}

std::vector<CompressedNode> quantizeCompressed(const std::vector<CompressedNode>& nodes) {
    CompressedNode n[sh::SFX_OIT_COMPRESSED_NODES];
    for (size_t i = 0; i < nodes.size() && i < size_t(sh::SFX_OIT_COMPRESSED_NODES); ++i) n[i] = nodes[i];
    const glm::uvec4 texel(sh::oitPackCompressedDepths(n[0].depth, n[1].depth), sh::oitPackCompressedDepths(n[2].depth, n[3].depth),
                           sh::oitPackCompressedOpacities(n[0].opacity, n[1].opacity, n[2].opacity, n[3].opacity), 0u);
    std::vector<CompressedNode> out(size_t(sh::SFX_OIT_COMPRESSED_NODES));
    for (int i = 0; i < sh::SFX_OIT_COMPRESSED_NODES; ++i) out[size_t(i)] = {sh::oitCompressedDepth(texel, i), sh::oitCompressedOpacity(texel, i)};
    return out;
}

Result<OitAoResult> opacityAmbientOcclusion(const FragmentImage& image, const OitAoConfig& config) {
    const AoConfig& c = config.ao;
    if (c.technique != AoTechnique::Alchemy && c.technique != AoTechnique::Scalable)
        return invalidArgument("OitAoConfig.ao.technique", toString(c.technique), "alchemy, scalable");
    const DepthReconstruction& rec = image.reconstruction;
    const uint32_t w = image.width, h = image.height;
    const CompressionConfig& cc = config.compression;

    // What a sample landing on each pixel sees.
    std::vector<std::vector<OitFragment>> sorted(image.fragments.size());
    std::vector<std::vector<Occluder>> occluders(image.fragments.size());
    for (size_t i = 0; i < sorted.size(); ++i) {
        sorted[i] = sortedFragments(image.fragments[i], image.opaque[i].depth);
        if (config.occluders == OitAoOccluders::BruteForce) {
            for (const OitFragment& f : sorted[i]) occluders[i].push_back({f.depth, f.alpha});
            if (!isSky(image.opaque[i].depth, rec.maxDepth)) occluders[i].push_back({image.opaque[i].depth, 1.0});
        } else {
            CompressionConfig m = cc;  // the texel holds at most 4 nodes
            m.nodes = std::clamp(cc.nodes, 1u, uint32_t(sh::SFX_OIT_COMPRESSED_NODES));
            for (const CompressedNode& n : quantizeCompressed(compressList(image.fragments[i], image.opaque[i], rec.maxDepth, m)))
                if (n.opacity > 0.0) occluders[i].push_back({cc.zNear + n.depth * (cc.zFar - cc.zNear), n.opacity});
        }
    }

    // Algorithm 1 for one receiver at pixel (x, y): every tap keeps its largest occlusion.
    auto visibility = [&](uint32_t x, uint32_t y, double z, const dvec3& n, double exteriorWeight) {
        const dvec3 C = positionAt(rec, int(x), int(y), z);
        double sum = 0.0;
        for (const AoTap& t : aoTaps(c, rec, w, h, x, y, z)) {
            double occlusion = 0.0;
            for (const Occluder& o : occluders[image.index(uint32_t(t.x), uint32_t(t.y))]) {
                const dvec3 v = positionAt(rec, t.x, t.y, o.depth) - C;
                occlusion = std::max(occlusion, occlusionOf(c, glm::dot(v, v), glm::dot(v, n), z, exteriorWeight, o.alpha));
            }
            sum += occlusion;
        }
        return std::clamp(aoFinishVisibility(aoOcclusionFromSum(c, sum, z), c.contrast), 0.0, 1.0);
    };

    OitAoResult out;
    out.blended = Grid(w, h, 1.0);
    out.opaque = Grid(w, h, 1.0);
    out.perFragment.resize(sorted.size());
    for (uint32_t y = 0; y < h; ++y) {
        for (uint32_t x = 0; x < w; ++x) {
            const size_t i = image.index(x, y);
            const OpaqueSurface& o = image.opaque[i];
            if (!isSky(o.depth, rec.maxDepth)) out.opaque.at(x, y) = visibility(x, y, o.depth, o.normal, 1.0);
            // Blended after the sort like colour, separately from it (so it can be filtered).
            double acc = 0.0, transmittance = 1.0;
            for (const OitFragment& f : sorted[i]) {
                const double v = visibility(x, y, f.depth, f.normal, sh::oitExteriorWeight(f.alpha, f.frontFacing));
                out.perFragment[i].push_back(v);
                acc += transmittance * f.alpha * v;
                transmittance *= 1.0 - f.alpha;
            }
            out.blended.at(x, y) = acc + transmittance * out.opaque.at(x, y);
        }
    }
    return out;
}

Grid multilayerVisibility(const DepthLayers& layers, const AoConfig& config) {
    AoConfig c = config;
    c.depthMipLevels = 1;
    const DepthReconstruction& rec = layers.reconstruction;
    Grid out(layers.width, layers.height, 1.0);
    for (uint32_t y = 0; y < layers.height; ++y) {
        for (uint32_t x = 0; x < layers.width; ++x) {
            const std::vector<double>& here = layers.depths[size_t(y) * layers.width + x];
            if (here.empty() || isSky(here[0], rec.maxDepth)) continue;
            const double z = here[0];
            const dvec3 C = positionAt(rec, int(x), int(y), z);
            const dvec3 n = layers.normals[size_t(y) * layers.width + x];
            double sum = 0.0;
            for (const AoTap& t : aoTaps(c, rec, layers.width, layers.height, x, y, z)) {
                double term = 0.0;
                for (double zl : layers.depths[size_t(t.y) * layers.width + size_t(t.x)]) {
                    if (isSky(zl, rec.maxDepth)) continue;
                    const dvec3 v = positionAt(rec, t.x, t.y, zl) - C;
                    term = std::max(term, aoTapTerm(c, glm::dot(v, v), glm::dot(v, n), z));
                }
                sum += term;
            }
            out.at(x, y) = std::clamp(aoFinishVisibility(aoOcclusionFromSum(c, sum, z), c.contrast), 0.0, 1.0);
        }
    }
    return out;
}

glm::dvec3 compositeWeightedBlended(const std::vector<OitFragment>& fragments, const OpaqueSurface& opaque) {
    // Both targets cleared to (0, 0, 0, 1); colour blends (ONE, ONE), alpha (ZERO, ONE_MINUS_SRC_ALPHA).
    dvec4 target0(0.0, 0.0, 0.0, 1.0), target1(0.0, 0.0, 0.0, 1.0);
    for (const OitFragment& f : sortedFragments(fragments, opaque.depth)) {
        dvec4 out0, out1;
        sh::oitWeightedBlendedOutputs(premultiplied(f), f.depth, out0, out1);
        target0 = dvec4(dvec3(target0) + dvec3(out0), target0.w * (1.0 - out0.w));
        target1 = dvec4(dvec3(target1) + dvec3(out1), target1.w * (1.0 - out1.w));
    }
    return sh::oitWeightedBlendedResolve(target0, target1, opaque.color);
}

}  // namespace sfx::reference
