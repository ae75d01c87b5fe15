// Hostile values on the GPU path: NaN, +-infinity, denormals and values at the formats' limits,
// uploaded with writeTexture straight into the effects' input textures (no tool in between).
// Each input follows one rule of the shared headers (sfx_shared*.h), which the CPU references
// apply as well; every output texel must be finite and agree with the reference. Each case adds
// its rows (effect, input, rule, backend, tier, result) to extremes_rows.md in the run's output
// directory; tests/check_extremes_doc.sh assembles docs/robustness_extremes.md from them.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <random>

#include "analytic_scenes.hpp"
#include "effect_runs.hpp"
#include "sfx/depth.hpp"
#include "sfx/half.hpp"
#include "sfx/reference/depth_reference.hpp"
#include "skips.hpp"
#include "test_device.hpp"

using namespace sfx;
using namespace sfx::reference;

namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kFloatMax = std::numeric_limits<float>::max();
constexpr float kDenormal = std::numeric_limits<float>::denorm_min() * 1024.0f;  // 1.4e-42
constexpr float kHalfMax = 65504.0f;

struct Hostile {
    const char* name;
    float value;
};

// The backend column: the backend, and the driver when it is not Mesa's llvmpipe (lavapipe on
// Vulkan), which runs every backend in the test run: "vulkan (SwiftShader Device)". Each
// driver's rows then have a key of their own in the document.
std::string backendColumn() {
    const std::string backend = toString(test::backendConfig()), driver = test::driverName();
    return driver == "llvmpipe" ? backend : backend + " (" + driver + ")";
}

// One row of the extremes table; the file is started afresh by the first row of the run.
void addRow(const std::string& effect, const std::string& input, const std::string& rule, bool passed) {
    static bool first = true;
    std::ofstream out(test::outputDir() + "/extremes_rows.md", first ? std::ios::trunc : std::ios::app);
    first = false;
    out << "| " << effect << " | " << input << " | " << rule << " | " << backendColumn() << " | " << toString(test::tier()) << " | "
        << (passed ? "finite, matches reference" : "FAILED") << " |\n";
}

bool drawsNothing() { return test::device().caps().backend == BackendKind::Null; }

bool allFinite(const std::vector<double>& v) {
    for (double x : v)
        if (!std::isfinite(x)) return false;
    return true;
}

// Pixels (x, y) the hostile values go to: two per value, `spacing` apart on a grid of 6 columns.
std::vector<std::pair<uint32_t, uint32_t>> pokeSites(size_t values, uint32_t spacing) {
    std::vector<std::pair<uint32_t, uint32_t>> sites;
    for (uint32_t k = 0; k < values * 2; ++k) sites.push_back({3 + (k % 6) * spacing, 3 + (k / 6) * spacing});
    return sites;
}

// ---- Ambient obscurance ---------------------------------------------------------------------

const AoTechnique kTechniques[] = {AoTechnique::Alchemy, AoTechnique::Scalable, AoTechnique::Crease, AoTechnique::Horizon};
// Per-pixel bound of the AO conformance test (its pixelTol, docs/ao.md): float-vs-double taps.
double aoPixelTolerance() { return test::tier() == Tier::High ? 0.03 : 0.05; }

// GPU vs reference around the poked pixels (the pixel and its 4 neighbours) and finiteness
// everywhere; the rest of the image is what the AO conformance test already bounds.
bool aoAgreesAround(const Grid& gpu, const Grid& ref, const std::vector<std::pair<uint32_t, uint32_t>>& sites) {
    bool ok = allFinite(gpu.values);
    for (auto [px, py] : sites)
        for (auto [dx, dy] : {std::pair{0, 0}, std::pair{-1, 0}, std::pair{1, 0}, std::pair{0, -1}, std::pair{0, 1}}) {
            const uint32_t x = uint32_t(int(px) + dx), y = uint32_t(int(py) + dy);
            const double e = std::abs(gpu.at(x, y) - ref.at(x, y));
            if (!(e <= aoPixelTolerance())) {
                UNSCOPED_INFO("(" << x << ", " << y << "): gpu " << gpu.at(x, y) << " reference " << ref.at(x, y));
                ok = false;
            }
        }
    return ok;
}

}  // namespace

