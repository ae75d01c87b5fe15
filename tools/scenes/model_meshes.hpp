// Triangle meshes from model files that are not OBJ (glmark2's 3DS horse and cat), read through
// Debian's libassimp-dev: triangulated, with smooth vertex normals, every node's transform applied.
#pragma once

#include <string>

#include "sfx/mesh_primitives.hpp"

namespace sfx::tools {

// FileError naming the path (and the package that provides it) when assimp cannot read it or it
// holds no triangles.
Result<scene::TriangleMesh> loadModelMesh(const std::string& path);

}  // namespace sfx::tools
