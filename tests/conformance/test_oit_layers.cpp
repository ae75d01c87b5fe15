// The A-buffer's work on the layers (high tier), on the device under test against the
// double-precision references of sfx/reference/oit_reference.hpp: list compression during the
// resolve (compressList + quantizeCompressed), opacity-based AO through the layers, brute force
// and from the compressed nodes (opacityAmbientOcclusion), Alchemy and Scalable; and the
// property any correct implementation has: AO on a floor beside a translucent wall falls
// monotonically with the wall's opacity, opacity 0 is no wall, opacity 1 an opaque wall.
// Tolerances: docs/oit.md ("AO through the layers").
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>

#include "portability_rows.hpp"
#include "sfx/half.hpp"
#include "sfx/oit.hpp"
#include "sfx/reference/ao_reference.hpp"
#include "sfx/reference/oit_ao_filter.hpp"
#include "sfx/reference/oit_reference.hpp"
#include "sfx_shared_oit.h"
#include "sfx_shared_oit_params.h"
#include "test_device.hpp"

using namespace sfx;
using namespace sfx::reference;
using glm::dvec3;

namespace {

constexpr uint32_t kW = 48, kH = 32;
constexpr double kNear = 0.5, kFar = 20.0;

// A quad in view space (camera at the origin looking down -z): corner + s * edgeU + t * edgeV,
// s, t in [0, 1]; `normal` the authored normal.
struct Quad {
    dvec3 corner, edgeU, edgeV, normal;
    double alpha = 0.5;
    bool opaque = false;  // drawn into the opaque depth instead of through the A-buffer
};

CameraProjection camera() {
    PerspectiveDesc pd;
    pd.aspect = double(kW) / kH;
    pd.nearPlane = kNear;
    pd.farPlane = kFar;
    pd.clipDepth = test::device().caps().clipDepth;
    return makePerspective(pd).value();
}

// The ray through pixel (x, y)'s centre, scaled so that its linear depth is 1.
dvec3 ray(const DepthReconstruction& rec, uint32_t x, uint32_t y) {
    const shared::dvec3 r = shared::reconstructViewPosition(x + 0.5, y + 0.5, 1.0, rec.projInfo);
    return {r.x, r.y, r.z};
}

// The quad's corners in window pixels (the reference's rows), snapped to the device's sub-pixel
// grid (DeviceLimits::subPixelPrecisionBits), as the GPU's rasteriser snaps vertices: at
// SwiftShader's 1/16 pixel the snap moves an edge by up to 0.044 pixels and a wall seen at a
// grazing angle by a visible depth, so the reference draws the snapped quad. Opaque quads are
// drawn the same way (their depth is uploaded), so an opaque wall is the translucent one at
// alpha 1.
struct WindowQuad {
    glm::dvec2 p[4];
    double w[4];  // view depth at each corner
};
WindowQuad windowQuad(const Quad& q, const DepthReconstruction& rec) {
    const double* pi = rec.projInfo;
    const dvec3 c[4] = {q.corner, q.corner + q.edgeU, q.corner + q.edgeU + q.edgeV, q.corner + q.edgeV};
    WindowQuad out;
    for (int i = 0; i < 4; ++i) {
        out.p[i] = test::snapToSubPixelGrid(glm::dvec2((c[i].x / -c[i].z - pi[2]) / pi[0], (c[i].y / -c[i].z - pi[3]) / pi[1]));
        out.w[i] = -c[i].z;
    }
    return out;
}

// How far (pixels) pixel (x, y)'s centre lies from the quad's outline on screen, inside or out:
// the scenes keep every centre clear of it, so coverage is no rounding decision.
double outlineDistancePx(const WindowQuad& wq, uint32_t x, uint32_t y) {
    const glm::dvec2 p(x + 0.5, y + 0.5);
    double best = std::numeric_limits<double>::infinity();
    for (int e = 0; e < 4; ++e) {
        const glm::dvec2 a = wq.p[e], d = wq.p[(e + 1) % 4] - a;
        const double t = std::clamp(glm::dot(p - a, d) / glm::dot(d, d), 0.0, 1.0);
        best = std::min(best, glm::length(p - (a + t * d)));
    }
    return best;
}

// The view depth where the snapped quad (triangles 0 1 2 and 0 2 3, as drawn) covers pixel
// (x, y)'s centre, perspective-correct from its corners; 0 where it does not cover it.
double rasterDepth(const WindowQuad& wq, uint32_t x, uint32_t y) {
    const glm::dvec2 c(x + 0.5, y + 0.5);
    for (const std::array<int, 3>& t : {std::array<int, 3>{0, 1, 2}, std::array<int, 3>{0, 2, 3}}) {
        const glm::dvec2 a = wq.p[t[0]], b = wq.p[t[1]], d = wq.p[t[2]];
        const double area = (b.x - a.x) * (d.y - a.y) - (b.y - a.y) * (d.x - a.x);
        if (area == 0.0) continue;
        double bary[3];
        bool inside = true;
        for (int e = 0; e < 3; ++e) {
            const glm::dvec2 p = wq.p[t[(e + 1) % 3]], q = wq.p[t[(e + 2) % 3]];
            bary[e] = ((q.x - p.x) * (c.y - p.y) - (q.y - p.y) * (c.x - p.x)) / area;
            inside = inside && bary[e] >= 0.0;  // on the diagonal either triangle gives the fragment
        }
        if (!inside) continue;
        return 1.0 / (bary[0] / wq.w[t[0]] + bary[1] / wq.w[t[1]] + bary[2] / wq.w[t[2]]);
    }
    return 0.0;
}

const Quad kFloor{{-30, -1, -0.5}, {60, 0, 0}, {0, 0, -40}, {0, 1, 0}, 1.0, true};

struct Frame {
    FragmentImage image;
    std::vector<float> storedDepth;  // what the opaque depth attachment holds
};

// The reference picture of the scene: opaque depth from the opaque quads (stored as float, and
// linearised from that float as the GPU reads it), fragments of the translucent quads.
Frame rasterize(const std::vector<Quad>& quads) {
    const CameraProjection cam = camera();
    const DepthReconstruction rec = makeDepthReconstruction(cam, kW, kH).value();
    Frame f{FragmentImage(kW, kH, rec), std::vector<float>(size_t(kW) * kH, 1.0f)};
    Grid stored(kW, kH, 1.0);
    std::vector<WindowQuad> windows;
    for (const Quad& q : quads) windows.push_back(windowQuad(q, rec));
    for (uint32_t y = 0; y < kH; ++y)
        for (uint32_t x = 0; x < kW; ++x) {
            double nearest = 0;
            for (size_t qi = 0; qi < quads.size(); ++qi) {
                const double margin = outlineDistancePx(windows[qi], x, y);
                INFO("pixel " << x << ", " << y << " is " << margin << " px from a quad's edge on " << test::label());
                REQUIRE(margin > 0.01);  // the scenes keep edges away from pixel centres
                const double t = rasterDepth(windows[qi], x, y);
                if (!(t > 0 && t < kFar * 0.999)) continue;  // not covered, or sky
                if (quads[qi].opaque && (nearest == 0 || t < nearest)) nearest = t;
            }
            if (nearest > 0) {
                f.storedDepth[y * kW + x] = float(storedDepthFromLinear(cam, nearest));
                stored.at(x, y) = double(f.storedDepth[y * kW + x]);
            }
        }
    const Grid linear = linearizeDepth(stored, rec);
    const std::vector<dvec3> normals = normalsFromDepth(linear, rec);
    uint32_t draw = 0;
    for (size_t qi = 0; qi < quads.size(); ++qi) {
        const Quad& q = quads[qi];
        if (q.opaque) continue;
        for (uint32_t y = 0; y < kH; ++y)
            for (uint32_t x = 0; x < kW; ++x) {
                const dvec3 d = ray(rec, x, y);
                const double t = rasterDepth(windows[qi], x, y);
                if (!(t > 0 && t < kFar * 0.999)) continue;
                OitFragment fr;
                fr.alpha = q.alpha;
                fr.depth = t;
                fr.normal = glm::normalize(q.normal);
                fr.frontFacing = glm::dot(fr.normal, t * d) < 0.0;
                fr.drawIndex = draw;
                f.image.fragments[f.image.index(x, y)].push_back(fr);
            }
        ++draw;
    }
    for (size_t i = 0; i < f.image.opaque.size(); ++i) {
        f.image.opaque[i].depth = linear.values[i];
        f.image.opaque[i].normal = normals[i];
    }
    return f;
}

struct Gpu {
    std::vector<double> blended, opaque;  // the AO output's r and g
    std::vector<uint32_t> compressed;     // SFX_OIT_COMPRESSED_WORDS per pixel
};

Gpu render(const std::vector<Quad>& quads, const Frame& frame, const TransparencyDesc& settings) {
    Device& dev = test::device();
    TransparencyDesc desc = settings;
    desc.width = kW;
    desc.height = kH;
    desc.profile = test::tierProfile();
    auto created = Transparency::create(dev, desc);
    INFO(created.status().toString());
    REQUIRE(created.isOk());
    std::unique_ptr<Transparency> oit = std::move(created.value());

    std::vector<uint16_t> color(size_t(kW) * kH * 4, floatToHalf(0.5f));
    auto opaque = dev.createTexture({kW, kH, 1, Format::RGBA16F, kTextureSampled | kTextureRenderTarget, "test opaque"});
    auto depth = dev.createTexture({kW, kH, 1, Format::D32F, kTextureSampled | kTextureRenderTarget, "test depth"});
    REQUIRE(opaque.isOk());
    REQUIRE(depth.isOk());
    SFX_REQUIRE_OK(dev.writeTexture(opaque.value(), 0, color.data(), color.size() * 2));
    SFX_REQUIRE_OK(dev.writeTexture(depth.value(), 0, frame.storedDepth.data(), frame.storedDepth.size() * 4));

    std::vector<TransparentVertex> vertices;
    std::vector<TransparentDraw> draws;
    for (const Quad& q : quads) {
        if (q.opaque) continue;
        const dvec3 c[4] = {q.corner, q.corner + q.edgeU, q.corner + q.edgeU + q.edgeV, q.corner + q.edgeV};
        for (int i : {0, 1, 2, 0, 2, 3}) {
            const glm::vec3 p(c[i]), n(q.normal);
            vertices.push_back({{p.x, p.y, p.z}, {n.x, n.y, n.z}});
        }
    }
    uint32_t draw = 0;
    for (const Quad& q : quads) {
        if (q.opaque) continue;
        TransparentDraw d;
        d.vertexCount = 6;
        d.color = glm::vec3(0.8f);
        d.opacity = float(q.alpha);
        d.id = draw++;
        draws.push_back(d);
    }
    // One buffer per draw (draws start at vertex 0).
    std::vector<BufferHandle> buffers;
    for (size_t i = 0; i < draws.size(); ++i) {
        auto b = dev.createBuffer({6 * sizeof(TransparentVertex), kBufferVertex, "test quad"});
        REQUIRE(b.isOk());
        SFX_REQUIRE_OK(dev.writeBuffer(b.value(), 0, vertices.data() + 6 * i, 6 * sizeof(TransparentVertex)));
        draws[i].vertices = b.value();
        buffers.push_back(b.value());
    }
    TransparencyInputs in;
    in.opaqueColor = opaque.value();
    in.opaqueDepth = depth.value();
    in.projection = glm::mat4(camera().projection);
    in.draws = draws;
    for (int f = 0; f < 2; ++f) {  // the second frame's pool is sized from the first's count
        SFX_REQUIRE_OK(oit->render(in));
        SFX_REQUIRE_OK(dev.flush());
    }
    auto stats = oit->stats();
    REQUIRE(stats.isOk());
    CHECK(stats->dropped == 0);
    Gpu g;
    if (!oit->aoOutput().isNull()) {
        std::vector<uint16_t> ao(size_t(kW) * kH * 2);
        SFX_REQUIRE_OK(dev.readTexture(oit->aoOutput(), 0, ao.data(), ao.size() * 2));
        for (size_t i = 0; i < size_t(kW) * kH; ++i) {
            g.blended.push_back(halfToFloat(ao[i * 2]));
            g.opaque.push_back(halfToFloat(ao[i * 2 + 1]));
        }
    }
    if (!oit->compressedLists().isNull()) {
        g.compressed.resize(size_t(kW) * kH * size_t(shared::SFX_OIT_COMPRESSED_WORDS));
        SFX_REQUIRE_OK(dev.readBuffer(oit->compressedLists(), 0, g.compressed.data(), g.compressed.size() * 4));
    }
    oit.reset();
    for (BufferHandle b : buffers) (void)dev.destroyBuffer(b);
    (void)dev.destroyTexture(opaque.value());
    (void)dev.destroyTexture(depth.value());
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
    return g;
}

// A translucent wall standing just above the floor right of the centre, its face (normal -x)
// toward the camera's axis, and an opacity-0 pane in the sky (so a frame always has a draw).
std::vector<Quad> wallScene(double alpha, bool opaqueWall) {
    Quad wall{{0.63, -0.95, -2.3}, {0, 0, -4.4}, {0, 1.37, 0}, {-1, 0, 0}, alpha, opaqueWall};
    Quad clear{{-2.03, 2.51, -6.1}, {1.13, 0, 0}, {0, 0.71, 0}, {0, 0, 1}, 0.0, false};
    return {kFloor, wall, clear};
}

// Panes facing the camera (one authored backwards, so back-facing) over the floor: up to six
// layers, more than four nodes, so compression drops some.
std::vector<Quad> paneScene() {
    return {kFloor,
            {{-1.53, -0.83, -2.2}, {2.11, 0, 0}, {0, 1.49, 0}, {0, 0, 1}, 0.35},
            {{-0.97, -0.91, -3.1}, {2.27, 0, 0}, {0, 1.61, 0}, {0, 0, -1}, 0.6},
            {{-2.21, -0.51, -4.3}, {2.63, 0, 0}, {0, 1.23, 0}, {0, 0, 1}, 0.2},
            {{-0.43, -0.93, -5.2}, {2.91, 0, 0}, {0, 2.03, 0}, {0, 0, 1}, 0.85},
            {{-1.87, -0.77, -6.3}, {3.33, 0, 0}, {0, 1.91, 0}, {0, 0, 1}, 0.45}};
}

AoConfig aoConfig(AoTechnique t) {
    AoConfig c;
    c.technique = t;
    c.radius = 0.8;
    c.samples = 12;
    c.intensity = t == AoTechnique::Scalable ? 3.0 : 1.0;
    c.bias = 0.01;
    return c;
}

TransparencyDesc aoDesc(AoTechnique t, TransparencyAoOccluders occluders, uint32_t nodes) {
    TransparencyDesc d;
    d.compressedNodes = nodes;
    d.ao.enabled = true;
    d.ao.config = aoConfig(t);
    d.ao.occluders = occluders;
    return d;
}

struct Errors {
    double worst = 0, above = 0, meanAbs = 0;  // worst pixel; fraction off by more than 0.03 (printed); mean |error|
};
Errors compare(const std::vector<double>& gpu, const Grid& want) {
    Errors e;
    size_t over = 0;
    for (size_t i = 0; i < gpu.size(); ++i) {
        const double d = std::abs(gpu[i] - want.values[i]);
        e.worst = std::max(e.worst, d);
        e.meanAbs += d / double(gpu.size());
        over += d > 0.03 ? 1 : 0;
    }
    e.above = double(over) / double(gpu.size());
    return e;
}

}  // namespace

