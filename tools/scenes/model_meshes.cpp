#include "model_meshes.hpp"

#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <assimp/Importer.hpp>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

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

Result<StandingModel> loadStandingModel(const std::string& variant, double height) {
    const std::string dir = "/usr/share/glmark2/models/";
    Result<scene::TriangleMesh> model = variant == "bunny" ? scene::loadObjMesh(dir + "bunny.obj") : loadModelMesh(dir + variant + ".3ds");
    if (!model) return model.status();
    // The cat is modelled z-up, the horse rolled 60 degrees about its length (z); the bunny is y-up.
    constexpr double kPi = 3.14159265358979323846;
    const glm::dmat4 upright = variant == "cat" ? glm::rotate(glm::dmat4(1.0), -kPi / 2, glm::dvec3(1, 0, 0))
        : variant == "horse"                    ? glm::rotate(glm::dmat4(1.0), -kPi / 3, glm::dvec3(0, 0, 1))
                                                : glm::dmat4(1.0);
    glm::dvec3 lo(1e30), hi(-1e30);
    for (const scene::Vertex& v : model->vertices) {
        const glm::dvec3 p(upright * glm::dvec4(glm::dvec3(v.position), 1.0));
        lo = glm::min(lo, p), hi = glm::max(hi, p);
    }
    StandingModel out;
    out.mesh = std::move(model.value());
    out.upright = upright;
    out.base = {(lo.x + hi.x) / 2, lo.y, (lo.z + hi.z) / 2};
    out.scale = height / (hi.y - lo.y);
    out.size = out.scale * (hi - lo);
    return out;
}

glm::dmat4 StandingModel::placed(const glm::dmat4& placement) const {
    return placement * glm::scale(glm::dmat4(1.0), glm::dvec3(scale)) * glm::translate(glm::dmat4(1.0), -base) * upright;
}

}  // namespace sfx::tools
