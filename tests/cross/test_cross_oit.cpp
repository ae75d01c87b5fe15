// Transparency and AO through layers compared across backends and drivers, as
// test_cross_backend.cpp compares the other effects: order-independent transparency in every
// mode of each tier (the A-buffer at K = 16, K = 32 and K = 2, which folds the back layers into
// the tail; weighted blended OIT on the current tier), the A-buffer's AO through the
// transparent layers (brute force and compressed occluders, raw and filtered), and multilayer
// AO of opaque depth layers. Bounds: cross_bounds.hpp.
#include <catch2/catch.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <map>

#include "cross_bounds.hpp"
#include "cross_compare.hpp"
#include "effect_runs.hpp"
#include "sfx/tiers.hpp"
#include "sfx_shared.h"
#include "test_device.hpp"  // SFX_REQUIRE_OK

using namespace sfx;
using namespace sfx::test;

namespace {

constexpr uint32_t kW = 96, kH = 64;

// An opaque picture to composite over: a smooth colour ramp, exact in fp16.
std::vector<glm::dvec4> opaqueRamp(uint32_t w, uint32_t h) {
    std::vector<glm::dvec4> c;
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) c.push_back({double(x % 32) / 32.0, double(y % 16) / 16.0, 0.5, 1.0});
    return c;
}

// The OIT mode a run exercises, for the messages.
std::string modeName(const TransparencyDesc& d, Tier tier) {
    if (tier == Tier::Current) return "weighted blended";
    return "A-buffer K=" + std::to_string(keptLayers(d));
}

void compareOit(Tier tier) {
    SFX_OPEN_AT_LEAST_TWO(devices, tier);
    // Three overlapping quads at view depths 2, 3 and 4 (TranslucentQuads; their edges lie at
    // least 0.1 px from any pixel centre, so coverage is the same on every rasteriser). Right of
    // x = 64 an opaque surface at view depth 3.5 hides the back quad there.
    std::vector<float> depth(size_t(kW) * kH, 1.0f);
    for (uint32_t y = 0; y < kH; ++y)
        for (uint32_t x = 64; x < kW; ++x) depth[size_t(y) * kW + x] = float((3.5 - 0.5) / 19.5);
    const std::vector<glm::dvec4> opaque = opaqueRamp(kW, kH);
    std::vector<TransparencyDesc> modes(1);
    if (tier == Tier::High) {
        modes.resize(3);
        modes[1].quality = TransparencyQuality::High;
        modes[2].maxLayers = 2;  // the third layer goes to the tail
    }
    for (TransparencyDesc desc : modes) {
        desc.width = kW;
        desc.height = kH;
        desc.profile = tiers::profile(tier);
        const std::string what = "oit " + modeName(desc, tier) + " at tier " + toString(tier);
        std::map<std::string, std::vector<double>> results;
        for (Opened& o : devices) {
            INFO(o.name << ": " << what);
            const TranslucentQuads quads(*o.device, kW, kH, 0.7f, {0.3f, 0.1f});
            const GpuTransparency g = runTransparency(*o.device, desc, opaque, depth, glm::mat4(1.0f), quads.projection, quads.draws);
            CHECK(g.stats.dropped == 0);
            results[o.name] = g.color;
        }
        requireNoValidation(devices);
        // Something to agree on: the layers move the picture away from the opaque colour.
        const std::vector<double>& any = results.begin()->second;
        double moved = 0;
        for (size_t i = 0; i < opaque.size(); ++i)
            for (int c = 0; c < 3; ++c) moved = std::max(moved, std::abs(any[i * 4 + size_t(c)] - opaque[i][c]));
        INFO(what << ": the layers move the opaque colour by up to " << moved);
        CHECK(moved > 0.3);
        requirePairsWithin(results, tier == Tier::High ? kAbufferPairWorst : kWeightedBlendedPairWorst, what);
    }
}

