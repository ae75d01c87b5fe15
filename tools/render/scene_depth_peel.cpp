// Depth peeling for multilayer AO: see scene_depth_peel.hpp.
#include "scene_depth_peel.hpp"

#include <cstring>
#include <glm/gtc/type_ptr.hpp>
#include <tuple>

#include "sfx_scene_shaders.hpp"
#include "sfx_shared_raster.h"

namespace sfx::render {
namespace {

void storeMatrix(float (&dst)[16], const glm::dmat4& m) {
    const glm::mat4 f(m);
    std::memcpy(dst, glm::value_ptr(f), sizeof dst);
}

}  // namespace

Result<std::unique_ptr<DepthPeel>> DepthPeel::create(Device& device, Tier tier, const tools::RasterScene& scene, uint32_t layers, uint32_t width,
                                                     uint32_t height) {
    std::unique_ptr<DepthPeel> p(new DepthPeel(device, width, height));
    Result<std::unique_ptr<LinearDepth>> linear = LinearDepth::create(device, {width, height, tier, 1, DepthKind::Hardware});
    if (!linear) return linear.status();
    p->linear_ = std::move(linear.value());
    Result<const CompiledProgram*> compiled = scene_shaders::find(gen::raster_depth_peel::kName, tier);
    if (!compiled) return compiled.status();
    Result<ProgramHandle> program = device.createProgram(*compiled.value());
    if (!program) return program.status();
    p->program_ = program.value();
    GraphicsPipelineDesc pd;
    pd.program = p->program_;
    pd.vertexLayout.stride = sizeof(tools::Vertex);
    pd.vertexLayout.attributes = {{0, VertexFormat::Float3, 0}};  // positions only: a peel needs no normal
    pd.depth = {true, true, CompareOp::Less};
    pd.colorFormats = {Format::R32F};
    pd.depthFormat = Format::D32F;
    pd.debugName = "render-depth-peel";
    Result<PipelineHandle> pipeline = device.createGraphicsPipeline(pd);
    if (!pipeline) return pipeline.status();
    p->pipeline_ = pipeline.value();

    for (uint32_t l = 1; l < layers; ++l) {
        Result<TextureHandle> t = device.createTexture({width, height, 1, Format::R32F, kTextureSampled | kTextureRenderTarget, "render-ao-layer"});
        if (!t) return t.status();
        p->layers_.push_back(t.value());
    }
    Result<TextureHandle> scratch = device.createTexture({width, height, 1, Format::D32F, kTextureRenderTarget, "render-peel-depth"});
    if (!scratch) return scratch.status();
    p->scratchDepth_ = scratch.value();

    // The peel draws the same meshes as the raster pass from buffers of its own (the samples'
    // renderer keeps its buffers private); the plan counts their bytes.
    for (const tools::Mesh& mesh : scene.meshes) {
        GpuMesh& g = p->meshes_.emplace_back();
        g.indexCount = uint32_t(mesh.indices.size());
        g.model = mesh.model;
        const uint64_t vb = mesh.vertices.size() * sizeof(tools::Vertex), ib = mesh.indices.size() * sizeof(uint32_t);
        for (auto [handle, size, usage] : {std::tuple{&g.vertices, vb, kBufferVertex}, std::tuple{&g.indices, ib, kBufferIndex},
                                           std::tuple{&g.params, uint64_t(sizeof(shared::RasterParams)), kBufferUniform}}) {
            Result<BufferHandle> b = device.createBuffer({size, usage, "render-peel-geometry"});
            if (!b) return b.status();
            *handle = b.value();
            p->geometryBytes_ += size;
        }
        SFX_TRY(device.writeBuffer(g.vertices, 0, mesh.vertices.data(), vb));
        SFX_TRY(device.writeBuffer(g.indices, 0, mesh.indices.data(), ib));
        p->triangles_ += g.indexCount / 3;
    }
    return p;
}

DepthPeel::~DepthPeel() {
    for (GpuMesh& m : meshes_)
        for (BufferHandle b : {m.vertices, m.indices, m.params})
            if (!b.isNull()) (void)device_.destroyBuffer(b);
    for (TextureHandle t : layers_) (void)device_.destroyTexture(t);
    if (!scratchDepth_.isNull()) (void)device_.destroyTexture(scratchDepth_);
    if (!pipeline_.isNull()) (void)device_.destroyPipeline(pipeline_);
    if (!program_.isNull()) (void)device_.destroyProgram(program_);
}

Status DepthPeel::render(const tools::RasterScene& scene, const DepthSource& hardwareDepth) {
    SFX_TRY(linear_->dispatch(hardwareDepth));
    const glm::dmat4 view = scene.view();
    const glm::dmat4& projection = hardwareDepth.camera.projection;
    std::vector<DrawDesc> draws;
    for (const GpuMesh& m : meshes_) {
        const glm::dmat4 modelView = view * m.model;
        shared::RasterParams p{};
        storeMatrix(p.modelView, modelView);
        storeMatrix(p.projection, projection);
        storeMatrix(p.normalMatrix, glm::transpose(glm::inverse(modelView)));
        storeMatrix(p.shutterOpenClip, projection * modelView);  // a still frame: no motion
        storeMatrix(p.shutterCloseClip, projection * modelView);
        p.viewportSize[0] = float(width_);
        p.viewportSize[1] = float(height_);
        SFX_TRY(device_.writeBuffer(m.params, 0, &p, sizeof p));
        DrawDesc d;
        d.pipeline = pipeline_;
        d.vertexBuffer = m.vertices;
        d.indexBuffer = m.indices;
        d.count = m.indexCount;
        d.bindings.uniformBuffers = {BufferBinding{gen::raster_depth_peel::RasterParams, m.params, 0, 0}};
        draws.push_back(d);
    }
    for (size_t l = 0; l < layers_.size(); ++l) {
        const TextureHandle previous = l == 0 ? linear_->texture() : layers_[l - 1];
        for (DrawDesc& d : draws) d.bindings.textures = {TextureBinding{gen::raster_depth_peel::uPreviousLayer, previous, 0, 1, {}}};
        RenderPassDesc pass;
        pass.colors = {ColorAttachment{layers_[l], 0, LoadOp::Clear, {0, 0, 0, 0}}};
        pass.depth = DepthAttachment{scratchDepth_, LoadOp::Clear, 1.0f};
        pass.debugName = "render-depth-peel";
        SFX_TRY(device_.renderPass(pass, draws));
    }
    return Status::ok();
}

std::vector<PlanLine> DepthPeel::plan() const {
    using K = PlanLine::Kind;
    const uint32_t w = width_, h = height_;
    const std::string n = std::to_string(layers_.size() + 1);
    std::vector<PlanLine> out;
    for (const PlannedPass& pass : linear_->plan().passes)
        out.push_back({K::Pass, "ao-layers", "layer 0: " + pass.name, pass.width, pass.height, 0,
                       "linear depth of the first visible surface: the AO's depth and what peel 1 must get behind"});
    for (size_t l = 1; l <= layers_.size(); ++l)
        out.push_back({K::Pass, "ao-layers", "peel layer " + std::to_string(l), w, h, 0,
                       "geometry pass " + std::to_string(l) + " of " + std::to_string(layers_.size()) + " (" + std::to_string(meshes_.size()) +
                           " objects, " + std::to_string(triangles_) + " triangles): the nearest surface strictly behind layer " +
                           std::to_string(l - 1) + ", for --ao-layers " + n});
    for (const PlannedResource& r : linear_->plan().resources)
        out.push_back({K::Resource, "ao-layers", "layer 0 (" + r.name + ")", r.width, r.height, r.bytes,
                       r.format == Format::Undefined
                           ? std::string("uniform buffer: the linearisation's constants")
                           : std::string(toString(r.format)) + ": layer 0's linear depth, which AO reads in place (no linearisation of its own)"});
    for (size_t l = 1; l <= layers_.size(); ++l) {
        const PlannedResource r = plannedTexture("ao-layers", "layer", {w, h, 1, Format::R32F, kTextureSampled | kTextureRenderTarget, "layer"});
        out.push_back({K::Resource, "ao-layers", "layer " + std::to_string(l) + " linear depth", w, h, r.bytes,
                       "R32F: what AO's taps test beside layer 0 (0 where no surface lies behind)"});
    }
    const PlannedResource d = plannedTexture("ao-layers", "peel depth", {w, h, 1, Format::D32F, kTextureRenderTarget, "peel"});
    out.push_back({K::Resource, "ao-layers", "peel depth", w, h, d.bytes, "D32F: each peel pass's nearest-fragment test, cleared per pass"});
    out.push_back({K::Resource, "ao-layers", "peel geometry", 0, 0, geometryBytes_,
                   "vertex, index and uniform buffers: the opaque meshes again, drawn by each peel pass"});
    return out;
}

}  // namespace sfx::render
