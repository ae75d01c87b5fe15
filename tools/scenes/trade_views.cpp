#include "trade_views.hpp"

#include <cmath>
#include <cstdio>

#include "scene_families.hpp"

namespace sfx::tools {

std::string TradeView::name() const {
    if (analytic) return "analytic-" + scene;
    if (!family.empty()) return family + "." + scene;
    char buf[64];
    if (distanceScale == 1 && lift == 0)
        std::snprintf(buf, sizeof buf, "@%g", turnDegrees);
    else
        std::snprintf(buf, sizeof buf, "@%g_%g_%g", turnDegrees, distanceScale, lift);
    return scene + buf;
}

Result<RasterScene> viewScene(const TradeView& view) {
    if (view.analytic) return invalidArgument("view", "'" + view.name() + "'", "a rasterised sample scene's view");
    if (!view.family.empty()) return familyScene(view);
    Result<RasterScene> scene = makeScene(view.scene);
    if (!scene) return scene.status();
    const double a = view.turnDegrees * 3.14159265358979323846 / 180.0;
    const glm::dvec3 d = scene->eye - scene->target;
    const glm::dvec3 turned(d.x * std::cos(a) + d.z * std::sin(a), d.y, -d.x * std::sin(a) + d.z * std::cos(a));
    scene->eye = scene->target + turned * view.distanceScale + glm::dvec3(0, view.lift, 0);
    scene->name = view.name();
    return scene;
}

Result<TruthScene> viewTruthScene(const TradeView& view, uint32_t width, uint32_t height) {
    if (view.analytic) return makeTruthScene(view.name(), width, height);
    Result<RasterScene> scene = viewScene(view);
    if (!scene) return scene.status();
    return makeTruthScene(scene.value(), width, height);
}

Result<std::unique_ptr<ViewInputs>> ViewInputs::create(Device& device, Tier tier, const TradeView& view, uint32_t width, uint32_t height) {
    std::unique_ptr<ViewInputs> in(new ViewInputs(device));
    if (!view.analytic) {
        Result<RasterScene> scene = viewScene(view);
        if (!scene) return scene.status();
        Result<std::unique_ptr<SceneRenderer>> renderer = SceneRenderer::create(device, tier);
        if (!renderer) return renderer.status();
        SFX_TRY(renderer.value()->load(scene.value()));
        Result<GBuffer> g = renderer.value()->render(scene.value(), width, height);
        if (!g) return g.status();
        in->kind_ = DepthKind::Hardware;
        in->depth_ = g->depth, in->normals_ = g->normals, in->camera_ = g->camera;
        g->depth = {}, g->normals = {};  // kept; the renderer frees velocity and albedo
        renderer.value()->destroy(g.value());
        return in;
    }
    Result<AnalyticSceneDesc> desc = analyticSceneDesc(view.scene);
    if (!desc) return desc.status();
    const AnalyticScene scene = castScene(desc.value(), width, height);
    std::vector<float> depth(scene.linearDepth.values.begin(), scene.linearDepth.values.end()), normals;
    for (const glm::dvec3& n : scene.normals) normals.insert(normals.end(), {float(n.x), float(n.y), float(n.z), 0.0f});
    Result<TextureHandle> d = device.createTexture({width, height, 1, Format::R32F, kTextureSampled, "trade-linear-depth"});
    if (!d) return d.status();
    in->depth_ = d.value();
    Result<TextureHandle> n = device.createTexture({width, height, 1, Format::RGBA32F, kTextureSampled, "trade-normals"});
    if (!n) return n.status();
    in->normals_ = n.value();
    SFX_TRY(device.writeTexture(in->depth_, 0, depth.data(), depth.size() * sizeof(float)));
    SFX_TRY(device.writeTexture(in->normals_, 0, normals.data(), normals.size() * sizeof(float)));
    in->kind_ = DepthKind::Linear;
    in->camera_ = scene.camera;
    return in;
}

ViewInputs::~ViewInputs() {
    for (TextureHandle t : {depth_, normals_})
        if (!t.isNull()) (void)device_.destroyTexture(t);
}

}  // namespace sfx::tools
