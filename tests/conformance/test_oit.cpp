// Order-independent transparency on the device under test (sfx/oit.hpp): the A-buffer on the
// high tier, weighted blended OIT under the GL ES 3.0 ceiling, against the double-precision
// references of sfx/reference/oit_reference.hpp, and the properties any correct implementation
// has. Tolerances are explained in docs/oit.md ("Conformance tolerances").
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <optional>
#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "sfx/half.hpp"
#include "sfx/oit.hpp"
#include "sfx/reference/oit_reference.hpp"
#include "test_device.hpp"

using namespace sfx;
using namespace sfx::reference;

namespace {

constexpr uint32_t kW = 24, kH = 12;
constexpr double kNear = 0.5, kFar = 20.0;
// The output is RGBA16F: half an 8-bit step (1/510) bounds fp16 storage of colours in [0, 1]
// (2^-11 relative) and the nodes' fp16 premultiplied colours with room to spare.
constexpr double kEightBit = 0.5 / 255.0;

// A layer: a full-viewport quad at view depth `depth` in colour `color`.
struct Layer {
    double depth;
    glm::dvec3 color;
    double opacity;
    uint32_t id;
};

// Orthographic along -z: x, y of the view map straight to clip x, y, and view depth d in
// [kNear, kFar] to the device's clip depth range, so window depth is (d - near) / (far - near).
glm::mat4 projection() {
    const bool zeroToOne = test::device().caps().clipDepth == ClipDepthRange::ZeroToOne;
    glm::mat4 p(1.0f);
    const float range = float(kFar - kNear);
    p[2][2] = zeroToOne ? -1.0f / range : -2.0f / range;
    p[3][2] = zeroToOne ? -float(kNear) / range : -2.0f * float(kNear) / range - 1.0f;
    return p;
}
double windowDepth(double viewDepth) { return (viewDepth - kNear) / (kFar - kNear); }

struct OitScene {
    std::vector<Layer> layers;
    // Opaque: left half sky (depth 1, the background colour), right half a surface at view depth 6.
    glm::dvec3 background{0.2, 0.4, 0.6};
    glm::dvec3 surface{0.9, 0.8, 0.1};
    double surfaceDepth = 6.0;
    bool surfaceAt(uint32_t x) const { return x >= kW / 2; }
};

double roundHalf(double v) { return double(halfToFloat(floatToHalf(float(v)))); }

struct Gpu {
    std::vector<glm::dvec3> color;
    TransparencyStats stats;
    std::vector<uint16_t> raw;
};

// Renders `frames` frames of the scene (draws in the given order) and reads the last one back.
// Two by default: the first frame's pool is a guess (4 nodes per pixel), the second is sized
// from the first's count, as a host's steady scene is.
Gpu render(const OitScene& scene, const std::vector<size_t>& order, std::optional<uint64_t> initialPoolNodes = {}, int frames = 2,
           std::vector<TransparencyStats>* perFrame = nullptr, std::optional<uint32_t> maxLayers = {}) {
    Device& dev = test::device();
    TransparencyDesc desc;
    desc.width = kW;
    desc.height = kH;
    desc.profile = test::tierProfile();
    desc.colorFormat = Format::RGBA16F;
    desc.depthFormat = Format::D32F;
    desc.initialPoolNodes = initialPoolNodes;
    desc.maxLayers = maxLayers;
    auto created = Transparency::create(dev, desc);
    INFO(created.status().toString());
    REQUIRE(created.isOk());
    std::unique_ptr<Transparency> oit = std::move(created.value());
    CHECK(oit->usesAbuffer() == (test::tier() == Tier::High));

    std::vector<uint16_t> color(size_t(kW) * kH * 4);
    std::vector<float> depth(size_t(kW) * kH);
    for (uint32_t y = 0; y < kH; ++y)
        for (uint32_t x = 0; x < kW; ++x) {
            const bool s = scene.surfaceAt(x);
            const glm::dvec3 c = s ? scene.surface : scene.background;
            for (int ch = 0; ch < 3; ++ch) color[(y * kW + x) * 4 + size_t(ch)] = floatToHalf(float(c[ch]));
            color[(y * kW + x) * 4 + 3] = floatToHalf(1.0f);
            depth[y * kW + x] = s ? float(windowDepth(scene.surfaceDepth)) : 1.0f;
        }
    auto opaque = dev.createTexture({kW, kH, 1, Format::RGBA16F, kTextureSampled | kTextureRenderTarget, "test opaque"});
    auto opaqueDepth = dev.createTexture({kW, kH, 1, Format::D32F, kTextureSampled | kTextureRenderTarget, "test depth"});
    REQUIRE(opaque.isOk());
    REQUIRE(opaqueDepth.isOk());
    SFX_REQUIRE_OK(dev.writeTexture(opaque.value(), 0, color.data(), color.size() * 2));
    SFX_REQUIRE_OK(dev.writeTexture(opaqueDepth.value(), 0, depth.data(), depth.size() * 4));

    // One quad mesh at z = 0; each layer moves it to its depth.
    const float c[6][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, -1}, {1, 1}, {-1, 1}};
    std::vector<TransparentVertex> quad;
    for (const auto& p : c) quad.push_back({{p[0], p[1], 0.0f}, {0.0f, 0.0f, 1.0f}});
    auto vb = dev.createBuffer({quad.size() * sizeof(TransparentVertex), kBufferVertex, "test quad"});
    REQUIRE(vb.isOk());
    SFX_REQUIRE_OK(dev.writeBuffer(vb.value(), 0, quad.data(), quad.size() * sizeof(TransparentVertex)));

