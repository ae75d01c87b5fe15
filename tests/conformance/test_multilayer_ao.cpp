// Multilayer AO of opaque geometry (AoSettings.depthLayers, docs/oit.md "Multilayer AO"): the
// GPU against reference::multilayerVisibility on synthetic layers, the named errors, and the
// scene renderer's depth peeling recovering a contact shadow a foreground object hides, against
// single-layer AO and the ray-traced truth.
#include <catch2/catch.hpp>

#include <cmath>

#include "analytic_scenes.hpp"
#include "effect_runs.hpp"
#include "portability_rows.hpp"
#include "scene.hpp"
#include "scene_runs.hpp"
#include "sfx/ao.hpp"
#include "sfx/reference/ao_reference.hpp"
#include "sfx/reference/oit_reference.hpp"
#include "sfx/scene_render.hpp"
#include "sfx/tiers.hpp"
#include "sfx/truth.hpp"
#include "skips.hpp"
#include "test_device.hpp"
#include "truth_scenes.hpp"

using namespace sfx;
using reference::Grid;

namespace {

// The worst pixel against the reference (docs/oit.md): an R32F output, so only float-vs-double
// taps remain; a tap that rounds onto the neighbouring pixel moves one term of 9 to 24, the
// single-layer AO bound (docs/ao.md, high tier) covers it.
constexpr double kMultilayerWorstPixel = 0.005;

bool multilayerTier() { return test::tierProfile().aoMaxDepthLayers > 1; }

// On a tier without multilayer AO (the current one) asking for two layers is the named error;
// the GPU cases check that instead of skipping (a skip would mark the whole tier's run skipped).
void checkRefusedHere() {
    AoSettings s;
    s.depthLayers = 2;
    auto ao = AmbientObscurance::create(test::device(), {64, 32, test::tierProfile(), s});
    REQUIRE_FALSE(ao.isOk());
    CHECK(ao.status().code() == StatusCode::InvalidArgument);
    CHECK(ao.status().message().find("AoSettings.depthLayers") != std::string::npos);
}

struct MultilayerRun {
    Grid gpu, reference, single;
};

MultilayerRun runMultilayer(const tools::AnalyticScene& scene, AoTechnique t, uint32_t layers) {
    const std::vector<std::vector<float>> depths = test::syntheticDepthLayers(scene, layers);
    const test::GpuMultilayerAo gpu = test::runMultilayerAo(test::device(), test::tierProfile(), scene, t, depths);
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
    MultilayerRun r;
    r.gpu = gpu.visibility;
    const size_t n = r.gpu.values.size();

    // The reference reads the same float depths; normals from layer 0 by the shaders' rule.
    reference::DepthLayers ref, one;
    ref.width = one.width = scene.width;
    ref.height = one.height = scene.height;
    ref.reconstruction = one.reconstruction = gpu.reconstruction;
    Grid layer0(scene.width, scene.height);
    for (size_t i = 0; i < n; ++i) layer0.values[i] = depths[0][i];
    ref.normals = one.normals = reference::normalsFromDepth(layer0, ref.reconstruction);
    ref.depths.resize(n);
    one.depths.resize(n);
    for (size_t i = 0; i < n; ++i) {
        one.depths[i] = {double(depths[0][i])};
        for (uint32_t l = 0; l < layers; ++l)
            if (l == 0 || depths[l][i] > 0.0f) ref.depths[i].push_back(depths[l][i]);
    }
    r.reference = reference::multilayerVisibility(ref, gpu.config);
    r.single = reference::multilayerVisibility(one, gpu.config);
    return r;
}

double worstDifference(const Grid& a, const Grid& b) {
    double worst = 0.0;
    for (size_t i = 0; i < a.values.size(); ++i) worst = std::max(worst, std::abs(a.values[i] - b.values[i]));
    return worst;
}

}  // namespace

