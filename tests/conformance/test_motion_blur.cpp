// Motion blur on the device under test: against the CPU reference, and the properties any
// correct motion blur has (the unit tests check the same properties on the reference).
// Tolerances are explained in docs/motion_blur.md ("Conformance tolerances").
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <optional>
#include <random>

#include "effect_runs.hpp"
#include "portability_rows.hpp"
#include "sfx/half.hpp"
#include "sfx/motion_blur.hpp"
#include "sfx/reference/motion_blur_reference.hpp"
#include "sfx/validation_errors.hpp"
#include "skips.hpp"
#include "test_device.hpp"

using namespace sfx;
using namespace sfx::reference;

namespace {

// The colour as the GPU sees it (rounded to fp16), so the reference starts from the same input.
ColorGrid toHalfGrid(const ColorGrid& c) {
    ColorGrid out = c;
    for (auto& px : out.values)
        for (double& ch : px) ch = roundToHalf(ch);
    return out;
}

CameraProjection testCamera(uint32_t w, uint32_t h) { return test::motionBlurTestCamera(w, h); }

// Runs the effect on the device under test and reads the output back as doubles.
ColorGrid runGpu(const ColorGrid& color, const Grid& depth, const VelocityGrid* velocity, const MotionBlurSettings& s,
                 const CameraMotion& camera = {}, DepthKind descInput = DepthKind::Linear) {
    return test::runMotionBlur(test::device(), test::tierProfile(), color, depth, velocity, s, camera, descInput);
}

MotionBlurSettings pixelSettings(std::optional<float> radius) {
    MotionBlurSettings s;
    s.maxRadiusPx = radius;
    s.referenceRows = 0;
    return s;
}
MotionBlurParams resolved(const MotionBlurSettings& s, uint32_t h) { return resolveMotionBlur(test::tierProfile(), s, h).value(); }

ColorGrid noise(uint32_t w, uint32_t h, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    ColorGrid c(w, h);
    for (auto& v : c.values) v = {u(rng), u(rng), u(rng), 1.0};
    return toHalfGrid(c);
}

// GPU vs reference: fp16 output rounding (<= 2^-11 relative), the fp16 velocity's last bit
// (the GPU may round toward zero where the reference rounds to nearest: up to 2^-11 * 2k px)
// and float-vs-double weights keep ordinary pixels within 2e-3. A few pixels may take a
// different discrete decision (an offset t*v rounding at exactly .5, the still threshold) when
// the fp16 velocity lands on the boundary, so up to 3% may differ more (1.5% measured on
// lavapipe, which rounds fp16 toward zero); the RMSE stays small (0.003 measured).
void compareWithReference(const ColorGrid& gpu, const ColorGrid& ref, const char* what) {
    size_t far = 0;
    double sq = 0, worst = 0, sumAbs = 0;
    for (size_t i = 0; i < gpu.values.size(); ++i)
        for (int c = 0; c < 4; ++c) {
            REQUIRE(std::isfinite(gpu.values[i][c]));
            const double e = std::fabs(gpu.values[i][c] - ref.values[i][c]);
            sq += e * e;
            sumAbs += e;
            worst = std::max(worst, e);
            if (e > 2e-3) ++far;
        }
    const double n = double(gpu.values.size() * 4);
    const double rmse = std::sqrt(sq / n);
    INFO(test::label() << " " << what << ": rmse " << rmse << ", worst " << worst << ", beyond 2e-3: " << far);
    CHECK(double(far) <= 0.03 * n);
    CHECK(rmse <= 5e-3);
    test::addPortabilityRow(std::string("motion blur, ") + what, worst, sumAbs / n);
}

}  // namespace

