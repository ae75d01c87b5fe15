#include "edge_bands.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <tuple>

namespace sfx::test {

size_t PixelMask::count() const { return size_t(std::count(set.begin(), set.end(), uint8_t(1))); }

void markSegmentBand(PixelMask& mask, glm::dvec2 a, glm::dvec2 b, double band) {
    const int x0 = std::max(0, int(std::floor(std::min(a.x, b.x) - band - 0.5)));
    const int x1 = std::min(int(mask.width) - 1, int(std::ceil(std::max(a.x, b.x) + band)));
    const int y0 = std::max(0, int(std::floor(std::min(a.y, b.y) - band - 0.5)));
    const int y1 = std::min(int(mask.height) - 1, int(std::ceil(std::max(a.y, b.y) + band)));
    const glm::dvec2 d = b - a;
    const double len2 = glm::dot(d, d);
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
            const glm::dvec2 c(x + 0.5, y + 0.5);
            const double t = len2 > 0 ? std::clamp(glm::dot(c - a, d) / len2, 0.0, 1.0) : 0.0;
            if (glm::length(c - (a + t * d)) < band) mask.set[size_t(y) * mask.width + size_t(x)] = 1;
        }
}

std::vector<std::pair<glm::vec3, glm::vec3>> changingEdges(const scene::TriangleMesh& mesh, const std::vector<int>& facing, bool creases) {
    using Key = std::array<float, 6>;
    std::map<Key, std::vector<size_t>> edges;  // the triangles using each edge
    const size_t tris = mesh.indices.size() / 3;
    std::vector<glm::dvec3> normal(tris);
    for (size_t t = 0; t < tris; ++t) {
        const uint32_t* ix = &mesh.indices[t * 3];
        const glm::dvec3 a(mesh.vertices[ix[0]].position), b(mesh.vertices[ix[1]].position), c(mesh.vertices[ix[2]].position);
        const glm::dvec3 n = glm::cross(b - a, c - a);
        normal[t] = glm::length(n) > 0 ? glm::normalize(n) : n;
        for (int e = 0; e < 3; ++e) {
            glm::vec3 p = mesh.vertices[ix[e]].position, q = mesh.vertices[ix[(e + 1) % 3]].position;
            if (std::tie(q.x, q.y, q.z) < std::tie(p.x, p.y, p.z)) std::swap(p, q);
            edges[{p.x, p.y, p.z, q.x, q.y, q.z}].push_back(t);
        }
    }
    std::vector<std::pair<glm::vec3, glm::vec3>> out;
    for (const auto& [key, ts] : edges) {
        bool changes = ts.size() != 2 || facing[ts[0]] != facing[ts[1]] || facing[ts[0]] == 0;
        // Coplanar: the same unit normal to well within float rounding of the mesh's positions.
        if (!changes && creases) changes = glm::dot(normal[ts[0]], normal[ts[1]]) < 1.0 - 1e-9;
        if (changes) out.push_back({{key[0], key[1], key[2]}, {key[3], key[4], key[5]}});
    }
    return out;
}

}  // namespace sfx::test
