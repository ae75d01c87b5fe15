// Depth linearisation and the depth MIP pyramid on the device under test, against the CPU
// reference. Tolerances are documented in docs/conformance.md.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

#include "depth_conventions.hpp"
#include "scene.hpp"
#include "sfx/depth.hpp"
#include "sfx/null_device.hpp"
#include "sfx/reference/depth_reference.hpp"
#include "sfx/tiers.hpp"
#include "sfx_shared.h"
#include "test_device.hpp"

using namespace sfx;

namespace {

// The GPU evaluates z = B / (d*s + c) in 32-bit float from the same float d the reference
// reads. Its relative error is bounded by the conditioning of the denominator:
//   |dz| / z <= eps * (2 * (|d*s| + |c|) / |d*s + c| + 1)
// (2 half-ulps for the multiply-add, 2 for rounding the constants s and c to float, relative
// to the operands' size; 1 ulp for the divide and the stored result). Only for a finite
// reference (a non-zero denominator); where it is not, see isSky.
double linearizeTolerance(double stored, const DepthReconstruction& r, double z) {
    const double eps = std::ldexp(1.0, -23);
    const double ds = stored * r.ndcScale;
    const double denom = std::abs(ds + r.denomOffset);
    REQUIRE(denom > 0.0);
    const double condition = (std::abs(ds) + std::abs(r.denomOffset)) / denom;
    return z * eps * (2.0 * condition + 1.0);
}

// Where the exact depth B / (d*s + c) is infinite or not positive (the far plane of an infinite
// projection, a cleared buffer, a depth past it), no tolerance is meaningful: the reference
// reports sky (maxDepth, sfxLinearDepthOrFar) and the GPU must report exactly the same float.
bool isSky(double stored, const DepthReconstruction& r) {
    const double denom = stored * r.ndcScale + r.denomOffset;
    return denom == 0.0 || !(r.numerator / denom > 0.0);
}

// The GPU's linear depth `have` against the reference `want` for one stored depth: sky exactly,
// anything else within linearizeTolerance. Returns |error| / tolerance (0 for sky).
double requireLinearMatches(double stored, const DepthReconstruction& r, double want, double have) {
    INFO("stored " << stored << " want " << want << " got " << have);
    REQUIRE(std::isfinite(have));
    if (isSky(stored, r)) {
        REQUIRE(want == r.maxDepth);
        REQUIRE(have == float(r.maxDepth));
        return 0.0;
    }
    const double tol = linearizeTolerance(stored, r, want);
    INFO("tolerance " << tol);
    REQUIRE(std::abs(have - want) <= tol);
    return std::abs(have - want) / tol;
}

std::vector<float> readLevel(Device& device, TextureHandle texture, uint32_t w, uint32_t h, uint32_t mip) {
    std::vector<float> values(size_t(mipExtent(w, mip)) * mipExtent(h, mip));
    const Status s = device.readTexture(texture, mip, values.data(), values.size() * sizeof(float));
    INFO(s.toString());
    REQUIRE(s.isOk());
    return values;
}

uint32_t levelsFor(Tier tier) { return tiers::profile(tier).aoDepthMipLevels; }

}  // namespace

