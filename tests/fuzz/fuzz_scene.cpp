// The scene-file reader (tools/scene: sfx/scene_file.hpp) on arbitrary text: a whole scene or a
// named error, never half a scene; every object of a scene it returns has triangles whose
// indices name its vertices, an opacity in [0, 1] and finite numbers. OBJ paths resolve against
// an empty folder, so the fuzzer explores the JSON and the key rules, not the file system.
#include <cmath>
#include <cstdlib>

#include "sfx/scene_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    sfx::Result<sfx::scene::Scene> scene = sfx::scene::loadSceneFromString(text, "/nonexistent-fuzz-dir");
    if (!scene) {
        if (scene.status().message().empty()) std::abort();  // every error says what is wrong
        return 0;
    }
    if (scene->width == 0 || scene->height == 0) std::abort();
    for (const sfx::scene::SceneObject& o : scene->objects) {
        if (!(o.opacity >= 0.0 && o.opacity <= 1.0)) std::abort();
        if (o.meshIndex >= scene->meshes.size()) std::abort();
        const sfx::scene::TriangleMesh& mesh = scene->meshes[o.meshIndex];
        for (uint32_t i : mesh.indices)
            if (i >= mesh.vertices.size()) std::abort();
        for (const sfx::scene::Vertex& v : mesh.vertices)
            if (!std::isfinite(v.position.x) || !std::isfinite(v.position.y) || !std::isfinite(v.position.z)) std::abort();
    }
    return 0;
}
