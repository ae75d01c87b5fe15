// Precision of the output formats (docs/robustness.md, "Precision"): each effect dispatched into
// every output format it accepts and the device renders holds what the docs say that format
// holds. The same dispatch into the 32-bit float format gives the value before storage; the
// stored value must be within the format's quantisation of it:
//   R8, RGBA8 (unorm):          |stored - value| <= 0.5 / 255   (round to nearest)
//   R16F, RG16F, RGBA16F:       |stored - value| <= 2^-10 |value| + 2^-24   (one fp16 step: the
//                               APIs let a float-to-half conversion round to nearest, 2^-11,
//                               or toward zero, as llvmpipe and lavapipe do; 2^-24 is the
//                               spacing of fp16's subnormals)
//   R32F, RGBA32F:              the value itself
// and its worst pixel against the CPU reference is within the effect's float bound plus that
// quantisation. Small targets: a few dispatches per format. The AO case writes each format's
// worst pixel and mean error against the reference to docs/portability.md's rows.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <sstream>

#include "analytic_scenes.hpp"
#include "effect_runs.hpp"
#include "portability_rows.hpp"
#include "sfx/half.hpp"
#include "sfx/oit.hpp"
#include "skips.hpp"
#include "test_device.hpp"

using namespace sfx;
using namespace sfx::reference;

namespace {

bool drawsNothing() { return test::device().caps().backend == BackendKind::Null; }

uint32_t channels(Format f) {
    switch (f) {
        case Format::R8:
        case Format::R16F:
        case Format::R32F: return 1;
        case Format::RG16F:
        case Format::RG32F: return 2;
        default: return 4;
    }
}
bool isUnorm8(Format f) { return f == Format::R8 || f == Format::RGBA8; }
bool isHalf(Format f) { return f == Format::R16F || f == Format::RG16F || f == Format::RGBA16F; }

// The stated quantisation of `f` around the value v (see the file comment). The float32 formats
// get the rounding of a double reference value to float, the unorm conversion one float ulp of
// slack (v * 255 is computed in float before it is rounded).
double quantisation(Format f, double v) {
    if (isUnorm8(f)) return 0.5 / 255.0 + 1e-6;
    if (isHalf(f)) return std::ldexp(std::abs(v), -10) + std::ldexp(1.0, -24);
    return std::ldexp(std::abs(v), -24);
}

// A texture's level 0 as doubles, `channels(f)` per texel.
std::vector<double> readAsDoubles(Device& d, TextureHandle t, Format f, uint32_t w, uint32_t h) {
    const size_t n = size_t(w) * h * channels(f);
    std::vector<double> out(n);
    if (isUnorm8(f)) {
        std::vector<uint8_t> px(n);
        SFX_REQUIRE_OK(d.readTexture(t, 0, px.data(), px.size()));
        for (size_t i = 0; i < n; ++i) out[i] = px[i] / 255.0;
    } else if (isHalf(f)) {
        std::vector<uint16_t> px(n);
        SFX_REQUIRE_OK(d.readTexture(t, 0, px.data(), px.size() * 2));
        for (size_t i = 0; i < n; ++i) out[i] = double(halfToFloat(px[i]));
    } else {
        std::vector<float> px(n);
        SFX_REQUIRE_OK(d.readTexture(t, 0, px.data(), px.size() * 4));
        for (size_t i = 0; i < n; ++i) out[i] = px[i];
    }
    return out;
}

// RGBA colours stored in `f` (RGBA8, RGBA16F or RGBA32F): the bytes to upload and, in `held`,
// the values the texture then holds.
std::vector<uint8_t> encodeRgba(Format f, const std::vector<glm::dvec4>& colors, std::vector<glm::dvec4>* held) {
    std::vector<uint8_t> bytes;
    held->clear();
    for (const glm::dvec4& c : colors) {
        glm::dvec4 h;
        for (int ch = 0; ch < 4; ++ch) {
            if (f == Format::RGBA8) {
                const uint8_t b = uint8_t(std::lround(std::clamp(c[ch], 0.0, 1.0) * 255.0));
                bytes.push_back(b);
                h[ch] = b / 255.0;
            } else if (f == Format::RGBA16F) {
                const uint16_t v = floatToHalf(float(c[ch]));
                bytes.push_back(uint8_t(v & 0xFF)), bytes.push_back(uint8_t(v >> 8));
                h[ch] = double(halfToFloat(v));
            } else {
                const float v = float(c[ch]);
                uint8_t b[4];
                std::memcpy(b, &v, 4);
                bytes.insert(bytes.end(), b, b + 4);
                h[ch] = v;
            }
        }
        held->push_back(h);
    }
    return bytes;
}

// The formats of `wanted` this device renders (and samples, when `sampled`); the rest are named
// in a warning so a run says what it did not cover.
std::vector<Format> usableFormats(std::initializer_list<Format> wanted, bool sampled) {
    const DeviceCaps& caps = test::device().caps();
    std::vector<Format> out;
    std::ostringstream missing;
    for (Format f : wanted) {
        if (caps.renderableFormat[size_t(f)] && (!sampled || caps.sampledFormat[size_t(f)]))
            out.push_back(f);
        else
            missing << " " << toString(f);
    }
    if (!missing.str().empty()) WARN(test::label() << ": not renderable here, not checked:" << missing.str());
    return out;
}

// The worst of |stored - value| - quantisation over every channel (<= 0 when all hold).
struct Excess {
    double worst = -1.0;
    size_t at = 0;
    void add(double stored, double value, Format f, size_t i) {
        const double e = std::abs(stored - value) - quantisation(f, value);
        if (e > worst) worst = e, at = i;
    }
};

// The AO conformance test's worst-pixel bounds against the reference on its scenes (docs/ao.md):
// float taps against double ones, the intermediate targets' rounding included.
constexpr double kAoWorstPixel[kTierCount] = {0.01, 0.005};

}  // namespace