TEST_CASE("linear depth matches the reference for every depth convention", "[depth][conformance]") {
    Device& device = test::device();
    const uint32_t W = 61, H = 37;  // odd sizes exercise the pyramid's edge texels
    for (const test::DepthConvention& c : test::kDepthConventions) {
        INFO(test::label() << " " << c.name);
        PerspectiveDesc pd;
        pd.nearPlane = 0.1;
        pd.farPlane = c.farPlane;
        pd.reversedZ = c.reversed;
        pd.clipDepth = c.clip;
        pd.aspect = double(W) / H;
        CameraProjection cam = makePerspective(pd).value();
        DepthReconstruction rec = makeDepthReconstruction(cam, W, H).value();

        // Depths spread geometrically from the near plane to past the far plane, plus sky texels.
        reference::Grid stored(W, H);
        std::vector<float> storedFloats(size_t(W) * H);
        for (uint32_t y = 0; y < H; ++y)
            for (uint32_t x = 0; x < W; ++x) {
                const double u = double(y * W + x) / double(W * H - 1);
                double z = 0.1 * std::pow(1000.0, u);  // 0.1 .. 100
                double d = storedDepthFromLinear(cam, std::min(z, 99.9));
                if ((x * 7 + y * 3) % 23 == 0) d = c.reversed ? 0.0 : 1.0;  // cleared depth: far / sky
                storedFloats[size_t(y) * W + x] = float(std::clamp(d, 0.0, 1.0));
                stored.at(x, y) = double(storedFloats[size_t(y) * W + x]);
            }
        reference::Grid expected = reference::linearizeDepth(stored, rec);

        Result<TextureHandle> src = device.createTexture({W, H, 1, Format::R32F, kTextureSampled, "test-stored-depth"});
        REQUIRE(src.isOk());
        SFX_REQUIRE_OK(device.writeTexture(src.value(), 0, storedFloats.data(), storedFloats.size() * sizeof(float)));
        auto linear = LinearDepth::create(device, {W, H, test::tier(), levelsFor(test::tier())});
        INFO(linear.status().toString());
        REQUIRE(linear.isOk());
        SFX_REQUIRE_OK(linear.value()->dispatch({src.value(), DepthKind::Hardware, cam}));
        std::vector<float> got = readLevel(device, linear.value()->texture(), W, H, 0);

        double worstRatio = 0;
        for (uint32_t y = 0; y < H; ++y)
            for (uint32_t x = 0; x < W; ++x) {
                INFO("texel (" << x << ", " << y << ")");
                worstRatio = std::max(worstRatio, requireLinearMatches(stored.at(x, y), rec, expected.at(x, y), got[size_t(y) * W + x]));
            }
        // Print how close to the bound the device came, so the tolerance stays honest.
        WARN(test::label() << " " << c.name << ": worst error / tolerance = " << worstRatio);
        (void)device.destroyTexture(src.value());
    }
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("depth pyramid levels are exact rotated-grid subsamples", "[depth][conformance]") {
    if (test::tier() != Tier::High) {
        // The current tier has no pyramid; asking for one is a named error (checked, not skipped).
        auto refused = LinearDepth::create(test::device(), {64, 64, Tier::Current, 2});
        CHECK(refused.status().code() == StatusCode::InvalidArgument);
        CHECK(refused.status().message().find("current tier") != std::string::npos);
        return;
    }
    Device& device = test::device();
    for (auto [W, H] : {std::pair<uint32_t, uint32_t>{61, 37}, {64, 32}, {17, 90}, {96, 360}}) {
        INFO(test::label() << " " << W << "x" << H);
        std::vector<float> linear(size_t(W) * H);
        for (size_t i = 0; i < linear.size(); ++i) linear[i] = 1.0f + float((i * 7919) % 1000) * 0.01f;
        Result<TextureHandle> src = device.createTexture({W, H, 1, Format::R32F, kTextureSampled});
        REQUIRE(src.isOk());
        SFX_REQUIRE_OK(device.writeTexture(src.value(), 0, linear.data(), linear.size() * 4));
        PerspectiveDesc pd;
        pd.aspect = double(W) / H;
        const uint32_t levels = std::min(levelsFor(Tier::High), maxMipLevels(W, H));
        auto depth = LinearDepth::create(device, {W, H, Tier::High, levels});
        REQUIRE(depth.isOk());
        SFX_REQUIRE_OK(depth.value()->dispatch({src.value(), DepthKind::Linear, makePerspective(pd).value()}));
        // Level 0 is the input (linear input is copied), every further level an exact subsample.
        std::vector<float> level0 = readLevel(device, depth.value()->texture(), W, H, 0);
        CHECK(level0 == linear);
        reference::Grid g0(W, H);
        for (size_t i = 0; i < linear.size(); ++i) g0.values[i] = level0[i];
        std::vector<reference::Grid> expected = reference::depthPyramid(g0, levels);
        for (uint32_t m = 1; m < levels; ++m) {
            std::vector<float> got = readLevel(device, depth.value()->texture(), W, H, m);
            REQUIRE(got.size() == expected[m].values.size());
            for (size_t i = 0; i < got.size(); ++i) REQUIRE(double(got[i]) == expected[m].values[i]);
        }
        // Starting at half size (halfSizeBase) gives levels 1.. of the same pyramid, exactly, and
        // plans no full-size pass or texture.
        LinearDepthDesc halfDesc{W, H, Tier::High, levels - 1};
        halfDesc.halfSizeBase = true;
        auto half = LinearDepth::create(device, halfDesc);
        REQUIRE(half.isOk());
        SFX_REQUIRE_OK(half.value()->dispatch({src.value(), DepthKind::Linear, makePerspective(pd).value()}));
        CHECK(half.value()->sourceTexture() == src.value());
        for (uint32_t m = 0; m + 1 < levels; ++m) {
            std::vector<float> got = readLevel(device, half.value()->texture(), mipExtent(W, 1), mipExtent(H, 1), m);
            REQUIRE(got.size() == expected[m + 1].values.size());
            for (size_t i = 0; i < got.size(); ++i) REQUIRE(double(got[i]) == expected[m + 1].values[i]);
        }
        for (const PlannedPass& pass : half.value()->plan().passes) CHECK(pass.width <= mipExtent(W, 1));
        (void)device.destroyTexture(src.value());
    }
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("rasterised hardware depth linearises to the scene's distances", "[depth][conformance]") {
    Device& device = test::device();
    const uint32_t W = 96, H = 64;
    auto renderer = tools::SceneRenderer::create(device, test::tier());
    INFO(renderer.status().toString());
    REQUIRE(renderer.isOk());
    tools::RasterScene scene = tools::makeScene("contact").value();
    SFX_REQUIRE_OK(renderer.value()->load(scene));
    auto g = renderer.value()->render(scene, W, H);
    INFO(g.status().toString());
    REQUIRE(g.isOk());
    auto linear = LinearDepth::create(device, {W, H, test::tier(), 1});
    REQUIRE(linear.isOk());
    SFX_REQUIRE_OK(linear.value()->dispatch({g->depth, DepthKind::Hardware, g->camera}));

    std::vector<float> hw(size_t(W) * H);
    SFX_REQUIRE_OK(device.readTexture(g->depth, 0, hw.data(), hw.size() * 4));
    reference::Grid stored(W, H);
    for (size_t i = 0; i < hw.size(); ++i) stored.values[i] = hw[i];
    const DepthReconstruction rec = makeDepthReconstruction(g->camera, W, H).value();
    reference::Grid expected = reference::linearizeDepth(stored, rec);
    std::vector<float> got = readLevel(device, linear.value()->texture(), W, H, 0);
    size_t covered = 0;
    for (size_t i = 0; i < got.size(); ++i) {
        requireLinearMatches(stored.values[i], rec, expected.values[i], got[i]);
        covered += got[i] < rec.maxDepth ? 1 : 0;
    }
    // The floor and spheres cover most of the view; the camera is ~3 units away.
    CHECK(covered > got.size() / 2);
    const float centre = got[size_t(H / 2) * W + W / 2];
    CHECK(centre > 1.5f);
    CHECK(centre < 4.0f);
    renderer.value()->destroy(g.value());
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("LinearDepth: bad input is a named error", "[depth][bad-input]") {
    Device& device = test::device();
    const Tier tier = test::tier();
    CHECK(LinearDepth::create(device, {0, 16, tier, 1}).status().code() == StatusCode::InvalidArgument);
    CHECK(LinearDepth::create(device, {16, 16, tier, 0}).status().message().find("LinearDepthDesc.mipLevels") != std::string::npos);
    CHECK(LinearDepth::create(device, {16, 16, tier, 99}).status().code() == StatusCode::InvalidArgument);
    auto depth = LinearDepth::create(device, {16, 16, tier, 1});
    REQUIRE(depth.isOk());
    CameraProjection cam = makePerspective({}).value();

    Result<TextureHandle> wrongSize = device.createTexture({8, 8, 1, Format::R32F, kTextureSampled});
    REQUIRE(wrongSize.isOk());
    Status s = depth.value()->dispatch({wrongSize.value(), DepthKind::Hardware, cam});
    CHECK(s.code() == StatusCode::InvalidArgument);
    CHECK(s.message().find("DepthSource.texture size") != std::string::npos);

    Result<TextureHandle> rgba = device.createTexture({16, 16, 1, Format::RGBA8, kTextureSampled});
    REQUIRE(rgba.isOk());
    CHECK(depth.value()->dispatch({rgba.value(), DepthKind::Hardware, cam}).code() == StatusCode::UnsupportedFormat);
    CHECK(depth.value()->dispatch({rgba.value(), DepthKind::Linear, cam}).code() == StatusCode::UnsupportedFormat);

    Result<TextureHandle> ok = device.createTexture({16, 16, 1, Format::R32F, kTextureSampled});
    REQUIRE(ok.isOk());
    CameraProjection identity;  // not a perspective projection
    CHECK(depth.value()->dispatch({ok.value(), DepthKind::Hardware, identity}).code() == StatusCode::InvalidArgument);
    CHECK(depth.value()->dispatch({TextureHandle{}, DepthKind::Hardware, cam}).code() == StatusCode::InvalidHandle);
    (void)device.destroyTexture(ok.value());
    CHECK(depth.value()->dispatch({ok.value(), DepthKind::Hardware, cam}).code() == StatusCode::StaleHandle);
    auto other = null::createDevice();
    TextureHandle foreign = other->createTexture({16, 16, 1, Format::R32F, kTextureSampled}).value();
    CHECK(depth.value()->dispatch({foreign, DepthKind::Hardware, cam}).code() == StatusCode::ForeignHandle);
    CHECK(depth.value()->resize(0, 4).code() == StatusCode::InvalidArgument);
    SFX_REQUIRE_OK(depth.value()->resize(32, 8));
    CHECK(depth.value()->desc().width == 32);
    (void)device.destroyTexture(wrongSize.value());
    (void)device.destroyTexture(rgba.value());
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("LinearDepth plan holds only what the tier needs", "[depth][plan]") {
    Device& device = test::device();
    auto flat = LinearDepth::create(device, {64, 64, test::tier(), 1});
    REQUIRE(flat.isOk());
    EffectPlan p = flat.value()->plan();
    CHECK(p.passes.size() == 1);
    CHECK(p.bytesOf("depth") == 64 * 64 * 4 + 32);
    if (test::tier() == Tier::High) {
        auto mip = LinearDepth::create(device, {64, 64, Tier::High, 3});
        REQUIRE(mip.isOk());
        EffectPlan pm = mip.value()->plan();
        CHECK(pm.passes.size() == 3);
        CHECK(pm.bytesOf("depth") == (64 * 64 + 32 * 32 + 16 * 16) * 4 + 32);
    }
}

TEST_CASE("LinearDepth: linear input without a pyramid runs no pass and holds no texture", "[depth][plan]") {
    Device& device = test::device();
    const uint32_t W = 24, H = 12;
    auto through = LinearDepth::create(device, {W, H, test::tier(), 1, DepthKind::Linear});
    REQUIRE(through.isOk());
    CHECK(through.value()->passThrough());
    // Known before any dispatch: no pass, no texture, no uniform buffer.
    const EffectPlan p = through.value()->plan();
    CHECK(p.passes.empty());
    CHECK(p.bytesOf("depth") == 0);
    CHECK(through.value()->texture().isNull());

    std::vector<float> depths(size_t(W) * H);
    for (size_t i = 0; i < depths.size(); ++i) depths[i] = 0.5f + 0.25f * float(i % 7);
    TextureHandle src = device.createTexture({W, H, 1, Format::R32F, kTextureSampled, "test-linear-depth"}).value();
    SFX_REQUIRE_OK(device.writeTexture(src, 0, depths.data(), depths.size() * 4));
    const CameraProjection cam = makePerspective({}).value();
    TimerHandle timer = device.createTimer().value();
    CHECK(through.value()->dispatch({src, DepthKind::Linear, cam}, std::span<const TimerHandle>(&timer, 1)).code() ==
          StatusCode::InvalidArgument);  // no planned pass to time
    SFX_REQUIRE_OK(through.value()->dispatch({src, DepthKind::Linear, cam}));
    CHECK(through.value()->texture() == src);
    CHECK(through.value()->reconstruction().maxDepth > 0.0);
    // Hardware depth needs the pass this LinearDepth was told it would not run.
    const Status wrongKind = through.value()->dispatch({src, DepthKind::Hardware, cam});
    CHECK(wrongKind.code() == StatusCode::InvalidArgument);
    CHECK(wrongKind.message().find("DepthSource.kind") != std::string::npos);

    // Said Hardware, given linear depth: the copy pass and its texture, as before, same values.
    auto copying = LinearDepth::create(device, {W, H, test::tier(), 1, DepthKind::Hardware});
    REQUIRE(copying.isOk());
    CHECK_FALSE(copying.value()->passThrough());
    CHECK(copying.value()->plan().passes.size() == 1);
    SFX_REQUIRE_OK(copying.value()->dispatch({src, DepthKind::Linear, cam}));
    CHECK(copying.value()->texture() != src);
    if (device.caps().backend != BackendKind::Null) CHECK(readLevel(device, copying.value()->texture(), W, H, 0) == depths);
    // With a pyramid (high tier) linear input still needs LinearDepth's own texture.
    if (test::tier() == Tier::High) {
        auto mip = LinearDepth::create(device, {W, H, Tier::High, 2, DepthKind::Linear});
        REQUIRE(mip.isOk());
        CHECK_FALSE(mip.value()->passThrough());
        CHECK(mip.value()->plan().passes.size() == 2);
    }
    SFX_REQUIRE_OK(device.destroyTimer(timer));
    SFX_REQUIRE_OK(device.destroyTexture(src));
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("LinearDepth: readers that linearize get the host's depth and the constants, no pass", "[depth][plan]") {
    // AO at half resolution without a pyramid linearizes each full-size depth as it fetches it.
    Device& device = test::device();
    const uint32_t W = 16, H = 8;
    LinearDepthDesc desc{W, H, test::tier(), 1, DepthKind::Hardware};
    desc.readersLinearize = true;
    auto readers = LinearDepth::create(device, desc);
    REQUIRE(readers.isOk());
    CHECK(readers.value()->passThrough());
    const EffectPlan p = readers.value()->plan();
    CHECK(p.passes.empty());
    REQUIRE(p.resources.size() == 1);  // the constants the readers use, nothing else
    CHECK(p.resources[0].name.find("linearize params") != std::string::npos);
    CHECK_FALSE(readers.value()->linearizeParams().isNull());

    const CameraProjection cam = makePerspective({}).value();
    TextureHandle hw = device.createTexture({W, H, 1, Format::D32F, kTextureSampled | kTextureRenderTarget, "test-hw-depth"}).value();
    SFX_REQUIRE_OK(readers.value()->dispatch({hw, DepthKind::Hardware, cam}));
    CHECK(readers.value()->texture() == hw);
    CHECK(readers.value()->sourceKind() == DepthKind::Hardware);
    CHECK(readers.value()->reconstruction().maxDepth > 0.0);
    // Linear input is read where it lies, as without the flag.
    TextureHandle lin = device.createTexture({W, H, 1, Format::R32F, kTextureSampled, "test-linear-depth"}).value();
    SFX_REQUIRE_OK(readers.value()->dispatch({lin, DepthKind::Linear, cam}));
    CHECK(readers.value()->texture() == lin);
    CHECK(readers.value()->sourceKind() == DepthKind::Linear);
    // The flag changes nothing where a pyramid is built: the pass and its texture stay.
    if (test::tier() == Tier::High) {
        LinearDepthDesc mipDesc{W, H, Tier::High, 2, DepthKind::Hardware};
        mipDesc.readersLinearize = true;
        auto mip = LinearDepth::create(device, mipDesc);
        REQUIRE(mip.isOk());
        CHECK_FALSE(mip.value()->passThrough());
        CHECK(mip.value()->plan().passes.size() == 2);
    }
    SFX_REQUIRE_OK(device.destroyTexture(hw));
    SFX_REQUIRE_OK(device.destroyTexture(lin));
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("depth passes stay finite and within bounds at the extremes", "[depth][conformance][extremes]") {
    Device& device = test::device();
    // Extreme depth ranges: a 1e-4 near plane with a 1e6 far plane, and an infinite far plane
    // with reversed-Z; depths spanning ten orders of magnitude.
    struct Range {
        double nearPlane, farPlane;
        bool reversed;
        ClipDepthRange clip;
    };
    const Range ranges[] = {{1e-4, 1e6, false, ClipDepthRange::ZeroToOne},
                            {1e-4, test::kInfiniteFar, true, ClipDepthRange::ZeroToOne},
                            {1e-3, 1e5, false, ClipDepthRange::MinusOneToOne},
                            {10.0, 10.5, false, ClipDepthRange::ZeroToOne}};  // a thin slab far away
    const uint32_t W = 33, H = 9;
    for (const Range& r : ranges) {
        INFO(test::label() << " near " << r.nearPlane << " far " << r.farPlane << (r.reversed ? " reversed" : ""));
        PerspectiveDesc pd;
        pd.nearPlane = r.nearPlane;
        pd.farPlane = r.farPlane;
        pd.reversedZ = r.reversed;
        pd.clipDepth = r.clip;
        pd.aspect = double(W) / H;
        CameraProjection cam = makePerspective(pd).value();
        DepthReconstruction rec = makeDepthReconstruction(cam, W, H).value();
        const double zFar = std::isinf(r.farPlane) ? 1e6 : r.farPlane;
        std::vector<float> stored(size_t(W) * H);
        reference::Grid storedGrid(W, H);
        for (size_t i = 0; i < stored.size(); ++i) {
            const double z = r.nearPlane * std::pow(zFar / r.nearPlane, double(i) / double(stored.size() - 1));
            stored[i] = float(std::clamp(storedDepthFromLinear(cam, z), 0.0, 1.0));
            storedGrid.values[i] = stored[i];
        }
        reference::Grid expected = reference::linearizeDepth(storedGrid, rec);
        TextureHandle src = device.createTexture({W, H, 1, Format::R32F, kTextureSampled}).value();
        SFX_REQUIRE_OK(device.writeTexture(src, 0, stored.data(), stored.size() * 4));
        auto linear = LinearDepth::create(device, {W, H, test::tier(), std::min(3u, levelsFor(test::tier()))});
        REQUIRE(linear.isOk());
        SFX_REQUIRE_OK(linear.value()->dispatch({src, DepthKind::Hardware, cam}));
        std::vector<float> got = readLevel(device, linear.value()->texture(), W, H, 0);
        for (size_t i = 0; i < got.size(); ++i) {
            INFO("texel " << i << " stored " << stored[i] << " want " << expected.values[i] << " got " << got[i]);
            REQUIRE(std::isfinite(got[i]));
            REQUIRE(got[i] > 0.0f);
            REQUIRE(got[i] <= float(rec.maxDepth));
            requireLinearMatches(storedGrid.values[i], rec, expected.values[i], got[i]);
        }
        (void)device.destroyTexture(src);
    }
    // Extreme sizes: one texel, and one texel thin; the pyramid only where the size allows.
    for (auto [w, h] : {std::pair<uint32_t, uint32_t>{1, 1}, {1, 129}, {257, 1}}) {
        INFO(test::label() << " " << w << "x" << h);
        const uint32_t levels = std::min({3u, maxMipLevels(w, h), levelsFor(test::tier())});
        auto linear = LinearDepth::create(device, {w, h, test::tier(), levels});
        REQUIRE(linear.isOk());
        std::vector<float> depths(size_t(w) * h, 5.0f);
        TextureHandle src = device.createTexture({w, h, 1, Format::R32F, kTextureSampled}).value();
        SFX_REQUIRE_OK(device.writeTexture(src, 0, depths.data(), depths.size() * 4));
        SFX_REQUIRE_OK(linear.value()->dispatch({src, DepthKind::Linear, makePerspective({}).value()}));
        for (uint32_t m = 0; m < levels; ++m)
            for (float v : readLevel(device, linear.value()->texture(), w, h, m)) REQUIRE(v == 5.0f);
        (void)device.destroyTexture(src);
    }
    if (test::tier() == Tier::High) {
        // A pyramid deeper than a 1x1 target allows is a named error, not a silent clamp.
        auto tooDeep = LinearDepth::create(device, {1, 1, Tier::High, 2});
        CHECK(tooDeep.status().code() == StatusCode::InvalidArgument);
        CHECK(tooDeep.status().message().find("for 1x1") != std::string::npos);
    }
    const uint32_t tooWide = device.caps().limits.maxTextureSize + 1;
    CHECK(LinearDepth::create(device, {tooWide, 4, test::tier(), 1}).status().code() == StatusCode::InvalidArgument);
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}
