// Analytic scenes for AO tests and the AO benchmark: planes and spheres ray-cast through a
// perspective camera (row 0 = top) into exact linear depth and view-space normals. No
// rasteriser: every pixel is the nearest hit along its centre's ray, in double precision.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "sfx/camera.hpp"
#include "sfx/reference/ao_reference.hpp"

namespace sfx::tools {

struct AnalyticShape {
    enum Kind { Plane, Sphere } kind = Plane;
    glm::dvec3 point{0, 0, 0};   // plane: a point on it; sphere: its centre (view space)
    glm::dvec3 normal{0, 0, 1};  // plane: its normal (either orientation)
    double radius = 0;           // sphere
};

struct AnalyticScene {
    std::string name;
    uint32_t width = 0, height = 0;
    CameraProjection camera;
    DepthReconstruction reconstruction;
    reference::Grid linearDepth;        // misses are the far plane (sky)
    std::vector<glm::dvec3> normals;    // unit, facing the camera; (0,0,1) for sky
    std::vector<glm::dvec3> positions;  // exact hit points (view space)

    reference::AoInput aoInput(bool withNormals) const;
};

struct AnalyticCamera {
    double fovYDegrees = 60.0;
    double nearPlane = 0.1;
    double farPlane = 100.0;  // may be +infinity (sky then lies at SFX_SKY_DEPTH)
    // The projection castScene traces a width x height picture with (row 0 = top, clip [0,1]).
    CameraProjection projection(uint32_t width, uint32_t height) const;
};

// A named analytic scene: its shapes (view space, camera at the origin looking down -z) and
// camera. The ray-traced truth (tools/scenes/truth_scenes.hpp) reads the same description.
struct AnalyticSceneDesc {
    std::string name;
    std::vector<AnalyticShape> shapes;
    AnalyticCamera camera;
};
// "facing_plane", "tilted_plane", "corner", "contact", "columns" (the scenes below).
std::vector<std::string> analyticSceneNames();
// InvalidArgument naming the known scenes for any other name.
Result<AnalyticSceneDesc> analyticSceneDesc(const std::string& name);

// Ray-casts the shapes, all scaled by `scale` about the eye (positions and radii).
AnalyticScene castScene(const AnalyticSceneDesc& desc, uint32_t width, uint32_t height, double scale = 1.0);

// A plane facing the camera at distance 4 (open: nothing occludes it).
AnalyticScene facingPlaneScene(uint32_t w, uint32_t h, double scale = 1.0);
// A plane tilted 50 degrees about the x axis through (0, 0, -4): open, seen obliquely.
AnalyticScene tiltedPlaneScene(uint32_t w, uint32_t h, double scale = 1.0);
// A 90-degree concave corner opening toward the camera: planes A (normal (0, 1, 1)/sqrt 2) and
// B (normal (0, -1, 1)/sqrt 2) meet in a horizontal crease through (0, 0, -4). Both are seen at
// 45 degrees, so pixels sample them evenly up to the crease.
AnalyticScene cornerScene(uint32_t w, uint32_t h, double scale = 1.0);
extern const glm::dvec3 kCornerCrease, kCornerNormalA, kCornerNormalB;
// A sphere of radius 0.6 resting on the floor y = -1 (one unit below the eye), touching it at
// (0.9, -1, -4). Floor within ~0.25 of the contact lies under the sphere's overhang, where the
// visible sphere surface is farther than the hidden underside: screen-space AO cannot see it
// (tests bin from 0.35 on).
AnalyticScene sphereOnPlaneScene(uint32_t w, uint32_t h, double scale = 1.0);
extern const glm::dvec3 kSphereContactPoint, kContactFloorNormal;
extern const double kContactSphereRadius;
// Four spheres resting on an open floor, sky above the horizon (infinite far plane): contact
// shadows, depth discontinuities at silhouettes, and sky.
AnalyticScene columnsScene(uint32_t w, uint32_t h, double scale = 1.0);

}  // namespace sfx::tools

namespace sfx::tools {

// Mean occlusion (1 - visibility) of the pixels of one surface in distance bins
// [edges[i], edges[i+1]); -1 for an empty bin. Positions are divided by `scale` first.
// onSurface(position, normal) picks the pixels, distanceOf(position) bins them.
template <class SurfaceFn, class DistanceFn>
std::vector<double> occlusionBins(const AnalyticScene& s, const reference::Grid& vis, double scale, const std::vector<double>& edges,
                                  SurfaceFn onSurface, DistanceFn distanceOf) {
    std::vector<double> sum(edges.size() - 1, 0.0), count(edges.size() - 1, 0.0);
    for (uint32_t y = 0; y < s.height; ++y)
        for (uint32_t x = 0; x < s.width; ++x) {
            const size_t i = size_t(y) * s.width + x;
            const glm::dvec3 p = s.positions[i] / scale;
            if (!onSurface(p, s.normals[i])) continue;
            const double d = distanceOf(p);
            for (size_t b = 0; b + 1 < edges.size(); ++b)
                if (d >= edges[b] && d < edges[b + 1]) {
                    sum[b] += 1.0 - vis.at(x, y);
                    count[b] += 1.0;
                }
        }
    std::vector<double> out(sum.size());
    for (size_t b = 0; b < out.size(); ++b) out[b] = count[b] > 0 ? sum[b] / count[b] : -1.0;
    return out;
}

// Plane A of the corner, binned by distance from the crease line.
inline bool onCornerPlaneA(const glm::dvec3& p, const glm::dvec3& n) {
    return glm::dot(n, kCornerNormalA) > 0.999 && std::abs(glm::dot(p - kCornerCrease, kCornerNormalA)) < 1e-6;
}
inline double distanceToCrease(const glm::dvec3& p) { return glm::length(glm::dvec2(p.y, p.z) - glm::dvec2(kCornerCrease.y, kCornerCrease.z)); }
// The floor around the sphere, binned by distance from the contact point.
inline bool onContactFloor(const glm::dvec3& p, const glm::dvec3& n) {
    return glm::dot(n, kContactFloorNormal) > 0.999 && std::abs(glm::dot(p - kSphereContactPoint, kContactFloorNormal)) < 1e-6;
}
inline double distanceToContact(const glm::dvec3& p) { return glm::length(p - kSphereContactPoint); }

// The 2x2 box average of a grid (for comparing a doubled resolution with the base one).
reference::Grid downsample2x(const reference::Grid& g);

}  // namespace sfx::tools
