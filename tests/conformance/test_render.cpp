// The scene renderer (sfx_render, behind `sfx render`) on every backend x tier: unlit objects
// and the background keep their colours exactly, AO only darkens lambert surfaces and does
// darken some, the plan holds only what the scene and options need (no transparency pass or
// resource without a translucent object), and translucent objects go through sfx::Transparency.
#include <catch2/catch.hpp>

#include <algorithm>
#include <string>

#include "scene_runs.hpp"
#include "sfx/scene_render.hpp"
#include "sfx/tiers.hpp"
#include "test_device.hpp"

using namespace sfx;

namespace {

// A lambert floor with a box standing on it (contact creases for AO), and an unlit quad
// facing the camera at the centre of the view. Colours are exact in half floats.
const char* kScene = R"({
  "width": 64, "height": 40,
  "camera": {"position": [0, 1.0, 2.5], "target": [0, 0.4, 0], "near": 0.1, "far": 20},
  "background": [0.25, 0.5, 0.75],
  "objects": [
    {"mesh": "box", "position": [0, -0.05, 0], "scale": [6, 0.1, 6], "color": [0.75, 0.75, 0.75]},
    {"mesh": "box", "position": [-0.7, 0.3, -0.3], "scale": 0.6, "color": [0.5, 0.75, 0.25]},
    {"mesh": "quad", "position": [0.45, 0.5, 0.3], "scale": 0.5, "color": [0.125, 0.375, 0.625], "shading": "unlit"}
  ]})";

scene::Scene loadScene(const std::string& text) {
    Result<scene::Scene> s = scene::loadSceneFromString(text, ".", "test-scene");
    INFO(s.status().toString());
    REQUIRE(s.isOk());
    return s.value();
}

tiers::TierChoice testTier() { return test::chooseTier(test::device(), test::tier()); }

render::RenderResult renderWith(const scene::Scene& scene, const render::RenderOptions& options, render::FramePlan* plan = nullptr) {
    return test::renderScene(test::device(), test::tier(), scene, options, plan);
}

bool hasPass(const render::FramePlan& plan, const std::string& effect) {
    return std::any_of(plan.lines.begin(), plan.lines.end(),
                       [&](const render::PlanLine& l) { return l.kind != render::PlanLine::Kind::Omitted && l.effect == effect; });
}

}  // namespace

