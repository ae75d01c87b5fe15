// Ray-traced ground truth for ambient obscurance, on the CPU with Embree 3. Not part of the SDK
// runtime: tools, samples and tests link it (target sfx_truth). The definition it computes is
// written in docs/trade.md: at the surface seen through each pixel centre, with the true
// geometric normal facing the camera, visibility = the fraction of cosine-weighted hemisphere
// directions whose ray hits nothing within the world radius r (binary, no falloff).
#pragma once

#include <glm/glm.hpp>

#include <cstdint>
#include <memory>
#include <vector>

#include "sfx/camera.hpp"
#include "sfx/status.hpp"

namespace sfx::truth {

// World-space geometry exactly as the rasteriser (or the analytic ray caster) drew it.
struct Geometry {
    std::vector<glm::vec3> vertices;
    std::vector<glm::uvec3> triangles;  // indices into vertices; either winding
    std::vector<glm::vec4> spheres;     // exact spheres: centre xyz, radius w
};

// The camera the effects saw: rays leave the eye through pixel centres (row 0 = top when the
// projection was built with rowZeroIsTop). Primary hits are kept between the near and far
// planes in linear depth, as the rasteriser clips.
struct Camera {
    CameraProjection projection;
    glm::dmat4 view{1.0};  // world -> view (camera looking down -z)
    uint32_t width = 0, height = 0;
};

struct Settings {
    double radius = 0.5;     // world units, > 0
    uint32_t samples = 256;  // a square number >= 256: sqrt(samples)^2 cosine-weighted strata
    uint32_t seed = 0;       // selects the per-pixel rotation and jitter (deterministic)
    uint32_t threads = 0;    // 0 = all hardware threads; the result does not depend on it
};

// Rays start this far from the surface along its normal, times max(1, primary hit distance),
// so that float rounding of the hit point never lets a ray hit the surface it leaves.
inline constexpr double kOriginOffset = 2e-4;

struct Image {
    uint32_t width = 0, height = 0, samples = 0;
    std::vector<float> visibility;  // row 0 = top; 1 on sky
    std::vector<uint8_t> surface;   // 1 = a surface was hit, 0 = sky (nothing within the far plane)
    bool isSurface(size_t i) const { return surface[i] != 0; }
};

// The binomial bound sqrt(v (1 - v) / N) on each pixel's standard error, averaged over surface
// pixels (0 when there are none); stratification makes the real error smaller (docs/trade.md
// measures it). Every pixel's is at most 0.5 / sqrt(N).
double meanStdErrorBound(const Image& image);

// Embree's scene of one Geometry, traced as often as wanted (thread-safe once built).
class Tracer {
public:
    // InvalidArgument when the geometry is empty, an index is out of range, or a sphere's radius
    // is not positive; BackendUnavailable when Embree cannot start.
    static Result<std::unique_ptr<Tracer>> create(const Geometry& geometry);
    ~Tracer();
    Tracer(const Tracer&) = delete;
    Tracer& operator=(const Tracer&) = delete;

    // The whole picture, multithreaded over rows. InvalidArgument naming Settings.radius,
    // Settings.samples or the camera's size when out of range.
    Result<Image> trace(const Camera& camera, const Settings& settings) const;

    // Visibility at one surface point with its unit normal (already facing the viewer); pixelKey
    // picks the per-pixel rotation and jitter exactly as trace() does for pixel (x, y); the
    // origin offset is kOriginOffset * max(1, |point|) (the tests' points lie near the origin).
    double visibilityAt(const glm::dvec3& point, const glm::dvec3& normal, const Settings& settings, uint32_t x = 0, uint32_t y = 0) const;

private:
    struct Impl;
    explicit Tracer(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
};

// InvalidArgument naming Settings.radius or Settings.samples (or the names a caller such as a
// command line gives them).
Status validate(const Settings& settings, const char* radiusName = "Settings.radius", const char* samplesName = "Settings.samples");

}  // namespace sfx::truth
