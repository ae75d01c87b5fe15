// Triangle meshes and the one OBJ reader of the samples (tinyobjloader underneath): the demo,
// the benchmarks and the tests load the bunny through it, and a fuzz target feeds it bytes.
#pragma once

#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

#include "sfx/status.hpp"

namespace sfx::samples {

struct Vertex {
    glm::vec3 position;
    glm::vec3 normal;
};

struct Mesh {
    std::vector<Vertex> vertices;
    std::vector<uint32_t> indices;  // triangles
    glm::dmat4 model{1.0};
    glm::dvec3 velocity{0.0};       // world units per shutter interval (for moving-object demos)
};

// An OBJ's triangles (polygons are triangulated) with area-weighted smooth vertex normals
// computed from the faces; the file's own normals and materials are ignored. FileError
// naming `path` when the text does not parse or a face refers to a vertex that is not there.
Result<Mesh> parseObj(const std::string& path, const std::string& text);
// parseObj on the file's contents; FileError when it cannot be read.
Result<Mesh> loadObj(const std::string& path);

}  // namespace sfx::samples
