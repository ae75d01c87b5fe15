// Ambient occlusion through layers (the OIT AO and multilayer AO references) on small ray-cast
// scenes in view space: a translucent wall beside an opaque floor (occlusion monotone in the
// wall's opacity, opacity 0 equal to no wall, opacity 1 equal to an opaque wall), consistency
// with the single-layer reference, and multilayer AO recovering occlusion hidden behind a
// foreground object.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "sfx/reference/ao_reference.hpp"
#include "sfx/reference/oit_reference.hpp"
#include "sfx_shared_oit.h"

using namespace sfx;
using namespace sfx::reference;
using glm::dvec3;

namespace {

constexpr uint32_t kW = 64, kH = 40;

// An axis-aligned rectangle in view space (camera at the origin looking down -z): the plane
// coordinate[axis] = at, bounded on the other two axes.
struct Rect {
    int axis;
    double at;
    dvec3 lo, hi;      // bounds (the axis' own entries ignored)
    dvec3 normal;      // authored (outward) normal
    double alpha = 1;  // 1 and opaque: an opaque surface
    bool opaque = true;
};

struct Hit {
    double depth;
    const Rect* rect;
};

DepthReconstruction reconstruction() {
    PerspectiveDesc pd;
    pd.aspect = double(kW) / kH;
    pd.nearPlane = 0.1;
    pd.farPlane = 100.0;
    return makeDepthReconstruction(makePerspective(pd).value(), kW, kH).value();
}

// Every hit of the ray through pixel (x, y)'s centre, nearest first. A point at linear depth t
// on that ray is reconstructViewPosition(centre, t), so t is the hit's linear depth.
std::vector<Hit> castAll(const DepthReconstruction& rec, const std::vector<Rect>& rects, uint32_t x, uint32_t y) {
    const shared::dvec3 r = shared::reconstructViewPosition(x + 0.5, y + 0.5, 1.0, rec.projInfo);
    const dvec3 d(r.x, r.y, r.z);
    std::vector<Hit> hits;
    for (const Rect& s : rects) {
        if (d[s.axis] == 0.0) continue;
        const double t = s.at / d[s.axis];
        if (!(t > 0.0)) continue;
        const dvec3 p = t * d;
        bool inside = true;
        for (int a = 0; a < 3; ++a)
            if (a != s.axis && (p[a] < s.lo[a] || p[a] > s.hi[a])) inside = false;
        if (inside) hits.push_back({t, &s});
    }
    std::sort(hits.begin(), hits.end(), [](const Hit& a, const Hit& b) { return a.depth < b.depth; });
    return hits;
}

// The fragment picture: the nearest opaque hit is the opaque surface, translucent hits in front
// of it are fragments (the normal kept as authored, facing from the view direction).
FragmentImage render(const std::vector<Rect>& rects) {
    const DepthReconstruction rec = reconstruction();
    FragmentImage img(kW, kH, rec);
    for (uint32_t y = 0; y < kH; ++y)
        for (uint32_t x = 0; x < kW; ++x) {
            const size_t i = img.index(x, y);
            uint32_t draw = 0;
            for (const Hit& h : castAll(rec, rects, x, y)) {
                const shared::dvec3 r = shared::reconstructViewPosition(x + 0.5, y + 0.5, 1.0, rec.projInfo);
                const bool front = glm::dot(h.rect->normal, dvec3(r.x, r.y, r.z)) < 0.0;
                if (h.rect->opaque) {
                    img.opaque[i].depth = h.depth;
                    img.opaque[i].normal = front ? h.rect->normal : -h.rect->normal;
                    break;
                }
                OitFragment f;
                f.alpha = h.rect->alpha;
                f.depth = h.depth;
                f.normal = h.rect->normal;
                f.frontFacing = front;
                f.drawIndex = draw++;
                img.fragments[i].push_back(f);
            }
        }
    return img;
}

const Rect kFloor{1, -1.0, {-20, 0, -40}, {20, 0, -0.5}, {0, 1, 0}};
// A wall facing the camera's left (normal -x) standing on the floor, right of the centre.
Rect wall(double alpha, bool opaque) { return Rect{0, 0.6, {0, -1.0, -7.0}, {0, 0.4, -2.0}, {-1, 0, 0}, alpha, opaque}; }

AoConfig aoConfig(AoTechnique t) {
    AoConfig c;
    c.technique = t;
    c.radius = 1.0;
    c.samples = 12;
    c.intensity = t == AoTechnique::Scalable ? 2.0 : 1.0;
    c.bias = 0.01;
    return c;
}

}  // namespace

