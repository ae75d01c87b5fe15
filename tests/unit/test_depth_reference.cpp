// CPU reference of depth linearisation and the depth pyramid, against closed forms.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "depth_conventions.hpp"
#include "sfx/camera.hpp"
#include "sfx/reference/depth_reference.hpp"
#include "sfx_shared.h"

using namespace sfx;

TEST_CASE("linearisation inverts the projection for every depth convention", "[depth]") {
    for (const test::DepthConvention& c : test::kDepthConventions) {
        INFO(c.name);
        PerspectiveDesc pd;
        pd.nearPlane = 0.1;
        pd.farPlane = c.farPlane;
        pd.reversedZ = c.reversed;
        pd.clipDepth = c.clip;
        CameraProjection cam = makePerspective(pd).value();
        DepthReconstruction rec = makeDepthReconstruction(cam, 8, 8).value();
        CHECK(rec.reversedZ == c.reversed);
        CHECK(rec.nearDepth == Approx(0.1).epsilon(1e-12));
        if (std::isinf(c.farPlane))
            CHECK(rec.maxDepth == double(shared::SFX_SKY_DEPTH));
        else
            CHECK(rec.maxDepth == Approx(100.0).epsilon(1e-9));
        reference::Grid stored(4, 1);
        const double depths[4] = {0.1, 1.0, 37.0, 99.0};
        for (uint32_t i = 0; i < 4; ++i) stored.at(i, 0) = storedDepthFromLinear(cam, depths[i]);
        reference::Grid linear = reference::linearizeDepth(stored, rec);
        for (uint32_t i = 0; i < 4; ++i) CHECK(linear.at(i, 0) == Approx(depths[i]).epsilon(1e-9));
        // The far end of the stored range is the far plane, or sky for an infinite projection.
        reference::Grid farStored(1, 1, c.reversed ? 0.0 : 1.0);
        CHECK(reference::linearizeDepth(farStored, rec).at(0, 0) == Approx(rec.maxDepth));
    }
}

TEST_CASE("position reconstruction matches the projection", "[depth]") {
    PerspectiveDesc pd;
    pd.aspect = 2.0;
    pd.rowZeroIsTop = true;
    CameraProjection cam = makePerspective(pd).value();
    // A jittered (off-centre) projection reconstructs too.
    cam.projection[2][0] = 0.01;
    cam.projection[2][1] = -0.02;
    const uint32_t W = 200, H = 100;
    DepthReconstruction rec = makeDepthReconstruction(cam, W, H).value();
    const glm::dvec4 view(0.7, -0.4, -3.0, 1.0);
    const glm::dvec4 clip = cam.projection * view;
    const double ndcX = clip.x / clip.w, ndcY = clip.y / clip.w;
    const double pcx = (ndcX + 1.0) * 0.5 * W, pcy = (ndcY + 1.0) * 0.5 * H;
    const shared::dvec3 p = shared::reconstructViewPosition(pcx, pcy, 3.0, rec.projInfo);
    CHECK(p.x == Approx(0.7).epsilon(1e-12));
    CHECK(p.y == Approx(-0.4).epsilon(1e-12));
    CHECK(p.z == Approx(-3.0));
    // rowZeroIsTop: a point above the axis lands in the upper half (small row numbers).
    const glm::dvec4 up = cam.projection * glm::dvec4(0, 1, -3, 1);
    CHECK((up.y / up.w + 1.0) * 0.5 * H < H / 2.0);
}

TEST_CASE("depth pyramid is the rotated-grid subsample, not an average", "[depth]") {
    reference::Grid level0(7, 5);
    for (uint32_t y = 0; y < 5; ++y)
        for (uint32_t x = 0; x < 7; ++x) level0.at(x, y) = 100.0 * y + x;
    std::vector<reference::Grid> p = reference::depthPyramid(level0, 3);
    REQUIRE(p.size() == 3);
    CHECK(p[1].width == 3);
    CHECK(p[1].height == 2);
    // texel (x, y) of level 1 = texel (2x + (y & 1), 2y + (x & 1)) of level 0
    CHECK(p[1].at(0, 0) == level0.at(0, 0));
    CHECK(p[1].at(1, 0) == level0.at(2, 1));
    CHECK(p[1].at(0, 1) == level0.at(1, 2));
    CHECK(p[1].at(2, 1) == level0.at(5, 2));
    CHECK(p[2].width == 1);
    CHECK(p[2].at(0, 0) == p[1].at(0, 0));
    // Every value of every level exists in level 0: nothing is invented.
    for (const auto& level : p)
        for (double v : level.values) CHECK(std::find(level0.values.begin(), level0.values.end(), v) != level0.values.end());
}

TEST_CASE("camera: bad projections and sizes are named errors", "[depth][bad-input]") {
    CameraProjection identity;  // orthographic-like identity is not a perspective projection
    Result<DepthReconstruction> r = makeDepthReconstruction(identity, 8, 8);
    CHECK(r.status().code() == StatusCode::InvalidArgument);
    CHECK(r.status().message().find("CameraProjection.projection") != std::string::npos);
    CameraProjection ok = makePerspective({}).value();
    CHECK(makeDepthReconstruction(ok, 0, 8).status().code() == StatusCode::InvalidArgument);
    ok.projection[0][0] = std::nan("");
    CHECK(makeDepthReconstruction(ok, 8, 8).status().code() == StatusCode::InvalidArgument);
    PerspectiveDesc bad;
    bad.nearPlane = 0.0;
    CHECK(makePerspective(bad).status().message().find("PerspectiveDesc.nearPlane") != std::string::npos);
    bad = {};
    bad.farPlane = 0.05;
    CHECK(makePerspective(bad).status().message().find("PerspectiveDesc.farPlane") != std::string::npos);
    bad = {};
    bad.fovYRadians = 4.0;
    CHECK(makePerspective(bad).status().code() == StatusCode::InvalidArgument);
}
