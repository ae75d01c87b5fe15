#include "raster_bands.hpp"

#include <cmath>

namespace sfx::test {

PixelMask sceneEdgeBand(const scene::Scene& scene, const render::RenderResult::OpaqueInputs& frame, uint32_t subPixelBits) {
    const uint32_t w = frame.color.width, h = frame.color.height;
    const double band = std::ldexp(1.0, -int(subPixelBits));
    const glm::dmat4 viewProj = frame.projection * frame.view;
    const glm::dvec3 eye(glm::inverse(frame.view)[3]);
    // The GPU clips at the near plane (clip w = near for these projections): edges are cut there,
    // and the cut adds an edge across each triangle it crosses.
    const double nearW = scene.camera.nearPlane;
    auto window = [&](const glm::dvec4& c) { return glm::dvec2((c.x / c.w + 1.0) * 0.5 * w, (c.y / c.w + 1.0) * 0.5 * h); };
    auto cut = [&](const glm::dvec4& a, const glm::dvec4& b) { return a + (b - a) * ((nearW - a.w) / (b.w - a.w)); };
    PixelMask mask(w, h);
    for (const scene::SceneObject& o : scene.objects) {
        const scene::TriangleMesh& mesh = scene.meshes[o.meshIndex];
        const glm::dmat4 mvp = viewProj * o.world;
        auto clip = [&](const glm::vec3& p) { return mvp * glm::dvec4(glm::dvec3(p), 1.0); };
        const size_t tris = mesh.indices.size() / 3;
        // Facing in world space: defined for triangles crossing the near plane too.
        std::vector<int> facing(tris);
        for (size_t t = 0; t < tris; ++t) {
            glm::dvec3 v[3];
            glm::dvec4 c[3];
            for (int k = 0; k < 3; ++k) {
                const glm::vec3& p = mesh.vertices[mesh.indices[t * 3 + size_t(k)]].position;
                v[k] = glm::dvec3(o.world * glm::dvec4(glm::dvec3(p), 1.0));
                c[k] = clip(p);
            }
            const double f = glm::dot(glm::cross(v[1] - v[0], v[2] - v[0]), eye - v[0]);
            facing[t] = f > 0 ? 1 : f < 0 ? -1 : 0;
            std::vector<glm::dvec4> crossing;
            for (int k = 0; k < 3; ++k)
                if ((c[k].w < nearW) != (c[(k + 1) % 3].w < nearW)) crossing.push_back(cut(c[k], c[(k + 1) % 3]));
            if (crossing.size() == 2) markSegmentBand(mask, window(crossing[0]), window(crossing[1]), band);
        }
        // Creases too: a lambert face's shading changes across them.
        for (const auto& [p, q] : changingEdges(mesh, facing, true)) {
            glm::dvec4 a = clip(p), b = clip(q);
            if (a.w < nearW && b.w < nearW) continue;
            if (a.w < nearW) a = cut(a, b);
            if (b.w < nearW) b = cut(a, b);
            markSegmentBand(mask, window(a), window(b), band);
        }
    }
    return mask;
}

}  // namespace sfx::test
