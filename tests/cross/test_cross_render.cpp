// The scene renderer (sfx_render, behind `sfx render`) compared across backends and drivers: the
// same scene drawn by every pair, on each tier, with AO, a translucent object through
// sfx::Transparency and (high tier) a peeled second depth layer for AO. Two scenes: one whose
// every edge lies half a pixel from the pixel centres, held to the bound between every pair
// (SwiftShader's coarser sub-pixel grid included), and test_render.cpp's boxes, whose edges are
// arbitrary lines, held to it between rasterisers of one sub-pixel grid; between grids the
// pixels near edges are counted and the rest printed (requireRasterPairsWithin says why).
// Bounds: cross_bounds.hpp.
#include <catch2/catch.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <string>

#include "cross_bounds.hpp"
#include "cross_compare.hpp"
#include "raster_bands.hpp"
#include "scene_runs.hpp"
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

// A scene every conformant rasteriser covers alike: seen head-on from the axis, a wall filling
// the view and two boxes centred on the axis (their sides face away, so only their front faces,
// window-aligned rectangles, show), and a translucent unlit quad over the near box's corner. The
// boxes' and the quad's sizes put every edge on a whole window pixel, half a pixel from every
// pixel centre (alignedEdgesMissPixelCentres checks it). AO darkens the wall and the middle box
// around the nearer outlines.
const char* kAlignedScene = R"({
  "width": 96, "height": 64,
  "camera": {"position": [0, 0, 3], "target": [0, 0, 0], "near": 0.1, "far": 20},
  "background": [0.25, 0.5, 0.75],
  "objects": [
    {"mesh": "box", "position": [0, 0, -1.1], "scale": [12, 12, 0.2], "color": [0.75, 0.75, 0.75]},
    {"mesh": "box", "position": [0, 0, -0.85], "scale": [4.11362, 2.74241, 0.1], "color": [0.5, 0.75, 0.25]},
    {"mesh": "box", "position": [0, 0, -0.65], "scale": [1.5372, 1.1529, 0.2], "color": [0.75, 0.25, 0.5]},
    {"mesh": "quad", "position": [0.46910, 0.18042, 1.0], "scale": [0.64952, 0.50518, 1], "color": [0.125, 0.375, 0.625], "shading": "unlit", "opacity": 0.5}
  ]})";

// The least distance, in pixels, from a pixel centre to an edge of a front face (the box's
// +z face, or the quad): above sqrt(2) / 32 no rasteriser's sub-pixel snap (1/16 pixel at the
// coarsest the specifications allow) can change which pixels a face covers.
double alignedEdgesMissPixelCentres(const scene::Scene& scene) {
    const glm::dmat4 proj = glm::perspective(glm::radians(scene.camera.fovYDegrees), double(scene.width) / scene.height, scene.camera.nearPlane,
                                             scene.camera.farPlane);
    const glm::dmat4 viewProj = proj * scene.camera.view();
    double margin = 1.0;
    for (const scene::SceneObject& o : scene.objects) {
        const double z = o.mesh == "box" ? 0.5 : 0.0;  // the front face in object space
        for (double x : {-0.5, 0.5})
            for (double y : {-0.5, 0.5}) {
                const glm::dvec4 clip = viewProj * o.world * glm::dvec4(x, y, z, 1.0);
                const double wx = (clip.x / clip.w + 1.0) * 0.5 * scene.width, wy = (clip.y / clip.w + 1.0) * 0.5 * scene.height;
                // Edges beyond the picture cover nothing in it.
                if (wx > 0.0 && wx < scene.width) margin = std::min(margin, std::abs(wx - std::floor(wx) - 0.5));
                if (wy > 0.0 && wy < scene.height) margin = std::min(margin, std::abs(wy - std::floor(wy) - 0.5));
            }
    }
    return margin;
}

constexpr float kAoRadius = 0.4f;