TEST_CASE("oit layers: the resolve compresses each list as the reference does (high tier)", "[oit][oit-layers]") {
    if (test::tier() != Tier::High) return;  // the current tier keeps no lists
    const std::vector<Quad> quads = paneScene();
    const Frame frame = rasterize(quads);
    for (uint32_t m : {4u, 2u}) {
        for (bool backHalf : {true, false}) {
            TransparencyDesc d;
            d.compressedNodes = m;
            d.compressBackHalfOnly = backHalf;
            const Gpu g = render(quads, frame, d);
            REQUIRE(g.compressed.size() == size_t(kW) * kH * 3);
            CompressionConfig cc;
            cc.nodes = m;
            cc.backHalfOnly = backHalf;
            cc.zNear = frame.image.reconstruction.nearDepth;
            cc.zFar = frame.image.reconstruction.maxDepth;
            double depthError = 0, opacityError = 0;
            size_t full = 0;
            for (size_t i = 0; i < size_t(kW) * kH; ++i) {
                const std::vector<CompressedNode> want = quantizeCompressed(
                    compressList(frame.image.fragments[i], frame.image.opaque[i], frame.image.reconstruction.maxDepth, cc));
                const glm::uvec4 texel(g.compressed[i * 3], g.compressed[i * 3 + 1], g.compressed[i * 3 + 2], 0u);
                full += frame.image.fragments[i].size() + 1 > m ? 1 : 0;
                for (int k = 0; k < 4; ++k) {
                    depthError = std::max(depthError, std::abs(shared::oitCompressedDepth(texel, k) - want[size_t(k)].depth));
                    opacityError = std::max(opacityError, std::abs(shared::oitCompressedOpacity(texel, k) - want[size_t(k)].opacity));
                }
            }
            WARN("compression M = " << m << (backHalf ? " (back half)" : " (anywhere)") << ": worst depth error " << depthError * 65535
                                    << " / 65535, opacity " << opacityError * 255 << " / 255; " << full << " pixels had more layers than nodes");
            CHECK(full > 100);  // the scene reaches the drop criterion
            // One 16-bit step (float vs double normalisation), one 8-bit step (fp16 opacity).
            CHECK(depthError <= 1.0 / 65535 + 1e-12);
            CHECK(opacityError <= 1.0 / 255 + 1e-12);
        }
    }
}

