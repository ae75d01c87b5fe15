// The geometry and camera of every sample scene as the ray-traced truth (sfx/truth.hpp) needs
// them: the rasterised scenes' meshes in world space exactly as SceneRenderer draws them at
// t = 0, and the analytic scenes' planes and spheres as castScene intersects them.
#pragma once

#include <string>
#include <vector>

#include "analytic_scenes.hpp"
#include "scene.hpp"
#include "sfx/truth.hpp"

namespace sfx::tools {

struct TruthScene {
    std::string name;
    truth::Geometry geometry;
    truth::Camera camera;
};

// The rasterised scenes (sceneNames()) and the analytic ones as "analytic-" + analyticSceneNames().
std::vector<std::string> truthSceneNames();
// InvalidArgument naming the known scenes; FileError from the bunny's loader.
Result<TruthScene> makeTruthScene(const std::string& name, uint32_t width, uint32_t height);
// A rasterised scene as given (e.g. with its camera moved); the truth scene takes its name.
Result<TruthScene> makeTruthScene(const RasterScene& scene, uint32_t width, uint32_t height);

// Every mesh's triangles moved by its model matrix (t = 0, as the benchmarks render).
truth::Geometry worldGeometry(const RasterScene& scene);
// Planes become squares of half-size kAnalyticPlaneHalfSize around the point nearest the eye
// (beyond any radius or view distance the scenes use); spheres stay exact.
truth::Geometry worldGeometry(const AnalyticSceneDesc& scene);
inline constexpr double kAnalyticPlaneHalfSize = 1000.0;

}  // namespace sfx::tools
