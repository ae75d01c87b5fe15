#include "model_meshes.hpp"

#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <assimp/Importer.hpp>
#include <cmath>

namespace sfx::tools {

Result<scene::TriangleMesh> loadModelMesh(const std::string& path) {
    Assimp::Importer importer;
    const unsigned flags = aiProcess_Triangulate | aiProcess_PreTransformVertices | aiProcess_GenSmoothNormals | aiProcess_JoinIdenticalVertices;
    const aiScene* file = importer.ReadFile(path, flags);
    if (!file) return Status{StatusCode::FileError, path + ": " + importer.GetErrorString() + " (install Debian's glmark2-data)"};
    scene::TriangleMesh mesh;
    for (unsigned m = 0; m < file->mNumMeshes; ++m) {
        const aiMesh* part = file->mMeshes[m];
        if (!part->HasNormals()) continue;
        const uint32_t base = uint32_t(mesh.vertices.size());
        for (unsigned v = 0; v < part->mNumVertices; ++v) {
            const aiVector3D p = part->mVertices[v], n = part->mNormals[v];
            const glm::vec3 normal(n.x, n.y, n.z);
            const float length = glm::length(normal);
            mesh.vertices.push_back({glm::vec3(p.x, p.y, p.z), std::isfinite(length) && length > 0 ? normal / length : glm::vec3(0, 1, 0)});
        }
        for (unsigned f = 0; f < part->mNumFaces; ++f) {
            const aiFace& face = part->mFaces[f];
            if (face.mNumIndices != 3) continue;  // points and lines left by the triangulation
            mesh.indices.insert(mesh.indices.end(), {base + face.mIndices[0], base + face.mIndices[1], base + face.mIndices[2]});
        }
    }
    if (mesh.indices.empty()) return Status{StatusCode::FileError, path + ": no triangles"};
    return mesh;
}

}  // namespace sfx::tools
