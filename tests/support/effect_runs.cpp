#include "effect_runs.hpp"

#include <catch2/catch.hpp>

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "bench_device.hpp"
#include "sfx/half.hpp"
#include "sfx_shared.h"
#include "sfx_shared_mb.h"
#include "test_device.hpp"

namespace sfx::test {

using namespace sfx::reference;

Format pickFormat(Device& device, std::initializer_list<Format> wanted, bool renderable) {
    const DeviceCaps& caps = device.caps();
    for (Format f : wanted)
        if (renderable ? caps.renderableFormat[size_t(f)] : caps.sampledFormat[size_t(f)]) return f;
    return Format::RGBA8;
}

double bentRounding(Format f) { return (f == Format::RGBA8 ? 2.0 / 255.0 : f == Format::RGBA16F ? 1.0 / 2048.0 : 0.0) + 1e-6; }

int bentIntermediates(const AoConfig& config) {
    const bool blur = config.blurRadius > 0;
    if (!blur && !config.halfResolution) return 0;
    return 1 + (blur ? 1 : 0) + (blur && config.halfResolution ? 1 : 0);
}

double bentComponentBound(double directionAllowance, double vectorLength, double resolveLength, Format intermediate, int intermediates,
                          Format output) {
    const double raw = directionAllowance / vectorLength;
    return (raw + std::sqrt(3.0) * intermediates * bentRounding(intermediate)) / resolveLength + bentRounding(output);
}

GpuAo runAo(Device& dev, const TierProfile& tier, const tools::AnalyticScene& scene, const AoSettings& settings, DepthKind descInput,
            Format bentFormat) {
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
    TextureHandle bentTex;
    if (settings.bentNormals)
        bentTex = dev.createTexture({scene.width, scene.height, 1, bentFormat, kTextureSampled | kTextureRenderTarget, "ao-test-bent"}).value();

    AoInputs in;
    in.depth = DepthSource{depthTex, DepthKind::Linear, scene.camera};
    in.normals = normalTex;
    in.output = outTex;
    in.bentNormals = bentTex;
    SFX_REQUIRE_OK(ao.value()->dispatch(in));
    SFX_REQUIRE_OK(dev.flush());
    Result<Grid> visibility = tools::readVisibility(dev, outTex, of, scene.width, scene.height);
    SFX_REQUIRE_OK(visibility.status());
    GpuAo result{std::move(visibility.value()), ao.value()->config(), ao.value()->plan(), {}};
    if (settings.bentNormals) {
        Result<std::vector<glm::dvec3>> bent = tools::readBentNormals(dev, bentTex, bentFormat, scene.width, scene.height);
        SFX_REQUIRE_OK(bent.status());
        result.bentNormals = std::move(bent.value());
    }
    for (TextureHandle t : {depthTex, normalTex, outTex, bentTex})
        if (!t.isNull()) SFX_REQUIRE_OK(dev.destroyTexture(t));
    return result;
}

std::vector<std::vector<float>> syntheticDepthLayers(const tools::AnalyticScene& s, uint32_t layers) {
    std::vector<std::vector<float>> out(layers, std::vector<float>(size_t(s.width) * s.height, 0.0f));
    for (uint32_t y = 0; y < s.height; ++y)
        for (uint32_t x = 0; x < s.width; ++x) {
            const size_t i = size_t(y) * s.width + x;
            const double z0 = s.linearDepth.values[i];
            out[0][i] = float(z0);
            if (!(z0 < s.reconstruction.maxDepth)) continue;
            uint32_t l = 1;
            double z = z0;
            if ((x / 8 + y / 8) % 3 == 0) {
                out[0][i] = float(0.6 * z0);
                out[1][i] = float(z0);
                l = 2;
            }
            for (; l < layers; ++l) {
                if ((x / 3 + y / 2 + l) % 5 == 0) break;  // no surface behind this one
                z += 0.12 * (1.0 + 0.5 * std::sin(0.3 * x + l) * std::cos(0.2 * y));
                out[l][i] = float(z);
            }
        }
    return out;
}

GpuMultilayerAo runMultilayerAo(Device& dev, const TierProfile& tier, const tools::AnalyticScene& scene, AoTechnique technique,
                                const std::vector<std::vector<float>>& layers) {
    AoSettings s = aoTestSettings(technique, 1.0);
    s.blur = false;  // the references are the raw estimate
    s.resolution = AoResolution::Full;
    s.depthLayers = uint32_t(layers.size());
    auto ao = AmbientObscurance::create(dev, {scene.width, scene.height, tier, s, DepthKind::Linear});
    INFO(ao.status().toString());
    REQUIRE(ao.isOk());
    std::vector<TextureHandle> textures;
    for (const std::vector<float>& d : layers) {
        TextureHandle tex = dev.createTexture({scene.width, scene.height, 1, Format::R32F, kTextureSampled, "ml-layer"}).value();
        SFX_REQUIRE_OK(dev.writeTexture(tex, 0, d.data(), d.size() * sizeof(float)));
        textures.push_back(tex);
    }
    TextureHandle out = dev.createTexture({scene.width, scene.height, 1, Format::R32F, kTextureSampled | kTextureRenderTarget, "ml-out"}).value();
    AoInputs in;
    in.depth = DepthSource{textures[0], DepthKind::Linear, scene.camera};
    for (size_t l = 1; l < layers.size(); ++l) in.depthLayers[l - 1] = textures[l];
    in.output = out;
    SFX_REQUIRE_OK(ao.value()->dispatch(in));
    SFX_REQUIRE_OK(dev.flush());
    std::vector<float> px(size_t(scene.width) * scene.height);
    SFX_REQUIRE_OK(dev.readTexture(out, 0, px.data(), px.size() * sizeof(float)));
    GpuMultilayerAo r{Grid(scene.width, scene.height), ao.value()->config(), ao.value()->linearDepth().reconstruction()};
    for (size_t i = 0; i < px.size(); ++i) r.visibility.values[i] = px[i];
    for (TextureHandle tex : textures) SFX_REQUIRE_OK(dev.destroyTexture(tex));
    SFX_REQUIRE_OK(dev.destroyTexture(out));
    return r;
}

AoSettings aoTestSettings(AoTechnique t, double scale) {
    AoSettings s;
    s.technique = t;
    s.radius = float(0.5 * scale);
    // The papers' look, not the tier's calibrated one, which would move the analytic expectations.
    s.intensity = t == AoTechnique::Scalable ? 2.0f : 1.0f;
    s.radiusExponent = 0.0f;               // one intensity at every radius, as the papers
    s.metresPerUnit = float(1.0 / scale);  // a scaled scene is the same scene in other units
    s.contrast = 1.0f;
    if (t == AoTechnique::Alchemy || t == AoTechnique::Scalable) s.bias = t == AoTechnique::Alchemy ? kAoAlchemyDefaultBias : kAoScalableDefaultBias;
    s.crease.bias = 0.25f;
    s.crease.range = 2.0f;  // the article's 1 world unit (times scale), in units of the radius
    s.crease.fadeStart = float(50 * scale);
    s.crease.fadeEnd = float(100 * scale);
    return s;
}

MotionScene movingAndStillLayersScene() {
    MotionScene scene{96, 54, {}};
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

MotionBlurGpuInputs::MotionBlurGpuInputs(Device& d, const ColorGrid& colorGrid, const Grid& depthGrid, const VelocityGrid* velocityGrid) : device(d) {
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
GpuMotionBlur runMotionBlurPasses(Device& d, const TierProfile& tier, const ColorGrid& color, const Grid& depth, const VelocityGrid* velocity,
                                  const MotionBlurSettings& s, const CameraMotion& camera, DepthKind descInput) {
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
    std::vector<uint16_t> out(size_t(w) * h * 4), packed(size_t(w) * h * 4);
    SFX_REQUIRE_OK(d.readTexture(mb.value()->output(), 0, out.data(), out.size() * 2));
    SFX_REQUIRE_OK(d.readTexture(mb.value()->packedVelocity(), 0, packed.data(), packed.size() * 2));
    GpuMotionBlur result{ColorGrid(w, h), VelocityGrid(w, h)};
    for (size_t i = 0; i < result.color.values.size(); ++i) {
        for (size_t c = 0; c < 4; ++c) result.color.values[i][c] = double(halfToFloat(out[i * 4 + c]));
        for (size_t c = 0; c < 2; ++c) result.radiusPx.values[i][c] = double(halfToFloat(packed[i * 4 + c]));
    }
    return result;
}

ColorGrid runMotionBlur(Device& d, const TierProfile& tier, const ColorGrid& color, const Grid& depth, const VelocityGrid* velocity,
                        const MotionBlurSettings& s, const CameraMotion& camera, DepthKind descInput) {
    return runMotionBlurPasses(d, tier, color, depth, velocity, s, camera, descInput).color;
}

size_t checkMotionBlurConformance(const ColorGrid& gpu, const ColorGrid& ref) {
    REQUIRE(gpu.values.size() == ref.values.size());
    size_t far = 0;
    for (size_t i = 0; i < ref.values.size(); ++i)
        for (size_t ch = 0; ch < 4; ++ch) {
            REQUIRE(std::isfinite(gpu.values[i][ch]));
            if (std::abs(gpu.values[i][ch] - ref.values[i][ch]) > 2e-3) ++far;
        }
    INFO("channels beyond 2e-3: " << far << " of " << ref.values.size() * 4);
    CHECK(double(far) <= 0.03 * double(ref.values.size() * 4));
    return far;
}

TranslucentQuads::TranslucentQuads(Device& d, uint32_t w, uint32_t h, float halfExtent, glm::vec2 step) : device(d) {
    opaqueDepth = d.createTexture({w, h, 1, Format::D32F, kTextureSampled | kTextureRenderTarget, "test-quads-opaque-depth"}).value();
    {
        const std::vector<float> far(size_t(w) * h, 1.0f);
        SFX_REQUIRE_OK(d.writeTexture(opaqueDepth, 0, far.data(), far.size() * 4));
    }
    const float corners[6][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, -1}, {1, 1}, {-1, 1}};
    std::vector<TransparentVertex> quad;
    for (const auto& c : corners) quad.push_back({{c[0] * halfExtent, c[1] * halfExtent, 0.0f}, {0.0f, 0.0f, 1.0f}});
    vertices = d.createBuffer({quad.size() * sizeof(TransparentVertex), kBufferVertex, "test-quads"}).value();
    SFX_REQUIRE_OK(d.writeBuffer(vertices, 0, quad.data(), quad.size() * sizeof(TransparentVertex)));
    for (uint32_t i = 0; i < 3; ++i) {
        TransparentDraw draw;
        draw.vertices = vertices;
        draw.vertexCount = 6;
        const float fi = float(i);
        draw.model = glm::translate(glm::mat4(1.0f), glm::vec3(step.x * (fi - 1.0f), step.y * fi, -2.0f - fi));
        draw.color = glm::vec3(0.9f - 0.3f * fi, 0.35f + 0.2f * fi, 0.2f + 0.3f * fi);
        draw.opacity = 0.3f + 0.2f * fi;
        draw.id = i;
        draws.push_back(draw);
    }
    const bool zeroToOne = d.caps().clipDepth == ClipDepthRange::ZeroToOne;
    projection[2][2] = zeroToOne ? -1.0f / 19.5f : -2.0f / 19.5f;
    projection[3][2] = zeroToOne ? -0.5f / 19.5f : -1.0f / 19.5f - 1.0f;
}

GpuTransparency runTransparency(Device& d, const TransparencyDesc& desc, const std::vector<glm::dvec4>& opaqueColor,
                                const std::vector<float>& opaqueDepth, const glm::mat4& view, const glm::mat4& projection,
                                std::span<const TransparentDraw> draws) {
    const uint32_t w = desc.width, h = desc.height;
    const size_t n = size_t(w) * h;
    REQUIRE(opaqueColor.size() == n);
    REQUIRE(opaqueDepth.size() == n);
    auto created = Transparency::create(d, desc);
    INFO(created.status().toString());
    REQUIRE(created.isOk());
    std::unique_ptr<Transparency> oit = std::move(created.value());
    std::vector<uint16_t> halves;
    for (const glm::dvec4& c : opaqueColor)
        for (int ch = 0; ch < 4; ++ch) halves.push_back(floatToHalf(float(c[ch])));
    TextureHandle color = d.createTexture({w, h, 1, Format::RGBA16F, kTextureSampled | kTextureRenderTarget, "test-oit-opaque"}).value();
    TextureHandle depth = d.createTexture({w, h, 1, Format::D32F, kTextureSampled | kTextureRenderTarget, "test-oit-depth"}).value();
    SFX_REQUIRE_OK(d.writeTexture(color, 0, halves.data(), halves.size() * 2));
    SFX_REQUIRE_OK(d.writeTexture(depth, 0, opaqueDepth.data(), opaqueDepth.size() * 4));
    TransparencyInputs in;
    in.opaqueColor = color;
    in.opaqueDepth = depth;
    in.view = view;
    in.projection = projection;
    in.draws = draws;
    for (int f = 0; f < 2; ++f) {
        SFX_REQUIRE_OK(oit->render(in));
        SFX_REQUIRE_OK(d.flush());
    }
    GpuTransparency g;
    std::vector<uint16_t> out(n * 4);
    SFX_REQUIRE_OK(d.readTexture(oit->output(), 0, out.data(), out.size() * 2));
    for (uint16_t v : out) g.color.push_back(double(halfToFloat(v)));
    if (!oit->aoOutput().isNull()) {
        std::vector<uint16_t> ao(n * 2);
        SFX_REQUIRE_OK(d.readTexture(oit->aoOutput(), 0, ao.data(), ao.size() * 2));
        for (uint16_t v : ao) g.ao.push_back(double(halfToFloat(v)));
    }
    Result<TransparencyStats> stats = oit->stats();
    REQUIRE(stats.isOk());
    g.stats = stats.value();
    oit.reset();
    SFX_REQUIRE_OK(d.destroyTexture(color));
    SFX_REQUIRE_OK(d.destroyTexture(depth));
    return g;
}

TranslucentQuads::~TranslucentQuads() {
    if (!vertices.isNull()) (void)device.destroyBuffer(vertices);
    if (!opaqueDepth.isNull()) (void)device.destroyTexture(opaqueDepth);
}

}  // namespace sfx::test
