// Triangle meshes from model files that are not OBJ (glmark2's 3DS horse and cat), read through
// Debian's libassimp-dev: triangulated, with smooth vertex normals, every node's transform applied.
#pragma once

#include <string>

#include <glm/glm.hpp>

#include "sfx/mesh_primitives.hpp"

namespace sfx::tools {

// FileError naming the path (and the package that provides it) when assimp cannot read it or it
// holds no triangles.
Result<scene::TriangleMesh> loadModelMesh(const std::string& path);

// glmark2's "horse", "cat" or "bunny" (Debian glmark2-data) standing upright: `model` turns it
// y-up, scales it to `height` and puts the centre of its base at the origin; `size` is its
// extent after that.
struct StandingModel {
    scene::TriangleMesh mesh;
    glm::dmat4 model{1.0};
    glm::dvec3 size{0.0};
};
Result<StandingModel> loadStandingModel(const std::string& variant, double height);

}  // namespace sfx::tools
