// The scene renderer: scene file -> the samples' G-buffer raster pass -> AO -> composite ->
// translucent objects through sfx::Transparency (scene_transparency.cpp).
#include "sfx/scene_render.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "scene.hpp"
#include "scene_depth_peel.hpp"
#include "scene_transparency.hpp"
#include "sfx/half.hpp"
#include "sfx/settings_ranges.hpp"
#include "sfx_shared_ao.h"
#include "sfx_shared_raster.h"

namespace sfx::render {
namespace {

std::string mib(uint64_t bytes) {
    std::ostringstream s;
    s.precision(3);
    s << double(bytes) / (1024.0 * 1024.0) << " MiB";
    return s.str();
}

std::string aoPassWhy(const PlannedPass& p) {
    if (p.name == "linearize") return "linear depth from the hardware depth, which the AO taps read";
    if (p.name.rfind("depth_mip", 0) == 0) return "depth MIP level the tier's Scalable AO reads for distant taps";
    if (p.name.find("blur") != std::string::npos) return "one direction of the depth-aware bilateral blur of the raw AO";
    return "the ambient obscurance estimate";
}

}  // namespace

Status validateOptions(const RenderOptions& o) {
    if (o.width > scene::kMaxSceneSize)
        return invalidArgument("--width", std::to_string(o.width), "0 (the scene's) or [1, " + std::to_string(scene::kMaxSceneSize) + "]");
    if (o.height > scene::kMaxSceneSize)
        return invalidArgument("--height", std::to_string(o.height), "0 (the scene's) or [1, " + std::to_string(scene::kMaxSceneSize) + "]");
    SFX_TRY(checkSetting(Setting::AoRadius, o.aoRadius, "--ao-radius"));
    SFX_TRY(checkSetting(Setting::AoDepthLayers, o.aoLayers, "--ao-layers"));
    if (o.aoLayers > 1 && !o.ao) return invalidArgument("--ao-layers", std::to_string(o.aoLayers), "1 with --ao off (the layers are for AO)");
    if (o.maxLayers != keptLayers(TransparencyQuality::Standard) && o.maxLayers != keptLayers(TransparencyQuality::High))
        return invalidArgument("--max-layers", std::to_string(o.maxLayers), "16 or 32 (the fragments the A-buffer resolve keeps exact per pixel)");
    // The table's 0 (no compression) is refused here: the renderer's layer AO reads the compressed lists.
    SFX_TRY(checkSetting(Setting::OitCompressedNodes, o.nodes, "--nodes"));
    if (o.nodes == 0) return invalidArgument("--nodes", "0", "at least 1 (AO through the layers reads the compressed lists)");
    return Status::ok();
}

uint64_t FramePlan::totalBytes() const {
    uint64_t total = 0;
    for (const PlanLine& l : lines) total += l.bytes;
    return total;
}

std::string FramePlan::describe() const {
    std::ostringstream s;
    const struct {
        PlanLine::Kind kind;
        const char* title;
    } sections[] = {{PlanLine::Kind::Pass, "passes"},
                    {PlanLine::Kind::Resource, "resources"},
                    {PlanLine::Kind::Host, "host steps"},
                    {PlanLine::Kind::Omitted, "not modelled"}};
    for (const auto& section : sections) {
        s << section.title << ":\n";
        for (const PlanLine& l : lines) {
            if (l.kind != section.kind) continue;
            s << "  " << l.effect << " / " << l.name;
            if (l.width) s << "  " << l.width << "x" << l.height;
            if (l.kind == PlanLine::Kind::Resource) s << "  " << l.bytes << " bytes";
            s << "  -- " << l.why << "\n";
        }
    }
    s << "total GPU memory: " << totalBytes() << " bytes (" << mib(totalBytes()) << ")\n";
    return s.str();
}

std::string RenderStats::describe() const {
    std::ostringstream s;
    s << "objects: " << opaqueObjects << " opaque, " << transparentObjects << " transparent; " << triangles << " opaque triangles\n";
    if (!transparencyRan) {
        s << "transparency: no pass ran (" << (transparentObjects ? "--oit off" : "nothing in the scene is transparent")
          << "): fragments 0, stored 0, dropped 0, pool nodes 0, pool bytes 0\n";
    } else if (!abuffer) {
        s << "transparency: weighted blended OIT, " << transparentTriangles
          << " triangles; no pool and no fragment counts on this path (fragments are blended, not stored)\n";
    } else {
        s << "transparency: A-buffer, " << transparentTriangles << " triangles, " << transparencyFrames << " frame(s)";
        if (firstFrameDropped) s << " (the first frame's guessed pool dropped " << firstFrameDropped << " fragments; redrawn)";
        s << "\n";
        s << "fragments: " << oit.fragments << ", stored: " << oit.stored << ", dropped: " << oit.dropped << ", pool nodes: " << oit.poolNodes
          << ", pool bytes: " << oit.poolBytes << "\n";
        s << "depth complexity: mean " << meanDepthComplexity << " fragments per pixel\n";
    }
    return s.str();
}

struct SceneRender::Impl {
    Device& device;
    tiers::TierChoice tier;
    scene::Scene file;  // a copy: the caller's scene may go away after create()
    RenderOptions options;
    tools::RasterScene scene;
    std::vector<size_t> transparent;
    std::unique_ptr<tools::SceneRenderer> raster;
    std::unique_ptr<AmbientObscurance> ao;
    std::unique_ptr<DepthPeel> peel;                  // only with --ao-layers > 1
    std::unique_ptr<SceneTransparency> transparency;  // only with a translucent object and --oit auto
    TextureHandle aoOutput;
    Format aoFormat = Format::Undefined;
    uint32_t width = 0, height = 0;
    uint32_t triangles = 0;