TEST_CASE("oit ao: with no translucent fragment it is the single-layer reference", "[oit][ao]") {
    const FragmentImage img = render({kFloor, wall(1.0, true)});
    AoInput in;
    in.reconstruction = img.reconstruction;
    in.linearDepth = Grid(kW, kH, img.reconstruction.maxDepth);
    in.normals.assign(size_t(kW) * kH, dvec3(0, 0, 1));
    for (size_t i = 0; i < img.opaque.size(); ++i)
        if (img.opaque[i].depth < img.reconstruction.maxDepth) {
            in.linearDepth.values[i] = img.opaque[i].depth;
            in.normals[i] = img.opaque[i].normal;
        }
    DepthLayers single;
    single.width = kW;
    single.height = kH;
    single.reconstruction = img.reconstruction;
    single.normals = in.normals;
    single.depths.resize(img.opaque.size());
    for (size_t i = 0; i < img.opaque.size(); ++i)
        if (img.opaque[i].depth < img.reconstruction.maxDepth) single.depths[i] = {img.opaque[i].depth};
    for (AoTechnique t : {AoTechnique::Alchemy, AoTechnique::Scalable}) {
        OitAoConfig oc;
        oc.ao = aoConfig(t);
        const Grid ref = rawVisibility(in, oc.ao);
        const OitAoResult r = opacityAmbientOcclusion(img, oc).value();
        const Grid ml = multilayerVisibility(single, oc.ao);
        double darkest = 1.0;
        for (size_t i = 0; i < ref.values.size(); ++i) {
            REQUIRE(r.blended.values[i] == Approx(ref.values[i]).margin(1e-12));
            REQUIRE(ml.values[i] == Approx(ref.values[i]).margin(1e-12));
            darkest = std::min(darkest, ref.values[i]);
        }
        CHECK(darkest < 0.9);  // the wall's contact with the floor is occluded at all
    }
    OitAoConfig crease;
    crease.ao.technique = AoTechnique::Crease;
    const Result<OitAoResult> bad = opacityAmbientOcclusion(img, crease);
    REQUIRE_FALSE(bad.isOk());
    CHECK(bad.status().message().find("OitAoConfig.ao.technique") != std::string::npos);
}

TEST_CASE("oit ao: a floor beside a translucent wall, monotone in the wall's opacity", "[oit][ao]") {
    const FragmentImage noWall = render({kFloor});
    const FragmentImage opaqueWall = render({kFloor, wall(1.0, true)});
    for (AoTechnique t : {AoTechnique::Alchemy, AoTechnique::Scalable})
        for (OitAoOccluders occ : {OitAoOccluders::BruteForce, OitAoOccluders::Compressed}) {
            INFO(toString(t) << (occ == OitAoOccluders::Compressed ? " compressed" : " brute force"));
            OitAoConfig oc;
            oc.ao = aoConfig(t);
            oc.occluders = occ;
            oc.compression.zNear = 0.1;
            oc.compression.zFar = 100.0;
            const Grid none = opacityAmbientOcclusion(noWall, oc).value().blended;
            const Grid solid = opacityAmbientOcclusion(opaqueWall, oc).value().blended;
            std::vector<Grid> byAlpha;
            for (double a : {0.0, 0.25, 0.5, 0.75, 1.0})
                byAlpha.push_back(opacityAmbientOcclusion(render({kFloor, wall(a, false)}), oc).value().blended);
            // The floor pixels the wall does not cover receive the same way in every scene.
            double largestStep = 0.0;
            size_t floorPixels = 0;
            for (uint32_t y = 0; y < kH; ++y)
                for (uint32_t x = 0; x < kW; ++x) {
                    const size_t i = noWall.index(x, y);
                    if (opaqueWall.opaque[i].depth != noWall.opaque[i].depth || !(noWall.opaque[i].depth < noWall.reconstruction.maxDepth)) continue;
                    ++floorPixels;
                    REQUIRE(byAlpha[0].values[i] == none.values[i]);
                    for (size_t k = 1; k < byAlpha.size(); ++k) REQUIRE(byAlpha[k].values[i] <= byAlpha[k - 1].values[i] + 1e-12);
                    if (occ == OitAoOccluders::BruteForce) REQUIRE(byAlpha.back().values[i] == Approx(solid.values[i]).margin(1e-12));
                    largestStep = std::max(largestStep, byAlpha[0].values[i] - byAlpha.back().values[i]);
                }
            CHECK(floorPixels > 200);
            CHECK(largestStep > 0.1);  // the wall does shadow the floor beside it
        }
}

