// Sizes at the edges: 1x1, one row, one column, odd and prime sizes. Every effect runs on them
// with finite output and agrees with its CPU reference, so the motion blur tiles and the AO
// depth MIP chain are right where the size is no multiple of the tile or of 2; a size above the
// device's limit is a named error. 7680x4320 runs every effect once for finite output (its
// own CTest entries, sizes_8k.*: the case is hidden from the conformance entries).
#include <catch2/catch.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>

#include "analytic_scenes.hpp"
#include "effect_runs.hpp"
#include "sfx/half.hpp"
#include "sfx/oit.hpp"
#include "skips.hpp"
#include "test_device.hpp"

using namespace sfx;
using namespace sfx::reference;

namespace {

struct Size {
    uint32_t w, h;
};
// The small odd and prime sizes compared with the references texel by texel.
const Size kSmallSizes[] = {{1, 1}, {1, 37}, {37, 1}, {2, 3}, {127, 61}};

bool drawsNothing() { return test::device().caps().backend == BackendKind::Null; }

}  // namespace

TEST_CASE("sizes: AO at 1x1, one row, one column and odd sizes matches the reference", "[sizes][ao]") {
    if (drawsNothing()) SFX_SKIP("the null backend draws nothing: GPU results are not compared on " << test::label());
    // The AO conformance test's per-pixel bound (docs/ao.md: float-vs-double taps), which at most
    // 1% of pixels may exceed (none at all below 100 pixels).
    const double worstBound = test::tier() == Tier::High ? 0.03 : 0.05;
    for (const Size& sz : kSmallSizes)
        for (AoTechnique t : {AoTechnique::Alchemy, AoTechnique::Scalable, AoTechnique::Crease, AoTechnique::Horizon}) {
            INFO(test::label() << " " << sz.w << "x" << sz.h << " " << toString(t));
            const tools::AnalyticScene scene = tools::cornerScene(sz.w, sz.h, 1.0);
            AoSettings s = test::aoTestSettings(t);
            const test::GpuAo gpu = test::runAo(test::device(), test::tierProfile(), scene, s);
            const Grid ref = ambientVisibility(scene.aoInput(false), gpu.config);
            size_t off = 0;
            for (size_t i = 0; i < ref.values.size(); ++i) {
                REQUIRE(std::isfinite(gpu.visibility.values[i]));
                if (std::abs(gpu.visibility.values[i] - ref.values[i]) > worstBound) ++off;
            }
            INFO("pixels beyond " << worstBound << ": " << off << " of " << ref.values.size());
            CHECK(double(off) <= 0.01 * double(ref.values.size()));
        }
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("sizes: motion blur tiles at 1x1, one row, one column and odd sizes match the reference", "[sizes][motion_blur]") {
    if (drawsNothing()) SFX_SKIP("the null backend draws nothing: GPU results are not compared on " << test::label());
    for (const Size& sz : kSmallSizes) {
        INFO(test::label() << " " << sz.w << "x" << sz.h);
        std::mt19937 rng(sz.w * 131 + sz.h);
        // Velocities below the radius: lengths clamped to it would tie in the tile max.
        std::uniform_real_distribution<double> u(0.0, 1.0), v(-3.0, 3.0);
        ColorGrid c(sz.w, sz.h);
        Grid z(sz.w, sz.h);
        VelocityGrid vel(sz.w, sz.h);
        for (auto& px : c.values) px = {roundToHalf(u(rng)), roundToHalf(u(rng)), roundToHalf(u(rng)), 1.0};
        for (auto& d : z.values) d = 2.0 + 6.0 * u(rng);
        for (auto& e : vel.values) e = {v(rng), v(rng)};
        MotionBlurSettings s;
        s.maxRadiusPx = 5;  // tiles of 5: no size above is a multiple of it
        s.referenceRows = 0;
        const ColorGrid gpu = test::runMotionBlur(test::device(), test::tierProfile(), c, z, &vel, s);
        const MotionBlurParams p = resolveMotionBlur(test::tierProfile(), s, sz.h).value();
        const double maxDepth = makeDepthReconstruction(test::motionBlurTestCamera(sz.w, sz.h), sz.w, sz.h).value().maxDepth;
        const ColorGrid ref = motionBlur(c, z, vel, p, maxDepth).color;
        // The motion blur conformance bound: 2e-3 per channel, at most 3% of channels beyond it.
        (void)test::checkMotionBlurConformance(gpu, ref);
    }
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("sizes: at 4320 rows the tier's default motion blur radius caps at the shaders' limit", "[sizes][motion_blur]") {
    // The tier's radius is defined at 720 rows (10 or 18 px), 60 or 108 px at 4320: the high
    // tier's exceeds the 64 px the shaders hold. The default caps and says so; a radius the
    // caller chose that scales beyond the limit stays a named error.
    const uint32_t rows = std::min(4320u, test::device().caps().limits.maxTextureSize);
    const TierProfile& profile = test::tierProfile();
    const double scaled = std::round(double(profile.mbMaxRadiusPx) * double(rows) / 720.0);
    const MotionBlurParams p = resolveMotionBlur(profile, {}, rows).value();
    INFO(test::label() << ": tier radius " << profile.mbMaxRadiusPx << " px at 720 rows, " << scaled << " px at " << rows);
    if (scaled > 64.0) {
        CHECK(p.radiusCapped);
        CHECK(p.radiusPx == 64u);
        CHECK(p.scaledRadiusPx == scaled);
    } else {
        CHECK_FALSE(p.radiusCapped);
        CHECK(p.radiusPx == uint32_t(scaled));
    }
    // The same radius given explicitly is refused, naming the field.
    MotionBlurSettings explicitRadius;
    explicitRadius.maxRadiusPx = 18.0f;
    const Result<MotionBlurParams> refused = resolveMotionBlur(profile, explicitRadius, 4320);
    INFO(refused.status().toString());
    CHECK(refused.status().code() == StatusCode::InvalidArgument);
    CHECK(refused.status().message().find("MotionBlurSettings.maxRadiusPx") != std::string::npos);

    // A narrow output with the full height, default settings: dispatch runs and matches the
    // reference at the capped radius, and the plan names the cap.
    const uint32_t w = 6;
    auto mb = MotionBlur::create(test::device(), {w, rows, profile, Format::RGBA16F, DepthKind::Linear});
    REQUIRE(mb.isOk());
    const std::string tilePass = mb.value()->plan().passes.at(mb.value()->plan().passes.size() - 3).name;
    INFO(tilePass);
    CHECK((tilePass.find("capped at the shaders' 64 px limit") != std::string::npos) == p.radiusCapped);
    if (drawsNothing()) return;
    // Colour a slow vertical sine (period 1500 rows): a sample one row off the reference's
    // changes it by under 2e-3, while the blur over +-64 rows (and the wrong radius) moves it by
    // more; blue steps by 0.01 a column. One depth, one velocity beyond the radius with a small
    // horizontal component: every pixel clamps to the same (0.96, 63.99) px ((0.90, 59.99) at 60),
    // whose fp16 code the target would round differently by device (to nearest or toward zero,
    // one step apart: 64 or 63.94 px) had pass 1 not put it on the fp16-exact grid of
    // sfx_shared_mb.h. At 64 px every high-tier tap's vertical offset t * 64 is a .5 tie, so a
    // step either way moved whole rows of taps: 4% of channels 3-6e-3 off before that grid.
    ColorGrid c(w, rows);
    Grid z(w, rows, 4.0);
    VelocityGrid vel(w, rows, {3.0, 200.0});
    for (uint32_t y = 0; y < rows; ++y)
        for (uint32_t x = 0; x < w; ++x) {
            const double s = std::sin(6.283185307179586 * double(y) / 1500.0);
            c.values[y * w + x] = {roundToHalf(0.5 + 0.4 * s), roundToHalf(0.5 - 0.3 * s), roundToHalf(0.25 + 0.01 * x), 1.0};
        }
    const test::GpuMotionBlur gpu = test::runMotionBlurPasses(test::device(), profile, c, z, &vel, {});
    const double maxDepth = makeDepthReconstruction(test::motionBlurTestCamera(w, rows), w, rows).value().maxDepth;
    const MotionBlurReferenceResult ref = motionBlur(c, z, vel, p, maxDepth);
    // Pass 1 bit for bit: the codes of this velocity lie far from the midpoints of the grid, so
    // float against double arithmetic cannot round them apart.
    size_t velocityDiffers = 0;
    for (size_t i = 0; i < ref.radiusPx.values.size(); ++i) velocityDiffers += gpu.radiusPx.values[i] != ref.radiusPx.values[i] ? 1 : 0;
    INFO("pass-1 velocity " << gpu.radiusPx.values[0][0] << ", " << gpu.radiusPx.values[0][1] << " px, reference " << ref.radiusPx.values[0][0]
                            << ", " << ref.radiusPx.values[0][1] << "; pixels differing: " << velocityDiffers);
    CHECK(velocityDiffers == 0);
    (void)test::checkMotionBlurConformance(gpu.color, ref.color);
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("sizes: above the device's maximum texture size is a named error", "[sizes]") {
    Device& d = test::device();
    const uint32_t tooWide = d.caps().limits.maxTextureSize + 1;
    AoDesc ao{tooWide, 4, test::tierProfile(), test::aoTestSettings(AoTechnique::Alchemy), DepthKind::Linear};
    Result<std::unique_ptr<AmbientObscurance>> a = AmbientObscurance::create(d, ao);
    INFO(a.status().toString());
    CHECK(a.status().code() == StatusCode::InvalidArgument);
    CHECK(a.status().message().find("width") != std::string::npos);
    Result<std::unique_ptr<MotionBlur>> m = MotionBlur::create(d, {4, tooWide, test::tierProfile(), Format::RGBA16F, DepthKind::Linear});
    INFO(m.status().toString());
    CHECK(m.status().code() == StatusCode::InvalidArgument);
    CHECK(m.status().message().find("height") != std::string::npos);
}

TEST_CASE("sizes: large and odd sizes run every effect with finite output", "[sizes]") {
    if (drawsNothing()) SFX_SKIP("the null backend draws nothing: GPU results are not compared on " << test::label());
    // 641x359 (odd, prime width) every technique; 3840x2160 one technique per effect, to keep
    // the suite short. Only finiteness here: the small sizes above compare with the references.
    struct Run {
        Size size;
        std::vector<AoTechnique> techniques;
    };
    const Run runs[] = {{{641, 359}, {AoTechnique::Alchemy, AoTechnique::Scalable, AoTechnique::Crease, AoTechnique::Horizon}},
                        {{3840, 2160}, {AoTechnique::Scalable}}};
    for (const Run& r : runs) {
        const uint32_t w = r.size.w, h = r.size.h;
        INFO(test::label() << " " << w << "x" << h);
        const tools::AnalyticScene scene = tools::cornerScene(w, h, 1.0);
        for (AoTechnique t : r.techniques) {
            const test::GpuAo gpu = test::runAo(test::device(), test::tierProfile(), scene, test::aoTestSettings(t));
            size_t nonFinite = 0;
            for (double v : gpu.visibility.values) nonFinite += std::isfinite(v) ? 0 : 1;
            INFO(toString(t));
            CHECK(nonFinite == 0);
        }
        ColorGrid c(w, h, {0.5, 0.25, 0.75, 1.0});
        VelocityGrid vel(w, h, {40.0, -7.0});
        const ColorGrid out = test::runMotionBlur(test::device(), test::tierProfile(), c, scene.linearDepth, &vel, {});
        size_t nonFinite = 0;
        for (const auto& px : out.values)
            for (double ch : px) nonFinite += std::isfinite(ch) ? 0 : 1;
        CHECK(nonFinite == 0);
    }
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

namespace {

// True when every value of a raw readback of `format` is finite (half, float) or the format
// cannot hold a non-finite value (unorm).
bool allFinite(Format format, const std::vector<uint8_t>& raw) {
    if (format == Format::R16F || format == Format::RG16F || format == Format::RGBA16F) {
        for (size_t i = 0; i + 1 < raw.size(); i += 2) {
            const uint16_t h = uint16_t(raw[i] | (raw[i + 1] << 8));
            if ((h & 0x7C00u) == 0x7C00u) return false;
        }
        return true;
    }
    if (format == Format::R32F || format == Format::RG32F || format == Format::RGBA32F) {
        for (size_t i = 0; i + 3 < raw.size(); i += 4) {
            float f;
            std::memcpy(&f, &raw[i], 4);
            if (!std::isfinite(f)) return false;
        }
    }
    return true;
}

Status readWhole(Device& d, TextureHandle t, Format* format, std::vector<uint8_t>& raw) {
    Result<TextureDesc> desc = d.textureDesc(t);
    if (!desc) return desc.status();
    *format = desc->format;
    raw.assign(size_t(mipLevelBytes(desc.value(), 0)), 0);
    return d.readTexture(t, 0, raw.data(), raw.size());
}

double secondsSince(std::chrono::steady_clock::time_point t0) { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); }

}  // namespace

TEST_CASE("sizes: 7680x4320 (or the device's maximum) runs every effect once with finite output", "[.][sizes][8k]") {
    if (drawsNothing()) SFX_SKIP("the null backend draws nothing: GPU results are not compared on " << test::label());
    Device& dev = test::device();
    const uint32_t maxSize = dev.caps().limits.maxTextureSize;
    const uint32_t w = std::min<uint32_t>(7680, maxSize), h = std::min<uint32_t>(4320, maxSize);
    INFO(test::label() << " " << w << "x" << h);
    const size_t n = size_t(w) * h;
    // Inputs built directly as the device holds them (no double-precision grids of 33M pixels):
    // a plane tilted in x with a step in y, a colour ramp and a velocity field of up to 40 px.
    std::vector<float> depth(n), velocity(n * 2);
    std::vector<uint16_t> color(n * 4);
    for (size_t i = 0; i < n; ++i) {
        const float x = float(i % w) / float(w), y = float(i / w) / float(h);
        depth[i] = 2.0f + 6.0f * x + (y > 0.5f ? 1.0f : 0.0f);
        velocity[i * 2] = 40.0f * (x - 0.5f), velocity[i * 2 + 1] = -7.0f * y;
        color[i * 4] = floatToHalf(x), color[i * 4 + 1] = floatToHalf(y), color[i * 4 + 2] = floatToHalf(0.5f);
        color[i * 4 + 3] = floatToHalf(1.0f);
    }
    struct Inputs {
        Device& dev;
        TextureHandle depth, color, velocity;
        ~Inputs() {
            for (TextureHandle t : {depth, color, velocity})
                if (!t.isNull()) (void)dev.destroyTexture(t);
        }
    } tex{dev, {}, {}, {}};
    tex.depth = dev.createTexture({w, h, 1, Format::R32F, kTextureSampled, "8k-depth"}).value();
    tex.color = dev.createTexture({w, h, 1, Format::RGBA16F, kTextureSampled | kTextureRenderTarget, "8k-colour"}).value();
    tex.velocity = dev.createTexture({w, h, 1, Format::RG32F, kTextureSampled, "8k-velocity"}).value();
    SFX_REQUIRE_OK(dev.writeTexture(tex.depth, 0, depth.data(), depth.size() * 4));
    SFX_REQUIRE_OK(dev.writeTexture(tex.color, 0, color.data(), color.size() * 2));
    SFX_REQUIRE_OK(dev.writeTexture(tex.velocity, 0, velocity.data(), velocity.size() * 4));
    depth = {}, velocity = {}, color = {};
    PerspectiveDesc pd;
    pd.aspect = double(w) / double(h);
    const CameraProjection camera = makePerspective(pd).value();
    std::vector<uint8_t> raw;
    Format format = Format::Undefined;

    {  // AO, one technique (Scalable: the depth MIP on the high tier), hardware depth in the desc.
        const auto t0 = std::chrono::steady_clock::now();
        const Format of = test::pickFormat(dev, {Format::R16F, Format::R32F, Format::RGBA8}, true);
        TextureHandle out = dev.createTexture({w, h, 1, of, kTextureSampled | kTextureRenderTarget, "8k-ao"}).value();
        auto ao = AmbientObscurance::create(dev, {w, h, test::tierProfile(), test::aoTestSettings(AoTechnique::Scalable), DepthKind::Hardware});
        INFO(ao.status().toString());
        REQUIRE(ao.isOk());
        AoInputs in;
        in.depth = DepthSource{tex.depth, DepthKind::Linear, camera};
        in.output = out;
        SFX_REQUIRE_OK(ao.value()->dispatch(in));
        SFX_REQUIRE_OK(dev.flush());
        SFX_REQUIRE_OK(readWhole(dev, out, &format, raw));
        CHECK(allFinite(format, raw));
        ao.value().reset();
        SFX_REQUIRE_OK(dev.destroyTexture(out));
        std::printf("sizes %s: AO scalable %ux%u in %.2f s\n", test::label().c_str(), w, h, secondsSince(t0));
    }
    {  // Motion blur with a velocity texture.
        const auto t0 = std::chrono::steady_clock::now();
        auto mb = MotionBlur::create(dev, {w, h, test::tierProfile(), Format::RGBA16F, DepthKind::Hardware});
        INFO(mb.status().toString());
        REQUIRE(mb.isOk());
        MotionBlurInputs in;
        in.color = tex.color;
        in.depth = DepthSource{tex.depth, DepthKind::Linear, camera};
        in.velocity = tex.velocity;
        // Default settings: the tier's radius scaled to the height, capped at the 64 px limit.
        SFX_REQUIRE_OK(mb.value()->dispatch(in, {}));
        SFX_REQUIRE_OK(dev.flush());
        SFX_REQUIRE_OK(readWhole(dev, mb.value()->output(), &format, raw));
        CHECK(allFinite(format, raw));
        std::printf("sizes %s: motion blur %ux%u in %.2f s\n", test::label().c_str(), w, h, secondsSince(t0));
    }
    {  // Transparency: three overlapping translucent quads over the colour ramp, no opaque depth.
        const auto t0 = std::chrono::steady_clock::now();
        const test::TranslucentQuads quads(dev, w, h, 0.7f, {0.2f, 0.0f});
        TransparencyDesc desc;
        desc.width = w;
        desc.height = h;
        desc.profile = test::tierProfile();
        // Room for the three layers where they overlap, not the default 4 nodes per pixel (4 GiB here).
        desc.initialPoolNodes = 3 * n / 2;
        auto oit = Transparency::create(dev, desc);
        INFO(oit.status().toString());
        REQUIRE(oit.isOk());
        TransparencyInputs in;
        in.opaqueColor = tex.color;
        in.opaqueDepth = quads.opaqueDepth;
        in.projection = quads.projection;
        in.draws = quads.draws;
        SFX_REQUIRE_OK(oit.value()->render(in));
        SFX_REQUIRE_OK(dev.flush());
        auto st = oit.value()->stats();
        REQUIRE(st.isOk());
        // The pool is bounded by the device's storage buffer size, far below 33M pixels' layers
        // on llvmpipe: what does not fit is dropped and counted (docs/oit.md), never garbage.
        CHECK(st->stored + st->dropped == st->fragments);
        std::printf("sizes %s: transparency %llu fragments, %llu stored, %llu dropped (pool %llu nodes)\n", test::label().c_str(),
                    (unsigned long long)st->fragments, (unsigned long long)st->stored, (unsigned long long)st->dropped,
                    (unsigned long long)st->poolNodes);
        SFX_REQUIRE_OK(readWhole(dev, oit.value()->output(), &format, raw));
        CHECK(allFinite(format, raw));
        oit.value().reset();
        std::printf("sizes %s: transparency %ux%u in %.2f s\n", test::label().c_str(), w, h, secondsSince(t0));
    }
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}
