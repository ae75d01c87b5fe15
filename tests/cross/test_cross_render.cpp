// The scene renderer (sfx_render, behind `sfx render`) compared across backends and drivers: the
// same scene file drawn by every pair, on each tier, with AO, a translucent object through
// sfx::Transparency and (high tier) a peeled second depth layer for AO. Bounds: cross_bounds.hpp.
#include <catch2/catch.hpp>

#include <map>
#include <string>

#include "cross_bounds.hpp"
#include "cross_compare.hpp"
#include "sfx/scene_render.hpp"
#include "sfx/tiers.hpp"

using namespace sfx;
using namespace sfx::test;

namespace {

// test_render.cpp's scene at 96x64: a lambert floor with a box on it (contact creases for AO), a
// second box in front of the first (a hidden crease for the peeled layer) and a translucent
// unlit quad facing the camera. Colours are exact in fp16.
const char* kScene = R"({
  "width": 96, "height": 64,
  "camera": {"position": [0, 1.0, 2.5], "target": [0, 0.4, 0], "near": 0.1, "far": 20},
  "background": [0.25, 0.5, 0.75],
  "objects": [
    {"mesh": "box", "position": [0, -0.05, 0], "scale": [6, 0.1, 6], "color": [0.75, 0.75, 0.75]},
    {"mesh": "box", "position": [-0.7, 0.3, -0.3], "scale": 0.6, "color": [0.5, 0.75, 0.25]},
    {"mesh": "box", "position": [-0.45, 0.15, 0.45], "scale": 0.3, "color": [0.75, 0.25, 0.5]},
    {"mesh": "quad", "position": [0.45, 0.5, 0.3], "scale": 0.5, "color": [0.125, 0.375, 0.625], "shading": "unlit", "opacity": 0.5}
  ]})";

void compareRender(Tier tier) {
    SFX_OPEN_AT_LEAST_TWO(devices, tier);
    Result<scene::Scene> scene = scene::loadSceneFromString(kScene, ".", "cross-scene");
    INFO(scene.status().toString());
    REQUIRE(scene.isOk());
    std::vector<uint32_t> layerCounts{1};
    if (tiers::profile(tier).aoMaxDepthLayers > 1) layerCounts.push_back(2);
    for (uint32_t layers : layerCounts) {
        render::RenderOptions options;
        options.ao = AoTechnique::Scalable;
        options.aoRadius = 0.4f;
        options.aoLayers = layers;
        const std::string what = "scene renderer, " + std::to_string(layers) + " AO layer(s), at tier " + toString(tier);
        std::map<std::string, std::vector<double>> color, ao;
        for (Opened& o : devices) {
            INFO(o.name << ": " << what);
            Result<tiers::TierChoice> choice = tiers::choose(o.device->caps(), tier);
            INFO(choice.status().toString());
            REQUIRE(choice.isOk());
            auto r = render::SceneRender::create(*o.device, choice.value(), scene.value(), options);
            INFO(r.status().toString());
            REQUIRE(r.isOk());
            Result<render::RenderResult> out = r.value()->render();
            INFO(out.status().toString());
            REQUIRE(out.isOk());
            CHECK(out->warnings.empty());
            CHECK(out->stats.transparencyRan);
            REQUIRE(out->ao.has_value());
            color[o.name].assign(out->color.pixels.begin(), out->color.pixels.end());
            ao[o.name].assign(out->ao->pixels.begin(), out->ao->pixels.end());
        }
        requireNoValidation(devices);
        requireSpan(color.begin()->second, 0.3, what + " colour");
        requireSpan(ao.begin()->second, 0.1, what + " AO");
        // The current tier's AO passes through 8-bit targets: one unorm8 step more, and the
        // colour multiplies it by an ambient share of at most 1.
        const double unorm8 = tier == Tier::Current ? kUnorm8Step : 0.0;
        requireRasterPairsWithin(devices, ao, kRenderPairWorst + unorm8, what + " AO");
        requireRasterPairsWithin(devices, color, kRenderPairWorst + unorm8, what + " colour");
    }
}

}  // namespace

TEST_CASE("the scene renderer agrees across backends: high tier", "[cross-backend][render]") { compareRender(Tier::High); }
TEST_CASE("the scene renderer agrees across backends: current tier", "[cross-backend][render]") { compareRender(Tier::Current); }
