// The OBJ reader of scenes and samples (tools/scene: sfx/mesh_primitives.hpp) on arbitrary text: a mesh or a
// FileError; every index of a mesh it returns names one of its vertices, every normal is unit.
#include <cmath>
#include <cstdlib>

#include "sfx/mesh_primitives.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    sfx::Result<sfx::scene::TriangleMesh> mesh = sfx::scene::parseObjMesh("input.obj", text);
    if (!mesh) {
        if (mesh.status().code() != sfx::StatusCode::FileError) std::abort();
        return 0;
    }
    if (mesh->indices.size() % 3 != 0) std::abort();
    for (uint32_t i : mesh->indices)
        if (i >= mesh->vertices.size()) std::abort();
    for (const sfx::scene::Vertex& v : mesh->vertices)  // normals are unit (or the fallback), never NaN
        if (!(std::abs(glm::length(v.normal) - 1.0f) < 1e-3f)) std::abort();
    return 0;
}
