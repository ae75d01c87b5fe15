#include "scene_families.hpp"

#include <cmath>
#include <cstdio>
#include <glm/gtc/matrix_transform.hpp>

#include "model_meshes.hpp"

namespace sfx::tools {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDegrees = kPi / 180.0;
const glm::dvec3 kUp{0, 1, 0};

// splitmix64: the same scene from the same seed on every machine and standard library.
class Rng {
public:
    explicit Rng(uint64_t seed) : state_(seed * 0x9E3779B97F4A7C15ull + 1) {}
    uint64_t next() {
        uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
    double in(double lo, double hi) { return lo + (hi - lo) * double(next() >> 11) * 0x1.0p-53; }
    uint32_t below(uint32_t n) { return uint32_t(next() % n); }

private:
    uint64_t state_;
};

// One view of a family: which scene (a seed or a named variant) and the camera, orbiting
// `target`: elevation above the horizontal (negative looks up), azimuth from +z toward +x.
// eyeHeight > 0 sets the elevation so that the eye is that high above the floor.
struct ViewSpec {
    const char* family;
    const char* variant;
    uint32_t seed;
    glm::dvec3 target;
    double elevation, azimuth, distance, eyeHeight, fovY, radius;
};

// clang-format off
const ViewSpec kViews[] = {
    {"blocks", "s11", 11, {-0.5, 0.3, -1.2}, 5, 20, 4.0, 0, 50, 0.5},
    {"blocks", "s12", 12, {-0.5, 0.3, -1.2}, 30, -20, 4.0, 0, 60, 1.0},
    {"blocks", "s13", 13, {-0.5, 0.3, -1.2}, 55, 30, 3.5, 0, 75, 0.25},
    {"blocks", "s14", 14, {-0.5, 0.3, -1.2}, 85, 0, 5.0, 0, 40, 2.0},
    {"interior", "s21", 21, {0, 2.0, -4}, 3, 0, 9.0, 0, 90, 1.0},
    {"interior", "s22", 22, {1, 2.5, -2}, -20, -60, 4.0, 0, 60, 2.0},
    {"interior", "s23", 23, {-1, 0.5, -3}, 50, 40, 6.0, 0, 70, 0.5},
    {"thin", "s31", 31, {0, 0.5, -0.5}, 6, 15, 3.0, 0, 60, 0.5},
    {"thin", "s32", 32, {0, 0.4, -0.3}, 35, -30, 2.8, 0, 45, 0.25},
    {"thin", "s33", 33, {0, 0.5, -0.5}, 80, 10, 3.0, 0, 80, 1.0},
    {"meshes", "horse", 0, {0, 0.45, -0.6}, 15, 30, 2.5, 0, 50, 0.5},
    {"meshes", "cat", 0, {0, 0.35, -0.6}, 15, -25, 2.6, 0, 65, 0.25},
    {"meshes", "bunny", 0, {0, 0.4, -0.6}, 65, 10, 3.2, 0, 90, 1.0},
    {"independent", "corner", 0, {0, 0.3, -1}, 0, 0, 3.5, 1.6, 60, 0.5},
    {"independent", "box", 0, {0, 0.3, -0.8}, 0, 0, 3.0, 1.6, 60, 0.5},
    {"independent", "sphere", 0, {0, 0.3, 0}, 0, 0, 3.0, 1.6, 60, 0.5},
};
// clang-format on

bool hasSolidSheet(const TradeView& view) {
    return view.family == "thin" && view.scene.size() > kSolidSheetSuffix.size() && view.scene.ends_with(kSolidSheetSuffix);
}

const ViewSpec* findView(const TradeView& view) {
    const std::string variant = hasSolidSheet(view) ? view.scene.substr(0, view.scene.size() - kSolidSheetSuffix.size()) : view.scene;
    for (const ViewSpec& v : kViews)
        if (view.family == v.family && variant == v.variant) return &v;
    return nullptr;
}

double elevationOf(const ViewSpec& v) { return v.eyeHeight > 0 ? std::asin((v.eyeHeight - v.target.y) / v.distance) / kDegrees : v.elevation; }

Mesh floorQuad(float halfSize, float y = 0.0f) {
    Mesh m;
    scene::addQuad(m, {-halfSize, y, halfSize}, {halfSize, y, halfSize}, {halfSize, y, -halfSize}, {-halfSize, y, -halfSize});
    return m;
}

// A wall in the plane z = z from x0 to x1, `height` tall.
Mesh wallZ(float z, float x0, float x1, float height) {
    Mesh m;
    scene::addQuad(m, {x0, 0, z}, {x1, 0, z}, {x1, height, z}, {x0, height, z});
    return m;
}

// A wall in the plane x = x from z0 to z1.
Mesh wallX(float x, float z0, float z1, float height) {
    Mesh m;
    scene::addQuad(m, {x, 0, z1}, {x, 0, z0}, {x, height, z0}, {x, height, z1});
    return m;
}

Mesh box(glm::dvec3 lo, glm::dvec3 hi) { return scene::boxMesh(glm::vec3(lo), glm::vec3(hi)); }
Mesh post(glm::dvec3 base, double radius, double height) { return scene::cylinderMesh(glm::vec3(base), float(radius), float(height), 32, true); }

// A semicircular arch: the half annulus between radii inner and outer about `centre` in the
// vertical plane along `span` (horizontal, unit), `depth` thick across it; smooth curved faces.
Mesh arch(glm::dvec3 centre, glm::dvec3 span, double inner, double outer, double depth, int segments = 24) {
    Mesh m;
    const glm::dvec3 across = glm::normalize(glm::cross(span, kUp)) * (depth / 2);
    auto strip = [&](auto vertexAt) {
        const uint32_t base = uint32_t(m.vertices.size());
        for (int k = 0; k <= segments; ++k) {
            const glm::dvec3 dir = span * std::cos(kPi * k / segments) + kUp * std::sin(kPi * k / segments);
            for (int side : {0, 1}) m.vertices.push_back(vertexAt(dir, side));
        }
        for (int k = 0; k < segments; ++k) {
            const uint32_t a = base + uint32_t(2 * k);
            m.indices.insert(m.indices.end(), {a, a + 1, a + 2, a + 1, a + 3, a + 2});
        }
    };
    const glm::dvec3 normalAcross = glm::normalize(across);
    for (double r : {inner, outer})
        strip([&](glm::dvec3 dir, int side) {
            const glm::dvec3 p = centre + dir * r + across * (side ? 1.0 : -1.0);
            return Vertex{glm::vec3(p), glm::vec3(r == inner ? -dir : dir)};
        });
    for (double face : {-1.0, 1.0})
        strip([&](glm::dvec3 dir, int side) {
            const glm::dvec3 p = centre + dir * (side ? outer : inner) + across * face;
            return Vertex{glm::vec3(p), glm::vec3(normalAcross * face)};
        });
    return m;
}

// Boxes, spheres and capped cylinders on a floor before a back wall (z = -3) and a short side
// wall (x = -3) that meet in a corner: each object stands free on the floor (boxes turned), against
// the back wall, in the corner, or stacked on an earlier box or cylinder.
RasterScene blocksScene(uint32_t seed) {
    Rng rng(seed);
    RasterScene s;
    s.meshes = {floorQuad(8.0f), wallZ(-3, -8, 8, 4), wallX(-3, -3, 0.5f, 4)};
    struct Placed {
        glm::dvec3 centre;
        double top, half;
    };
    std::vector<Placed> stackable;
    const uint32_t count = 7 + rng.below(3);
    for (uint32_t i = 0; i < count; ++i) {
        const uint32_t kind = rng.below(3);  // box, sphere, cylinder
        uint32_t where = rng.below(4);       // floor, wall, corner, stacked
        if (where == 3 && stackable.empty()) where = 0;
        const double hx = kind == 0 ? rng.in(0.15, 0.55) : kind == 1 ? rng.in(0.15, 0.45) : rng.in(0.1, 0.35);
        const double hz = kind == 0 ? rng.in(0.15, 0.55) : hx;
        const double height = kind == 0 ? 2 * rng.in(0.15, 0.5) : kind == 1 ? 2 * hx : rng.in(0.3, 1.2);
        glm::dvec3 base(rng.in(-2.0, 2.0), 0, rng.in(-2.0, 1.0));
        double turn = 0;
        if (where == 0) turn = rng.in(0, 90) * kDegrees;
        if (where == 1) base.z = -3 + hz;
        if (where == 2) base = {-3 + hx + rng.in(0, 1.0), 0, -3 + hz};
        if (where == 3) {
            const Placed& below = stackable[rng.below(uint32_t(stackable.size()))];
            base = {below.centre.x + rng.in(-0.3, 0.3) * below.half, below.top, below.centre.z + rng.in(-0.3, 0.3) * below.half};
        }
        Mesh m;
        if (kind == 0) {
            m = box({-hx, 0, -hz}, {hx, height, hz});
            m.model = glm::rotate(glm::translate(glm::dmat4(1.0), base), turn, kUp);
        } else if (kind == 1) {
            m = scene::sphereMesh(glm::vec3(base + glm::dvec3(0, hx, 0)), float(hx));
        } else {
            m = post(base, hx, height);
        }
        if (kind != 1) stackable.push_back({base, base.y + height, std::min(hx, hz)});
        s.meshes.push_back(std::move(m));
    }
    return s;
}

// Thin occluders on an open floor (sky beyond): free posts, a railing (posts, top and middle
// rails) and a thin sheet held above the floor on four thin legs, or in its place a solid block
// of the sheet's footprint and height (solidSheet).
RasterScene thinScene(uint32_t seed, bool solidSheet) {
    Rng rng(seed);
    RasterScene s;
    s.meshes = {floorQuad(8.0f)};
    const uint32_t posts = 3 + rng.below(3);
    for (uint32_t i = 0; i < posts; ++i) s.meshes.push_back(post({rng.in(-2.0, 2.0), 0, rng.in(-2.0, 0.0)}, rng.in(0.025, 0.05), rng.in(0.8, 1.4)));
    const double x0 = rng.in(-2.0, -1.0), length = rng.in(2.0, 3.0), z = rng.in(-1.6, -0.6);
    for (double x = x0; x <= x0 + length + 1e-9; x += 0.5) s.meshes.push_back(post({x, 0, z}, 0.03, 1.0));
    s.meshes.push_back(box({x0, 0.97, z - 0.025}, {x0 + length, 1.02, z + 0.025}));
    s.meshes.push_back(box({x0, 0.48, z - 0.02}, {x0 + length, 0.52, z + 0.02}));
    const double w = rng.in(1.0, 1.6), d = rng.in(0.6, 1.0), h = rng.in(0.1, 0.4), cx = rng.in(-0.5, 1.0), cz = rng.in(0.0, 1.0);
    if (solidSheet) {
        s.meshes.push_back(box({cx - w / 2, 0, cz - d / 2}, {cx + w / 2, h + 0.02, cz + d / 2}));
        return s;
    }
    s.meshes.push_back(box({cx - w / 2, h, cz - d / 2}, {cx + w / 2, h + 0.02, cz + d / 2}));
    for (double sx : {-1.0, 1.0})
        for (double sz : {-1.0, 1.0}) s.meshes.push_back(post({cx + sx * (w / 2 - 0.05), 0, cz + sz * (d / 2 - 0.05)}, 0.02, h));
    return s;
}

// A hall 10 x 16 x 6: two rows of columns (plinth, shaft, abacus) carrying arcades of
// semicircular arches along the hall and arches across the nave, benches on the floor, a ceiling.
RasterScene interiorScene(uint32_t seed) {
    Rng rng(seed);
    RasterScene s;
    Mesh ceiling;
    scene::addQuad(ceiling, {-5, 6, -9}, {5, 6, -9}, {5, 6, 7}, {-5, 6, 7});
    s.meshes = {floorQuad(9.0f), ceiling, wallZ(-9, -5, 5, 6), wallZ(7, -5, 5, 6), wallX(-5, -9, 7, 6), wallX(5, -9, 7, 6)};
    const double spacing = rng.in(2.2, 2.8), radius = rng.in(0.22, 0.35), shaft = 3.0, abacus = 0.15, rowX = 2.4;
    const double spring = shaft + 0.25 + abacus, ring = 0.3;
    int index = 0;
    for (double z = -7.0; z <= 3.5; z += spacing, ++index)
        for (double x : {-rowX, rowX}) {
            const double p = radius + 0.08, a = radius + 0.1;
            s.meshes.push_back(box({x - p, 0, z - p}, {x + p, 0.25, z + p}));
            s.meshes.push_back(post({x, 0.25, z}, radius, shaft));
            s.meshes.push_back(box({x - a, shaft + 0.25, z - a}, {x + a, spring, z + a}));
            if (z + spacing <= 3.5 + 1e-9) {
                const double inner = spacing / 2 - radius;
                s.meshes.push_back(arch({x, spring, z + spacing / 2}, {0, 0, 1}, inner, inner + ring, 2 * radius));
            }
            if (x > 0 && index % 2 == 0) s.meshes.push_back(arch({0, spring, z}, {1, 0, 0}, rowX - radius, rowX - radius + ring, 2 * radius));
        }
    const uint32_t benches = 2 + rng.below(3);
    for (uint32_t i = 0; i < benches; ++i) {
        const double bx = rng.in(-1.2, 0.6), bz = rng.in(-6.0, 2.0);
        s.meshes.push_back(box({bx, 0, bz}, {bx + rng.in(0.6, 1.4), 0.45, bz + 0.4}));
    }
    return s;
}

// A glmark2 model scaled to `height`, standing on the floor 0.15 in front of a back wall.
Result<RasterScene> meshScene(const std::string& variant) {
    Result<StandingModel> model = loadStandingModel(variant, variant == "cat" ? 0.8 : 1.0);
    if (!model) return model.status();
    const double wall = -1.2;
    Mesh m(std::move(model->mesh));
    m.model = model->placed(glm::translate(glm::dmat4(1.0), glm::dvec3(0, 0, wall + 0.15 + model->size.z / 2)));
    RasterScene s;
    s.meshes = {floorQuad(6.0f), wallZ(float(wall), -6, 6, 3)};
    s.meshes.push_back(std::move(m));
    return s;
}

// The three scenes made outside the project's generator: a 90-degree corner (floor and wall),
// a box on a floor before a wall, a sphere resting on a floor.
RasterScene independentScene(const std::string& variant) {
    RasterScene s;
    s.meshes = {floorQuad(8.0f)};
    if (variant == "corner") s.meshes.push_back(wallZ(-1, -8, 8, 4));
    if (variant == "box") {
        s.meshes.push_back(wallZ(-1.5f, -8, 8, 4));
        s.meshes.push_back(box({-0.3, 0, -1.1}, {0.3, 0.6, -0.5}));
    }
    if (variant == "sphere") s.meshes.push_back(scene::sphereMesh({0, 0.5f, 0}, 0.5f, 96, 48));
    return s;
}

}  // namespace

std::vector<SceneFamily> sceneFamilies() {
    return {
        {"blocks", false, "7-9 boxes, spheres and capped cylinders from a seed, on a floor, against a wall, in a corner and stacked"},
        {"interior", false,
         "a hall with two rows of columns carrying arcades of semicircular arches and arches across the nave, benches from a seed"},
        {"thin", true, "posts, a railing and a thin sheet on legs above an open floor, sizes and places from a seed"},
        {"meshes", true, "glmark2's horse, cat and bunny (Debian glmark2-data) standing on a floor before a wall"},
        {"independent", true, "a 90-degree corner, a box on a floor before a wall, a sphere resting on a floor; eye height 1.6, fov-y 60, r 0.5"},
    };
}

std::vector<TradeView> familyViews(bool heldOut) {
    std::vector<TradeView> views;
    for (const SceneFamily& f : sceneFamilies()) {
        if (f.heldOut != heldOut) continue;
        uint32_t index = 0;
        for (const ViewSpec& v : kViews) {
            if (f.name != v.family) continue;
            TradeView t;
            t.scene = v.variant;
            t.family = v.family;
            t.index = index++;
            t.radius = v.radius;
            views.push_back(t);
        }
    }
    return views;
}

std::vector<TradeView> allFamilyViews() {
    std::vector<TradeView> views = familyViews(false), heldOut = familyViews(true);
    views.insert(views.end(), heldOut.begin(), heldOut.end());
    return views;
}

TradeView withSolidSheet(TradeView view) {
    if (view.family == "thin" && !hasSolidSheet(view)) view.scene += kSolidSheetSuffix;
    return view;
}

std::string describeCamera(const TradeView& view) {
    const ViewSpec* v = findView(view);
    if (!v) return "unknown view";
    char buf[160];
    std::snprintf(buf, sizeof buf, "elevation %.0f deg, azimuth %.0f deg, distance %g, fov-y %g, r %g", elevationOf(*v), v->azimuth, v->distance,
                  v->fovY, v->radius);
    return buf;
}

Result<RasterScene> familyScene(const TradeView& view) {
    const ViewSpec* v = findView(view);
    if (!v) return invalidArgument("family view", "'" + view.name() + "'", "a view of sceneFamilies()");
    RasterScene s;
    const std::string family = v->family;
    if (family == "blocks") s = blocksScene(v->seed);
    if (family == "thin") s = thinScene(v->seed, hasSolidSheet(view));
    if (family == "interior") s = interiorScene(v->seed);
    if (family == "independent") s = independentScene(v->variant);
    if (family == "meshes") {
        Result<RasterScene> m = meshScene(v->variant);
        if (!m) return m.status();
        s = std::move(m.value());
    }
    const double el = elevationOf(*v) * kDegrees, az = v->azimuth * kDegrees;
    s.name = view.name();
    s.target = v->target;
    s.eye = v->target + v->distance * glm::dvec3(std::sin(az) * std::cos(el), std::sin(el), std::cos(az) * std::cos(el));
    s.fovYDegrees = v->fovY;
    return s;
}

}  // namespace sfx::tools