TEST_CASE("extremes: hostile linear depth is sky in AO", "[extremes][ao]") {
    if (drawsNothing()) SFX_SKIP("the null backend draws nothing: GPU results are not compared on " << test::label());
    const Hostile values[] = {
        {"NaN", kNaN},       {"+inf", kInf},          {"-inf", -kInf}, {"denormal", kDenormal}, {"0", 0.0f}, {"-float max", -kFloatMax},
        {"65504", kHalfMax}, {"float max", kFloatMax}};
    tools::AnalyticScene scene = tools::cornerScene(48, 36, 1.0);
    const auto sites = pokeSites(std::size(values), 7);
    for (size_t k = 0; k < sites.size(); ++k) scene.linearDepth.at(sites[k].first, sites[k].second) = values[k % std::size(values)].value;
    bool ok = true;
    for (AoTechnique t : kTechniques)
        for (bool blur : {false, true}) {
            AoSettings s = test::aoTestSettings(t);
            s.blur = blur;
            INFO(test::label() << " " << toString(t) << (blur ? " blur" : ""));
            const test::GpuAo gpu = test::runAo(test::device(), test::tierProfile(), scene, s);
            const Grid ref = ambientVisibility(scene.aoInput(false), gpu.config);
            bool runOk = aoAgreesAround(gpu.visibility, ref, sites);
            for (auto [x, y] : sites) runOk = runOk && gpu.visibility.at(x, y) == 1.0;  // sky: unoccluded
            CHECK(runOk);
            ok = ok && runOk;
        }
    for (const Hostile& v : values) addRow("AO", std::string("linear depth R32F ") + v.name, "sky (sfxLinearDepthOrFar)", ok);
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("extremes: unusable host normals fall back to the derived normal", "[extremes][ao]") {
    if (drawsNothing()) SFX_SKIP("the null backend draws nothing: GPU results are not compared on " << test::label());
    if (test::pickFormat(test::device(), {Format::RGBA32F}, false) != Format::RGBA32F)
        SFX_SKIP("RGBA32F cannot be sampled on " << test::label() << ": hostile float normals need it");
    struct HostileNormal {
        const char* name;
        glm::dvec3 n;
        const char* rule;
    };
    const char* derived = "derived from depth (aoHostNormalOrZero)";
    const HostileNormal normals[] = {{"zero", {0, 0, 0}, derived},
                                     {"NaN", {kNaN, 0, 1}, derived},
                                     {"+inf", {kInf, 0, 0}, derived},
                                     {"-inf", {0, -kInf, 1}, derived},
                                     {"denormal", {kDenormal, kDenormal, 0}, derived},
                                     {"float max", {kFloatMax, kFloatMax, kFloatMax}, "normalised, no overflow"},
                                     {"65504 x true normal", {}, "normalised, no overflow"}};
    tools::AnalyticScene scene = tools::cornerScene(48, 36, 1.0);
    const auto sites = pokeSites(std::size(normals), 7);
    for (size_t k = 0; k < sites.size(); ++k) {
        glm::dvec3& n = scene.normals[size_t(sites[k].second) * scene.width + sites[k].first];
        const HostileNormal& h = normals[k % std::size(normals)];
        n = h.name[0] == '6' ? n * double(kHalfMax) : h.n;
    }
    bool ok = true;
    for (AoTechnique t : kTechniques) {
        AoSettings s = test::aoTestSettings(t);
        s.blur = false;
        s.normals = AoNormals::FromTexture;
        INFO(test::label() << " " << toString(t));
        const test::GpuAo gpu = test::runAo(test::device(), test::tierProfile(), scene, s);
        const bool runOk = aoAgreesAround(gpu.visibility, ambientVisibility(scene.aoInput(true), gpu.config), sites);
        CHECK(runOk);
        ok = ok && runOk;
    }
    for (const HostileNormal& h : normals) addRow("AO", std::string("normal RGBA32F ") + h.name, h.rule, ok);
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("extremes: hostile hardware depth linearises to sky", "[extremes][depth]") {
    if (drawsNothing()) SFX_SKIP("the null backend draws nothing: GPU results are not compared on " << test::label());
    Device& device = test::device();
    const uint32_t W = 17, H = 9;
    PerspectiveDesc pd;
    pd.nearPlane = 0.1;
    pd.farPlane = 100.0;
    pd.aspect = double(W) / H;
    const CameraProjection cam = makePerspective(pd).value();
    const DepthReconstruction rec = makeDepthReconstruction(cam, W, H).value();
    const Hostile values[] = {
        {"NaN", kNaN},           {"+inf", kInf},           {"-inf", -kInf},        {"-1", -1.0f}, {"2", 2.0f}, {"float max", kFloatMax},
        {"denormal", kDenormal}, {"0 (near plane)", 0.0f}, {"1 (far plane)", 1.0f}};
    struct Source {
        Format format;
        const char* name;
        bool floatStore;
    };
    for (const Source& src : {Source{Format::R32F, "R32F", true}, Source{Format::D32F, "D32F", true}, Source{Format::D24S8, "D24S8", false}}) {
        if (!device.caps().sampledFormat[size_t(src.format)]) continue;
        INFO(test::label() << " " << src.name);
        // GL clamps depth-component uploads to [0, 1] (its rule for depth formats), so there a
        // D32F texture cannot hold a hostile value: only R32F can, and D32F gets the range's ends.
        const bool gl = device.caps().backend == BackendKind::GL || device.caps().backend == BackendKind::GLES;
        const bool holdsAny = src.floatStore && !(gl && src.format == Format::D32F);
        auto stores = [&](float v) { return holdsAny || (v >= 0.0f && v <= 1.0f && v != kDenormal); };
        // A ramp of in-range depths with the hostile values in the first texels; D24S8 holds only
        // [0, 1], so its extremes are the two ends of the range.
        Grid stored(W, H);
        for (uint32_t i = 0; i < W * H; ++i) stored.values[i] = 0.5 + 0.4 * double(i) / double(W * H);
        size_t poked = 0;
        for (const Hostile& v : values)
            if (stores(v.value)) stored.values[poked++] = v.value;
        std::vector<uint32_t> words(size_t(W) * H);
        for (size_t i = 0; i < words.size(); ++i) {
            const float f = float(stored.values[i]);
            if (src.floatStore) {
                std::memcpy(&words[i], &f, 4);
            } else {
                words[i] = uint32_t(std::lround(double(f) * 16777215.0)) << 8;
                stored.values[i] = double(words[i] >> 8) / 16777215.0;
            }
        }
        const Grid expected = linearizeDepth(stored, rec);
        TextureHandle t = device.createTexture({W, H, 1, src.format, kTextureSampled, "extremes-hardware-depth"}).value();
        SFX_REQUIRE_OK(device.writeTexture(t, 0, words.data(), words.size() * 4));
        auto linear = LinearDepth::create(device, {W, H, test::tier(), 1});
        REQUIRE(linear.isOk());
        SFX_REQUIRE_OK(linear.value()->dispatch({t, DepthKind::Hardware, cam}));
        std::vector<float> got(size_t(W) * H);
        SFX_REQUIRE_OK(device.readTexture(linear.value()->texture(), 0, got.data(), got.size() * 4));
        // Sky is exactly maxDepth on both sides; a surface within a few float roundings of the
        // divide (1e-6 relative, as the depth conformance test's bound is for these depths).
        bool ok = true;
        for (size_t i = 0; i < got.size(); ++i) {
            const double want = expected.values[i];
            const bool match = std::isfinite(got[i]) && std::abs(double(got[i]) - want) <= 1e-6 * want;
            if (!match) UNSCOPED_INFO("texel " << i << " stored " << stored.values[i] << " want " << want << " got " << got[i]);
            ok = ok && match;
        }
        CHECK(ok);
        (void)device.destroyTexture(t);
        for (size_t i = 0; i < std::size(values); ++i) {
            const Hostile& v = values[i];
            if (!stores(v.value)) continue;
            const bool inRange = v.value >= 0.0f && v.value < 1.0f;
            addRow("depth", std::string("hardware depth ") + src.name + " " + v.name,
                   inRange ? "linearised (sfxLinearizeDepth)" : "sky (outside [0, 1] or far plane)", ok);
        }
    }
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

namespace {

// ---- Motion blur ----------------------------------------------------------------------------

// GPU vs reference, relative to the value's size (colours up to 65504): the motion blur
// conformance test's 2e-3 per channel, at most 3% of channels beyond it (docs/motion_blur.md).
bool motionBlurAgrees(const ColorGrid& gpu, const ColorGrid& ref) {
    size_t far = 0, n = 0;
    for (size_t i = 0; i < gpu.values.size(); ++i)
        for (int c = 0; c < 4; ++c, ++n) {
            if (!std::isfinite(gpu.values[i][c])) return false;
            if (std::abs(gpu.values[i][c] - ref.values[i][c]) > 2e-3 * std::max(1.0, std::abs(ref.values[i][c]))) ++far;
        }
    UNSCOPED_INFO("channels beyond 2e-3 (relative): " << far << " of " << n);
    return double(far) <= 0.03 * double(n);
}

struct MotionBlurCase {
    ColorGrid color;
    Grid depth;
    VelocityGrid velocity;
};

// Hostile velocities clamp to the radius (6), and two velocities of equal length in one
// neighbourhood make the tile max a tie that float and double may break differently: the sites
// lie 20 px apart (more than 3 tiles), and the ordinary velocities stay below the radius.
constexpr uint32_t kMbSpacing = 20, kMbWidth = 126, kMbHeight = 66;

MotionBlurCase motionBlurBase(uint32_t w, uint32_t h) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(0.0, 1.0), v(-3.0, 3.0);
    MotionBlurCase c{ColorGrid(w, h), Grid(w, h), VelocityGrid(w, h)};
    for (auto& px : c.color.values) px = {roundToHalf(u(rng)), roundToHalf(u(rng)), roundToHalf(u(rng)), 1.0};
    for (auto& z : c.depth.values) z = 2.0 + 6.0 * u(rng);
    for (auto& e : c.velocity.values) e = {v(rng), v(rng)};
    return c;
}

bool runAndCompare(const MotionBlurCase& c) {
    MotionBlurSettings s;
    s.maxRadiusPx = 6;
    s.referenceRows = 0;
    const ColorGrid gpu = test::runMotionBlur(test::device(), test::tierProfile(), c.color, c.depth, &c.velocity, s);
    const MotionBlurParams p = resolveMotionBlur(test::tierProfile(), s, c.color.height).value();
    const uint32_t w = c.color.width, h = c.color.height;
    const double maxDepth = makeDepthReconstruction(test::motionBlurTestCamera(w, h), w, h).value().maxDepth;
    return motionBlurAgrees(gpu, motionBlur(c.color, c.depth, c.velocity, p, maxDepth).color);
}

}  // namespace

TEST_CASE("extremes: hostile velocities are still or clamped in their direction", "[extremes][motion_blur]") {
    if (drawsNothing()) SFX_SKIP("the null backend draws nothing: GPU results are not compared on " << test::label());
    struct HostileVelocity {
        const char* name;
        std::array<double, 2> v;
        const char* rule;
    };
    const char* still = "still (mbClampVelocity)";
    const char* clamped = "clamped to the radius, same direction";
    const HostileVelocity velocities[] = {{"(NaN, 1)", {kNaN, 1}, still},
                                          {"(1, NaN)", {1, kNaN}, still},
                                          {"(+inf, 3)", {kInf, 3}, "clamped along +x"},
                                          {"(-inf, +inf)", {-kInf, kInf}, "clamped along the diagonal"},
                                          {"(1e6, -2e5)", {1e6, -2e5}, clamped},
                                          {"(float max, float max)", {kFloatMax, kFloatMax}, clamped},
                                          {"(65504, 65520)", {kHalfMax, 65520.0}, clamped},
                                          {"denormal", {kDenormal, -kDenormal}, "still (below the still threshold)"}};
    MotionBlurCase c = motionBlurBase(kMbWidth, kMbHeight);
    const auto sites = pokeSites(std::size(velocities), kMbSpacing);
    for (size_t k = 0; k < sites.size(); ++k) c.velocity.at(sites[k].first, sites[k].second) = velocities[k % std::size(velocities)].v;
    const bool ok = runAndCompare(c);
    CHECK(ok);
    for (const HostileVelocity& v : velocities) addRow("motion blur", std::string("velocity RG32F ") + v.name, v.rule, ok);
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("extremes: hostile colour is not spread to its neighbours", "[extremes][motion_blur]") {
    if (drawsNothing()) SFX_SKIP("the null backend draws nothing: GPU results are not compared on " << test::label());
    const char* dropped = "left out of gathers; reads 0 itself";
    const Hostile values[] = {{"NaN", kNaN},       {"+inf", kInf},        {"-inf", -kInf},
                              {"65504", kHalfMax}, {"-65504", -kHalfMax}, {"half denormal", float(std::ldexp(1.0, -24))}};
    MotionBlurCase c = motionBlurBase(kMbWidth, kMbHeight);
    const auto sites = pokeSites(std::size(values), kMbSpacing);
    for (size_t k = 0; k < sites.size(); ++k) {
        auto& px = c.color.at(sites[k].first, sites[k].second);
        px[k % 4] = values[k % std::size(values)].value;  // one channel per site, each channel in turn
    }
    const bool ok = runAndCompare(c);
    CHECK(ok);
    for (const Hostile& v : values)
        addRow("motion blur", std::string("colour RGBA16F ") + v.name, std::isfinite(v.value) ? "gathered as it is" : dropped, ok);
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("extremes: hostile linear depth is sky in motion blur", "[extremes][motion_blur]") {
    if (drawsNothing()) SFX_SKIP("the null backend draws nothing: GPU results are not compared on " << test::label());
    const Hostile values[] = {{"NaN", kNaN}, {"+inf", kInf}, {"-inf", -kInf}, {"0", 0.0f}, {"denormal", kDenormal}, {"float max", kFloatMax}};
    MotionBlurCase c = motionBlurBase(kMbWidth, kMbHeight);
    const auto sites = pokeSites(std::size(values), kMbSpacing);
    for (size_t k = 0; k < sites.size(); ++k) c.depth.at(sites[k].first, sites[k].second) = values[k % std::size(values)].value;
    const bool ok = runAndCompare(c);
    CHECK(ok);
    for (const Hostile& v : values) addRow("motion blur", std::string("linear depth R32F ") + v.name, "sky (sfxLinearDepthOrFar)", ok);
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}
