// The scene renderer's transparency step: scene objects -> TransparentDraws -> sfx::Transparency.
#include "scene_transparency.hpp"

#include <algorithm>
#include <numeric>
#include <string>

#include "sfx/half.hpp"

namespace sfx::render {

Result<std::unique_ptr<SceneTransparency>> SceneTransparency::create(Device& device, const tiers::TierChoice& tier, const scene::Scene& file,
                                                                     const std::vector<size_t>& objects, const std::vector<uint32_t>& drawOrder,
                                                                     uint32_t width, uint32_t height, uint32_t maxLayers,
                                                                     const LayerAoOptions& layerAo) {
    std::vector<uint32_t> order = drawOrder;
    if (order.empty()) {
        order.resize(objects.size());
        std::iota(order.begin(), order.end(), 0u);
    }
    std::vector<uint32_t> sorted = order;
    std::sort(sorted.begin(), sorted.end());
    bool permutation = sorted.size() == objects.size();
    for (size_t i = 0; permutation && i < sorted.size(); ++i) permutation = sorted[i] == i;
    if (!permutation)
        return invalidArgument("RenderOptions.transparentDrawOrder", std::to_string(order.size()) + " entries",
                               "empty or a permutation of 0.." + std::to_string(objects.size() - 1) + " (the scene's " +
                                   std::to_string(objects.size()) + " translucent objects in file order)");

    std::unique_ptr<SceneTransparency> t(new SceneTransparency(device));
    t->width_ = width;
    t->height_ = height;
    TransparencyDesc desc;
    desc.width = width;
    desc.height = height;
    desc.profile = tier.profile;
    desc.colorFormat = Format::RGBA16F;
    desc.depthFormat = Format::D32F;  // the samples' raster pass depth attachment
    desc.quality = maxLayers > keptLayers(TransparencyQuality::Standard) ? TransparencyQuality::High : TransparencyQuality::Standard;
    // AO through the layers where the tier keeps layers and the technique has an opacity-based
    // form (Alchemy, Scalable): the taps read the lists compressed to M nodes.
    if (tier.profile.abufferOit && layerAo.technique && (*layerAo.technique == AoTechnique::Alchemy || *layerAo.technique == AoTechnique::Scalable)) {
        AoSettings s;
        s.technique = *layerAo.technique;
        s.radius = layerAo.radius;
        Result<AoConfig> c = resolveAoConfig(s, tier.profile, 1, height);
        if (!c) return c.status();
        desc.compressedNodes = layerAo.nodes;
        desc.ao.enabled = true;
        desc.ao.config = c.value();
        desc.ao.occluders = TransparencyAoOccluders::Compressed;
        // The raw AO is noisy at the tier's few rotated taps: filtered by depth, as the opaque AO's blur.
        desc.ao.filterRadius = layerAo.filterRadius;
    }
    Result<std::unique_ptr<Transparency>> effect = Transparency::create(device, desc);
    if (!effect) return effect.status();
    t->effect_ = std::move(effect.value());
    Result<TextureHandle> opaque = device.createTexture({width, height, 1, Format::RGBA16F, kTextureSampled, "render-opaque-colour"});
    if (!opaque) return opaque.status();
    t->opaqueColor_ = opaque.value();

    // One vertex buffer per mesh the translucent objects use (objects sharing a mesh share it).
    std::vector<BufferHandle> meshBuffers(file.meshes.size());
    std::vector<uint32_t> meshCounts(file.meshes.size(), 0);
    for (uint32_t k : order) {
        const scene::SceneObject& o = file.objects[objects[k]];
        if (meshBuffers[o.meshIndex].isNull()) {
            const scene::TriangleMesh& mesh = file.meshes[o.meshIndex];
            std::vector<TransparentVertex> v;
            v.reserve(mesh.indices.size());
            for (uint32_t index : mesh.indices) {
                const scene::Vertex& src = mesh.vertices[index];
                v.push_back({{src.position.x, src.position.y, src.position.z}, {src.normal.x, src.normal.y, src.normal.z}});
            }
            const uint64_t bytes = v.size() * sizeof(TransparentVertex);
            Result<BufferHandle> b = device.createBuffer({bytes, kBufferVertex, "render-transparent-vertices"});
            if (!b) return b.status();
            meshBuffers[o.meshIndex] = b.value();
            meshCounts[o.meshIndex] = uint32_t(v.size());
            t->ownedBuffers_.push_back(b.value());
            t->vertexBytes_ += bytes;
            SFX_TRY(device.writeBuffer(b.value(), 0, v.data(), bytes));
        }
    }
    for (uint32_t k : order) {
        const scene::SceneObject& o = file.objects[objects[k]];
        Object d;
        d.vertices = meshBuffers[o.meshIndex];
        d.vertexCount = meshCounts[o.meshIndex];
        d.model = glm::mat4(o.world);
        d.color = glm::vec3(o.color);
        d.opacity = float(o.opacity);
        d.id = uint32_t(objects[k]);  // the object's index in the file: stable whatever the draw order
        t->objects_.push_back(d);
        t->triangles_ += d.vertexCount / 3;
    }
    return t;
}

SceneTransparency::~SceneTransparency() {
    effect_.reset();
    for (BufferHandle b : ownedBuffers_) (void)device_.destroyBuffer(b);
    if (!opaqueColor_.isNull()) (void)device_.destroyTexture(opaqueColor_);
}

std::vector<PlanLine> SceneTransparency::plan() const {
    using K = PlanLine::Kind;
    std::vector<PlanLine> lines;
    const std::string n = std::to_string(objects_.size());
    const std::string path = effect_->usesAbuffer() ? "A-buffer (high tier: fragment stores and atomics)"
                                                    : "weighted blended OIT (current tier: one blend state, no storage)";
    const EffectPlan p = effect_->plan(true);
    for (const PlannedPass& pass : p.passes)
        lines.push_back(
            {K::Pass, "transparency", pass.name, pass.width, pass.height, 0, n + " translucent objects through sfx::Transparency, " + path});
    for (const PlannedResource& r : p.resources) {
        std::string why = r.format == Format::Undefined ? std::string("buffer") : std::string(toString(r.format));
        why += ": held by sfx::Transparency for the " + path;
        lines.push_back({K::Resource, "transparency", r.name, r.width, r.height, r.bytes, why});
    }
    const PlannedResource opaque = plannedTexture("transparency", "opaque colour", {width_, height_, 1, Format::RGBA16F, kTextureSampled});
    lines.push_back({K::Resource, "transparency", "opaque colour", width_, height_, opaque.bytes,
                     "RGBA16F: the host composite uploaded, what the resolve blends the layers over"});
    lines.push_back({K::Resource, "transparency", "vertex buffers", 0, 0, vertexBytes_,
                     "non-indexed TransparentVertex triangle lists, one per mesh the translucent objects use"});
    lines.push_back({K::Host, "transparency", "upload + read back", width_, height_, 0,
                     "the composited opaque picture up to the effect, its output back (the composite runs on the host)"});
    if (effect_->aoThroughLayers()) {
        lines.push_back({K::Host, "transparency", "recomposite with AO through layers", width_, height_, 0,
                         "the opaque picture shaded again with the layer AO's opaque visibility (translucent occluders by "
                         "opacity), composited in one more frame; --ao-out gets the visibility blended through the layers"});
        lines.push_back({K::Omitted, "transparency", "shading of layers", 0, 0, 0,
                         "translucent layers are flat colour x opacity: their own AO is in the blended AO buffer, not in the picture"});
    } else {
        lines.push_back({K::Omitted, "transparency", "shading of layers", 0, 0, 0,
                         effect_->usesAbuffer()
                             ? "translucent objects are flat: colour x opacity; no AO through layers (--ao off or crease)"
                             : "translucent objects are flat: colour x opacity; AO uses the opaque layer only (current tier keeps no layers)"});
    }
    return lines;
}

Status SceneTransparency::render(TextureHandle opaqueDepth, const glm::dmat4& view, const glm::dmat4& projection, io::Image& color,
                                 RenderStats& stats, io::Image* uploaded, const Recomposite& recomposite, io::Image* layerAo) {
    const size_t pixels = size_t(width_) * height_;
    std::vector<uint16_t> halves(pixels * 4);
    auto upload = [&](const io::Image& picture) -> Status {
        for (size_t i = 0; i < pixels; ++i) {
            for (int c = 0; c < 3; ++c) halves[i * 4 + size_t(c)] = floatToHalf(picture.pixels[i * 3 + size_t(c)]);
            halves[i * 4 + 3] = floatToHalf(1.0f);
        }
        if (uploaded) {
            *uploaded = io::Image(width_, height_, 3);
            for (size_t i = 0; i < pixels; ++i)
                for (size_t c = 0; c < 3; ++c) uploaded->pixels[i * 3 + c] = halfToFloat(halves[i * 4 + c]);
        }
        return device_.writeTexture(opaqueColor_, 0, halves.data(), halves.size() * sizeof(uint16_t));
    };
    SFX_TRY(upload(color));

    std::vector<TransparentDraw> draws;
    for (const Object& o : objects_) {
        TransparentDraw d;
        d.vertices = o.vertices;
        d.vertexCount = o.vertexCount;
        d.model = o.model;
        d.color = o.color;
        d.opacity = o.opacity;
        d.id = o.id;
        draws.push_back(d);
    }
    TransparencyInputs in;
    in.opaqueColor = opaqueColor_;
    in.opaqueDepth = opaqueDepth;
    in.view = glm::mat4(view);
    in.projection = glm::mat4(projection);
    in.draws = draws;
    // The first frame's pool is a guess; a frame that dropped fragments is drawn again with the
    // pool the effect sized from its count (a steady scene is exact from its second frame).
    TransparencyStats s;
    for (uint32_t frame = 0; frame < 3; ++frame) {
        SFX_TRY(effect_->render(in));
        SFX_TRY(device_.flush());
        Result<TransparencyStats> r = effect_->stats();
        if (!r) return r.status();
        s = r.value();
        stats.transparencyFrames = frame + 1;
        if (frame == 0) stats.firstFrameDropped = s.dropped;
        if (s.dropped == 0) break;
    }
    if (!effect_->aoOutput().isNull()) {
        std::vector<uint16_t> ao(pixels * 2);
        SFX_TRY(device_.readTexture(effect_->aoOutput(), 0, ao.data(), ao.size() * sizeof(uint16_t)));
        std::vector<float> opaqueVisibility(pixels);
        for (size_t i = 0; i < pixels; ++i) opaqueVisibility[i] = halfToFloat(ao[i * 2 + 1]);
        if (layerAo) {
            *layerAo = io::Image(width_, height_, 1);
            for (size_t i = 0; i < pixels; ++i) layerAo->pixels[i] = halfToFloat(ao[i * 2]);
        }
        if (recomposite) {
            // The same lists, over the opaque picture shaded with the layer AO.
            SFX_TRY(upload(recomposite(opaqueVisibility)));
            SFX_TRY(effect_->render(in));
            SFX_TRY(device_.flush());
            stats.transparencyFrames += 1;
        }
    }
    SFX_TRY(device_.readTexture(effect_->output(), 0, halves.data(), halves.size() * sizeof(uint16_t)));
    for (size_t i = 0; i < pixels; ++i)
        for (size_t c = 0; c < 3; ++c) color.pixels[i * 3 + c] = halfToFloat(halves[i * 4 + c]);
    stats.transparencyRan = true;
    stats.transparentTriangles = triangles_;
    stats.abuffer = effect_->usesAbuffer();
    stats.oit = s;
    stats.meanDepthComplexity = pixels ? double(s.fragments) / double(pixels) : 0.0;
    return Status::ok();
}

}  // namespace sfx::render