    Impl(Device& d, const tiers::TierChoice& t, const scene::Scene& f, const RenderOptions& o) : device(d), tier(t), file(f), options(o) {}
    ~Impl() {
        ao.reset();
        peel.reset();
        transparency.reset();
        if (!aoOutput.isNull()) (void)device.destroyTexture(aoOutput);
    }
};

SceneRender::SceneRender(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {
    width_ = impl_->width;
    height_ = impl_->height;
}
SceneRender::~SceneRender() = default;

Result<std::unique_ptr<SceneRender>> SceneRender::create(Device& device, const tiers::TierChoice& tier, const scene::Scene& file,
                                                         const RenderOptions& options) {
    SFX_TRY(validateOptions(options));
    auto impl = std::make_unique<Impl>(device, tier, file, options);
    impl->width = options.width ? options.width : file.width;
    impl->height = options.height ? options.height : file.height;
    impl->scene = tools::opaqueScene(file);
    for (size_t i = 0; i < file.objects.size(); ++i)
        if (file.objects[i].translucent()) impl->transparent.push_back(i);
    for (const tools::Mesh& m : impl->scene.meshes) impl->triangles += uint32_t(m.indices.size() / 3);

    Result<std::unique_ptr<tools::SceneRenderer>> raster = tools::SceneRenderer::create(device, tier.tier, Format::RGBA16F);
    if (!raster) return raster.status();
    impl->raster = std::move(raster.value());
    SFX_TRY(impl->raster->load(impl->scene));

    if (options.ao) {
        AoSettings s;
        s.technique = *options.ao;
        s.radius = options.aoRadius;
        s.normals = AoNormals::FromTexture;
        DepthKind aoDepth = DepthKind::Hardware;
        if (options.aoLayers > 1) {
            if (options.aoLayers > tier.profile.aoMaxDepthLayers)
                return invalidArgument("--ao-layers", std::to_string(options.aoLayers),
                                       "[1, " + std::to_string(tier.profile.aoMaxDepthLayers) + "] on the " + toString(tier.tier) +
                                           " tier (multilayer AO needs the high tier)");
            Result<std::unique_ptr<DepthPeel>> peel = DepthPeel::create(device, tier.tier, impl->scene, options.aoLayers, impl->width, impl->height);
            if (!peel) return peel.status();
            impl->peel = std::move(peel.value());
            s.depthLayers = options.aoLayers;
            aoDepth = DepthKind::Linear;  // layer 0 from the peel's linearisation, read in place
        }
        Result<std::unique_ptr<AmbientObscurance>> ao = AmbientObscurance::create(device, {impl->width, impl->height, tier.profile, s, aoDepth});
        if (!ao) return ao.status();
        impl->ao = std::move(ao.value());
        impl->aoFormat = device.caps().renderableFormat[size_t(Format::R32F)] ? Format::R32F : Format::RGBA8;
        Result<TextureHandle> out = device.createTexture(
            {impl->width, impl->height, 1, impl->aoFormat, kTextureSampled | kTextureRenderTarget, "render-ao"});
        if (!out) return out.status();
        impl->aoOutput = out.value();
    }
    if (!impl->transparent.empty() && options.oit) {
        Result<std::unique_ptr<SceneTransparency>> t = SceneTransparency::create(device, tier, file, impl->transparent, options.transparentDrawOrder,
                                                                                 impl->width, impl->height, options.maxLayers,
                                                                                 LayerAoOptions{options.ao, options.aoRadius, options.nodes});
        if (!t) return t.status();
        impl->transparency = std::move(t.value());
    }
    return std::unique_ptr<SceneRender>(new SceneRender(std::move(impl)));
}

FramePlan SceneRender::plan() const {
    const Impl& m = *impl_;
    const uint32_t w = m.width, h = m.height;
    FramePlan p;
    using K = PlanLine::Kind;
    p.lines.push_back(
        {K::Pass, "scene", "raster", w, h, 0,
         std::to_string(m.scene.meshes.size()) + " opaque objects, " + std::to_string(m.triangles) + " triangles into depth, normals and colour"});
    const struct {
        const char* name;
        Format format;
        const char* why;
    } targets[] = {{"depth", Format::D32F, "hardware depth: visibility, and the depth AO reads"},
                   {"normals", Format::RGBA16F, "view-space normals: lambert shading and AO's tap normals"},
                   {"velocity", Format::RG16F, "written by the shared raster pass (motion blur's input); a still frame leaves it unread"},
                   {"albedo", Format::RGBA16F, "linear colour exact in half floats, shading code in alpha"}};
    for (const auto& t : targets) {
        const PlannedResource r = plannedTexture("scene", t.name, {w, h, 1, t.format, kTextureSampled | kTextureRenderTarget, t.name});
        p.lines.push_back({K::Resource, "scene", t.name, w, h, r.bytes, std::string(toString(t.format)) + ": " + t.why});
    }
    if (m.peel) {
        const std::vector<PlanLine> peel = m.peel->plan();
        p.lines.insert(p.lines.end(), peel.begin(), peel.end());
    }
    if (m.ao) {
        const EffectPlan aoPlan = m.ao->plan();
        const std::string tech = toString(*m.options.ao);
        for (const PlannedPass& pass : aoPlan.passes)
            p.lines.push_back({K::Pass, pass.effect, pass.name, pass.width, pass.height, 0, aoPassWhy(pass)});
        for (const PlannedResource& r : aoPlan.resources)
            p.lines.push_back({K::Resource, r.effect, r.name, r.width, r.height, r.bytes,
                               (r.format == Format::Undefined ? std::string("uniform buffer") : std::string(toString(r.format))) +
                                   ": held by the AO effect (--ao " + tech + ")"});
        const PlannedResource out = plannedTexture("ao", "visibility", {w, h, 1, m.aoFormat, kTextureSampled | kTextureRenderTarget, "ao"});
        p.lines.push_back({K::Resource, "ao", "visibility", w, h, out.bytes,
                           std::string(toString(m.aoFormat)) + ": the AO result the composite multiplies into the ambient term"});
        if (!m.peel)
            p.lines.push_back({K::Omitted, "ao", "multilayer depth", 0, 0, 0, "not asked (--ao-layers 1): AO tests the first visible layer only"});
    } else {
        p.lines.push_back({K::Omitted, "ao", "all", 0, 0, 0, "--ao off: no linear depth, AO or blur passes and no AO textures"});
    }
    p.lines.push_back({K::Host, "composite", "shade", w, h, 0,
                       "lambert: colour * (ambient * AO + light * n.l); unlit: colour exactly; background where nothing is drawn"});
    if (m.transparent.empty()) {
        p.lines.push_back({K::Omitted, "transparency", "oit", 0, 0, 0, "nothing in the scene is transparent: no A-buffer, node pool or OIT pass"});
    } else if (!m.options.oit) {
        p.lines.push_back({K::Omitted, "transparency", "oit", 0, 0, 0,
                           "--oit off: " + std::to_string(m.transparent.size()) + " transparent objects are not drawn"});
    } else {
        const std::vector<PlanLine> t = m.transparency->plan();
        p.lines.insert(p.lines.end(), t.begin(), t.end());
    }
    return p;
}

namespace {

struct ReadTargets {
    std::vector<uint16_t> albedo, normals;  // RGBA16F halves
    std::vector<float> visibility;          // one per pixel; empty without AO
};

Result<ReadTargets> readTargets(Device& device, const tools::GBuffer& g, TextureHandle ao, Format aoFormat) {
    const size_t n = size_t(g.width) * g.height;
    ReadTargets t;
    t.albedo.resize(n * 4);
    t.normals.resize(n * 4);
    SFX_TRY(device.readTexture(g.albedo, 0, t.albedo.data(), t.albedo.size() * sizeof(uint16_t)));
    SFX_TRY(device.readTexture(g.normals, 0, t.normals.data(), t.normals.size() * sizeof(uint16_t)));
    if (ao.isNull()) return t;
    t.visibility.resize(n);
    if (aoFormat == Format::R32F) {
        SFX_TRY(device.readTexture(ao, 0, t.visibility.data(), n * sizeof(float)));
    } else {
        std::vector<uint8_t> px(n * 4);
        SFX_TRY(device.readTexture(ao, 0, px.data(), px.size()));
        for (size_t i = 0; i < n; ++i) t.visibility[i] = px[i * 4] / 255.0f;
    }
    return t;
}

io::Image composite(const ReadTargets& t, uint32_t w, uint32_t h, const glm::dvec3& background) {
    const glm::dvec3 light = glm::normalize(glm::dvec3(kLightDirectionView[0], kLightDirectionView[1], kLightDirectionView[2]));
    io::Image out(w, h, 3);
    for (size_t i = 0; i < size_t(w) * h; ++i) {
        const double code = halfToFloat(t.albedo[i * 4 + 3]);
        const glm::dvec3 albedo(halfToFloat(t.albedo[i * 4]), halfToFloat(t.albedo[i * 4 + 1]), halfToFloat(t.albedo[i * 4 + 2]));
        glm::dvec3 c = background;
        if (code > 0.75) {
            const glm::dvec3 n(halfToFloat(t.normals[i * 4]), halfToFloat(t.normals[i * 4 + 1]), halfToFloat(t.normals[i * 4 + 2]));
            const double ao = t.visibility.empty() ? 1.0 : double(t.visibility[i]);
            c = albedo * (kAmbient * ao + kDirect * std::max(0.0, glm::dot(n, light)));
        } else if (code > 0.0) {
            c = albedo;
        }
        for (int k = 0; k < 3; ++k) out.pixels[i * 3 + k] = float(c[k]);
    }
    return out;
}

}  // namespace

Result<RenderResult> SceneRender::render() {
    Impl& m = *impl_;
    RenderResult result;
    result.plan = plan();
    result.stats.opaqueObjects = uint32_t(m.scene.meshes.size());
    result.stats.transparentObjects = uint32_t(m.transparent.size());
    result.stats.triangles = m.triangles;

    Result<tools::GBuffer> g = m.raster->render(m.scene, m.width, m.height);
    if (!g) return g.status();
    auto work = [&]() -> Status {
        if (m.ao) {
            AoInputs in;
            in.depth = {g->depth, DepthKind::Hardware, g->camera};
            if (m.peel) {
                SFX_TRY(m.peel->render(m.scene, in.depth));
                in.depth = {m.peel->layer0(), DepthKind::Linear, g->camera};
                for (size_t l = 0; l < m.peel->peeled().size(); ++l) in.depthLayers[l] = m.peel->peeled()[l];
            }
            in.normals = g->normals;
            in.output = m.aoOutput;
            SFX_TRY(m.ao->dispatch(in));
        }
        SFX_TRY(m.device.flush());
        Result<ReadTargets> t = readTargets(m.device, g.value(), m.aoOutput, m.aoFormat);
        if (!t) return t.status();
        result.color = composite(t.value(), m.width, m.height, m.file.background);
        if (m.transparency) {
            const glm::dmat4 view = m.scene.view();
            RenderResult::OpaqueInputs kept;
            // With AO through the layers the opaque picture is shaded again with its opaque visibility.
            const ReadTargets& targets = t.value();
            auto recomposite = [&](const std::vector<float>& visibility) {
                ReadTargets shaded = targets;
                shaded.visibility = visibility;
                return composite(shaded, m.width, m.height, m.file.background);
            };
            std::optional<io::Image> layerAo;
            if (m.transparency->aoThroughLayers()) layerAo.emplace();
            SFX_TRY(m.transparency->render(g->depth, view, g->camera.projection, result.color, result.stats,
                                           m.options.keepOpaqueInputs ? &kept.color : nullptr, recomposite, layerAo ? &*layerAo : nullptr));
            if (layerAo) result.ao = std::move(layerAo);
            if (m.options.keepOpaqueInputs) {
                kept.storedDepth.resize(size_t(m.width) * m.height);
                SFX_TRY(m.device.readTexture(g->depth, 0, kept.storedDepth.data(), kept.storedDepth.size() * sizeof(float)));
                kept.view = view;
                kept.projection = g->camera.projection;
                kept.clipDepth = g->camera.clipDepth;
                result.opaque = std::move(kept);
            }
        }
        if (m.ao && !result.ao) {
            io::Image ao(m.width, m.height, 1);
            ao.pixels = t->visibility;
            result.ao = std::move(ao);
        }
        return Status::ok();
    };
    Status s = work();
    m.raster->destroy(g.value());
    SFX_TRY(s);
    if (!m.transparent.empty() && !m.options.oit)
        result.warnings.push_back("--oit off: " + std::to_string(m.transparent.size()) + " transparent objects not drawn");
    return result;
}

double linearToSrgb(double linear) {
    const double v = std::clamp(std::isnan(linear) ? 0.0 : linear, 0.0, 1.0);
    return v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
}

io::Image srgbEncoded(const io::Image& linear) {
    io::Image out = linear;
    for (uint32_t i = 0; i < out.pixels.size(); ++i) {
        const bool alpha = out.channels == 4 && i % 4 == 3;
        if (!alpha) out.pixels[i] = float(linearToSrgb(out.pixels[i]));
    }
    return out;
}

Status writeRendered(const std::string& path, const io::Image& linear, const char* flag) {
    const std::string ext = io::extensionOf(path);
    if (ext == ".png") return io::writePng(path, srgbEncoded(linear));
    if (ext == ".pfm" || ext == ".exr") return io::writeImage(path, linear);
    return invalidArgument(flag, "'" + path + "'", "a .pfm, .exr (linear RGB) or .png (sRGB) file");
}

}  // namespace sfx::render
