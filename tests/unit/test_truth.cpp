// The ray-traced AO truth (tools/truth) on cases with closed-form answers, within the
// estimator's noise bound: an open plane, a floor beside a perpendicular wall (the 90-degree
// concave wedge), a floor under a sphere; plus determinism, the primary ray through the pixel
// centre, the sample scenes' export, the metrics and settings validation.
#include <catch2/catch.hpp>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>

#include "sfx/truth.hpp"
#include "sfx/truth_metrics.hpp"
#include "truth_scenes.hpp"

using namespace sfx;

namespace {

constexpr double kPi = 3.14159265358979323846;

// A square of half-size h in the plane through `centre` spanned by unit u, v.
void addSquare(truth::Geometry& g, glm::dvec3 centre, glm::dvec3 u, glm::dvec3 v, double h) {
    const uint32_t base = uint32_t(g.vertices.size());
    for (glm::dvec2 c : {glm::dvec2(-1, -1), glm::dvec2(1, -1), glm::dvec2(1, 1), glm::dvec2(-1, 1)})
        g.vertices.push_back(glm::vec3(centre + h * (c.x * u + c.y * v)));
    g.triangles.push_back({base, base + 1, base + 2});
    g.triangles.push_back({base, base + 2, base + 3});
}

// Floor y = 0 (x, z in [-50, 50]); with `wall`, the plane x = 0 rising from it (y in [0, 100]).
truth::Geometry floorAndWall(bool wall) {
    truth::Geometry g;
    addSquare(g, {0, 0, 0}, {1, 0, 0}, {0, 0, 1}, 50.0);
    if (wall) addSquare(g, {0, 50, 0}, {0, 1, 0}, {0, 0, 1}, 50.0);
    return g;
}

// Visibility on the floor at distance d from a perpendicular wall, radius r. Cosine-weighted
// directions project to points uniform on the unit disk (Malley); a direction reaches the wall
// within r exactly when its component toward the wall is at least a = d / r, i.e. its disk
// point lies in the circular segment beyond the chord at a, of area acos(a) - a sqrt(1 - a^2).
double wedgeVisibility(double d, double r) {
    const double a = d / r;
    if (a >= 1.0) return 1.0;
    return 1.0 - (std::acos(a) - a * std::sqrt(1.0 - a * a)) / kPi;
}

// A w x h camera at `eye` looking at `target` (60 degrees vertical, row 0 = top).
truth::Camera lookAtCamera(uint32_t w, uint32_t h, glm::dvec3 eye, glm::dvec3 target) {
    truth::Camera cam;
    cam.width = w;
    cam.height = h;
    PerspectiveDesc pd;
    pd.aspect = double(w) / double(h);
    cam.projection = makePerspective(pd).value();
    cam.view = glm::lookAt(eye, target, glm::dvec3(0, 1, 0));
    return cam;
}

// The standard-error bound of one pixel's estimate (binary samples: variance <= 1/4).
double stdErrorBound(uint32_t samples) { return 0.5 / std::sqrt(double(samples)); }

// The mean of visibilityAt over `pixels` different per-pixel patterns.
double meanOverPixels(const truth::Tracer& t, glm::dvec3 p, glm::dvec3 n, const truth::Settings& s, uint32_t pixels, double* worst, double expected) {
    double sum = 0;
    for (uint32_t x = 0; x < pixels; ++x) {
        const double v = t.visibilityAt(p, n, s, x, 7);
        *worst = std::max(*worst, std::abs(v - expected));
        sum += v;
    }
    return sum / pixels;
}

}  // namespace

TEST_CASE("truth: an open plane is unoccluded and the sky is marked", "[truth]") {
    auto tracer = truth::Tracer::create(floorAndWall(false));
    REQUIRE(tracer);
    const truth::Camera cam = lookAtCamera(48, 27, {0, 1, 3}, {0, 0.8, 0});  // the horizon in the picture
    truth::Settings s;
    s.radius = 2.0;
    auto image = tracer.value()->trace(cam, s);
    REQUIRE(image);
    size_t surface = 0, sky = 0;
    for (size_t i = 0; i < image->visibility.size(); ++i) {
        CHECK(image->visibility[i] == 1.0f);  // every direction above a lone plane escapes
        (image->isSurface(i) ? surface : sky)++;
    }
    CHECK(surface > 200);
    CHECK(sky > 200);
    CHECK(image->isSurface(size_t(26) * 48 + 24));  // bottom row: the floor
    CHECK_FALSE(image->isSurface(24));              // top row: above the horizon
    CHECK(truth::meanStdErrorBound(image.value()) == 0.0);
}

