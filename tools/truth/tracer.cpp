// The Embree tracer behind sfx::truth (docs/trade.md states the definition and the estimator).
#include <embree3/rtcore.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <string>
#include <thread>

#include "sfx/truth.hpp"

namespace sfx::truth {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A 32-bit integer hash (the "lowbias32" mixer): decorrelates pixels, samples and seeds.
uint32_t mix(uint32_t v) {
    v ^= v >> 16;
    v *= 0x7feb352dU;
    v ^= v >> 15;
    v *= 0x846ca68bU;
    v ^= v >> 16;
    return v;
}
double unitFloat(uint32_t h) { return double(h >> 8) * (1.0 / 16777216.0); }  // [0, 1)

uint32_t pixelKey(uint32_t x, uint32_t y, uint32_t seed) { return mix(mix(mix(seed * 0x9e3779b9U + 1U) ^ x) ^ (y * 0x85ebca6bU)); }

// An orthonormal tangent frame around unit n (Duff et al.'s branchless construction).
void tangentFrame(const glm::dvec3& n, glm::dvec3& t, glm::dvec3& b) {
    const double sign = std::copysign(1.0, n.z);
    const double a = -1.0 / (sign + n.z), c = n.x * n.y * a;
    t = glm::dvec3(1.0 + sign * n.x * n.x * a, sign * c, -sign * n.x);
    b = glm::dvec3(c, sign + n.y * n.y * a, -n.y);
}

uint32_t strataPerAxis(uint32_t samples) { return uint32_t(std::lround(std::sqrt(double(samples)))); }

}  // namespace

Status validate(const Settings& s, const char* radiusName, const char* samplesName) {
    if (!(s.radius > 0.0) || !std::isfinite(s.radius))
        return invalidArgument(radiusName, std::to_string(s.radius), "a finite world-space distance > 0");
    const uint32_t k = strataPerAxis(s.samples);
    if (s.samples < 256 || k * k != s.samples || s.samples > 65536)
        return invalidArgument(samplesName, std::to_string(s.samples), "a square number from 256 to 65536 (256, 324, 400, ..., 1024, ...)");
    return Status::ok();
}

struct Tracer::Impl {
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    ~Impl() {
        if (scene) rtcReleaseScene(scene);
        if (device) rtcReleaseDevice(device);
    }

    // 1 when nothing lies within `radius` of `origin` along unit `dir`.
    bool open(const glm::dvec3& origin, const glm::dvec3& dir, double radius) const {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        RTCRay ray{};
        ray.org_x = float(origin.x), ray.org_y = float(origin.y), ray.org_z = float(origin.z);
        ray.dir_x = float(dir.x), ray.dir_y = float(dir.y), ray.dir_z = float(dir.z);
        ray.tnear = 0.0f;
        ray.tfar = float(radius);
        ray.mask = 0xffffffffU;
        rtcOccluded1(scene, &context, &ray);
        return ray.tfar >= 0.0f;  // Embree sets tfar to -inf on a hit
    }

    // The stratified cosine-weighted estimate: sqrt(N) x sqrt(N) strata of the unit square,
    // one jittered point in each, mapped to the disk (r = sqrt(u1), phi = 2 pi u2, the
    // projection of the cosine-weighted hemisphere) and lifted to it; the azimuth is rotated
    // per pixel so neighbouring pixels do not share one pattern.
    double visibility(const glm::dvec3& point, const glm::dvec3& normal, const Settings& s, uint32_t key, double offset) const {
        glm::dvec3 t, b;
        tangentFrame(normal, t, b);
        const glm::dvec3 origin = point + normal * offset;
        const uint32_t k = strataPerAxis(s.samples);
        const double rotation = 2.0 * kPi * unitFloat(mix(key ^ 0x68e31da4U));
        uint32_t open = 0;
        for (uint32_t i = 0; i < k; ++i)
            for (uint32_t j = 0; j < k; ++j) {
                const uint32_t h = mix(key + (i * k + j) * 0x9e3779b9U);
                const double u1 = (i + unitFloat(h)) / k, u2 = (j + unitFloat(mix(h))) / k;
                const double r = std::sqrt(u1), phi = 2.0 * kPi * u2 + rotation;
                const glm::dvec3 dir = t * (r * std::cos(phi)) + b * (r * std::sin(phi)) + normal * std::sqrt(std::max(0.0, 1.0 - u1));
                open += this->open(origin, dir, s.radius) ? 1U : 0U;
            }
        return double(open) / double(k * k);
    }
};

