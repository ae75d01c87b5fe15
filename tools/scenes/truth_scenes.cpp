#include "truth_scenes.hpp"

namespace sfx::tools {

std::vector<std::string> truthSceneNames() {
    std::vector<std::string> names = sceneNames();
    for (const std::string& n : analyticSceneNames()) names.push_back("analytic-" + n);
    return names;
}

truth::Geometry worldGeometry(const RasterScene& scene) {
    truth::Geometry g;
    for (const Mesh& mesh : scene.meshes) {
        const uint32_t base = uint32_t(g.vertices.size());
        for (const Vertex& v : mesh.vertices) g.vertices.push_back(glm::vec3(mesh.model * glm::dvec4(glm::dvec3(v.position), 1.0)));
        for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3)
            g.triangles.push_back(glm::uvec3(mesh.indices[t], mesh.indices[t + 1], mesh.indices[t + 2]) + base);
    }
    return g;
}

truth::Geometry worldGeometry(const AnalyticSceneDesc& scene) {
    truth::Geometry g;
    for (const AnalyticShape& s : scene.shapes) {
        if (s.kind == AnalyticShape::Sphere) {
            g.spheres.push_back(glm::vec4(glm::vec3(s.point), float(s.radius)));
            continue;
        }
        const glm::dvec3 n = glm::normalize(s.normal);
        const glm::dvec3 centre = n * glm::dot(s.point, n);  // the plane's point nearest the eye (origin)
        const glm::dvec3 u = glm::normalize(glm::cross(n, std::abs(n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0)));
        const glm::dvec3 v = glm::cross(n, u);
        const uint32_t base = uint32_t(g.vertices.size());
        for (const glm::dvec2 c : {glm::dvec2(-1, -1), glm::dvec2(1, -1), glm::dvec2(1, 1), glm::dvec2(-1, 1)})
            g.vertices.push_back(glm::vec3(centre + kAnalyticPlaneHalfSize * (c.x * u + c.y * v)));
        g.triangles.push_back({base, base + 1, base + 2});
        g.triangles.push_back({base, base + 2, base + 3});
    }
    return g;
}

Result<TruthScene> makeTruthScene(const RasterScene& scene, uint32_t width, uint32_t height) {
    if (width == 0 || height == 0) return invalidArgument("width/height", std::to_string(width) + "x" + std::to_string(height), "at least 1x1");
    TruthScene t;
    t.name = scene.name;
    t.camera.width = width;
    t.camera.height = height;
    t.geometry = worldGeometry(scene);
    t.camera.view = scene.view(0.0);
    Result<CameraProjection> projection = scene.projection(width, height, ClipDepthRange::ZeroToOne);
    if (!projection) return projection.status();
    t.camera.projection = projection.value();
    return t;
}

Result<TruthScene> makeTruthScene(const std::string& name, uint32_t width, uint32_t height) {
    if (width == 0 || height == 0) return invalidArgument("width/height", std::to_string(width) + "x" + std::to_string(height), "at least 1x1");
    TruthScene t;
    t.name = name;
    t.camera.width = width;
    t.camera.height = height;
    const std::string prefix = "analytic-";
    if (name.rfind(prefix, 0) == 0) {
        Result<AnalyticSceneDesc> desc = analyticSceneDesc(name.substr(prefix.size()));
        if (desc) {
            t.geometry = worldGeometry(desc.value());
            t.camera.projection = desc->camera.projection(width, height);  // at the origin: view = identity
            return t;
        }
    } else if (Result<RasterScene> scene = makeScene(name); scene) {
        return makeTruthScene(scene.value(), width, height);
    } else if (scene.status().code() != StatusCode::InvalidArgument) {
        return scene.status();  // the bunny's file
    }
    std::string known;
    for (const auto& n : truthSceneNames()) known += (known.empty() ? "" : ", ") + n;
    return invalidArgument("scene", "'" + name + "'", known);
}

}  // namespace sfx::tools