TEST_CASE("truth: the floor beside a perpendicular wall matches the circular-segment formula", "[truth]") {
    auto tracer = truth::Tracer::create(floorAndWall(true));
    REQUIRE(tracer);
    truth::Settings s;
    s.radius = 1.0;
    const uint32_t pixels = 64;
    for (double d : {0.001, 0.1, 0.25, 0.5, 0.75, 0.95, 1.5}) {
        const double expected = wedgeVisibility(d, s.radius);
        double worst = 0;
        const double mean = meanOverPixels(*tracer.value(), {d, 0, 0}, {0, 1, 0}, s, pixels, &worst, expected);
        INFO("distance " << d << ": expected " << expected << ", mean " << mean << ", worst pixel off by " << worst);
        // Each pixel within 4 standard-error bounds; the mean of 64 independent patterns within 4 of its own.
        CHECK(worst <= 4 * stdErrorBound(s.samples));
        CHECK(std::abs(mean - expected) <= 4 * stdErrorBound(s.samples * pixels));
    }
    // In the crease itself half the cosine-weighted directions face the wall.
    CHECK(wedgeVisibility(0.0, 1.0) == Approx(0.5));
}

TEST_CASE("truth: a floor point under a sphere sees 1 - (R/h)^2", "[truth]") {
    // The sphere subtends a cone of half-angle asin(R / h) about the normal; the cosine-weighted
    // measure of such a cone is sin^2 of its half-angle. A radius beyond the tangent distance
    // sqrt(h^2 - R^2) reaches the whole sphere.
    for (auto [h, R] : {std::pair{1.0, 0.5}, std::pair{2.0, 1.5}, std::pair{1.0, 0.2}}) {
        truth::Geometry g = floorAndWall(false);
        g.spheres.push_back(glm::vec4(0.0f, float(h), 0.0f, float(R)));
        auto tracer = truth::Tracer::create(g);
        REQUIRE(tracer);
        truth::Settings s;
        s.radius = std::sqrt(h * h - R * R) + 0.01;
        const double expected = 1.0 - (R / h) * (R / h);
        double worst = 0;
        const double mean = meanOverPixels(*tracer.value(), {0, 0, 0}, {0, 1, 0}, s, 64, &worst, expected);
        INFO("h " << h << " R " << R << ": expected " << expected << ", mean " << mean);
        CHECK(worst <= 4 * stdErrorBound(s.samples));
        CHECK(std::abs(mean - expected) <= 4 * stdErrorBound(s.samples * 64));
        // Just short of the nearest point of the sphere, nothing is reached.
        s.radius = (h - R) * 0.99;
        CHECK(tracer.value()->visibilityAt({0, 0, 0}, {0, 1, 0}, s) == 1.0);
    }
}

TEST_CASE("truth: pictures trace the pixel-centre ray, are deterministic and their noise is within the bound", "[truth]") {
    auto tracer = truth::Tracer::create(floorAndWall(true));
    REQUIRE(tracer);
    const truth::Camera cam = lookAtCamera(40, 30, {1.5, 1.2, 1.5}, {0.3, 0.0, 0.0});
    truth::Settings s;
    s.radius = 0.8;
    s.threads = 1;
    auto one = tracer.value()->trace(cam, s);
    s.threads = 3;
    auto three = tracer.value()->trace(cam, s);
    s.seed = 1;
    auto reseeded = tracer.value()->trace(cam, s);
    REQUIRE(one);
    REQUIRE(three);
    REQUIRE(reseeded);
    CHECK(one->visibility == three->visibility);
    CHECK(one->surface == three->surface);

    // Floor pixels against the formula at the exact floor point of each pixel-centre ray.
    const DepthReconstruction rec = makeDepthReconstruction(cam.projection, cam.width, cam.height).value();
    const glm::dmat4 toWorld = glm::inverse(cam.view);
    const glm::dvec3 eye(toWorld[3]);
    double sumError = 0, sqDiff = 0, worst = 0;
    size_t floorPixels = 0, surface = 0;
    for (uint32_t y = 0; y < cam.height; ++y)
        for (uint32_t x = 0; x < cam.width; ++x) {
            const size_t i = size_t(y) * cam.width + x;
            if (!one->isSurface(i)) continue;
            ++surface;
            const double dv = one->visibility[i] - reseeded->visibility[i];
            sqDiff += dv * dv;
            const glm::dvec3 d = glm::dmat3(toWorld) *
                glm::dvec3((x + 0.5) * rec.projInfo[0] + rec.projInfo[2], (y + 0.5) * rec.projInfo[1] + rec.projInfo[3], -1.0);
            const double tFloor = -eye.y / d.y, tWall = -eye.x / d.x;
            if (!(d.y < 0 && (d.x >= 0 || tFloor < tWall))) continue;  // the wall is nearer
            const glm::dvec3 p = eye + tFloor * d;
            if (p.x < 0.02) continue;  // within float rounding of the crease
            const double e = one->visibility[i] - wedgeVisibility(p.x, s.radius);
            worst = std::max(worst, std::abs(e));
            sumError += e;
            ++floorPixels;
        }
    REQUIRE(floorPixels > 300);
    INFO("floor pixels " << floorPixels << ", worst " << worst << ", mean error " << sumError / floorPixels);
    CHECK(worst <= 4 * stdErrorBound(s.samples));
    CHECK(std::abs(sumError / floorPixels) <= 4 * stdErrorBound(s.samples) / std::sqrt(double(floorPixels)));
    // Two seeds are independent estimates: their difference has twice each one's variance.
    const double measured = std::sqrt(sqDiff / double(surface) / 2.0);
    INFO("measured per-pixel standard error " << measured);
    CHECK(measured > 0.0);
    CHECK(measured <= stdErrorBound(s.samples));
    CHECK(truth::meanStdErrorBound(one.value()) <= stdErrorBound(s.samples));
}