TEST_CASE("oit layers: opacity-based AO matches the reference, brute force and compressed (high tier)", "[oit][oit-layers]") {
    if (test::tier() != Tier::High) return;
    std::map<std::string, std::pair<double, double>> rows;  // worst, mean |error| over the two scenes
    for (const auto& quads : {paneScene(), wallScene(0.6, false)}) {
        const Frame frame = rasterize(quads);
        for (AoTechnique t : {AoTechnique::Alchemy, AoTechnique::Scalable}) {
            for (TransparencyAoOccluders occ : {TransparencyAoOccluders::BruteForce, TransparencyAoOccluders::Compressed}) {
                const Gpu g = render(quads, frame, aoDesc(t, occ, 4));
                OitAoConfig rc;
                rc.ao = aoConfig(t);
                rc.occluders = occ == TransparencyAoOccluders::Compressed ? OitAoOccluders::Compressed : OitAoOccluders::BruteForce;
                rc.compression.nodes = 4;
                rc.compression.zNear = frame.image.reconstruction.nearDepth;
                rc.compression.zFar = frame.image.reconstruction.maxDepth;
                Result<OitAoResult> want = opacityAmbientOcclusion(frame.image, rc);
                REQUIRE(want.isOk());
                const Errors blended = compare(g.blended, want->blended), opaque = compare(g.opaque, want->opaque);
                double occluded = 0;
                for (double v : want->blended.values) occluded += v < 0.99 ? 1 : 0;
                WARN("AO through layers, " << toString(t) << (occ == TransparencyAoOccluders::Compressed ? ", compressed" : ", brute force")
                                           << ": blended worst " << blended.worst << " (" << blended.above * 100 << "% above 0.03), opaque worst "
                                           << opaque.worst << "; " << occluded << " occluded pixels");
                CHECK(occluded > 10);  // the scene is occluded somewhere (Scalable beside the wall: 15 pixels)
                // fp16 output (2^-11 relative) and float arithmetic: measured 5.6e-4 at worst.
                CHECK(blended.worst <= 2e-3);
                CHECK(opaque.worst <= 2e-3);
                std::pair<double, double>& row = rows[std::string("AO through transparent layers, ") + toString(t) +
                                                      (occ == TransparencyAoOccluders::Compressed ? ", compressed" : ", brute force")];
                row.first = std::max(row.first, blended.worst);
                row.second += blended.meanAbs / 2.0;
            }
        }
    }
    for (const auto& [effect, figures] : rows) test::addPortabilityRow(effect, figures.first, figures.second);
}