// test_oit_layers.cpp's panes over an opaque floor: up to five layers, one pane authored
// backwards (back-facing), so compression drops some and every AO branch runs. Each faces the
// camera, so it is a window-aligned rectangle; its corners are moved (by at most 0.052 units) so
// that its edges fall on whole window pixels, half a pixel from every pixel centre
// (panesMissPixelCentres checks it): no rasteriser's sub-pixel snap can change their coverage.
constexpr double kNear = 0.5, kFar = 20.0;
struct Pane {
    glm::dvec3 corner, edgeU, edgeV, normal;
    double alpha;
};
const Pane kPanes[] = {{{-1.548, -0.8335, -2.2}, {2.1434, 0, 0}, {0, 1.5083, 0}, {0, 0, 1}, 0.35},
                       {{-0.9508, -0.8949, -3.1}, {2.2372, 0, 0}, {0, 1.622, 0}, {0, 0, -1}, 0.6},
                       {{-2.1723, -0.5431, -4.3}, {2.5602, 0, 0}, {0, 1.2413, 0}, {0, 0, 1}, 0.2},
                       {{-0.4691, -0.9382, -5.2}, {2.9084, 0, 0}, {0, 2.064, 0}, {0, 0, 1}, 0.85},
                       {{-1.8187, -0.7957, -6.3}, {3.2964, 0, 0}, {0, 1.9324, 0}, {0, 0, 1}, 0.45}};

// The panes' vertex buffers on one device, and their draws (ids 0..4).
struct Panes {
    Device& device;
    std::vector<BufferHandle> buffers;
    std::vector<TransparentDraw> draws;
    explicit Panes(Device& d) : device(d) {
        uint32_t id = 0;
        for (const Pane& q : kPanes) {
            const glm::dvec3 c[4] = {q.corner, q.corner + q.edgeU, q.corner + q.edgeU + q.edgeV, q.corner + q.edgeV};
            std::vector<TransparentVertex> v;
            for (int i : {0, 1, 2, 0, 2, 3}) {
                const glm::vec3 p(c[i]), n(q.normal);
                v.push_back({{p.x, p.y, p.z}, {n.x, n.y, n.z}});
            }
            BufferHandle b = d.createBuffer({v.size() * sizeof(TransparentVertex), kBufferVertex, "cross pane"}).value();
            SFX_REQUIRE_OK(d.writeBuffer(b, 0, v.data(), v.size() * sizeof(TransparentVertex)));
            buffers.push_back(b);
            TransparentDraw draw;
            draw.vertices = b;
            draw.vertexCount = 6;
            draw.color = glm::vec3(0.8f, 0.5f + 0.1f * float(id), 0.3f);
            draw.opacity = float(q.alpha);
            draw.id = id++;
            draws.push_back(draw);
        }
    }
    Panes(const Panes&) = delete;
    Panes& operator=(const Panes&) = delete;
    ~Panes() {
        for (BufferHandle b : buffers) (void)device.destroyBuffer(b);
    }
};

CameraProjection paneCamera(ClipDepthRange clip) {
    PerspectiveDesc pd;
    pd.aspect = double(kW) / kH;
    pd.nearPlane = kNear;
    pd.farPlane = kFar;
    pd.clipDepth = clip;
    return makePerspective(pd).value();
}

// The opaque floor y = -1 under the panes, as the depth attachment holds it: computed per pixel
// centre on the host (no rasteriser involved), sky beyond the far plane.
std::vector<float> floorDepth(const CameraProjection& cam) {
    const DepthReconstruction rec = makeDepthReconstruction(cam, kW, kH).value();
    std::vector<float> out(size_t(kW) * kH, 1.0f);
    for (uint32_t y = 0; y < kH; ++y)
        for (uint32_t x = 0; x < kW; ++x) {
            const shared::dvec3 r = shared::reconstructViewPosition(x + 0.5, y + 0.5, 1.0, rec.projInfo);
            if (r.y >= 0.0) continue;
            const double t = -1.0 / r.y;  // the linear depth where the ray meets y = -1
            if (t < kFar * 0.999) out[size_t(y) * kW + x] = float(storedDepthFromLinear(cam, t));
        }
    return out;
}

// The least distance, in pixels, from a pixel centre to a pane's edge: every rasteriser covers
// the same pixels when it exceeds how far a snap can move an edge, at most sqrt(2) / 32 pixel on
// the coarsest sub-pixel grid the specifications allow (1/16 pixel).
double panesMissPixelCentres(const CameraProjection& cam) {
    const glm::dmat4 p = cam.projection;
    double margin = 1.0;
    for (const Pane& q : kPanes)
        for (const glm::dvec3& corner : {q.corner, q.corner + q.edgeU + q.edgeV}) {
            const glm::dvec4 clip = p * glm::dvec4(corner, 1.0);
            const double x = (clip.x / clip.w + 1.0) * 0.5 * kW, y = (clip.y / clip.w + 1.0) * 0.5 * kH;
            for (double w : {x, y}) margin = std::min(margin, std::abs(w - std::floor(w) - 0.5));
        }
    return margin;
}

}  // namespace