    std::vector<TransparentDraw> draws;
    for (size_t i : order) {
        const Layer& l = scene.layers[i];
        TransparentDraw d;
        d.vertices = vb.value();
        d.vertexCount = 6;
        d.model = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, -float(l.depth)));
        d.color = glm::vec3(l.color);
        d.opacity = float(l.opacity);
        d.id = l.id;
        draws.push_back(d);
    }
    TransparencyInputs in;
    in.opaqueColor = opaque.value();
    in.opaqueDepth = opaqueDepth.value();
    in.projection = projection();
    in.draws = draws;
    for (int f = 0; f < frames; ++f) {
        SFX_REQUIRE_OK(oit->render(in));
        SFX_REQUIRE_OK(dev.flush());
        if (perFrame) {
            auto s = oit->stats();
            REQUIRE(s.isOk());
            perFrame->push_back(s.value());
        }
    }
    Gpu g;
    g.raw.resize(color.size());
    SFX_REQUIRE_OK(dev.readTexture(oit->output(), 0, g.raw.data(), g.raw.size() * 2));
    for (size_t i = 0; i < size_t(kW) * kH; ++i)
        g.color.push_back({halfToFloat(g.raw[i * 4]), halfToFloat(g.raw[i * 4 + 1]), halfToFloat(g.raw[i * 4 + 2])});
    auto s = oit->stats();
    REQUIRE(s.isOk());
    g.stats = s.value();
    oit.reset();
    (void)dev.destroyBuffer(vb.value());
    (void)dev.destroyTexture(opaque.value());
    (void)dev.destroyTexture(opaqueDepth.value());
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
    return g;
}

std::vector<size_t> identity(size_t n) {
    std::vector<size_t> o(n);
    for (size_t i = 0; i < n; ++i) o[i] = i;
    return o;
}

// The pixel's fragments and opaque surface for the references (colours as the GPU holds them).
std::vector<OitFragment> fragmentsAt(const OitScene& scene) {
    std::vector<OitFragment> f;
    for (const Layer& l : scene.layers) {
        OitFragment fr;
        fr.color = l.color;
        fr.alpha = l.opacity;
        fr.depth = l.depth;
        fr.drawIndex = l.id;
        f.push_back(fr);
    }
    return f;
}
OpaqueSurface opaqueAt(const OitScene& scene, uint32_t x) {
    OpaqueSurface o;
    o.color = scene.surfaceAt(x) ? scene.surface : scene.background;
    for (int c = 0; c < 3; ++c) o.color[c] = roundHalf(o.color[c]);
    o.depth = scene.surfaceAt(x) ? scene.surfaceDepth : std::numeric_limits<double>::infinity();
    return o;
}

// The worst channel difference against a per-pixel reference.
template <class Ref>
double worstError(const Gpu& g, const OitScene& scene, Ref reference) {
    double worst = 0;
    for (uint32_t y = 0; y < kH; ++y)
        for (uint32_t x = 0; x < kW; ++x) {
            const glm::dvec3 want = reference(fragmentsAt(scene), opaqueAt(scene, x));
            for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(g.color[y * kW + x][c] - want[c]));
        }
    return worst;
}

OitScene layeredScene(uint32_t n, uint32_t seed, double maxOpacity = 0.8) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    OitScene s;
    for (uint32_t i = 0; i < n; ++i)
        s.layers.push_back({1.0 + 8.0 * double(i) / double(n), {u(rng), u(rng), u(rng)}, 0.1 + (maxOpacity - 0.1) * u(rng), 10 + i});
    std::shuffle(s.layers.begin(), s.layers.end(), rng);
    return s;
}

}  // namespace

