// Scene files: the JSON description `sfx render` and the samples draw. A file holds the target
// size, the camera, the background and a list of objects, each a mesh (a primitive or an OBJ
// file) with a transform, a linear RGB colour, an opacity and a shading mode:
//
//   { "width": 320, "height": 180,
//     "camera": {"position": [0, 1, 5], "target": [0, 0, 0], "up": [0, 1, 0],
//                "fovY": 60, "near": 0.1, "far": 100},
//     "background": [0.6, 0.7, 0.8],
//     "objects": [{"mesh": "quad", "position": [0, 0, -2], "rotation": [0, 0, 0], "scale": 2,
//                  "color": [1, 0, 0], "opacity": 0.5, "shading": "unlit"}] }
//
// Required: width, height, camera (position, target), objects, and each object's mesh. Defaults:
// camera up [0, 1, 0], fovY 60, near 0.1, far 100; background [0, 0, 0]; position [0, 0, 0],
// rotation [0, 0, 0] (degrees, about X, then Y, then Z), scale 1 (a number or three), color
// [0.8, 0.8, 0.8], opacity 1, shading "lambert". Any other key is an error, as is any value out
// of range; the message names the file, the key path (objects[2].opacity) and what is allowed.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "sfx/mesh_primitives.hpp"
#include "sfx/status.hpp"

namespace sfx::scene {

enum class Shading {
    Lambert,  // a fixed directional light plus an ambient term that AO multiplies
    Unlit,    // the colour exactly, untouched by lighting or AO
};
const char* toString(Shading shading);  // "lambert", "unlit"

struct SceneCamera {
    glm::dvec3 position{0.0, 0.0, 5.0};
    glm::dvec3 target{0.0};
    glm::dvec3 up{0.0, 1.0, 0.0};
    double fovYDegrees = 60.0;
    double nearPlane = 0.1, farPlane = 100.0;
    glm::dmat4 view() const;  // world to view (camera looking down -z)
};

struct SceneObject {
    std::string mesh;      // "quad", "box", "sphere", or the OBJ path as written in the file
    size_t meshIndex = 0;  // into Scene::meshes (objects naming the same mesh share it)
    glm::dvec3 position{0.0};
    glm::dvec3 rotationDegrees{0.0};
    glm::dvec3 scale{1.0};
    glm::dmat4 world{1.0};  // translate * rotateZ * rotateY * rotateX * scale
    glm::dvec3 color{0.8};  // linear RGB
    double opacity = 1.0;   // [0, 1]
    Shading shading = Shading::Lambert;
    bool translucent() const { return opacity < 1.0; }
};

struct Scene {
    std::string path;  // the file it came from ("<string>" for loadSceneFromString)
    uint32_t width = 0, height = 0;
    SceneCamera camera;
    glm::dvec3 background{0.0};
    std::vector<TriangleMesh> meshes;
    std::vector<SceneObject> objects;
    bool hasTranslucency() const;
};

// Largest width or height a scene may ask for.
inline constexpr uint32_t kMaxSceneSize = 16384;

// Reads and parses a scene file; OBJ paths are relative to the file's folder.
Result<Scene> loadSceneFile(const std::string& path);
// Parses scene text; OBJ paths are relative to baseDir; `name` stands for the file in messages.
// Never crashes or throws on any input: every problem is a Status.
Result<Scene> loadSceneFromString(const std::string& text, const std::string& baseDir, const std::string& name = "<string>");

}  // namespace sfx::scene
