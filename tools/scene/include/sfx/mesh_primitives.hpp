// Triangle meshes for scenes: the primitives a scene file names (quad, box, sphere), cylinders for the sample scenes, and OBJ
// files through tinyobjloader, with vertex normals. Shared by the scene-file loader and the
// sample scenes.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "sfx/status.hpp"

namespace sfx::scene {

struct Vertex {
    glm::vec3 position;
    glm::vec3 normal;
};

struct TriangleMesh {
    std::vector<Vertex> vertices;
    std::vector<uint32_t> indices;  // triangles, counter-clockwise seen from the side the normal faces
};

// Appends the planar quad a, b, c, d (counter-clockwise), normal from its winding.
void addQuad(TriangleMesh& mesh, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d);
// The square [-0.5, 0.5]^2 in the XY plane, normal +Z (one sided: drawn without culling it
// shows both sides).
TriangleMesh quadMesh();
// The axis-aligned box from lo to hi, faces outward (flat normals).
TriangleMesh boxMesh(glm::vec3 lo, glm::vec3 hi);
// A UV sphere, smooth normals.
TriangleMesh sphereMesh(glm::vec3 centre, float radius, int slices = 48, int stacks = 24);
// A vertical cylinder standing on `base`, smooth side normals; capped: closed by flat discs.
TriangleMesh cylinderMesh(glm::vec3 base, float radius, float height, int slices = 32, bool capped = false);
// An OBJ file (faces triangulated), smooth area-weighted normals from its faces. FileError naming
// the path when it does not exist, does not parse, has no triangles, an index out of range or a
// coordinate that is not finite.
Result<TriangleMesh> loadObjMesh(const std::string& path);
// The same on an OBJ file's text (`path` only names it in messages): what the fuzz target feeds.
// Every index of a mesh it returns names one of its vertices and every normal is unit.
Result<TriangleMesh> parseObjMesh(const std::string& path, const std::string& text);

}  // namespace sfx::scene
