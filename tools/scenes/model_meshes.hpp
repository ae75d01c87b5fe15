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

// glmark2's "horse", "cat" or "bunny" (Debian glmark2-data) standing upright: turned y-up by
// `upright`, scaled by `scale` to the height asked, the centre of its base at `base` before the
// scale; `size` is its extent once scaled.
struct StandingModel {
    scene::TriangleMesh mesh;
    glm::dmat4 upright{1.0};
    glm::dvec3 base{0.0};
    double scale = 1;
    glm::dvec3 size{0.0};
    // The world matrix that stands the model with its base centre at the origin, then applies
    // `placement`: placement * scale * translate(-base) * upright, multiplied left to right.
    glm::dmat4 placed(const glm::dmat4& placement) const;
};
Result<StandingModel> loadStandingModel(const std::string& variant, double height);

}  // namespace sfx::tools