TEST_CASE("motion blur: zero velocity returns the input exactly", "[motion_blur][conformance]") {
    const ColorGrid c = noise(45, 31, 1);
    const Grid z(45, 31, 4.0);
    const VelocityGrid v(45, 31);
    const ColorGrid out = runGpu(c, z, &v, {});
    for (size_t i = 0; i < c.values.size(); ++i) REQUIRE(out.values[i] == c.values[i]);
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("motion blur: matches the reference on a scene with moving and still layers", "[motion_blur][conformance]") {
    const MotionScene scene = test::movingAndStillLayersScene();
    const SceneFrame f = scene.render(0);
    const ColorGrid c = toHalfGrid(f.color);
    for (std::optional<float> radius : {std::optional<float>{}, std::optional<float>{7.0f}}) {
        const MotionBlurSettings s = pixelSettings(radius);
        const ColorGrid gpu = runGpu(c, f.depth, &f.velocity, s);
        const ColorGrid ref = motionBlur(c, f.depth, f.velocity, resolved(s, scene.height)).color;
        compareWithReference(gpu, ref, radius ? "radius 7" : "tier radius");
    }
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("motion blur: the jitter pattern a profile may choose instead of its tier's matches the reference", "[motion_blur][conformance]") {
    // Both tiers use the checkerboard; the 4x4 pattern stays a profile choice, so it is run here.
    TierProfile profile = test::tierProfile();
    profile.mbJitterSize = profile.mbJitterSize == 2 ? 4 : 2;
    const MotionScene scene = test::movingAndStillLayersScene();
    const SceneFrame f = scene.render(0);
    const ColorGrid c = toHalfGrid(f.color);
    const MotionBlurSettings s = pixelSettings(7.0f);
    const ColorGrid gpu = test::runMotionBlur(test::device(), profile, c, f.depth, &f.velocity, s, {}, DepthKind::Linear);
    const ColorGrid ref = motionBlur(c, f.depth, f.velocity, resolveMotionBlur(profile, s, scene.height).value()).color;
    compareWithReference(gpu, ref, profile.mbJitterSize == 4 ? "4x4 jitter" : "checkerboard jitter");
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("motion blur: camera-only velocity matches the reference", "[motion_blur][conformance]") {
    const uint32_t w = 64, h = 40;
    const CameraProjection cam = testCamera(w, h);
    Grid z(w, h);
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) z.at(x, y) = 2.0 + 0.2 * x + ((x / 8 + y / 8) % 2) * 3.0;
    glm::dmat4 prevView(1.0);
    prevView[3][0] = 0.15;  // the camera slid sideways
    prevView[3][1] = -0.05;
    const CameraMotion motion{cam.projection * prevView, cam.projection};
    const ColorGrid c = noise(w, h, 5);
    const MotionBlurSettings s = pixelSettings(6);
    const ColorGrid gpu = runGpu(c, z, nullptr, s, motion);
    const VelocityGrid v = cameraVelocity(z, cam.projection, motion);
    const ColorGrid ref = motionBlur(c, z, v, resolved(s, h)).color;
    compareWithReference(gpu, ref, "camera-only");
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("motion blur: uniform horizontal motion blurs only along rows", "[motion_blur][conformance]") {
    const uint32_t w = 128, h = 16;
    const Grid z(w, h, 5.0);
    const VelocityGrid v(w, h, {12.0, 0.0});
    const MotionBlurSettings s = pixelSettings(8);
    ColorGrid stripes(w, h);
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) stripes.at(x, y) = {double(y % 3) / 2.0, double(y % 2), 0.25, 1.0};
    const ColorGrid s1 = runGpu(stripes, z, &v, s);
    for (size_t i = 0; i < s1.values.size(); ++i)
        for (int c = 0; c < 4; ++c) REQUIRE(s1.values[i][c] == Approx(stripes.values[i][c]).margin(1e-3));

    const ColorGrid c = noise(w, h, 2);
    const ColorGrid out = runGpu(c, z, &v, s);
    for (uint32_t y = 0; y < h; ++y) {
        double inMean = 0, outMean = 0;
        for (uint32_t x = 16; x < w - 16; ++x) inMean += c.at(x, y)[1], outMean += out.at(x, y)[1];
        INFO("row " << y);
        CHECK(std::fabs(inMean - outMean) / (w - 32) < 0.02);  // as the reference test, plus fp16
    }
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("motion blur: moving object blurs past its silhouette, still ones stay sharp", "[motion_blur][conformance]") {
    SceneLayer bg;
    bg.depth = 20, bg.cell = 4, bg.colorA = {0.2, 0.2, 0.2, 1}, bg.colorB = {0.4, 0.4, 0.4, 1};
    SceneLayer box;
    box.shape = SceneLayer::Shape::Rect, box.depth = 5, box.centre = {32, 16}, box.halfSize = {6, 6};
    box.velocityPx = {16, 0}, box.colorA = {1, 0.9, 0.1, 1};
    const MotionBlurSettings s = pixelSettings(10);

    MotionScene moving{64, 32, {bg, box}};
    SceneFrame f = moving.render(0);
    f.color = toHalfGrid(f.color);
    ColorGrid out = runGpu(f.color, f.depth, &f.velocity, s);
    CHECK(out.at(40, 16)[0] > f.color.at(40, 16)[0] + 0.05);
    CHECK(out.at(2, 2) == f.color.at(2, 2));
    for (uint32_t x = 26; x < 38; ++x)
        for (int ch = 0; ch < 4; ++ch) CHECK(out.at(x, 8)[ch] == Approx(f.color.at(x, 8)[ch]).margin(1e-3));

    SceneLayer mbg = bg;
    mbg.velocityPx = {16, 0};
    SceneLayer still = box;
    still.velocityPx = {0, 0}, still.cell = 2;
    MotionScene s2{64, 32, {mbg, still}};
    f = s2.render(0);
    f.color = toHalfGrid(f.color);
    out = runGpu(f.color, f.depth, &f.velocity, s);
    for (uint32_t y = 10; y < 22; ++y)
        for (uint32_t x = 26; x < 38; ++x)
            for (int c = 0; c < 4; ++c) REQUIRE(out.at(x, y)[c] == Approx(f.color.at(x, y)[c]).margin(1e-3));

    // Depth sign: moving behind a still occluder does not bleed over it; in front, it does.
    SceneLayer occluder = still;
    occluder.halfSize = {4, 12};
    SceneLayer behind = box;
    behind.depth = 10, behind.centre = {24, 16};
    MotionScene s3{64, 32, {bg, behind, occluder}};
    f = s3.render(0);
    f.color = toHalfGrid(f.color);
    out = runGpu(f.color, f.depth, &f.velocity, s);
    for (uint32_t y = 5; y < 27; ++y)
        for (uint32_t x = 29; x < 35; ++x)
            for (int c = 0; c < 4; ++c) REQUIRE(out.at(x, y)[c] == Approx(f.color.at(x, y)[c]).margin(1e-3));
    s3.layers[1].depth = 2;
    f = s3.render(0);
    f.color = toHalfGrid(f.color);
    out = runGpu(f.color, f.depth, &f.velocity, s);
    CHECK(std::fabs(out.at(30, 16)[2] - f.color.at(30, 16)[2]) > 0.02);
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("motion blur: velocities at and beyond the maximum are clamped; no NaN", "[motion_blur][conformance]") {
    const uint32_t w = 48, h = 24;
    const ColorGrid c = noise(w, h, 3);
    const Grid z(w, h, 3.0);
    const MotionBlurSettings s = pixelSettings(6);
    const VelocityGrid atMax(w, h, {12.0, 0.0}), beyond(w, h, {600.0, 0.0});
    const ColorGrid a = runGpu(c, z, &atMax, s), b = runGpu(c, z, &beyond, s);
    for (size_t i = 0; i < a.values.size(); ++i) REQUIRE(a.values[i] == b.values[i]);

    // A bright column in a flat field, huge velocity toward the image edges: only columns within
    // the radius change, and edge pixels (whose samples were clamped into the image) stay finite.
    ColorGrid flat(w, h, {0.5, 0.5, 0.5, 1});
    for (uint32_t y = 0; y < h; ++y) flat.at(24, y) = {1, 1, 1, 1};
    const VelocityGrid huge(w, h, {-1000.0, 3.0});
    const ColorGrid out = runGpu(flat, z, &huge, s);
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) {
            for (int ch = 0; ch < 4; ++ch) REQUIRE(std::isfinite(out.at(x, y)[ch]));
            if (x + 7 < 24 || x > 24 + 7) REQUIRE(out.at(x, y) == flat.at(x, y));
        }

    // Random velocities with NaN and infinities, sky depth: every output finite.
    std::mt19937 rng(9);
    std::uniform_real_distribution<double> u(-50.0, 50.0);
    VelocityGrid wild(w, h);
    for (auto& e : wild.values) e = {u(rng), u(rng)};
    wild.at(3, 3) = {NAN, 1.0};
    wild.at(20, 10) = {INFINITY, -INFINITY};
    Grid zz(w, h);
    for (auto& d : zz.values) d = 0.2 + std::fabs(u(rng));
    zz.at(5, 5) = 1e8;
    const ColorGrid wildOut = runGpu(c, zz, &wild, {});
    for (const auto& px : wildOut.values)
        for (double ch : px) REQUIRE(std::isfinite(ch));
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("motion blur: bad inputs are named errors", "[motion_blur][conformance]") {
    Device& d = test::device();
    Result<std::unique_ptr<MotionBlur>> zeroWide = MotionBlur::create(d, {0, 16, test::tierProfile(), Format::RGBA16F});
    CHECK(zeroWide.status().code() == StatusCode::InvalidArgument);
    CHECK(zeroWide.status().message().find("MotionBlurDesc.width is 0") != std::string::npos);
    const uint32_t tooTall = d.caps().limits.maxTextureSize + 1;
    CHECK(MotionBlur::create(d, {32, tooTall, test::tierProfile(), Format::RGBA16F}).status().message().find("MotionBlurDesc.height") !=
          std::string::npos);
    Result<std::unique_ptr<MotionBlur>> mb = MotionBlur::create(d, {32, 16, test::tierProfile(), Format::RGBA16F});
    REQUIRE(mb.isOk());
    test::MotionBlurGpuInputs in(d, ColorGrid(32, 16), Grid(32, 16, 1.0), nullptr);
    MotionBlurInputs inputs{in.color, {in.depth, DepthKind::Linear, testCamera(32, 16)}, {}, {}};
    MotionBlurSettings s;
    s.samples = 4;
    Status st = mb.value()->dispatch(inputs, s);
    CHECK(st.code() == StatusCode::InvalidArgument);
    CHECK(st.message().find("samples") != std::string::npos);
    inputs.velocity = in.depth;  // R32F: not a velocity format
    st = mb.value()->dispatch(inputs, {});
    CHECK(st.code() == StatusCode::UnsupportedFormat);
    CHECK(st.message().find("velocity") != std::string::npos);
    SFX_REQUIRE_OK(mb.value()->resize(40, 20));
    inputs.velocity = {};
    st = mb.value()->dispatch(inputs, {});  // colour still 32x16
    CHECK(st.code() == StatusCode::InvalidArgument);
    CHECK(st.message().find("color size") != std::string::npos);
    const EffectPlan plan = mb.value()->plan();
    CHECK(plan.passes.size() == 5);  // linearize + 4 motion blur passes
    CHECK(plan.bytesOf("motion_blur") > 0);
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

// The host's output texture gets exactly the bits of the effect's own: the same passes, only the
// last one's target differs. A texture of the wrong size, format or usage is refused with the
// validation table's row (validation_cases.cpp has its parity case), and a refused dispatch
// leaves the host's texture alone.
TEST_CASE("motion blur: a host output texture gets the bits of output()", "[motion_blur][conformance]") {
    Device& d = test::device();
    const MotionScene scene = test::movingAndStillLayersScene();
    const SceneFrame f = scene.render(0);
    const uint32_t w = scene.width, h = scene.height;
    Result<std::unique_ptr<MotionBlur>> mb = MotionBlur::create(d, {w, h, test::tierProfile(), Format::RGBA16F, DepthKind::Linear});
    REQUIRE(mb.isOk());
    test::MotionBlurGpuInputs in(d, toHalfGrid(f.color), f.depth, &f.velocity);
    MotionBlurInputs inputs{in.color, {in.depth, DepthKind::Linear, testCamera(w, h)}, in.velocity, {}, {}};
    const MotionBlurSettings s = pixelSettings(7);
    const size_t bytes = size_t(w) * h * 8;
    auto read = [&](TextureHandle t) {
        std::vector<uint16_t> texels(bytes / 2);
        SFX_REQUIRE_OK(d.readTexture(t, 0, texels.data(), bytes));
        return texels;
    };
    SFX_REQUIRE_OK(mb.value()->dispatch(inputs, s));
    const std::vector<uint16_t> own = read(mb.value()->output());

    TextureHandle host = d.createTexture({w, h, 1, Format::RGBA16F, kTextureSampled | kTextureRenderTarget, "host output"}).value();
    const std::vector<uint16_t> marker(bytes / 2, floatToHalf(-3.0f));
    SFX_REQUIRE_OK(d.writeTexture(host, 0, marker.data(), bytes));
    SFX_REQUIRE_OK(d.writeTexture(mb.value()->output(), 0, marker.data(), bytes));
    inputs.output = host;
    SFX_REQUIRE_OK(mb.value()->dispatch(inputs, s));
    CHECK(read(host) == own);
    CHECK(read(mb.value()->output()) == marker);  // the effect's own texture is not written
    size_t moved = 0;
    for (size_t i = 0; i < own.size(); i += 4) moved += halfToFloat(own[i]) != float(roundToHalf(f.color.values[i / 4][0]));
    CHECK(moved > 0);  // the scene blurs: not a copy of the input

    TextureHandle small = d.createTexture({w / 2, h, 1, Format::RGBA16F, kTextureSampled | kTextureRenderTarget}).value();
    TextureHandle rgba8 = d.createTexture({w, h, 1, Format::RGBA8, kTextureSampled | kTextureRenderTarget}).value();
    TextureHandle sampledOnly = d.createTexture({w, h, 1, Format::RGBA16F, kTextureSampled}).value();
    SFX_REQUIRE_OK(d.writeTexture(host, 0, marker.data(), bytes));
    const std::pair<TextureHandle, validation::Error> refusals[] = {{small, validation::Error::MotionBlurOutputSize},
                                                                    {rgba8, validation::Error::MotionBlurOutputFormat},
                                                                    {sampledOnly, validation::Error::MotionBlurOutputUsage}};
    for (const auto& [texture, rule] : refusals) {
        inputs.output = texture;
        const Status st = mb.value()->dispatch(inputs, s);
        INFO(validation::entry(rule).name << ": " << st.toString());
        CHECK(st.code() == StatusCode::InvalidArgument);
        CHECK(st.message().rfind("MotionBlurInputs.output", 0) == 0);
    }
    CHECK(read(host) == marker);
    for (TextureHandle t : {host, small, rgba8, sampledOnly}) SFX_REQUIRE_OK(d.destroyTexture(t));
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("motion blur: linear depth read in place gives the same output as the copy, one pass fewer", "[motion_blur][plan]") {
    Device& d = test::device();
    for (DepthKind input : {DepthKind::Hardware, DepthKind::Linear}) {
        Result<std::unique_ptr<MotionBlur>> mb = MotionBlur::create(d, {32, 16, test::tierProfile(), Format::RGBA16F, input});
        REQUIRE(mb.isOk());
        const EffectPlan plan = mb.value()->plan();
        CHECK(plan.passes.size() == (input == DepthKind::Linear ? 4u : 5u));
        CHECK((plan.bytesOf("depth") > 0) == (input == DepthKind::Hardware));
    }
    if (test::device().caps().backend == BackendKind::Null) SFX_SKIP("the null backend draws nothing: outputs are not compared on " << test::label());
    // Depths in range, beyond the far plane and sky: reading in place clamps as the copy does.
    const uint32_t w = 48, h = 24;
    const ColorGrid c = noise(w, h, 7);
    Grid z(w, h, 2.0);
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) z.at(x, y) = x < 16 ? 1.0 + 0.01 * y : (x < 32 ? 2.5 : 1e9);
    VelocityGrid v(w, h, {9.0, 3.0});
    for (const VelocityGrid* vel : {static_cast<const VelocityGrid*>(&v), static_cast<const VelocityGrid*>(nullptr)}) {
        CameraMotion cam;
        cam.currentViewProjection = testCamera(w, h).projection;
        glm::dmat4 pan(1.0);
        pan[3][0] = 0.05;  // the camera moved sideways between the frames
        cam.previousViewProjection = cam.currentViewProjection * pan;
        const ColorGrid copied = runGpu(c, z, vel, {}, cam, DepthKind::Hardware);
        const ColorGrid inPlace = runGpu(c, z, vel, {}, cam, DepthKind::Linear);
        CHECK(inPlace.values == copied.values);
    }
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("motion blur: profiling times exactly the planned passes and leaves the output unchanged", "[motion_blur][profiling]") {
    Device& d = test::device();
    const MotionScene scene = test::movingAndStillLayersScene();
    const SceneFrame f = scene.render(0);
    const uint32_t w = scene.width, h = scene.height;
    // Hardware depth in the desc: the linearisation pass runs and is timed too.
    Result<std::unique_ptr<MotionBlur>> created = MotionBlur::create(d, {w, h, test::tierProfile(), Format::RGBA16F, DepthKind::Hardware});
    REQUIRE(created.isOk());
    MotionBlur& mb = *created.value();
    test::MotionBlurGpuInputs in(d, toHalfGrid(f.color), f.depth, &f.velocity);
    const MotionBlurInputs inputs{in.color, {in.depth, DepthKind::Linear, testCamera(w, h)}, in.velocity, {}, {}};
    const size_t bytes = size_t(w) * h * 8;
    auto runOnce = [&](const MotionBlurSettings& s) {
        SFX_REQUIRE_OK(mb.dispatch(inputs, s));
        SFX_REQUIRE_OK(d.flush());
        std::vector<uint16_t> texels(bytes / 2);
        SFX_REQUIRE_OK(d.readTexture(mb.output(), 0, texels.data(), bytes));
        return texels;
    };
    const MotionBlurSettings s = pixelSettings(7);
    CHECK_FALSE(mb.profiling());
    CHECK(mb.passTimings().status().code() == StatusCode::InvalidArgument);
    const std::vector<uint16_t> plain = runOnce(s);

    SFX_REQUIRE_OK(mb.setProfiling(true));
    CHECK(mb.passTimings().status().code() == StatusCode::InvalidArgument);  // nothing dispatched yet
    // Twice: the second profiled frame records its passes again rather than replaying the first.
    for (int frame = 0; frame < 2; ++frame) {
        INFO(test::label() << " profiled frame " << frame);
        CHECK(runOnce(s) == plain);
        Result<std::vector<PassTiming>> timings = mb.passTimings();
        INFO(timings.status().toString());
        REQUIRE(timings.isOk());
        const EffectPlan plan = mb.plan(s);
        REQUIRE(timings->size() == plan.passes.size());
        for (size_t i = 0; i < plan.passes.size(); ++i) {
            CHECK(timings.value()[i].effect == plan.passes[i].effect);
            CHECK(timings.value()[i].name == plan.passes[i].name);
            CHECK(timings.value()[i].reading.milliseconds > 0.0);
            CHECK(timings.value()[i].reading.source == d.caps().timing);
        }
    }
    // Other settings name other passes ("reconstruct N taps"); the timings follow them.
    MotionBlurSettings other = s;
    other.samples = 3;
    (void)runOnce(other);
    Result<std::vector<PassTiming>> timings = mb.passTimings();
    REQUIRE(timings.isOk());
    CHECK(timings->back().name == mb.plan(other).passes.back().name);

    SFX_REQUIRE_OK(mb.setProfiling(false));
    CHECK(mb.passTimings().status().code() == StatusCode::InvalidArgument);
    CHECK(runOnce(s) == plain);
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}