TEST_CASE("oit: N translucent layers composite to the exact sorted result", "[oit]") {
    const OitScene scene = layeredScene(5, 1);
    const Gpu g = render(scene, identity(scene.layers.size()));
    const double exact = worstError(g, scene, compositeExact);
    const double weighted = worstError(g, scene, compositeWeightedBlended);
    INFO("worst error vs exact " << exact << ", vs weighted blended reference " << weighted);
    if (test::tier() == Tier::High) {
        CHECK(exact <= kEightBit);
        CHECK(g.stats.dropped == 0);
        // Right half: 5 layers, 3 of them (depth < 6) in front of the surface; left half all 5.
        CHECK(g.stats.fragments == uint64_t(kH) * (kW / 2) * 5 + uint64_t(kH) * (kW / 2) * 4);
    } else {
        // Weighted blended OIT is held to its own reference (fp16 targets: 2e-3 relative on
        // weights up to 3e3), and its distance from the exact result is bounded below.
        CHECK(weighted <= 4.0 * kEightBit);
    }
}

TEST_CASE("oit: more layers than K keep the nearest K exact and fold the rest (high tier)", "[oit]") {
    if (test::tier() != Tier::High) return;  // the fallback has no K
    const OitScene scene = layeredScene(22, 2, 0.3);
    // The quality's K (16), and K = 4 through TransparencyDesc::maxLayers.
    for (std::optional<uint32_t> maxLayers : {std::optional<uint32_t>{}, std::optional<uint32_t>{4u}}) {
        const Gpu g = render(scene, identity(scene.layers.size()), {}, 2, nullptr, maxLayers);
        const uint32_t k = maxLayers.value_or(keptLayers(TransparencyQuality::Standard));
        const double kept = worstError(g, scene, [&](const auto& f, const auto& o) { return compositeKept(f, o, k); });
        INFO("worst error vs kept-" << k << " reference " << kept);
        CHECK(kept <= kEightBit);
    }
}

TEST_CASE("oit: shuffled draw order gives the same output", "[oit]") {
    const OitScene scene = layeredScene(20, 3, 0.5);
    const Gpu a = render(scene, identity(scene.layers.size()));
    std::vector<size_t> order = identity(scene.layers.size());
    std::mt19937 rng(7);
    std::shuffle(order.begin(), order.end(), rng);
    const Gpu b = render(scene, order);
    if (test::tier() == Tier::High) {
        CHECK(a.raw == b.raw);  // bit-identical: sorted, with the tail folded in sorted order
    } else {
        // Blending sums in fp16 in draw order: the same within rounding, not bit for bit.
        double worst = 0;
        for (size_t i = 0; i < a.color.size(); ++i)
            for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(a.color[i][c] - b.color[i][c]));
        CHECK(worst <= kEightBit);
    }
}

TEST_CASE("oit: equal depths are ordered by draw id, not by draw order", "[oit]") {
    OitScene scene;
    scene.layers = {{3.0, {1, 0, 0}, 0.5, 1}, {3.0, {0, 1, 0}, 0.5, 2}, {3.0, {0, 0, 1}, 0.5, 3}};
    const Gpu a = render(scene, {0, 1, 2});
    const Gpu b = render(scene, {2, 0, 1});
    if (test::tier() == Tier::High) {
        CHECK(a.raw == b.raw);
        CHECK(worstError(a, scene, compositeExact) <= kEightBit);
    }
}

TEST_CASE("oit: opacity 0 changes nothing; opacity 1 matches the opaque path", "[oit]") {
    OitScene base = layeredScene(3, 4, 0.6);
    const Gpu without = render(base, identity(base.layers.size()));
    OitScene withClear = base;
    withClear.layers.push_back({2.5, {1, 1, 1}, 0.0, 99});
    const Gpu with = render(withClear, identity(withClear.layers.size()));
    CHECK(with.raw == without.raw);

    OitScene solid;
    solid.layers = {{2.0, {0.25, 0.5, 0.75}, 1.0, 1}};
    const Gpu g = render(solid, {0});
    double worst = 0;
    for (const glm::dvec3& c : g.color) worst = std::max({worst, std::abs(c.r - 0.25), std::abs(c.g - 0.5), std::abs(c.b - 0.75)});
    CHECK(worst <= kEightBit);
    if (test::tier() == Tier::High) {
        // In front of more layers, an opaque layer hides them exactly.
        solid.layers.push_back({4.0, {1, 0, 0}, 0.5, 2});
        solid.layers.push_back({5.0, {0, 1, 0}, 0.7, 3});
        const Gpu h = render(solid, {2, 0, 1});
        for (const glm::dvec3& c : h.color) CHECK(c == glm::dvec3(0.25, 0.5, 0.75));
    }
}