TEST_CASE("oit layers: the layer AO is bit-identical whatever the draw order (high tier)", "[oit][oit-layers]") {
    if (test::tier() != Tier::High) return;
    // The AO pass walks each list in the order the fill's races left it and sums in fixed point,
    // with each fragment's transmittance from the resolve's sorted order: no bit may move.
    const std::vector<Quad> quads = paneScene();
    std::vector<Quad> reversed = quads;
    std::reverse(reversed.begin() + 1, reversed.end());  // the floor stays first, the panes reversed
    const Frame frame = rasterize(quads);
    for (TransparencyAoOccluders occ : {TransparencyAoOccluders::BruteForce, TransparencyAoOccluders::Compressed}) {
        const Gpu a = render(quads, frame, aoDesc(AoTechnique::Scalable, occ, 4));
        const Gpu b = render(reversed, frame, aoDesc(AoTechnique::Scalable, occ, 4));
        size_t occluded = 0;
        for (double v : a.blended) occluded += v < 0.99 ? 1 : 0;
        CHECK(occluded > 10);
        CHECK(a.blended == b.blended);
        CHECK(a.opaque == b.opaque);
    }
}

TEST_CASE("oit layers: the bilateral filter of the layer AO matches the reference's (high tier)", "[oit][oit-layers]") {
    if (test::tier() != Tier::High) return;
    for (const auto& quads : {paneScene(), wallScene(0.6, false)}) {
        const Frame frame = rasterize(quads);
        for (TransparencyAoOccluders occ : {TransparencyAoOccluders::BruteForce, TransparencyAoOccluders::Compressed}) {
            for (uint32_t radius : {1u, 3u}) {
                TransparencyDesc d = aoDesc(AoTechnique::Scalable, occ, 4);
                d.ao.filterRadius = radius;
                const Gpu g = render(quads, frame, d);
                OitAoConfig rc;
                rc.ao = aoConfig(AoTechnique::Scalable);
                rc.occluders = occ == TransparencyAoOccluders::Compressed ? OitAoOccluders::Compressed : OitAoOccluders::BruteForce;
                rc.compression.nodes = 4;
                rc.compression.zNear = frame.image.reconstruction.nearDepth;
                rc.compression.zFar = frame.image.reconstruction.maxDepth;
                Result<OitAoResult> raw = opacityAmbientOcclusion(frame.image, rc);
                REQUIRE(raw.isOk());
                const OitAoResult want = filterLayerAo(frame.image, raw.value(), radius);
                const Errors blended = compare(g.blended, want.blended), opaque = compare(g.opaque, want.opaque);
                // How much the filter moved the reference: a device returning the raw AO fails.
                const Errors moved = compare(raw->blended.values, want.blended);
                WARN("filtered layer AO, radius " << radius << (occ == TransparencyAoOccluders::Compressed ? ", compressed" : ", brute force")
                                                  << ": blended worst " << blended.worst << ", opaque worst " << opaque.worst
                                                  << "; the filter moves the reference by up to " << moved.worst);
                CHECK(moved.worst > 0.01);
                // fp16 intermediate and output (2^-11 relative) and float arithmetic, as unfiltered.
                CHECK(blended.worst <= 2e-3);
                CHECK(opaque.worst <= 2e-3);
            }
        }
    }
}