TEST_CASE("multilayer ao: the GPU matches reference::multilayerVisibility", "[ao][multilayer]") {
    if (!multilayerTier()) return checkRefusedHere();
    const tools::AnalyticScene scene = tools::cornerScene(96, 64);
    for (AoTechnique t : {AoTechnique::Alchemy, AoTechnique::Scalable, AoTechnique::Crease})
        for (uint32_t layers : {2u, 4u}) {
            const MultilayerRun r = runMultilayer(scene, t, layers);
            const double worst = worstDifference(r.gpu, r.reference);
            const double layersMatter = worstDifference(r.reference, r.single);
            INFO(test::label() << " " << toString(t) << ", " << layers << " layers: worst pixel " << worst << ", layers move the reference by up to "
                               << layersMatter);
            CHECK(layersMatter > 0.05);  // the hidden layers occlude: a GPU ignoring them would fail below
            CHECK(worst <= kMultilayerWorstPixel);
            for (double v : r.gpu.values) REQUIRE(std::isfinite(v));
            WARN("multilayer worst pixel " << test::label() << " " << toString(t) << " L=" << layers << ": " << worst);
            double meanAbs = 0.0;
            for (size_t i = 0; i < r.gpu.values.size(); ++i)
                meanAbs += std::abs(r.gpu.values[i] - r.reference.values[i]) / double(r.gpu.values.size());
            test::addPortabilityRow("multilayer AO " + std::string(toString(t)) + ", " + std::to_string(layers) + " layers", worst, meanAbs);
        }
}

TEST_CASE("multilayer ao: bad layer counts, resolutions and layer textures are named errors", "[ao][multilayer][bad-input]") {
    Device& dev = test::device();
    const TierProfile& profile = test::tierProfile();
    AoSettings s;
    s.depthLayers = 0;
    auto zero = AmbientObscurance::create(dev, {64, 32, profile, s});
    REQUIRE_FALSE(zero.isOk());
    CHECK(zero.status().message().find("AoSettings.depthLayers") != std::string::npos);
    s.depthLayers = profile.aoMaxDepthLayers + 1;
    auto tooMany = AmbientObscurance::create(dev, {64, 32, profile, s});
    REQUIRE_FALSE(tooMany.isOk());
    CHECK(tooMany.status().code() == StatusCode::InvalidArgument);
    CHECK(tooMany.status().message().find("AoSettings.depthLayers") != std::string::npos);
    if (!multilayerTier()) {
        CHECK(tooMany.status().message().find("1 on the current tier") != std::string::npos);
        return;
    }
    s.depthLayers = 2;
    s.resolution = AoResolution::Half;
    auto half = AmbientObscurance::create(dev, {64, 32, profile, s});
    REQUIRE_FALSE(half.isOk());
    CHECK(half.status().message().find("AoSettings.resolution") != std::string::npos);
    s.resolution = AoResolution::Tier;  // resolves to full size with layers
    // Horizon reads the first layer only; where it is the profile's technique (the high tier's
    // default) and none is named, the error says to name one.
    if (profile.aoTechnique == AoTechnique::Horizon) {
        auto horizon = AmbientObscurance::create(dev, {64, 32, profile, s, DepthKind::Linear});
        REQUIRE_FALSE(horizon.isOk());
        CHECK(horizon.status().message().find("set AoSettings.technique to Alchemy, Scalable or Crease") != std::string::npos);
    }
    s.technique = AoTechnique::Scalable;
    auto ao = AmbientObscurance::create(dev, {64, 32, profile, s, DepthKind::Linear});
    REQUIRE(ao.isOk());
    CHECK_FALSE(ao.value()->config().halfResolution);
    CHECK(ao.value()->config().depthMipLevels == 1);
    TextureHandle depth = dev.createTexture({64, 32, 1, Format::R32F, kTextureSampled}).value();
    TextureHandle out = dev.createTexture({64, 32, 1, Format::RGBA8, kTextureSampled | kTextureRenderTarget}).value();
    TextureHandle small = dev.createTexture({32, 32, 1, Format::R32F, kTextureSampled}).value();
    TextureHandle rgba = dev.createTexture({64, 32, 1, Format::RGBA8, kTextureSampled | kTextureRenderTarget}).value();
    AoInputs in;
    in.depth = DepthSource{depth, DepthKind::Linear, makePerspective({}).value()};
    in.output = out;
    Status missing = ao.value()->dispatch(in);
    CHECK_FALSE(missing.isOk());
    CHECK(missing.message().find("AoInputs.depthLayers[0]") != std::string::npos);
    in.depthLayers[0] = small;
    Status size = ao.value()->dispatch(in);
    CHECK(size.code() == StatusCode::InvalidArgument);
    CHECK(size.message().find("AoInputs.depthLayers[0] size") != std::string::npos);
    in.depthLayers[0] = rgba;
    Status format = ao.value()->dispatch(in);
    CHECK(format.code() == StatusCode::UnsupportedFormat);
    CHECK(format.message().find("R32F") != std::string::npos);
    for (TextureHandle t : {depth, out, small, rgba}) SFX_REQUIRE_OK(dev.destroyTexture(t));
}

