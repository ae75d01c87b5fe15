#include "mb_families.hpp"

#include <algorithm>
#include <cmath>

#include "seeded_draw.hpp"

namespace sfx::tools {

using namespace sfx::reference;

namespace {

// The pose of one object at one instant: centre, rotation and scale.
struct Pose {
    double cx, cy, cosA, sinA, scale;
};
Pose poseAt(const FamilyObject& o, double t) {
    const double a = o.angleRad + o.spinRad * t;
    return {o.centre[0] + o.velocityPx[0] * t, o.centre[1] + o.velocityPx[1] * t, std::cos(a), std::sin(a), o.scale * std::exp(o.growth * t)};
}

bool moves(const FamilyObject& o) { return o.velocityPx[0] != 0 || o.velocityPx[1] != 0 || o.spinRad != 0 || o.growth != 0; }

// Colour of object `o` posed at `q` seen at pixel centre (px, py); false when it does not cover it.
bool shade(const FamilyObject& o, const Pose& q, double px, double py, std::array<double, 4>& color) {
    const double dx = px - q.cx, dy = py - q.cy;
    // Into the object's own frame: rotate back by the angle, divide by the scale.
    const double lx = (q.cosA * dx + q.sinA * dy) / q.scale, ly = (-q.sinA * dx + q.cosA * dy) / q.scale;
    if (o.shape == FamilyObject::Shape::Rect && (std::fabs(lx) >= o.halfSize[0] || std::fabs(ly) >= o.halfSize[1])) return false;
    if (o.shape == FamilyObject::Shape::Disc && lx * lx + ly * ly >= o.halfSize[0] * o.halfSize[0]) return false;
    bool b = false;
    if (o.texture == FamilyObject::Texture::Checker) b = ((long(std::floor(lx / o.cell)) + long(std::floor(ly / o.cell))) & 1) != 0;
    if (o.texture == FamilyObject::Texture::Stripes) b = (long(std::floor(lx / o.cell)) & 1) != 0;
    color = b ? o.colorB : o.colorA;
    return true;
}

std::array<double, 4> grey(double v) { return {v, v, v, 1}; }
std::array<double, 4> hue(Draw& d) { return {d(0.15, 0.95), d(0.15, 0.95), d(0.15, 0.95), 1}; }

FamilyObject background(FamilyObject::Texture texture, double cell, uint32_t w, uint32_t h) {
    FamilyObject bg;
    bg.shape = FamilyObject::Shape::Plane, bg.texture = texture, bg.cell = cell, bg.depth = 50;
    bg.centre = {w * 0.5, h * 0.5}, bg.colorA = {0.25, 0.35, 0.45, 1}, bg.colorB = {0.75, 0.7, 0.6, 1};
    return bg;
}

// A direction of unit length drawn from the seed.
std::array<double, 2> direction(Draw& d) {
    const double a = d(0, 6.283185307179586);
    return {std::cos(a), std::sin(a)};
}

}  // namespace

SceneFrame FamilyScene::render(double t) const {
    SceneFrame f;
    f.color = ColorGrid(width, height, {0, 0, 0, 1});
    f.depth = Grid(width, height, 1.0e4);
    f.velocity = VelocityGrid(width, height);
    f.layer.assign(size_t(width) * height, -1);
    std::vector<Pose> poses;
    for (const FamilyObject& o : objects) poses.push_back(poseAt(o, t));
    for (uint32_t y = 0; y < height; ++y)
        for (uint32_t x = 0; x < width; ++x) {
            const double px = x + 0.5, py = y + 0.5;
            for (size_t i = 0; i < objects.size(); ++i) {
                const FamilyObject& o = objects[i];
                std::array<double, 4> c;
                if (o.depth >= f.depth.at(x, y) || !shade(o, poses[i], px, py, c)) continue;
                f.color.at(x, y) = c;
                f.depth.at(x, y) = o.depth;
                // d/dt of the point's position: translation + growth and spin about the centre.
                const double rx = px - poses[i].cx, ry = py - poses[i].cy;
                f.velocity.at(x, y) = {o.velocityPx[0] + o.growth * rx - o.spinRad * ry, o.velocityPx[1] + o.growth * ry + o.spinRad * rx};
                f.layer[size_t(y) * width + x] = int(i);
            }
        }
    return f;
}

ColorGrid FamilyScene::truth(uint32_t instants) const {
    return reference::shutterAverage(width, height, instants, [this](double t) { return render(t); });
}

FamilyMasks familyMasks(const FamilyScene& scene, uint32_t instants) {
    const size_t n = size_t(scene.width) * scene.height;
    FamilyMasks m{std::vector<bool>(n, false), std::vector<bool>(n, false), std::vector<bool>(n, false)};
    std::vector<int> first;
    for (uint32_t i = 0; i < instants; ++i) {
        const SceneFrame f = scene.render((i + 0.5) / instants - 0.5);
        if (i == 0) first = f.layer;
        for (size_t p = 0; p < n; ++p) {
            const int l = f.layer[p];
            if ((l >= 0 && moves(scene.objects[size_t(l)])) || l != first[p]) m.moving[p] = true;
            if (i + 1 < instants || l == first[p] || l < 0 || first[p] < 0) continue;
            const bool closerAtClose = scene.objects[size_t(l)].depth < scene.objects[size_t(first[p])].depth;
            (closerAtClose ? m.leading : m.trailing)[p] = true;
        }
    }
    return m;
}

std::vector<std::string> familyNames() { return {"sizes", "crossing", "thin", "rotating", "approach", "square"}; }
bool familyHeldOut(const std::string& family) { return family != "sizes" && family != "crossing"; }

FamilyCase makeFamilyCase(const std::string& family, double speedPx, uint32_t seed, uint32_t w, uint32_t h) {
    using Shape = FamilyObject::Shape;
    using Texture = FamilyObject::Texture;
    Draw d(seed * 7919u + uint32_t(family.size()) * 104729u + uint32_t(speedPx * 16));
    FamilyCase c{family, familyHeldOut(family), speedPx, {w, h, {}}, {}};
    std::vector<FamilyObject>& obj = c.scene.objects;
    const double s = h / 240.0;  // layouts are designed at 320 x 240
    if (family == "sizes") {
        // Objects of three sizes and three textures, each moving at the speed in its own direction.
        obj.push_back(background(Texture::Checker, d(6, 14) * s, w, h));
        const double radii[] = {5 * s, 18 * s, 42 * s};
        const Texture tex[] = {Texture::Flat, Texture::Stripes, Texture::Checker};
        for (int i = 0; i < 3; ++i) {
            FamilyObject o;
            o.shape = d(0, 1) < 0.5 ? Shape::Disc : Shape::Rect, o.texture = tex[i], o.cell = d(3, 8) * s;
            o.halfSize = {radii[i], radii[i] * d(0.6, 1.0)};
            o.centre = {d(0.2, 0.8) * w, d(0.25, 0.75) * h}, o.depth = 5 + i, o.colorA = hue(d), o.colorB = hue(d);
            const auto dir = direction(d);
            o.velocityPx = {dir[0] * speedPx, dir[1] * speedPx};
            obj.push_back(o);
        }
    } else if (family == "crossing") {
        // Two objects passing each other at different depths, overlapping at mid-shutter.
        obj.push_back(background(Texture::Stripes, d(5, 10) * s, w, h));
        const double cy = d(0.4, 0.6) * h, cx = d(0.4, 0.6) * w;
        for (int i = 0; i < 2; ++i) {
            FamilyObject o;
            o.shape = i == 0 ? Shape::Disc : Shape::Rect, o.texture = i == 0 ? Texture::Flat : Texture::Checker, o.cell = d(4, 8) * s;
            o.halfSize = {d(25, 40) * s, d(20, 35) * s}, o.depth = i == 0 ? 6 : 12, o.colorA = hue(d), o.colorB = hue(d);
            o.centre = {cx + (i == 0 ? -12 : 12) * s, cy + (i == 0 ? -8 : 8) * s};
            const double dy = d(-0.3, 0.3);
            o.velocityPx = {(i == 0 ? 1 : -1) * speedPx, dy * speedPx};
            obj.push_back(o);
        }
    } else if (family == "thin") {
        // Posts (vertical, 1-2 px wide) moving sideways and wires (horizontal) moving up or down.
        obj.push_back(background(Texture::Checker, d(5, 9) * s, w, h));
        for (int i = 0; i < 5; ++i) {
            FamilyObject o;
            const bool post = i < 3;
            const double thick = d(0, 1) < 0.5 ? 0.5 : 1.0;  // half width: 1 or 2 px
            o.halfSize = post ? std::array<double, 2>{thick, d(0.25, 0.4) * h} : std::array<double, 2>{d(0.25, 0.4) * w, thick};
            o.centre = {d(0.25, 0.75) * w, d(0.3, 0.7) * h}, o.depth = 4 + i, o.colorA = i % 2 ? grey(0.95) : grey(0.05);
            const double sign = d(0, 1) < 0.5 ? -1 : 1;
            o.velocityPx = post ? std::array<double, 2>{sign * speedPx, 0} : std::array<double, 2>{0, sign * speedPx};
            obj.push_back(o);
        }
    } else if (family == "rotating") {
        // A striped disc and a checkered bar turning about their centres; their rims move at the speed.
        obj.push_back(background(Texture::Checker, d(6, 12) * s, w, h));
        FamilyObject disc;
        disc.shape = Shape::Disc, disc.texture = Texture::Stripes, disc.cell = d(4, 8) * s, disc.halfSize = {d(35, 50) * s, 0};
        disc.centre = {d(0.25, 0.4) * w, d(0.4, 0.6) * h}, disc.depth = 8, disc.colorA = hue(d), disc.colorB = hue(d);
        disc.spinRad = speedPx / disc.halfSize[0];
        FamilyObject bar;
        bar.shape = Shape::Rect, bar.texture = Texture::Checker, bar.cell = d(4, 7) * s, bar.halfSize = {d(40, 55) * s, d(5, 9) * s};
        bar.centre = {d(0.6, 0.75) * w, d(0.4, 0.6) * h}, bar.depth = 6, bar.colorA = hue(d), bar.colorB = hue(d);
        bar.spinRad = (d(0, 1) < 0.5 ? -1 : 1) * speedPx / bar.halfSize[0];
        obj.push_back(disc), obj.push_back(bar);
    } else if (family == "approach") {
        // Objects coming toward the camera: they grow about their centres, their rims moving
        // outward at the speed.
        obj.push_back(background(Texture::Stripes, d(5, 9) * s, w, h));
        for (int i = 0; i < 2; ++i) {
            FamilyObject o;
            o.shape = i == 0 ? Shape::Disc : Shape::Rect, o.texture = i == 0 ? Texture::Checker : Texture::Stripes, o.cell = d(4, 8) * s;
            o.halfSize = {d(25, 45) * s, d(20, 40) * s};
            o.centre = {(i == 0 ? d(0.25, 0.4) : d(0.6, 0.75)) * w, d(0.4, 0.6) * h}, o.depth = 6 + 3 * i, o.colorA = hue(d), o.colorB = hue(d);
            o.growth = speedPx / std::max(o.halfSize[0], o.halfSize[1]);
            obj.push_back(o);
        }
    } else {
        // The independent scene: a checkered square moving right over static vertical stripes.
        // Layout 1 is the scene as it was given: the square centred, its edges on stripe
        // boundaries at mid-shutter, so the stripe a moving edge hides is never the one beside it.
        // Other layouts shift the square by up to one period of the stripes (two stripes), so
        // its edges meet the stripes at every phase.
        obj.push_back(background(Texture::Stripes, 4 * s, w, h));
        obj[0].colorA = grey(0.1), obj[0].colorB = grey(0.9);
        FamilyObject sq;
        sq.texture = Texture::Checker, sq.cell = 8 * s, sq.halfSize = {32 * s, 32 * s}, sq.depth = 5;
        const double shift = seed == 1 ? 0.0 : d(0, 8) * s;
        sq.centre = {w * 0.5 + shift, h * 0.5}, sq.colorA = {0.9, 0.2, 0.2, 1}, sq.colorB = {0.2, 0.2, 0.9, 1}, sq.velocityPx = {speedPx, 0};
        obj.push_back(sq);
        c.rowsMask.assign(size_t(w) * h, false);
        for (uint32_t y = 0; y < h; ++y)
            if (std::fabs(y + 0.5 - sq.centre[1]) < sq.halfSize[1])
                for (uint32_t x = 0; x < w; ++x) c.rowsMask[size_t(y) * w + x] = true;
    }
    return c;
}

}  // namespace sfx::tools