TEST_CASE("scene renderer: unlit and background exact, AO only darkens lambert surfaces", "[render][conformance]") {
    const scene::Scene scene = loadScene(kScene);
    render::RenderOptions off;
    off.ao.reset();
    render::RenderOptions on;
    on.ao = AoTechnique::Alchemy;
    on.aoRadius = 0.4f;
    render::FramePlan offPlan, onPlan;
    const render::RenderResult a = renderWith(scene, off, &offPlan);
    const render::RenderResult b = renderWith(scene, on, &onPlan);
    REQUIRE(a.color.width == 64);
    REQUIRE(a.color.height == 40);
    CHECK_FALSE(a.ao.has_value());
    REQUIRE(b.ao.has_value());

    const glm::dvec3 unlit(0.125, 0.375, 0.625);
    size_t unlitPixels = 0, skyPixels = 0, darkened = 0;
    for (size_t i = 0; i < size_t(64) * 40; ++i) {
        const glm::dvec3 ca(a.color.pixels[i * 3], a.color.pixels[i * 3 + 1], a.color.pixels[i * 3 + 2]);
        const glm::dvec3 cb(b.color.pixels[i * 3], b.color.pixels[i * 3 + 1], b.color.pixels[i * 3 + 2]);
        INFO("pixel " << i);
        if (ca == unlit) ++unlitPixels;
        if (ca == scene.background) ++skyPixels;
        if (ca == unlit || ca == scene.background) {
            REQUIRE(cb == ca);  // untouched by AO
            continue;
        }
        for (int c = 0; c < 3; ++c) REQUIRE(cb[c] <= ca[c] + 1e-6);  // AO multiplies the ambient term by <= 1
        if (cb.x < ca.x - 1e-3) ++darkened;
        const float v = b.ao->pixels[i];
        REQUIRE(v >= 0.0f);
        REQUIRE(v <= 1.0f);
    }
    CHECK(unlitPixels > 20);  // the quad covers about 12 x 12 pixels
    CHECK(skyPixels > 20);
    CHECK(darkened > 10);  // the creases at the box's foot

    CHECK_FALSE(hasPass(offPlan, "ao"));
    CHECK_FALSE(hasPass(offPlan, "depth"));
    CHECK(hasPass(onPlan, "ao"));
    CHECK_FALSE(hasPass(onPlan, "transparency"));
    CHECK(b.warnings.empty());
    CHECK(b.stats.transparentObjects == 0);
    CHECK(b.stats.opaqueObjects == 3);
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("scene renderer: translucent objects through sfx::Transparency, or not at all with --oit off", "[render][conformance]") {
    std::string text = kScene;
    const std::string unlitKey = "\"shading\": \"unlit\"";
    text.replace(text.find(unlitKey), unlitKey.size(), unlitKey + ", \"opacity\": 0.5");
    const scene::Scene scene = loadScene(text);
    render::RenderOptions options;
    render::FramePlan plan;
    const render::RenderResult r = renderWith(scene, options, &plan);
    CHECK(r.warnings.empty());
    CHECK(hasPass(plan, "transparency"));
    CHECK(plan.describe().find("1 translucent objects through sfx::Transparency") != std::string::npos);
    CHECK(r.stats.transparentObjects == 1);
    CHECK(r.stats.opaqueObjects == 2);
    CHECK(r.stats.transparencyRan);
    CHECK(r.stats.abuffer == (test::tier() == Tier::High));

    render::RenderOptions off;
    off.oit = false;
    render::FramePlan offPlan;
    const render::RenderResult o = renderWith(scene, off, &offPlan);
    REQUIRE(o.warnings.size() == 1);
    CHECK(o.warnings[0].find("--oit off: 1 transparent") != std::string::npos);
    CHECK_FALSE(hasPass(offPlan, "transparency"));
    CHECK_FALSE(o.stats.transparencyRan);
    // The quad's pixels differ (half of it over the opaque picture); the rest is the same.
    size_t changed = 0;
    for (size_t i = 0; i < o.color.pixels.size(); ++i) changed += o.color.pixels[i] != r.color.pixels[i];
    CHECK(changed > 20);
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("scene renderer: bad options are named errors", "[render][bad-input]") {
    const scene::Scene scene = loadScene(kScene);
    const struct {
        void (*edit)(render::RenderOptions&);
        const char* field;
    } cases[] = {{[](render::RenderOptions& o) { o.aoRadius = 0.0f; }, "--ao-radius"},
                 {[](render::RenderOptions& o) { o.aoLayers = 0; }, "--ao-layers"},
                 {[](render::RenderOptions& o) { o.aoLayers = 5; }, "--ao-layers"},
                 {[](render::RenderOptions& o) { o.aoLayers = 2, o.ao.reset(); }, "--ao-layers"},
                 {[](render::RenderOptions& o) { o.maxLayers = 0; }, "--max-layers"},
                 {[](render::RenderOptions& o) { o.maxLayers = 24; }, "--max-layers"},
                 {[](render::RenderOptions& o) { o.nodes = 9; }, "--nodes"},
                 {[](render::RenderOptions& o) { o.width = scene::kMaxSceneSize + 1; }, "--width"}};
    for (const auto& c : cases) {
        render::RenderOptions o;
        c.edit(o);
        auto r = render::SceneRender::create(test::device(), testTier(), scene, o);
        INFO(c.field);
        REQUIRE_FALSE(r.isOk());
        CHECK(r.status().code() == StatusCode::InvalidArgument);
        CHECK(r.status().message().find(c.field) == 0);
    }
}

TEST_CASE("scene renderer: --ao-layers 2 peels a layer on the high tier, a named error on the current one", "[render][multilayer]") {
    const scene::Scene scene = loadScene(kScene);
    render::RenderOptions o;
    o.aoLayers = 2;
    const tiers::TierChoice tier = testTier();
    if (tier.profile.aoMaxDepthLayers < 2) {
        auto r = render::SceneRender::create(test::device(), tier, scene, o);
        REQUIRE_FALSE(r.isOk());
        CHECK(r.status().code() == StatusCode::InvalidArgument);
        CHECK(r.status().message().find("--ao-layers") == 0);
        CHECK(r.status().message().find("current tier") != std::string::npos);
        return;
    }
    render::FramePlan plan;
    const render::RenderResult multi = renderWith(scene, o, &plan);
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
    size_t peels = 0, layerBytes = 0;
    for (const render::PlanLine& l : plan.lines) {
        if (l.kind == render::PlanLine::Kind::Pass && l.name.rfind("peel layer", 0) == 0) ++peels;
        if (l.kind == render::PlanLine::Kind::Resource && l.name == "layer 1 linear depth") layerBytes = l.bytes;
        CHECK_FALSE((l.kind == render::PlanLine::Kind::Omitted && l.name == "multilayer depth"));
    }
    CHECK(peels == 1);
    CHECK(layerBytes == size_t(scene.width) * scene.height * 4);  // R32F
    REQUIRE(multi.ao.has_value());
    for (float v : multi.ao->pixels) REQUIRE((v >= 0.0f && v <= 1.0f));
}