TEST_CASE("oit agrees across backends in every mode: high tier", "[cross-backend][oit]") { compareOit(Tier::High); }
TEST_CASE("oit agrees across backends: current tier (weighted blended)", "[cross-backend][oit]") { compareOit(Tier::Current); }

TEST_CASE("ao through transparent layers agrees across backends (high tier)", "[cross-backend][oit][oit-layers]") {
    SFX_OPEN_AT_LEAST_TWO(devices, Tier::High);
    const double margin = panesMissPixelCentres(paneCamera(ClipDepthRange::ZeroToOne));
    INFO("the panes' edges pass " << margin << " px from the nearest pixel centre");
    REQUIRE(margin > std::sqrt(2.0) / 32.0);
    struct Case {
        AoTechnique technique;
        TransparencyAoOccluders occluders;
        uint32_t filterRadius;
    };
    const Case cases[] = {{AoTechnique::Alchemy, TransparencyAoOccluders::BruteForce, 0},
                          {AoTechnique::Scalable, TransparencyAoOccluders::BruteForce, 0},
                          {AoTechnique::Scalable, TransparencyAoOccluders::Compressed, 0},
                          {AoTechnique::Scalable, TransparencyAoOccluders::BruteForce, 2}};
    for (const Case& c : cases) {
        TransparencyDesc desc;
        desc.width = kW;
        desc.height = kH;
        desc.profile = tiers::profile(Tier::High);
        desc.compressedNodes = 4;
        desc.ao.enabled = true;
        desc.ao.config.technique = c.technique;
        desc.ao.config.radius = 0.8;
        desc.ao.config.samples = 12;
        desc.ao.config.intensity = c.technique == AoTechnique::Scalable ? 3.0 : 1.0;
        desc.ao.config.bias = 0.01;
        desc.ao.occluders = c.occluders;
        desc.ao.filterRadius = c.filterRadius;
        const std::string what = std::string("ao through layers ") + toString(c.technique) +
            (c.occluders == TransparencyAoOccluders::Compressed ? " compressed" : " brute force") + " filter " + std::to_string(c.filterRadius);
        std::map<std::string, std::vector<double>> ao, color;
        for (Opened& o : devices) {
            INFO(o.name << ": " << what);
            const CameraProjection cam = paneCamera(o.device->caps().clipDepth);
            const Panes panes(*o.device);
            const GpuTransparency g = runTransparency(*o.device, desc, opaqueRamp(kW, kH), floorDepth(cam), glm::mat4(1.0f),
                                                      glm::mat4(cam.projection), panes.draws);
            REQUIRE(g.ao.size() == size_t(kW) * kH * 2);
            CHECK(g.stats.dropped == 0);
            ao[o.name] = g.ao;
            color[o.name] = g.color;
        }
        requireNoValidation(devices);
        requireSpan(ao.begin()->second, 0.1, what);
        requirePairsWithin(ao, kLayerAoPairWorst, what, c.technique == AoTechnique::Alchemy ? kAlchemyTieFraction : 0.0);
        requirePairsWithin(color, kAbufferPairWorst, "oit colour under perspective, " + what);
    }
}

TEST_CASE("multilayer ao agrees across backends (high tier)", "[cross-backend][ao][multilayer]") {
    SFX_OPEN_AT_LEAST_TWO(devices, Tier::High);
    const tools::AnalyticScene scene = tools::cornerScene(kW, kH);
    for (AoTechnique t : {AoTechnique::Alchemy, AoTechnique::Scalable, AoTechnique::Crease})
        for (uint32_t layers : {2u, 4u}) {
            const std::vector<std::vector<float>> depths = syntheticDepthLayers(scene, layers);
            const std::string what = std::string("multilayer ao ") + toString(t) + " " + std::to_string(layers) + " layers";
            std::map<std::string, std::vector<double>> results;
            for (Opened& o : devices) {
                INFO(o.name << ": " << what);
                results[o.name] = runMultilayerAo(*o.device, tiers::profile(Tier::High), scene, t, depths).visibility.values;
            }
            requireNoValidation(devices);
            requireSpan(results.begin()->second, 0.05, what);
            requirePairsWithin(results, kAoPairWorst, what);
        }
}