TEST_CASE("oit layers: AO on a floor beside a translucent wall is monotone in its opacity (high tier)", "[oit][oit-layers]") {
    if (test::tier() != Tier::High) return;
    for (AoTechnique t : {AoTechnique::Alchemy, AoTechnique::Scalable}) {
        const TransparencyDesc d = aoDesc(t, TransparencyAoOccluders::BruteForce, 0);
        // The floor pixels the opaque wall does not cover, nor any of their 4 neighbours: there the
        // opaque surface's normal (from depth) is the floor's in both pictures (beside the opaque
        // wall's silhouette it is derived across the depth step, which the A-buffer picture lacks).
        const Frame opaqueFrame = rasterize(wallScene(1.0, true));
        const Frame noWallFrame = rasterize(wallScene(0.0, false));
        auto same = [&](int x, int y) {
            if (x < 0 || y < 0 || x >= int(kW) || y >= int(kH)) return true;
            const size_t i = size_t(y) * kW + size_t(x);
            return opaqueFrame.image.opaque[i].depth == noWallFrame.image.opaque[i].depth;
        };
        std::vector<size_t> floor;
        for (int y = 0; y < int(kH); ++y)
            for (int x = 0; x < int(kW); ++x)
                if (same(x, y) && same(x - 1, y) && same(x + 1, y) && same(x, y - 1) && same(x, y + 1) &&
                    noWallFrame.image.opaque[size_t(y) * kW + size_t(x)].depth < noWallFrame.image.reconstruction.maxDepth)
                    floor.push_back(size_t(y) * kW + size_t(x));
        REQUIRE(floor.size() > 200);
        // No wall at all: the floor alone (the clear pane keeps a draw in the frame).
        std::vector<Quad> none = wallScene(0.0, false);
        none.erase(none.begin() + 1);
        const Gpu noWall = render(none, rasterize(none), d);
        const Gpu opaqueWall = render(wallScene(1.0, true), opaqueFrame, d);
        std::vector<Gpu> runs;
        for (double alpha : {0.0, 0.25, 0.5, 0.75, 1.0}) runs.push_back(render(wallScene(alpha, false), rasterize(wallScene(alpha, false)), d));
        double rise = 0, toNoWall = 0, toOpaque = 0, darkest = 0;
        for (size_t i : floor) {
            for (size_t k = 1; k < runs.size(); ++k) rise = std::max(rise, runs[k].blended[i] - runs[k - 1].blended[i]);
            toNoWall = std::max(toNoWall, std::abs(runs.front().blended[i] - noWall.blended[i]));
            toOpaque = std::max(toOpaque, std::abs(runs.back().blended[i] - opaqueWall.blended[i]));
            darkest = std::max(darkest, noWall.blended[i] - opaqueWall.blended[i]);
        }
        WARN(toString(t) << ": largest rise with opacity " << rise << ", alpha 0 vs no wall " << toNoWall << ", alpha 1 vs opaque wall " << toOpaque
                         << ", the opaque wall darkens the floor by up to " << darkest);
        CHECK(darkest > 0.1);     // the wall occludes the floor beside it
        CHECK(rise <= 1e-3);      // visibility never rises with opacity (fp16 output: 1e-3)
        CHECK(toNoWall == 0.0);   // opacity 0 occludes nothing, exactly
        CHECK(toOpaque <= 2e-3);  // opacity 1 is an opaque wall (its depth from the fragment vs the depth buffer)
    }
}