namespace {

std::string scenePath(const char* name) { return test::sourceDir() + "/tests/data/scenes/" + name; }

}  // namespace

TEST_CASE("multilayer ao: depth peeling recovers the contact shadow a foreground object hides", "[ao][multilayer][render]") {
    if (!multilayerTier()) return checkRefusedHere();
    // A wall standing on a floor and a floating bar near the camera hiding their contact line:
    // the floor just in front of the contact stays visible, and the taps that land on the bar
    // see only the bar with one layer. The bar is a quad seen from both sides, so layer 1 is
    // the wall behind it.
    Result<scene::Scene> file = scene::loadSceneFile(scenePath("hidden_contact.json"));
    INFO(file.status().toString());
    REQUIRE(file.isOk());
    auto renderAo = [&](uint32_t layers) {
        render::RenderOptions o;
        o.ao = AoTechnique::Alchemy;
        o.aoRadius = 0.5f;
        o.aoLayers = layers;
        render::RenderResult out = test::renderScene(test::device(), test::tier(), file.value(), o);
        REQUIRE(out.ao.has_value());
        SFX_REQUIRE_NO_VALIDATION_MESSAGES();
        return out.ao->pixels;
    };
    const std::vector<float> single = renderAo(1), multi = renderAo(2);
    const uint32_t w = file->width, h = file->height;

    Result<tools::TruthScene> ts = tools::makeTruthScene(tools::opaqueScene(file.value()), w, h);
    REQUIRE(ts.isOk());
    Result<std::unique_ptr<truth::Tracer>> tracer = truth::Tracer::create(ts->geometry);
    if (!tracer && tracer.status().code() == StatusCode::BackendUnavailable) SFX_SKIP("Embree: " << tracer.status().message());
    REQUIRE(tracer.isOk());
    truth::Settings ss;
    ss.radius = 0.5;
    ss.samples = 256;
    Result<truth::Image> truth = tracer.value()->trace(ts->camera, ss);
    REQUIRE(truth.isOk());

    // The pixels single-layer AO misses: occluded in the truth (below 0.9), left open (above
    // 0.97) by single-layer AO. There multilayer AO must be clearly darker and nearer the truth.
    double singleSum = 0, multiSum = 0, truthSum = 0;
    size_t count = 0;
    for (size_t i = 0; i < single.size(); ++i) {
        if (!truth->isSurface(i) || !(truth->visibility[i] < 0.9) || !(single[i] > 0.97)) continue;
        singleSum += single[i];
        multiSum += multi[i];
        truthSum += truth->visibility[i];
        ++count;
    }
    REQUIRE(count >= 20);
    const double meanSingle = singleSum / count, meanMulti = multiSum / count, meanTruth = truthSum / count;
    INFO(count << " missed pixels: mean visibility single " << meanSingle << ", multilayer " << meanMulti << ", truth " << meanTruth);
    WARN("hidden contact " << test::label() << ": " << count << " pixels, single " << meanSingle << ", multilayer " << meanMulti << ", truth "
                           << meanTruth);
    CHECK(meanMulti < meanSingle - 0.03);                                       // occlusion recovered
    CHECK(std::abs(meanMulti - meanTruth) < std::abs(meanSingle - meanTruth));  // nearer the truth
    // Elsewhere the layers change little: the open floor and wall away from the bar.
    double worstOpen = 0.0;
    for (size_t i = 0; i < single.size(); ++i)
        if (truth->isSurface(i) && truth->visibility[i] > 0.995) worstOpen = std::max(worstOpen, double(single[i] - multi[i]));
    CHECK(worstOpen < 0.1);
}