TEST_CASE("truth: the analytic scenes' export sees what castScene sees", "[truth]") {
    for (const std::string name : {"contact", "corner", "columns"}) {
        const tools::AnalyticScene cast = tools::castScene(tools::analyticSceneDesc(name).value(), 64, 36);
        auto scene = tools::makeTruthScene("analytic-" + name, 64, 36);
        REQUIRE(scene);
        auto tracer = truth::Tracer::create(scene->geometry);
        REQUIRE(tracer);
        truth::Settings s;
        s.radius = 0.5;
        auto image = tracer.value()->trace(scene->camera, s);
        REQUIRE(image);
        size_t mismatched = 0, occluded = 0;
        for (size_t i = 0; i < image->surface.size(); ++i) {
            const bool castHit = cast.linearDepth.values[i] < cast.reconstruction.maxDepth;
            mismatched += castHit != image->isSurface(i) ? 1 : 0;
            occluded += image->visibility[i] < 0.95f ? 1 : 0;
        }
        INFO(name << ": " << mismatched << " pixels disagree on sky, " << occluded << " occluded");
        CHECK(mismatched == 0);
        CHECK(occluded > 20);
    }
    auto rasterised = tools::makeTruthScene("steps", 32, 18);
    REQUIRE(rasterised);
    CHECK(rasterised->geometry.triangles.size() == 2 + 6 * 12);  // the floor and six boxes
    auto unknown = tools::makeTruthScene("nowhere", 32, 18);
    REQUIRE_FALSE(unknown);
    CHECK(unknown.status().message().find("analytic-contact") != std::string::npos);
}

TEST_CASE("truth: metrics against the truth", "[truth]") {
    truth::Image t;
    t.width = 4;
    t.height = 1;
    t.visibility = {1.0f, 0.5f, 0.25f, 1.0f};
    t.surface = {0, 1, 1, 1};
    auto same = truth::compare(t, {1.0, 0.5, 0.25, 1.0});
    REQUIRE(same);
    CHECK(std::isinf(same->psnr));
    CHECK(same->occludedPixels == 2);
    auto brighter = truth::compare(t, {1.0, 0.6, 0.35, 1.0});  // +0.1 on the two occluded pixels
    REQUIRE(brighter);
    CHECK(brighter->psnrOccluded == Approx(20.0));
    CHECK(brighter->psnr == Approx(-10.0 * std::log10(0.02 / 4)));
    CHECK(brighter->meanSignedError == Approx(0.05));
    CHECK(brighter->meanSignedErrorOccluded == Approx(0.1));
    CHECK(brighter->worstError == Approx(0.1));
    CHECK(brighter->worstX == 1);  // the first of the equal worst
    CHECK_FALSE(truth::compare(t, {1.0, 0.5}));
    auto nan = truth::compare(t, {1.0, std::numeric_limits<double>::quiet_NaN(), 0.25, 1.0});
    REQUIRE_FALSE(nan);
    CHECK(nan.status().message().find("estimate[1]") != std::string::npos);
}

TEST_CASE("truth: settings and geometry are validated with named errors", "[truth]") {
    truth::Settings s;
    s.radius = 0.0;
    Status st = truth::validate(s);
    CHECK(st.code() == StatusCode::InvalidArgument);
    CHECK(st.message().find("Settings.radius") != std::string::npos);
    s.radius = 1.0;
    for (uint32_t bad : {0u, 100u, 255u, 300u}) {
        s.samples = bad;
        CHECK(truth::validate(s).message().find("Settings.samples") != std::string::npos);
    }
    s.samples = 1024;
    CHECK(truth::validate(s));
    CHECK_FALSE(truth::Tracer::create(truth::Geometry{}));
    truth::Geometry broken;
    broken.vertices = {glm::vec3(0)};
    broken.triangles = {glm::uvec3(0, 1, 2)};
    auto b = truth::Tracer::create(broken);
    REQUIRE_FALSE(b);
    CHECK(b.status().message().find("Geometry.triangles[0]") != std::string::npos);
    auto tracer = truth::Tracer::create(floorAndWall(false));
    REQUIRE(tracer);
    truth::Camera cam;  // 0 x 0
    CHECK(tracer.value()->trace(cam, truth::Settings{}).status().message().find("Camera.width/height") != std::string::npos);
}