TEST_CASE("oit layers: settings out of range are refused by name; the plan names the passes", "[oit][oit-layers]") {
    Device& dev = test::device();
    TransparencyDesc d;
    d.width = kW;
    d.height = kH;
    d.profile = test::tierProfile();
    d.maxLayers = 33;
    auto r = Transparency::create(dev, d);
    REQUIRE(!r.isOk());
    CHECK(r.status().message().find("TransparencyDesc.maxLayers") != std::string::npos);
    d.maxLayers = 0;  // unset is the quality's K; 0 is out of range
    r = Transparency::create(dev, d);
    REQUIRE(!r.isOk());
    CHECK(r.status().message().find("TransparencyDesc.maxLayers is 0") != std::string::npos);
    d.maxLayers.reset();
    d.compressedNodes = 5;
    r = Transparency::create(dev, d);
    REQUIRE(!r.isOk());
    CHECK(r.status().message().find("TransparencyDesc.compressedNodes") != std::string::npos);
    d.compressedNodes = 0;
    d.ao.enabled = true;
    d.ao.occluders = TransparencyAoOccluders::Compressed;
    r = Transparency::create(dev, d);
    REQUIRE(!r.isOk());
    CHECK(r.status().message().find("TransparencyDesc.compressedNodes") != std::string::npos);
    d.ao.occluders = TransparencyAoOccluders::BruteForce;
    d.ao.config.technique = AoTechnique::Crease;
    r = Transparency::create(dev, d);
    REQUIRE(!r.isOk());
    CHECK(r.status().message().find("TransparencyDesc.ao.config.technique") != std::string::npos);
    d.ao.config.technique = AoTechnique::Alchemy;
    d.ao.config.samples = 0;
    r = Transparency::create(dev, d);
    REQUIRE(!r.isOk());
    CHECK(r.status().message().find("TransparencyDesc.ao.config.samples") != std::string::npos);
    d.ao.config.samples = 8;
    d.ao.filterRadius = 9;
    r = Transparency::create(dev, d);
    REQUIRE(!r.isOk());
    CHECK(r.status().message().find("TransparencyDesc.ao.filterRadius") != std::string::npos);
    d.ao.filterRadius = 0;
    d.compressedNodes = 4;
    d.ao.occluders = TransparencyAoOccluders::Compressed;
    r = Transparency::create(dev, d);
    REQUIRE(r.isOk());
    const EffectPlan p = r.value()->plan(true);
    std::string names;
    for (const PlannedPass& pass : p.passes) names += pass.name + "\n";
    INFO(names);
    if (test::tier() == Tier::High) {
        CHECK(p.passes.size() == 4u);
        CHECK(names.find("compress lists to 4 nodes") != std::string::npos);
        CHECK(names.find("AO through layers") != std::string::npos);
        CHECK(names.find("bilateral filter") == std::string::npos);  // listed only when used
        d.ao.filterRadius = 2;
        auto filtered = Transparency::create(dev, d);
        REQUIRE(filtered.isOk());
        std::string withFilter;
        for (const PlannedPass& pass : filtered.value()->plan(true).passes) withFilter += pass.name + "\n";
        INFO(withFilter);
        CHECK(filtered.value()->plan(true).passes.size() == 6u);
        CHECK(withFilter.find("bilateral filter, horizontal") != std::string::npos);
    } else {
        CHECK(names.find("opaque layer only") != std::string::npos);
    }
    CHECK(r.value()->plan(false).passes.empty());
}