double meanStdErrorBound(const Image& image) {
    double sum = 0;
    size_t count = 0;
    for (size_t i = 0; i < image.visibility.size(); ++i) {
        if (!image.isSurface(i)) continue;
        const double v = image.visibility[i];
        sum += std::sqrt(v * (1.0 - v) / double(image.samples));
        ++count;
    }
    return count ? sum / double(count) : 0.0;
}

Tracer::Tracer(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Tracer::~Tracer() = default;

Result<std::unique_ptr<Tracer>> Tracer::create(const Geometry& g) {
    if (g.triangles.empty() && g.spheres.empty())
        return invalidArgument("Geometry", "no triangles and no spheres", "at least one triangle or sphere");
    for (size_t i = 0; i < g.triangles.size(); ++i)
        for (int c = 0; c < 3; ++c)
            if (g.triangles[i][c] >= g.vertices.size())
                return invalidArgument("Geometry.triangles[" + std::to_string(i) + "]", std::to_string(g.triangles[i][c]),
                                       "indices below the vertex count " + std::to_string(g.vertices.size()));
    for (size_t i = 0; i < g.spheres.size(); ++i)
        if (!(g.spheres[i].w > 0.0f))
            return invalidArgument("Geometry.spheres[" + std::to_string(i) + "].w", std::to_string(g.spheres[i].w), "a radius > 0");

    auto impl = std::make_unique<Impl>();
    impl->device = rtcNewDevice(nullptr);
    if (!impl->device)
        return Status{StatusCode::BackendUnavailable, "Embree: rtcNewDevice failed (error " + std::to_string(int(rtcGetDeviceError(nullptr))) + ")"};
    impl->scene = rtcNewScene(impl->device);
    rtcSetSceneFlags(impl->scene, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(impl->scene, RTC_BUILD_QUALITY_HIGH);
    if (!g.triangles.empty()) {
        RTCGeometry mesh = rtcNewGeometry(impl->device, RTC_GEOMETRY_TYPE_TRIANGLE);
        auto* v = static_cast<float*>(
            rtcSetNewGeometryBuffer(mesh, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), g.vertices.size()));
        auto* idx = static_cast<uint32_t*>(
            rtcSetNewGeometryBuffer(mesh, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(uint32_t), g.triangles.size()));
        for (size_t i = 0; i < g.vertices.size(); ++i)
            for (int c = 0; c < 3; ++c) v[3 * i + c] = g.vertices[i][c];
        for (size_t i = 0; i < g.triangles.size(); ++i)
            for (int c = 0; c < 3; ++c) idx[3 * i + c] = g.triangles[i][c];
        rtcCommitGeometry(mesh);
        rtcAttachGeometry(impl->scene, mesh);
        rtcReleaseGeometry(mesh);
    }
    if (!g.spheres.empty()) {
        RTCGeometry points = rtcNewGeometry(impl->device, RTC_GEOMETRY_TYPE_SPHERE_POINT);
        auto* v = static_cast<float*>(
            rtcSetNewGeometryBuffer(points, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, 4 * sizeof(float), g.spheres.size()));
        for (size_t i = 0; i < g.spheres.size(); ++i)
            for (int c = 0; c < 4; ++c) v[4 * i + c] = g.spheres[i][c];
        rtcCommitGeometry(points);
        rtcAttachGeometry(impl->scene, points);
        rtcReleaseGeometry(points);
    }
    rtcCommitScene(impl->scene);
    if (RTCError e = rtcGetDeviceError(impl->device); e != RTC_ERROR_NONE)
        return Status{StatusCode::BackendUnavailable, "Embree: building the scene failed (error " + std::to_string(int(e)) + ")"};
    return std::unique_ptr<Tracer>(new Tracer(std::move(impl)));
}

double Tracer::visibilityAt(const glm::dvec3& point, const glm::dvec3& normal, const Settings& s, uint32_t x, uint32_t y) const {
    return impl_->visibility(point, normal, s, pixelKey(x, y, s.seed), kOriginOffset * std::max(1.0, glm::length(point)));
}

Result<Image> Tracer::trace(const Camera& camera, const Settings& s) const {
    SFX_TRY(validate(s));
    if (camera.width == 0 || camera.height == 0 || camera.width > 16384 || camera.height > 16384)
        return invalidArgument("Camera.width/height", std::to_string(camera.width) + "x" + std::to_string(camera.height), "1 to 16384 each");
    Result<DepthReconstruction> rec = makeDepthReconstruction(camera.projection, camera.width, camera.height);
    if (!rec) return rec.status();
    const double* pi = rec->projInfo;
    const glm::dmat4 viewToWorld = glm::inverse(camera.view);
    const glm::dvec3 eye(viewToWorld[3]);
    const glm::dmat3 rotate(viewToWorld);

    Image out;
    out.width = camera.width;
    out.height = camera.height;
    out.samples = s.samples;
    const size_t n = size_t(camera.width) * camera.height;
    out.visibility.assign(n, 1.0f);
    out.surface.assign(n, 0);
    std::atomic<uint32_t> nextRow{0};
    auto worker = [&] {
        RTCIntersectContext context;
        for (uint32_t y; (y = nextRow.fetch_add(1)) < camera.height;)
            for (uint32_t x = 0; x < camera.width; ++x) {
                // The view-space ray through the pixel centre with z = -1, so t is linear depth.
                const glm::dvec3 d = rotate * glm::dvec3((x + 0.5) * pi[0] + pi[2], (y + 0.5) * pi[1] + pi[3], -1.0);
                rtcInitIntersectContext(&context);
                RTCRayHit hit{};
                hit.ray.org_x = float(eye.x), hit.ray.org_y = float(eye.y), hit.ray.org_z = float(eye.z);
                hit.ray.dir_x = float(d.x), hit.ray.dir_y = float(d.y), hit.ray.dir_z = float(d.z);
                hit.ray.tnear = float(rec->nearDepth);
                hit.ray.tfar = float(rec->maxDepth);
                hit.ray.mask = 0xffffffffU;
                hit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
                rtcIntersect1(impl_->scene, &context, &hit);
                if (hit.hit.geomID == RTC_INVALID_GEOMETRY_ID) continue;
                glm::dvec3 normal = glm::normalize(glm::dvec3(hit.hit.Ng_x, hit.hit.Ng_y, hit.hit.Ng_z));
                if (glm::dot(normal, d) > 0.0) normal = -normal;
                const double t = hit.ray.tfar;
                const glm::dvec3 point = eye + d * t;
                const double offset = kOriginOffset * std::max(1.0, t * glm::length(d));
                const double v = impl_->visibility(point, normal, s, pixelKey(x, y, s.seed), offset);
                const size_t i = size_t(y) * camera.width + x;
                out.visibility[i] = float(v);
                out.surface[i] = 1;
            }
    };
    const uint32_t threads = std::clamp(s.threads ? s.threads : std::thread::hardware_concurrency(), 1U, camera.height);
    std::vector<std::thread> pool;
    for (uint32_t i = 1; i < threads; ++i) pool.emplace_back(worker);
    worker();
    for (std::thread& th : pool) th.join();
    return out;
}

}  // namespace sfx::truth