// The scene renderer's colour and AO of `text` on every device, with AO (and, where the tier
// has it, a second peeled layer for AO when `layers` is 2).
struct Rendered {
    std::map<std::string, std::vector<double>> color, ao;
    std::optional<render::RenderResult::OpaqueInputs> frame;  // the first device's camera
};
Rendered renderOnEach(std::vector<Opened>& devices, Tier tier, const scene::Scene& scene, uint32_t layers, const std::string& what, bool ao = true) {
    render::RenderOptions options;
    options.ao = ao ? std::optional<AoTechnique>(AoTechnique::Scalable) : std::nullopt;
    options.aoRadius = kAoRadius;
    options.aoLayers = layers;
    options.keepOpaqueInputs = true;
    Rendered r;
    for (Opened& o : devices) {
        INFO(o.name << ": " << what);
        const render::RenderResult out = test::renderScene(*o.device, tier, scene, options);
        CHECK(out.warnings.empty());
        CHECK(out.stats.transparencyRan);
        REQUIRE(out.ao.has_value() == ao);
        r.color[o.name].assign(out.color.pixels.begin(), out.color.pixels.end());
        if (ao) r.ao[o.name].assign(out.ao->pixels.begin(), out.ao->pixels.end());
        if (!r.frame) r.frame = out.opaque;
    }
    requireNoValidation(devices);
    requireSpan(r.color.begin()->second, 0.3, what + " colour");
    if (ao) requireSpan(r.ao.begin()->second, 0.1, what + " AO");
    return r;
}

scene::Scene load(const char* text) {
    Result<scene::Scene> scene = scene::loadSceneFromString(text, ".", "cross-scene");
    INFO(scene.status().toString());
    REQUIRE(scene.isOk());
    return scene.value();
}

void compareRender(Tier tier) {
    SFX_OPEN_AT_LEAST_TWO(devices, tier);
    // The current tier's AO passes through 8-bit targets: one unorm8 step more, and the colour
    // multiplies it by an ambient share of at most 1.
    const double bound = kRenderPairWorst + (tier == Tier::Current ? kUnorm8Step : 0.0);
    const scene::Scene aligned = load(kAlignedScene);
    const double margin = alignedEdgesMissPixelCentres(aligned);
    INFO("the aligned scene's edges pass " << margin << " px from the nearest pixel centre");
    REQUIRE(margin > std::sqrt(2.0) / 32.0);
    const scene::Scene boxes = load(kScene);
    std::vector<uint32_t> layerCounts{1};
    if (tiers::profile(tier).aoMaxDepthLayers > 1) layerCounts.push_back(2);
    for (uint32_t layers : layerCounts) {
        const std::string what = std::to_string(layers) + " AO layer(s), at tier " + toString(tier);
        const Rendered a = renderOnEach(devices, tier, aligned, layers, "scene renderer, aligned scene, " + what);
        requirePairsWithin(a.ao, bound, "scene renderer, aligned scene, " + what + " AO");
        requirePairsWithin(a.color, bound, "scene renderer, aligned scene, " + what + " colour");
        const Rendered b = renderOnEach(devices, tier, boxes, layers, "scene renderer, boxes, " + what);
        REQUIRE(b.frame.has_value());
        auto band = [&](uint32_t bits) { return sceneEdgeBand(boxes, *b.frame, bits); };
        requireRasterPairsWithin(devices, b.ao, 1, bound, "scene renderer, boxes, " + what + " AO", band, OutsideBand::Printed);
        requireRasterPairsWithin(devices, b.color, 3, bound, "scene renderer, boxes, " + what + " colour", band, OutsideBand::Printed);
    }
    // Without AO the boxes' colour is coverage, flat shading and the transparency step: held to
    // the bound outside the band between every pair.
    const std::string flatWhat = std::string("scene renderer, boxes without AO, at tier ") + toString(tier);
    const Rendered flat = renderOnEach(devices, tier, boxes, 1, flatWhat, false);
    REQUIRE(flat.frame.has_value());
    requireRasterPairsWithin(
        devices, flat.color, 3, bound, flatWhat + ", colour", [&](uint32_t bits) { return sceneEdgeBand(boxes, *flat.frame, bits); },
        OutsideBand::Checked);
}

}  // namespace

TEST_CASE("the scene renderer agrees across backends: high tier", "[cross-backend][render]") { compareRender(Tier::High); }
TEST_CASE("the scene renderer agrees across backends: current tier", "[cross-backend][render]") { compareRender(Tier::Current); }
