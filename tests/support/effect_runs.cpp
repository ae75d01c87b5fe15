#include "effect_runs.hpp"

#include <catch2/catch.hpp>

#include <cmath>

#include "sfx/half.hpp"
#include "test_device.hpp"

namespace sfx::test {

using namespace sfx::reference;

Format pickFormat(Device& device, std::initializer_list<Format> wanted, bool renderable) {
    const DeviceCaps& caps = device.caps();
    for (Format f : wanted)
        if (renderable ? caps.renderableFormat[size_t(f)] : caps.sampledFormat[size_t(f)]) return f;
    return Format::RGBA8;
}

GpuAo runAo(Device& dev, const TierProfile& tier, const samples::AnalyticScene& scene, const AoSettings& settings,
            DepthKind descInput) {
    AoDesc desc{scene.width, scene.height, tier, settings, descInput};
    Result<std::unique_ptr<AmbientObscurance>> ao = AmbientObscurance::create(dev, desc);
    INFO(ao.status().toString());
    REQUIRE(ao.isOk());

    std::vector<float> depth(scene.linearDepth.values.begin(), scene.linearDepth.values.end());
    TextureHandle depthTex = dev.createTexture({scene.width, scene.height, 1, Format::R32F, kTextureSampled, "ao-test-depth"}).value();
    SFX_REQUIRE_OK(dev.writeTexture(depthTex, 0, depth.data(), depth.size() * sizeof(float)));
    TextureHandle normalTex;
    if (settings.normals == AoNormals::FromTexture) {
        const Format nf = pickFormat(dev, {Format::RGBA32F, Format::RGBA16F}, false);
        normalTex = dev.createTexture({scene.width, scene.height, 1, nf, kTextureSampled, "ao-test-normals"}).value();
        if (nf == Format::RGBA32F) {
            std::vector<float> n;
            for (const glm::dvec3& v : scene.normals) n.insert(n.end(), {float(v.x), float(v.y), float(v.z), 0.0f});
            SFX_REQUIRE_OK(dev.writeTexture(normalTex, 0, n.data(), n.size() * sizeof(float)));
        } else {
            std::vector<uint8_t> n;
            for (const glm::dvec3& v : scene.normals)
                for (double c : {v.x, v.y, v.z, 1.0}) n.push_back(uint8_t(std::lround((c * 0.5 + 0.5) * 255.0)));
            SFX_REQUIRE_OK(dev.writeTexture(normalTex, 0, n.data(), n.size()));
        }
    }
    const Format of = pickFormat(dev, {Format::R32F, Format::R16F, Format::RGBA8}, true);
    TextureHandle outTex = dev.createTexture({scene.width, scene.height, 1, of, kTextureSampled | kTextureRenderTarget, "ao-test-out"}).value();

    AoInputs in;
    in.depth = DepthSource{depthTex, DepthKind::Linear, scene.camera};
    in.normals = normalTex;
    in.output = outTex;
    SFX_REQUIRE_OK(ao.value()->dispatch(in));
    SFX_REQUIRE_OK(dev.flush());
    GpuAo result{Grid(scene.width, scene.height), ao.value()->config(), ao.value()->plan()};
    const size_t n = size_t(scene.width) * scene.height;
    if (of == Format::R32F) {
        std::vector<float> px(n);
        SFX_REQUIRE_OK(dev.readTexture(outTex, 0, px.data(), px.size() * sizeof(float)));
        for (size_t i = 0; i < n; ++i) result.visibility.values[i] = px[i];
    } else if (of == Format::RGBA8) {
        std::vector<uint8_t> px(n * 4);
        SFX_REQUIRE_OK(dev.readTexture(outTex, 0, px.data(), px.size()));
        for (size_t i = 0; i < n; ++i) result.visibility.values[i] = px[i * 4] / 255.0;
    } else {
        std::vector<uint16_t> px(n);
        SFX_REQUIRE_OK(dev.readTexture(outTex, 0, px.data(), px.size() * 2));
        for (size_t i = 0; i < n; ++i) result.visibility.values[i] = double(halfToFloat(px[i]));
    }
    for (TextureHandle t : {depthTex, normalTex, outTex})
        if (!t.isNull()) SFX_REQUIRE_OK(dev.destroyTexture(t));
    return result;
}

AoSettings aoTestSettings(AoTechnique t, double scale) {
    AoSettings s;
    s.technique = t;
    s.radius = float(0.5 * scale);
    if (t == AoTechnique::Scalable) s.intensity = 2.0f;
    s.crease.range = float(scale);
    s.crease.fadeStart = float(50 * scale);
    s.crease.fadeEnd = float(100 * scale);
    return s;
}

Scene movingAndStillLayersScene() {
    Scene scene{96, 54, {}};
    SceneLayer bg;
    bg.depth = 30, bg.cell = 6, bg.colorA = {0.25, 0.3, 0.35, 1}, bg.colorB = {0.6, 0.55, 0.5, 1}, bg.velocityPx = {-6, 2};
    SceneLayer disc;
    disc.shape = SceneLayer::Shape::Disc, disc.depth = 8, disc.centre = {40, 26}, disc.halfSize = {12, 0};
    disc.cell = 3, disc.colorA = {1, 0.8, 0.2, 1}, disc.colorB = {0.9, 0.1, 0.1, 1}, disc.velocityPx = {22, 6};
    SceneLayer post;  // still, in front of everything
    post.shape = SceneLayer::Shape::Rect, post.depth = 3, post.centre = {70, 27}, post.halfSize = {4, 30};
    post.colorA = {0.1, 0.9, 0.3, 1};
    scene.layers = {bg, disc, post};
    return scene;
}

MotionBlurGpuInputs::MotionBlurGpuInputs(Device& d, const ColorGrid& colorGrid, const Grid& depthGrid,
                                         const VelocityGrid* velocityGrid)
    : device(d) {
    const uint32_t w = colorGrid.width, h = colorGrid.height;
    color = d.createTexture({w, h, 1, Format::RGBA16F, kTextureSampled, "mb-test-color"}).value();
    std::vector<uint16_t> c;
    for (const auto& px : colorGrid.values)
        for (double ch : px) c.push_back(floatToHalf(float(roundToHalf(ch))));
    SFX_REQUIRE_OK(d.writeTexture(color, 0, c.data(), c.size() * 2));
    depth = d.createTexture({w, h, 1, Format::R32F, kTextureSampled, "mb-test-depth"}).value();
    std::vector<float> z(depthGrid.values.begin(), depthGrid.values.end());
    SFX_REQUIRE_OK(d.writeTexture(depth, 0, z.data(), z.size() * 4));
    if (velocityGrid) {
        velocity = d.createTexture({w, h, 1, Format::RG32F, kTextureSampled, "mb-test-velocity"}).value();
        std::vector<float> v;
        for (const auto& e : velocityGrid->values) v.push_back(float(e[0])), v.push_back(float(e[1]));
        SFX_REQUIRE_OK(d.writeTexture(velocity, 0, v.data(), v.size() * 4));
    }
}

MotionBlurGpuInputs::~MotionBlurGpuInputs() {
    for (TextureHandle t : {color, depth, velocity})
        if (!t.isNull()) (void)device.destroyTexture(t);
}

CameraProjection motionBlurTestCamera(uint32_t w, uint32_t h) {
    PerspectiveDesc pd;
    pd.aspect = double(w) / h;
    return makePerspective(pd).value();
}

// descInput: what the effect is told it will get. The depth is linear, so Linear reads it where
// it lies (no linearisation pass); Hardware copies it into LinearDepth's texture first.
ColorGrid runMotionBlur(Device& d, const TierProfile& tier, const ColorGrid& color, const Grid& depth,
                        const VelocityGrid* velocity, const MotionBlurSettings& s, const CameraMotion& camera,
                        DepthKind descInput) {
    const uint32_t w = color.width, h = color.height;
    MotionBlurGpuInputs in(d, color, depth, velocity);
    Result<std::unique_ptr<MotionBlur>> mb = MotionBlur::create(d, {w, h, tier, Format::RGBA16F, descInput});
    INFO(mb.status().toString());
    REQUIRE(mb.isOk());
    MotionBlurInputs inputs;
    inputs.color = in.color;
    inputs.depth = {in.depth, DepthKind::Linear, motionBlurTestCamera(w, h)};
    inputs.velocity = in.velocity;
    inputs.camera = camera;
    SFX_REQUIRE_OK(mb.value()->dispatch(inputs, s));
    SFX_REQUIRE_OK(d.flush());
    std::vector<uint16_t> out(size_t(w) * h * 4);
    SFX_REQUIRE_OK(d.readTexture(mb.value()->output(), 0, out.data(), out.size() * 2));
    ColorGrid result(w, h);
    for (size_t i = 0; i < result.values.size(); ++i)
        for (int c = 0; c < 4; ++c) result.values[i][c] = double(halfToFloat(out[i * 4 + size_t(c)]));
    return result;
}

}  // namespace sfx::test
