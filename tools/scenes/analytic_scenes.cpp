#include "analytic_scenes.hpp"

#include <cmath>
#include <limits>

namespace sfx::tools {

const glm::dvec3 kSphereContactPoint{0.9, -1.0, -4.0};
const glm::dvec3 kContactFloorNormal{0.0, 1.0, 0.0};
const double kContactSphereRadius = 0.6;
const glm::dvec3 kCornerCrease{0.0, 0.0, -4.0};
const glm::dvec3 kCornerNormalA{0.0, 0.7071067811865476, 0.7071067811865476};
const glm::dvec3 kCornerNormalB{0.0, -0.7071067811865476, 0.7071067811865476};

reference::AoInput AnalyticScene::aoInput(bool withNormals) const {
    reference::AoInput in;
    in.linearDepth = linearDepth;
    in.reconstruction = reconstruction;
    if (withNormals) in.normals = normals;
    return in;
}

CameraProjection AnalyticCamera::projection(uint32_t width, uint32_t height) const {
    PerspectiveDesc p;
    p.fovYRadians = fovYDegrees * 3.14159265358979323846 / 180.0;
    p.aspect = double(width) / double(height);
    p.nearPlane = nearPlane;
    p.farPlane = farPlane;
    p.rowZeroIsTop = true;
    return makePerspective(p).value();  // the scenes' cameras are valid by construction
}

AnalyticScene castScene(const AnalyticSceneDesc& desc, uint32_t width, uint32_t height, double scale) {
    const std::vector<AnalyticShape>& shapes = desc.shapes;
    const AnalyticCamera& cam = desc.camera;
    AnalyticScene s;
    s.name = desc.name;
    s.width = width;
    s.height = height;
    s.camera = cam.projection(width, height);
    s.reconstruction = makeDepthReconstruction(s.camera, width, height).value();
    s.linearDepth = reference::Grid(width, height, s.reconstruction.maxDepth);
    s.normals.assign(size_t(width) * height, glm::dvec3(0, 0, 1));
    s.positions.assign(size_t(width) * height, glm::dvec3(0, 0, -s.reconstruction.maxDepth));
    const double* pi = s.reconstruction.projInfo;
    for (uint32_t y = 0; y < height; ++y) {
        for (uint32_t x = 0; x < width; ++x) {
            // The ray through the pixel centre, scaled so that its z is -1: t is linear depth.
            const glm::dvec3 d((x + 0.5) * pi[0] + pi[2], (y + 0.5) * pi[1] + pi[3], -1.0);
            double best = std::numeric_limits<double>::infinity();
            glm::dvec3 bestN(0, 0, 1);
            for (const AnalyticShape& sh : shapes) {
                const glm::dvec3 c = sh.point * scale;
                if (sh.kind == AnalyticShape::Plane) {
                    const double dn = glm::dot(sh.normal, d);
                    if (dn == 0.0) continue;
                    const double t = glm::dot(sh.normal, c) / dn;
                    if (t > cam.nearPlane && t < best) {
                        best = t;
                        bestN = glm::normalize(dn > 0 ? -sh.normal : sh.normal);
                    }
                } else {
                    const double r = sh.radius * scale;
                    const double a = glm::dot(d, d), b = -2.0 * glm::dot(d, c), k = glm::dot(c, c) - r * r;
                    const double disc = b * b - 4 * a * k;
                    if (disc < 0) continue;
                    const double t = (-b - std::sqrt(disc)) / (2 * a);
                    if (t > cam.nearPlane && t < best) {
                        best = t;
                        bestN = glm::normalize(t * d - c);
                    }
                }
            }
            if (best < s.reconstruction.maxDepth) {
                s.linearDepth.at(x, y) = best;
                s.normals[size_t(y) * width + x] = bestN;
                s.positions[size_t(y) * width + x] = best * d;
            }
        }
    }
    return s;
}

std::vector<std::string> analyticSceneNames() { return {"facing_plane", "tilted_plane", "corner", "contact", "columns"}; }

Result<AnalyticSceneDesc> analyticSceneDesc(const std::string& name) {
    AnalyticSceneDesc d;
    d.name = name;
    if (name == "facing_plane") {
        d.shapes = {{AnalyticShape::Plane, {0, 0, -4}, {0, 0, 1}, 0}};
    } else if (name == "tilted_plane") {
        const double a = 50.0 * 3.14159265358979323846 / 180.0;
        d.shapes = {{AnalyticShape::Plane, {0, 0, -4}, {0, std::sin(a), std::cos(a)}, 0}};
    } else if (name == "corner") {
        d.shapes = {{AnalyticShape::Plane, kCornerCrease, kCornerNormalA, 0}, {AnalyticShape::Plane, kCornerCrease, kCornerNormalB, 0}};
    } else if (name == "contact") {
        d.shapes = {{AnalyticShape::Plane, kSphereContactPoint, kContactFloorNormal, 0},
                    {AnalyticShape::Sphere, kSphereContactPoint + kContactSphereRadius * kContactFloorNormal, {}, kContactSphereRadius}};
    } else if (name == "columns") {
        d.shapes = {{AnalyticShape::Plane, {0, -1, 0}, {0, 1, 0}, 0}};
        for (int i = 0; i < 4; ++i) d.shapes.push_back({AnalyticShape::Sphere, {-1.8 + 1.2 * i, -0.55, -4.0 - 0.8 * i}, {}, 0.45});
        // A wall that stops at the horizon is not a plane; a second, far floor-like plane is not
        // needed: above the horizon there is sky (infinite far plane).
        d.camera.farPlane = std::numeric_limits<double>::infinity();
    } else {
        std::string known;
        for (const auto& n : analyticSceneNames()) known += (known.empty() ? "" : ", ") + n;
        return invalidArgument("analytic scene", "'" + name + "'", known);
    }
    return d;
}

AnalyticScene facingPlaneScene(uint32_t w, uint32_t h, double scale) { return castScene(analyticSceneDesc("facing_plane").value(), w, h, scale); }
AnalyticScene tiltedPlaneScene(uint32_t w, uint32_t h, double scale) { return castScene(analyticSceneDesc("tilted_plane").value(), w, h, scale); }
AnalyticScene cornerScene(uint32_t w, uint32_t h, double scale) { return castScene(analyticSceneDesc("corner").value(), w, h, scale); }
AnalyticScene sphereOnPlaneScene(uint32_t w, uint32_t h, double scale) { return castScene(analyticSceneDesc("contact").value(), w, h, scale); }
AnalyticScene columnsScene(uint32_t w, uint32_t h, double scale) { return castScene(analyticSceneDesc("columns").value(), w, h, scale); }

}  // namespace sfx::tools

namespace sfx::tools {
reference::Grid downsample2x(const reference::Grid& g) {
    reference::Grid out(g.width / 2, g.height / 2);
    for (uint32_t y = 0; y < out.height; ++y)
        for (uint32_t x = 0; x < out.width; ++x)
            out.at(x, y) = 0.25 * (g.at(2 * x, 2 * y) + g.at(2 * x + 1, 2 * y) + g.at(2 * x, 2 * y + 1) + g.at(2 * x + 1, 2 * y + 1));
    return out;
}
}  // namespace sfx::tools
