#include "mb_raster.hpp"

#include <algorithm>
#include <cmath>

#include "motion_cases.hpp"

namespace sfx::tools {

using namespace sfx::reference;

namespace {
constexpr std::array<double, 4> kSky{0.55, 0.7, 0.9, 1.0};
}  // namespace

// View space, because a pan only translates the camera: surfaces keep their shading.
ColorGrid shadeGBuffer(const GBufferContents& g) {
    const glm::dvec3 light = glm::normalize(glm::dvec3(-0.4, 0.8, 0.45));
    ColorGrid c(g.width, g.height, kSky);
    for (size_t i = 0; i < c.values.size(); ++i) {
        if (!g.drawn(i)) continue;
        const double k = 0.35 + 0.65 * std::max(0.0, glm::dot(glm::dvec3(g.normals[i]), light));
        for (size_t ch = 0; ch < 3; ++ch) c.values[i][ch] = g.albedo[i * 4 + ch] / 255.0 * k;
    }
    return c;
}

Result<ShadedFrame> readFrame(Device& device, const GBuffer& g) {
    Result<GBufferContents> contents = readBack(device, g);
    if (!contents) return contents.status();
    ShadedFrame f;
    f.color = shadeGBuffer(contents.value());
    const size_t n = size_t(g.width) * g.height;
    Grid stored(g.width, g.height);
    for (size_t i = 0; i < n; ++i) stored.values[i] = contents->storedDepth[i];
    Result<DepthReconstruction> rec = makeDepthReconstruction(g.camera, g.width, g.height);
    if (!rec) return rec.status();
    f.linearDepth = linearizeDepth(stored, rec.value());
    f.velocity = VelocityGrid(g.width, g.height);
    f.drawn.resize(n);
    for (size_t i = 0; i < n; ++i) {
        f.velocity.values[i] = {double(contents->velocity[i].x), double(contents->velocity[i].y)};
        f.drawn[i] = contents->drawn(i);
    }
    return f;
}

Result<SceneTruth> sceneGroundTruth(Device& device, SceneRenderer& renderer, const RasterScene& scene, uint32_t w, uint32_t h, uint32_t instants,
                                    const InstantObserver& observe) {
    ColorGrid sum(w, h), even(w, h);
    const uint32_t evenCount = (instants + 1) / 2;
    for (uint32_t i = 0; i < instants; ++i) {
        const double t = (i + 0.5) / instants - 0.5;
        Result<GBuffer> g = renderer.render(scene, w, h, t);
        if (!g) return g.status();
        Result<ShadedFrame> frame = readFrame(device, g.value());
        renderer.destroy(g.value());
        if (!frame) return frame.status();
        const ColorGrid& c = frame->color;
        for (size_t p = 0; p < sum.values.size(); ++p)
            for (size_t ch = 0; ch < 4; ++ch) {
                sum.values[p][ch] += c.values[p][ch] / instants;
                if (i % 2 == 0) even.values[p][ch] += c.values[p][ch] / evenCount;
            }
        if (observe) observe(i, frame.value());
    }
    const ColorErrors residual = colorErrors(even, sum, std::vector<bool>(sum.values.size(), false));
    return SceneTruth{std::move(sum), residual.rmse};
}

}  // namespace sfx::tools
