#include "mb_raster_families.hpp"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "mb_raster.hpp"
#include "model_meshes.hpp"
#include "seeded_draw.hpp"
#include "sfx_shared_raster.h"

namespace sfx::tools {

using namespace sfx::reference;

namespace {

// Checkered (the raster pass's checker on world coordinates, 0.25 units a cell) unless coloured.
Mesh quad(glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d) {
    Mesh m;
    scene::addQuad(m, a, b, c, d);
    return m;
}

glm::dvec4 lambert(double r, double g, double b) { return {r, g, b, shared::SFX_RASTER_SHADING_LAMBERT}; }

// A glmark2 model standing at `at`, turned by `yawDegrees` about the vertical.
Result<Mesh> standing(const std::string& variant, double height, glm::dvec3 at, double yawDegrees, glm::dvec4 surface) {
    Result<StandingModel> model = loadStandingModel(variant, height);
    if (!model) return model.status();
    Mesh m(std::move(model->mesh));
    m.model = model->placed(glm::translate(glm::dmat4(1.0), at) * glm::rotate(glm::dmat4(1.0), glm::radians(yawDegrees), glm::dvec3(0, 1, 0)));
    m.surface = surface;
    return m;
}

// Layout `layout` of a family: 1 is the family as designed; any other moves its objects, turns
// them and tilts its motion within the ranges below (seeded_draw.hpp: the same on every compiler).
struct LayoutDraw {
    Draw draw;
    bool designed;
    explicit LayoutDraw(uint32_t layout) : draw(layout * 2654435761u + 97u), designed(layout == 1) {}
    // The designed value on layout 1, else uniform in [value - spread, value + spread).
    double operator()(double value, double spread) {
        const double drawn = draw(value - spread, value + spread);
        return designed ? value : drawn;
    }
};

// The scene with unit motion: object velocities / eye velocity in world units per shutter.
Result<RasterScene> unitScene(const std::string& family, uint32_t layout) {
    LayoutDraw d(layout);
    RasterScene s;
    s.name = family;
    s.fovYDegrees = 50;
    if (family == "models") {
        // The horse (near, moving right) passes in front of the cat (moving left and toward the
        // camera) before a checkered wall and floor; a still camera.
        s.meshes.push_back(quad({-8, -1, -2}, {8, -1, -2}, {8, 6, -2}, {-8, 6, -2}));
        s.meshes.push_back(quad({-8, 0, 6}, {8, 0, 6}, {8, 0, -2}, {-8, 0, -2}));
        // One draw per statement: the order of a call's arguments is the compiler's.
        const double horseX = d(-0.3, 0.3), horseZ = d(1.0, 0.3), horseYaw = d(90, 25), horseDz = d(0, 0.3);
        const double catX = d(0.4, 0.3), catZ = d(-0.6, 0.3), catYaw = d(0, 40), catDz = d(0.3, 0.3);
        Result<Mesh> horse = standing("horse", 1.0, {horseX, 0, horseZ}, horseYaw, lambert(0.75, 0.42, 0.22));
        if (!horse) return horse.status();
        horse->velocity = {1, 0, horseDz};
        Result<Mesh> cat = standing("cat", 0.8, {catX, 0, catZ}, catYaw, lambert(0.35, 0.45, 0.8));
        if (!cat) return cat.status();
        cat->velocity = {-0.7, 0, catDz};
        s.meshes.push_back(std::move(horse.value()));
        s.meshes.push_back(std::move(cat.value()));
        s.eye = {0, 0.8, 3.2};
        s.target = {0, 0.55, 0};
    } else if (family == "camera") {
        // Nothing moves but the camera, which pans right and dollies in: a sphere at depth 2.5,
        // a thin post at 4, the bunny (floating) at 5.5, a box at 8.5 and the wall at 12.
        s.meshes.push_back(quad({-12, -6, -8}, {12, -6, -8}, {12, 8, -8}, {-12, 8, -8}));
        const float sphereX = float(d(0.9, 0.4)), sphereY = float(d(1.2, 0.3)), postX = float(d(-0.5, 0.5));
        const double bunnyX = d(-1.6, 0.4), bunnyYaw = d(30, 60);
        const float boxX = float(d(1.6, 0.5));
        const double eyeDy = d(0, 0.3), eyeDz = d(-0.3, 0.3);
        Mesh sphere(scene::sphereMesh({sphereX, sphereY, 1.5f}, 0.35f));
        s.meshes.push_back(std::move(sphere));
        s.meshes.push_back(Mesh(scene::cylinderMesh({postX, -0.5f, 0}, 0.06f, 3.0f)));
        s.meshes.back().surface = lambert(0.9, 0.9, 0.85);
        Result<Mesh> bunny = standing("bunny", 1.0, {bunnyX, 0.4, -1.5}, bunnyYaw, lambert(0.8, 0.55, 0.5));
        if (!bunny) return bunny.status();
        s.meshes.push_back(std::move(bunny.value()));
        s.meshes.push_back(Mesh(scene::boxMesh({boxX, -1.6f, -4.6f}, {boxX + 1.4f, -0.4f, -3.6f})));
        s.eye = {0, 1.0, 4.0};
        s.target = {0, 1.0, 0};
        s.eyeVelocity = {1, eyeDy, eyeDz};
    } else if (family == "turning") {
        // Turning objects, still camera: a two-bladed cross spinning in the picture plane (its
        // blade tips fastest, its hub still) and the horse turning on the spot about the
        // vertical (nose and tail swinging across and in depth), before a checkered wall and floor.
        s.meshes.push_back(quad({-8, -1, -2}, {8, -1, -2}, {8, 6, -2}, {-8, 6, -2}));
        s.meshes.push_back(quad({-8, 0, 6}, {8, 0, 6}, {8, 0, -2}, {-8, 0, -2}));
        const double hubX = d(0.75, 0.3), hubY = d(1.2, 0.2), bladeSpin = d(1.0, 0.5), horseSpin = d(0.6, 0.3);
        const double standX = d(-0.7, 0.3), standZ = d(0.6, 0.3), horseYaw = d(70, 40);
        const glm::dvec3 hub{hubX, hubY, -0.4};
        for (int blade = 0; blade < 2; ++blade) {
            // Different thicknesses: the blades' front faces are not coplanar where they cross.
            const glm::vec3 half = blade == 0 ? glm::vec3(0.7f, 0.06f, 0.03f) : glm::vec3(0.06f, 0.7f, 0.05f);
            Mesh m(scene::boxMesh(glm::vec3(hub) - half, glm::vec3(hub) + half));
            m.surface = blade == 0 ? lambert(0.85, 0.8, 0.3) : lambert(0.3, 0.75, 0.5);
            m.spinRadians = bladeSpin;
            m.spinAxis = {0, 0, 1};
            m.spinCentre = hub;
            s.meshes.push_back(std::move(m));
        }
        const glm::dvec3 stand{standX, 0, standZ};
        Result<Mesh> horse = standing("horse", 0.9, stand, horseYaw, lambert(0.75, 0.42, 0.22));
        if (!horse) return horse.status();
        horse->spinRadians = horseSpin;
        horse->spinAxis = {0, 1, 0};
        horse->spinCentre = stand;
        s.meshes.push_back(std::move(horse.value()));
        s.eye = {0, 0.8, 3.2};
        s.target = {0, 0.7, 0};
    } else {
        return invalidArgument("raster motion blur family", "'" + family + "'", "models, camera, turning");
    }
    return s;
}

void scaleMotion(RasterScene& s, double k) {
    for (Mesh& m : s.meshes) {
        m.velocity *= k;
        m.spinRadians *= k;
    }
    s.eyeVelocity *= k;
}

double largestSpeed(const ShadedFrame& f) {
    double v = 0;
    for (const auto& e : f.velocity.values) v = std::max(v, std::hypot(e[0], e[1]));
    return v;
}

Result<ShadedFrame> renderAt(Device& device, SceneRenderer& renderer, const RasterScene& s, uint32_t w, uint32_t h, double t) {
    Result<GBuffer> g = renderer.render(s, w, h, t);
    if (!g) return g.status();
    Result<ShadedFrame> f = readFrame(device, g.value());
    renderer.destroy(g.value());
    return f;
}

// Records the first instant's surfaces and marks the masks as instants arrive.
struct MaskBuilder {
    FamilyMasks masks;
    ShadedFrame first;
    uint32_t instants = 0;
    static bool nearer(const ShadedFrame& a, const ShadedFrame& b, size_t p) {  // b's surface in front of a's
        if (!b.drawn[p]) return false;
        return !a.drawn[p] || b.linearDepth.values[p] < 0.9 * a.linearDepth.values[p];
    }
    void operator()(uint32_t i, const ShadedFrame& f) {
        const size_t n = f.drawn.size();
        if (i == 0) {
            first = f;
            masks = {std::vector<bool>(n, false), std::vector<bool>(n, false), std::vector<bool>(n, false)};
        }
        for (size_t p = 0; p < n; ++p) {
            const bool closer = nearer(first, f, p), farther = nearer(f, first, p);
            const auto& v = f.velocity.values[p];
            if ((f.drawn[p] && (v[0] != 0 || v[1] != 0)) || closer || farther) masks.moving[p] = true;
            if (i + 1 < instants) continue;
            if (closer) masks.leading[p] = true;
            if (farther) masks.trailing[p] = true;
        }
    }
};

}  // namespace

std::vector<std::string> rasterFamilyNames() { return {"models", "camera", "turning"}; }

Result<RasterScene> rasterFamilyScene(Device& device, SceneRenderer& renderer, const std::string& family, double speedPx, uint32_t w, uint32_t h,
                                      uint32_t layout) {
    Result<RasterScene> s = unitScene(family, layout);
    if (!s) return s;
    SFX_TRY(renderer.load(s.value()));
    // Three rescalings: exact for a motion parallel to the picture, within 1e-3 with the dolly
    // (a turning object's velocity is the chord of its arc, so its speed is not quite linear either).
    for (int step = 0; step < 3; ++step) {
        Result<ShadedFrame> f = renderAt(device, renderer, s.value(), w, h, 0.0);
        if (!f) return f.status();
        const double v = largestSpeed(f.value());
        if (v <= 0) return Status{StatusCode::InvalidArgument, "raster motion blur family " + family + ": nothing moves"};
        scaleMotion(s.value(), speedPx / v);
    }
    return s;
}

Result<RasterFamilyCase> makeRasterFamilyCase(Device& device, SceneRenderer& renderer, const std::string& family, double speedPx, uint32_t w,
                                              uint32_t h, uint32_t instants, uint32_t layout) {
    Result<RasterScene> s = rasterFamilyScene(device, renderer, family, speedPx, w, h, layout);
    if (!s) return s.status();
    const RasterScene scene = std::move(s.value());
    SFX_TRY(renderer.load(scene));  // render() reads the motion from the loaded meshes
    RasterFamilyCase c;
    c.family = family;
    c.speedPx = speedPx;
    MaskBuilder masks;
    masks.instants = instants;
    Result<SceneTruth> truth = sceneGroundTruth(device, renderer, scene, w, h, instants, std::ref(masks));
    if (!truth) return truth.status();
    c.truth = std::move(truth->color);
    c.residualRmse = truth->residualRmse;
    c.masks = std::move(masks.masks);
    Result<ShadedFrame> f = renderAt(device, renderer, scene, w, h, 0.0);
    if (!f) return f.status();
    c.measuredSpeedPx = largestSpeed(f.value());
    c.frame.color = std::move(f->color);
    c.frame.depth = std::move(f->linearDepth);
    c.frame.velocity = std::move(f->velocity);
    c.frame.layer.resize(f->drawn.size());
    for (size_t p = 0; p < f->drawn.size(); ++p) c.frame.layer[p] = f->drawn[p] ? 0 : -1;
    return c;
}

}  // namespace sfx::tools