TEST_CASE("oit ao: W weighs the hemispheres, each occluder counts by its opacity", "[oit][ao]") {
    CHECK(shared::oitExteriorWeight(0.3, true) == 0.3);
    CHECK(shared::oitExteriorWeight(0.3, false) == Approx(0.7));
    CHECK(shared::oitOpacityOcclusion(0.8, 0.2, 0.25, 0.5) == Approx(0.5 * (0.25 * 0.8 + 0.75 * 0.2)));
    // A tap straight along the normal is all exterior; along -n all interior.
    const double ext = shared::oitAlchemyOcclusion(0.25, 0.5, 1.0, 1.0, 0.0, 1e-4, 1.0, 1.0);
    CHECK(ext > 0.0);
    CHECK(shared::oitAlchemyOcclusion(0.25, 0.5, 1.0, 1.0, 0.0, 1e-4, 0.0, 1.0) == 0.0);
    CHECK(shared::oitAlchemyOcclusion(0.25, -0.5, 1.0, 1.0, 0.0, 1e-4, 0.0, 1.0) == Approx(ext));
    CHECK(shared::oitScalableOcclusion(0.25, -0.5, 1.0, 0.0, 1e-4, 0.4, 0.5) ==
          Approx(0.5 * 0.6 * shared::aoScalableTerm(0.25, 0.5, 1.0, 0.0, 1e-4)));
}

TEST_CASE("oit ao: a translucent receiver's AO is blended after the sort like colour", "[oit][ao]") {
    // A translucent quad facing the camera above the floor: its fragments see the floor below
    // through the interior hemisphere as much as 1 - alpha allows.
    const Rect pane{2, -3.0, {-0.8, -0.95, 0}, {0.8, 0.2, 0}, {0, 0, 1}, 0.5, false};
    OitAoConfig oc;
    oc.ao = aoConfig(AoTechnique::Alchemy);
    const FragmentImage img = render({kFloor, pane});
    const OitAoResult r = opacityAmbientOcclusion(img, oc).value();
    bool seen = false;
    for (size_t i = 0; i < img.fragments.size(); ++i) {
        REQUIRE(r.perFragment[i].size() == img.fragments[i].size());
        for (double v : r.perFragment[i]) {
            REQUIRE(v >= 0.0);
            REQUIRE(v <= 1.0);
        }
        if (!r.perFragment[i].empty()) {
            seen = true;
            const double a = img.fragments[i][0].alpha;
            // Blended after the sort: alpha * own + (1 - alpha) * the floor's.
            REQUIRE(r.blended.values[i] == Approx(a * r.perFragment[i][0] + (1 - a) * r.opaque.values[i]).margin(1e-12));
        }
    }
    CHECK(seen);
}

TEST_CASE("multilayer ao recovers occlusion hidden behind a foreground object", "[oit][ao][multilayer]") {
    // A wall standing on the floor far away, and a floating bar near the camera hiding their
    // contact line (its lower edge just below it): the floor in front of the contact stays
    // visible, and single-layer taps that land on the bar see only the bar.
    const Rect backWall{2, -6.0, {-3, -1, 0}, {3, 1.5, 0}, {0, 0, 1}};
    const Rect bar{2, -2.5, {-3, -0.425, 0}, {3, 0.3, 0}, {0, 0, 1}};
    const std::vector<Rect> scene = {kFloor, backWall, bar};
    const DepthReconstruction rec = reconstruction();
    DepthLayers single, multi;
    for (DepthLayers* l : {&single, &multi}) {
        l->width = kW;
        l->height = kH;
        l->reconstruction = rec;
        l->depths.resize(size_t(kW) * kH);
        l->normals.assign(size_t(kW) * kH, dvec3(0, 0, 1));
    }
    for (uint32_t y = 0; y < kH; ++y)
        for (uint32_t x = 0; x < kW; ++x) {
            const std::vector<Hit> hits = castAll(rec, scene, x, y);
            const size_t i = size_t(y) * kW + x;
            if (hits.empty()) continue;
            single.normals[i] = multi.normals[i] = hits[0].rect->normal;
            single.depths[i] = {hits[0].depth};
            for (size_t k = 0; k < hits.size() && k < 4; ++k) multi.depths[i].push_back(hits[k].depth);
        }
    for (AoTechnique t : {AoTechnique::Alchemy, AoTechnique::Scalable}) {
        INFO(toString(t));
        const AoConfig c = aoConfig(t);
        const Grid one = multilayerVisibility(single, c), four = multilayerVisibility(multi, c);
        double recovered = 0.0;
        for (size_t i = 0; i < one.values.size(); ++i) {
            REQUIRE(four.values[i] <= one.values[i] + 1e-12);  // never less occlusion
            recovered = std::max(recovered, one.values[i] - four.values[i]);
        }
        double darkest = 1.0;
        for (double v : four.values) darkest = std::min(darkest, v);
        // ... and more where the bar hid the contact: a clear share of the picture's strongest
        // occlusion (Scalable's squared sum makes its occlusion weak here, about 0.04 at most).
        INFO("recovered " << recovered << ", darkest " << darkest);
        CHECK(darkest < 0.99);
        CHECK(recovered > 0.05 * (1.0 - darkest));
    }
}