TEST_CASE("oit: a pool smaller than the scene counts what it drops and grows the next frame (high tier)", "[oit]") {
    if (test::tier() != Tier::High) return;
    const OitScene scene = layeredScene(6, 5);
    const uint64_t inFront = uint64_t(
        std::count_if(scene.layers.begin(), scene.layers.end(), [&](const Layer& l) { return l.depth < scene.surfaceDepth; }));
    const uint64_t fragments = uint64_t(kH) * (kW / 2) * (6 + inFront);
    const uint64_t small = 100;
    std::vector<TransparencyStats> frames;
    const Gpu g = render(scene, identity(scene.layers.size()), small, 2, &frames);
    REQUIRE(frames.size() == 2);
    CHECK(frames[0].fragments == fragments);
    CHECK(frames[0].poolNodes == small);
    CHECK(frames[0].stored == small);
    CHECK(frames[0].dropped == fragments - small);
    // The second frame's pool holds the measured count with headroom: nothing dropped, exact.
    CHECK(frames[1].dropped == 0);
    CHECK(frames[1].poolNodes == uint64_t(std::ceil(double(fragments) * kOitPoolHeadroom)));
    CHECK(worstError(g, scene, compositeExact) <= kEightBit);
}

TEST_CASE("oit: an overflowing frame stays in range and keeps each pixel's stored layers in order (high tier)", "[oit]") {
    if (test::tier() != Tier::High) return;
    const OitScene scene = layeredScene(6, 6);
    const Gpu g = render(scene, identity(scene.layers.size()), 150, 1);
    CHECK(g.stats.dropped > 0);
    // Every pixel is the exact composite of some subset of its layers: within the convex hull
    // of the colours involved, never NaN, never out of [0, 1].
    for (const glm::dvec3& c : g.color)
        for (int ch = 0; ch < 3; ++ch) {
            CHECK(std::isfinite(c[ch]));
            CHECK(c[ch] >= 0.0);
            CHECK(c[ch] <= 1.0 + kEightBit);
        }
}

TEST_CASE("oit: weighted blended error against the exact sorted result is bounded (current tier)", "[oit]") {
    if (test::tier() != Tier::Current) return;
    // Low opacities in the weight's depth range: the case weighted blending is made for.
    const OitScene gentle = layeredScene(4, 8, 0.3);
    const double gentleError = worstError(render(gentle, identity(4)), gentle, compositeExact);
    // High opacities: its known failure (docs/oit.md).
    const OitScene hard = layeredScene(4, 9, 0.95);
    const double hardError = worstError(render(hard, identity(4)), hard, compositeExact);
    WARN("weighted blended vs exact, worst channel: opacity <= 0.3: " << gentleError << ", <= 0.95: " << hardError);
    // Measured 0.18 and 0.11 on every backend (docs/oit.md); the bound is the measurement
    // rounded up, so a regression of the weight or the blend state shows.
    CHECK(gentleError <= 0.2);
    CHECK(hardError <= 0.2);
    CHECK(gentleError > 0.0);  // an approximation: exact would mean the test does not reach it
}

TEST_CASE("oit: a frame without transparent draws plans, records and allocates nothing", "[oit]") {
    Device& dev = test::device();
    TransparencyDesc desc;
    desc.width = kW;
    desc.height = kH;
    desc.profile = test::tierProfile();
    auto created = Transparency::create(dev, desc);
    REQUIRE(created.isOk());
    std::unique_ptr<Transparency> oit = std::move(created.value());
    CHECK(oit->plan(false).passes.empty());
    CHECK(oit->plan(false).totalBytes() == 0);
    CHECK(oit->plan(true).passes.size() == (test::tier() == Tier::High ? 3u : 2u));
    auto opaque = dev.createTexture({kW, kH, 1, Format::RGBA16F, kTextureSampled | kTextureRenderTarget, "test opaque"});
    REQUIRE(opaque.isOk());
    TransparencyInputs in;
    in.opaqueColor = opaque.value();
    SFX_REQUIRE_OK(oit->render(in));
    CHECK(oit->output() == opaque.value());
    auto s = oit->stats();
    REQUIRE(s.isOk());
    CHECK(s->poolBytes == 0);
    // A bad draw is refused with its field named, before anything is recorded.
    TransparentDraw bad;
    bad.vertexCount = 4;
    std::vector<TransparentDraw> draws{bad};
    in.draws = draws;
    in.opaqueDepth = opaque.value();
    Status st = oit->render(in);
    CHECK(st.code() == StatusCode::InvalidArgument);
    CHECK(st.message().find("draws[0].vertices") != std::string::npos);
    oit.reset();
    (void)dev.destroyTexture(opaque.value());
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}