TEST_CASE("precision: AO output formats hold the visibility to their stated quantisation", "[precision][ao]") {
    if (drawsNothing()) SFX_SKIP("the null backend draws nothing: GPU results are not compared on " << test::label());
    Device& dev = test::device();
    const std::vector<Format> formats = usableFormats(
        {Format::R8, Format::RGBA8, Format::R16F, Format::RG16F, Format::RGBA16F, Format::R32F, Format::RGBA32F}, false);
    const bool haveFloat = dev.caps().renderableFormat[size_t(Format::R32F)];
    const tools::AnalyticScene scene = tools::cornerScene(96, 64, 1.0);
    const uint32_t w = scene.width, h = scene.height;
    const size_t n = size_t(w) * h;
    TextureHandle depth = dev.createTexture({w, h, 1, Format::R32F, kTextureSampled, "precision-depth"}).value();
    {
        std::vector<float> z(scene.linearDepth.values.begin(), scene.linearDepth.values.end());
        SFX_REQUIRE_OK(dev.writeTexture(depth, 0, z.data(), z.size() * 4));
    }
    // Per format, over both dispatches: the worst |stored - reference| and the sum of them, for
    // docs/portability.md.
    std::vector<std::pair<double, double>> againstReference(formats.size());
    // Without blur the AO pass writes the output; with it the second blur pass does.
    for (auto [technique, blur] : {std::pair{AoTechnique::Alchemy, false}, std::pair{AoTechnique::Scalable, true}}) {
        AoSettings s = test::aoTestSettings(technique);
        s.blur = blur;
        auto ao = AmbientObscurance::create(dev, {w, h, test::tierProfile(), s, DepthKind::Linear});
        REQUIRE(ao.isOk());
        auto run = [&](Format f) {
            TextureHandle out = dev.createTexture({w, h, 1, f, kTextureSampled | kTextureRenderTarget, "precision-ao"}).value();
            AoInputs in;
            in.depth = DepthSource{depth, DepthKind::Linear, scene.camera};
            in.output = out;
            SFX_REQUIRE_OK(ao.value()->dispatch(in));
            SFX_REQUIRE_OK(dev.flush());
            std::vector<double> v = readAsDoubles(dev, out, f, w, h);
            SFX_REQUIRE_OK(dev.destroyTexture(out));
            return v;
        };
        const std::vector<double> value = haveFloat ? run(Format::R32F) : std::vector<double>{};
        const Grid ref = ambientVisibility(scene.aoInput(false), ao.value()->config());
        for (size_t k = 0; k < formats.size(); ++k) {
            const Format f = formats[k];
            INFO(test::label() << " " << toString(technique) << (blur ? " blur" : "") << " into " << toString(f));
            const std::vector<double> stored = run(f);
            const uint32_t c = channels(f);
            Excess excess;
            double worstRef = 0;
            for (size_t i = 0; i < n; ++i) {
                const double v = stored[i * c];
                REQUIRE(std::isfinite(v));
                // Every colour channel holds the visibility, alpha (RGBA) is 1.
                for (uint32_t ch = 1; ch < c; ++ch) REQUIRE(stored[i * c + ch] == (ch == 3 ? 1.0 : v));
                if (haveFloat) excess.add(v, value[i], f, i);
                worstRef = std::max(worstRef, std::abs(v - ref.values[i]) - quantisation(f, ref.values[i]));
                againstReference[k].first = std::max(againstReference[k].first, std::abs(v - ref.values[i]));
                againstReference[k].second += std::abs(v - ref.values[i]);
            }
            if (haveFloat) {
                INFO("worst excess over the quantisation " << excess.worst << " at pixel " << excess.at << ": stored " << stored[excess.at * c]
                                                           << ", value " << value[excess.at]);
                CHECK(excess.worst <= 0.0);
            }
            INFO("worst |stored - reference| beyond the quantisation " << worstRef);
            CHECK(worstRef <= kAoWorstPixel[size_t(test::tier())]);
        }
    }
    for (size_t k = 0; k < formats.size(); ++k)
        test::addPortabilityRow(std::string("AO output format ") + toString(formats[k]), againstReference[k].first,
                                againstReference[k].second / double(2 * n));
    SFX_REQUIRE_OK(dev.destroyTexture(depth));
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("precision: motion blur colour formats hold the blurred colour to their stated quantisation", "[precision][motion_blur]") {
    if (drawsNothing()) SFX_SKIP("the null backend draws nothing: GPU results are not compared on " << test::label());
    Device& dev = test::device();
    const std::vector<Format> formats = usableFormats({Format::RGBA8, Format::RGBA16F, Format::RGBA32F}, true);
    const bool haveFloat = dev.caps().renderableFormat[size_t(Format::RGBA32F)] && dev.caps().sampledFormat[size_t(Format::RGBA32F)];
    const uint32_t w = 48, h = 32;
    const size_t n = size_t(w) * h;
    std::mt19937 rng(48032);
    std::uniform_real_distribution<double> u(0.0, 1.0), vel(-5.0, 5.0);
    std::vector<glm::dvec4> colors(n);
    Grid z(w, h);
    VelocityGrid velocity(w, h);
    for (auto& c : colors) c = {u(rng), u(rng), u(rng), 1.0};
    for (auto& d : z.values) d = 2.0 + 6.0 * u(rng);
    for (auto& e : velocity.values) e = {vel(rng), vel(rng)};
    MotionBlurSettings settings;
    settings.maxRadiusPx = 6;
    settings.referenceRows = 0;
    const CameraProjection camera = test::motionBlurTestCamera(w, h);
    const MotionBlurParams params = resolveMotionBlur(test::tierProfile(), settings, h).value();
    const double maxDepth = makeDepthReconstruction(camera, w, h).value().maxDepth;

    TextureHandle depth = dev.createTexture({w, h, 1, Format::R32F, kTextureSampled, "precision-mb-depth"}).value();
    TextureHandle velTex = dev.createTexture({w, h, 1, Format::RG32F, kTextureSampled, "precision-mb-velocity"}).value();
    {
        std::vector<float> zf(z.values.begin(), z.values.end()), vf;
        for (const auto& e : velocity.values) vf.push_back(float(e[0])), vf.push_back(float(e[1]));
        SFX_REQUIRE_OK(dev.writeTexture(depth, 0, zf.data(), zf.size() * 4));
        SFX_REQUIRE_OK(dev.writeTexture(velTex, 0, vf.data(), vf.size() * 4));
    }
    // The blur of `input` (held in `f`, uploaded as `f`), read back.
    auto run = [&](Format f, const std::vector<glm::dvec4>& input) {
        std::vector<glm::dvec4> held;
        const std::vector<uint8_t> bytes = encodeRgba(f, input, &held);
        TextureHandle color = dev.createTexture({w, h, 1, f, kTextureSampled, "precision-mb-colour"}).value();
        SFX_REQUIRE_OK(dev.writeTexture(color, 0, bytes.data(), bytes.size()));
        auto mb = MotionBlur::create(dev, {w, h, test::tierProfile(), f, DepthKind::Linear});
        REQUIRE(mb.isOk());
        MotionBlurInputs in;
        in.color = color;
        in.depth = DepthSource{depth, DepthKind::Linear, camera};
        in.velocity = velTex;
        SFX_REQUIRE_OK(mb.value()->dispatch(in, settings));
        SFX_REQUIRE_OK(dev.flush());
        std::vector<double> out = readAsDoubles(dev, mb.value()->output(), f, w, h);
        SFX_REQUIRE_OK(dev.destroyTexture(color));
        return out;
    };
    for (Format f : formats) {
        INFO(test::label() << " colour " << toString(f));
        std::vector<glm::dvec4> held;
        (void)encodeRgba(f, colors, &held);
        const std::vector<double> stored = run(f, held);
        // The value before storage: the same blur from the same held colours, in float.
        const std::vector<double> value = haveFloat ? run(Format::RGBA32F, held) : std::vector<double>{};
        ColorGrid in(w, h);
        for (size_t i = 0; i < n; ++i) in.values[i] = {held[i].r, held[i].g, held[i].b, held[i].a};
        const ColorGrid ref = motionBlur(in, z, velocity, params, maxDepth).color;
        Excess excess;
        size_t far = 0;
        for (size_t i = 0; i < n * 4; ++i) {
            REQUIRE(std::isfinite(stored[i]));
            if (haveFloat) excess.add(stored[i], value[i], f, i);
            const double r = ref.values[i / 4][int(i % 4)];
            // The motion blur conformance bound (2e-3 per channel, at most 3% beyond) plus the quantisation.
            if (std::abs(stored[i] - r) > 2e-3 + quantisation(f, r)) ++far;
        }
        if (haveFloat) {
            INFO("worst excess over the quantisation " << excess.worst << " at channel " << excess.at << ": stored " << stored[excess.at]
                                                       << ", value " << value[excess.at]);
            CHECK(excess.worst <= 0.0);
        }
        INFO("channels beyond 2e-3 plus the quantisation: " << far << " of " << n * 4);
        CHECK(double(far) <= 0.03 * double(n * 4));
    }
    SFX_REQUIRE_OK(dev.destroyTexture(depth));
    SFX_REQUIRE_OK(dev.destroyTexture(velTex));
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("precision: transparency colour formats hold the composite to their stated quantisation", "[precision][oit]") {
    if (drawsNothing()) SFX_SKIP("the null backend draws nothing: GPU results are not compared on " << test::label());
    Device& dev = test::device();
    const std::vector<Format> formats = usableFormats({Format::RGBA8, Format::RGBA16F, Format::RGBA32F}, true);
    if (!(dev.caps().renderableFormat[size_t(Format::RGBA32F)] && dev.caps().sampledFormat[size_t(Format::RGBA32F)]))
        SFX_SKIP(test::label() << " renders no RGBA32F: no float composite to compare the stored ones with");
    const uint32_t w = 32, h = 16;
    const size_t n = size_t(w) * h;
    std::mt19937 rng(3216);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<glm::dvec4> opaque(n);
    for (auto& c : opaque) c = {u(rng), u(rng), u(rng), 1.0};
    const test::TranslucentQuads quads(dev, w, h, 0.8f, {0.3f, 0.1f});
    auto run = [&](Format f, const std::vector<glm::dvec4>& input) {
        std::vector<glm::dvec4> held;
        const std::vector<uint8_t> bytes = encodeRgba(f, input, &held);
        TextureHandle color = dev.createTexture({w, h, 1, f, kTextureSampled | kTextureRenderTarget, "precision-oit-opaque"}).value();
        SFX_REQUIRE_OK(dev.writeTexture(color, 0, bytes.data(), bytes.size()));
        TransparencyDesc desc;
        desc.width = w;
        desc.height = h;
        desc.profile = test::tierProfile();
        desc.colorFormat = f;
        auto oit = Transparency::create(dev, desc);
        INFO(oit.status().toString());
        REQUIRE(oit.isOk());
        TransparencyInputs in;
        in.opaqueColor = color;
        in.opaqueDepth = quads.opaqueDepth;
        in.projection = quads.projection;
        in.draws = quads.draws;
        SFX_REQUIRE_OK(oit.value()->render(in));
        SFX_REQUIRE_OK(dev.flush());
        std::vector<double> out = readAsDoubles(dev, oit.value()->output(), f, w, h);
        SFX_REQUIRE_OK(dev.destroyTexture(color));
        return out;
    };
    for (Format f : formats) {
        INFO(test::label() << " colour " << toString(f));
        std::vector<glm::dvec4> held;
        (void)encodeRgba(f, opaque, &held);
        const std::vector<double> stored = run(f, held);
        const std::vector<double> value = run(Format::RGBA32F, held);
        Excess excess;
        for (size_t i = 0; i < n * 4; ++i) {
            REQUIRE(std::isfinite(stored[i]));
            excess.add(stored[i], value[i], f, i);
        }
        INFO("worst excess over the quantisation " << excess.worst << " at channel " << excess.at << ": stored " << stored[excess.at] << ", value "
                                                   << value[excess.at]);
        CHECK(excess.worst <= 0.0);
    }
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}
