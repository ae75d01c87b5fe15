#include "scene.hpp"

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "sfx/half.hpp"
#include "sfx_scene_shaders.hpp"
#include "sfx_shared_raster.h"

namespace sfx::tools {
namespace {

constexpr double kPi = 3.14159265358979323846;
const char* kBunnyPath = "/usr/share/glmark2/models/bunny.obj";

using scene::addQuad;

Mesh box(glm::vec3 lo, glm::vec3 hi) { return scene::boxMesh(lo, hi); }

Mesh floorPlane(float halfSize, float y = 0.0f) {
    Mesh m;
    addQuad(m, {-halfSize, y, halfSize}, {halfSize, y, halfSize}, {halfSize, y, -halfSize}, {-halfSize, y, -halfSize});
    return m;
}

Mesh sphere(glm::vec3 centre, float radius) { return scene::sphereMesh(centre, radius); }

Mesh cylinder(glm::vec3 base, float radius, float height) { return scene::cylinderMesh(base, radius, height); }

Result<Mesh> loadObj(const std::string& path) {
    Result<scene::TriangleMesh> mesh = scene::loadObjMesh(path);
    if (!mesh) return Status{mesh.status().code(), mesh.status().message() + " (install Debian's glmark2-data)"};
    return Mesh(std::move(mesh.value()));
}

}  // namespace

glm::dmat4 Mesh::modelAt(double time) const {
    glm::dmat4 turned = model;
    if (spinRadians != 0.0)
        turned = glm::translate(glm::dmat4(1.0), spinCentre) * glm::rotate(glm::dmat4(1.0), spinRadians * time, spinAxis) *
            glm::translate(glm::dmat4(1.0), -spinCentre) * model;
    return glm::translate(glm::dmat4(1.0), velocity * time) * turned;
}

glm::dmat4 RasterScene::view(double time) const {
    const glm::dvec3 shift = eyeVelocity * time;
    return glm::lookAt(eye + shift, target + shift, up);
}

Result<CameraProjection> RasterScene::projection(uint32_t width, uint32_t height, ClipDepthRange clipDepth) const {
    PerspectiveDesc pd;
    pd.fovYRadians = fovYDegrees * kPi / 180.0;
    pd.aspect = double(width) / double(height);
    pd.nearPlane = nearPlane;
    pd.farPlane = farPlane;
    pd.clipDepth = clipDepth;
    pd.rowZeroIsTop = true;
    return makePerspective(pd);
}

std::vector<std::string> sceneNames() { return {"corner", "steps", "columns", "contact", "bunny"}; }

RasterScene opaqueScene(const scene::Scene& in) {
    RasterScene out;
    out.name = in.path;
    out.eye = in.camera.position;
    out.target = in.camera.target;
    out.up = in.camera.up;
    out.fovYDegrees = in.camera.fovYDegrees;
    out.nearPlane = in.camera.nearPlane;
    out.farPlane = in.camera.farPlane;
    for (const scene::SceneObject& o : in.objects) {
        if (o.translucent()) continue;
        Mesh m(in.meshes[o.meshIndex]);
        m.model = o.world;
        const double code = o.shading == scene::Shading::Unlit ? shared::SFX_RASTER_SHADING_UNLIT : shared::SFX_RASTER_SHADING_LAMBERT;
        m.surface = glm::dvec4(o.color, code);
        out.meshes.push_back(std::move(m));
    }
    return out;
}

Result<RasterScene> makeScene(const std::string& name) {
    RasterScene s;
    s.name = name;
    if (name == "corner") {
        // Inside a room corner: floor and two walls meet at 90 degrees, a box in the crease.
        s.meshes.push_back(floorPlane(4.0f));
        Mesh back;
        addQuad(back, {-4, 0, -2}, {4, 0, -2}, {4, 4, -2}, {-4, 4, -2});
        s.meshes.push_back(back);
        Mesh side;
        addQuad(side, {-2, 0, 4}, {-2, 0, -4}, {-2, 4, -4}, {-2, 4, 4});
        s.meshes.push_back(side);
        s.meshes.push_back(box({-0.3f, 0, -1.2f}, {0.5f, 0.8f, -0.4f}));
        s.eye = {1.8, 1.6, 2.6};
        s.target = {-0.8, 0.6, -1.0};
    } else if (name == "steps") {
        s.meshes.push_back(floorPlane(5.0f));
        for (int i = 0; i < 6; ++i) {
            const float h = 0.25f * float(i + 1);
            s.meshes.push_back(box({-1.5f, 0, -0.4f * float(i) - 0.4f}, {1.5f, h, -0.4f * float(i)}));
        }
        s.eye = {2.5, 2.2, 2.5};
        s.target = {0, 0.6, -1.2};
    } else if (name == "columns") {
        s.meshes.push_back(floorPlane(6.0f));
        for (int i = 0; i < 5; ++i) s.meshes.push_back(cylinder({-2.0f + float(i), 0, -1.0f}, 0.22f, 2.5f));
        s.meshes.push_back(box({-3, 2.5f, -1.4f}, {3, 2.8f, -0.6f}));  // the lintel
        s.eye = {0.4, 1.4, 3.2};
        s.target = {0, 1.0, -1.0};
    } else if (name == "contact") {
        s.meshes.push_back(floorPlane(4.0f));
        s.meshes.push_back(sphere({0, 0.6f, 0}, 0.6f));
        s.meshes.push_back(sphere({1.3f, 0.3f, 0.4f}, 0.3f));
        s.meshes.push_back(sphere({-1.2f, 0.45f, -0.5f}, 0.45f));
        s.eye = {0, 1.3, 3.0};
        s.target = {0, 0.4, 0};
    } else if (name == "bunny") {
        Result<Mesh> bunny = loadObj(kBunnyPath);
        if (!bunny) return bunny.status();
        // glmark2's bunny spans about [-1, 1]: stand it on the floor.
        double minY = 1e9;
        for (const Vertex& v : bunny->vertices) minY = std::min(minY, double(v.position.y));
        bunny->model = glm::translate(glm::dmat4(1.0), glm::dvec3(0, -minY, 0));
        s.meshes.push_back(floorPlane(4.0f));
        s.meshes.push_back(std::move(bunny.value()));
        s.eye = {1.6, 1.6, 3.2};
        s.target = {0, 0.8, 0};
    } else {
        std::string known;
        for (const auto& n : sceneNames()) known += (known.empty() ? "" : ", ") + n;
        return invalidArgument("scene", "'" + name + "'", known);
    }
    return s;
}

// The raster pass's uniform block, declared once in sfx_shared_raster.h for GLSL and C++.
using shared::RasterParams;

namespace {
// A column-major matrix into a block's mat4 member.
void store(float (&dst)[16], const glm::dmat4& m) {
    const glm::mat4 f(m);
    std::memcpy(dst, glm::value_ptr(f), sizeof dst);
}
}  // namespace

Result<std::unique_ptr<SceneRenderer>> SceneRenderer::create(Device& device, Tier tier, Format albedoFormat) {
    if (albedoFormat != Format::RGBA8 && albedoFormat != Format::RGBA16F)
        return invalidArgument("SceneRenderer albedoFormat", toString(albedoFormat), "RGBA8 or RGBA16F");
    std::unique_ptr<SceneRenderer> r(new SceneRenderer(device, albedoFormat));
    Result<const CompiledProgram*> program = scene_shaders::find(gen::raster_gbuffer::kName, tier);
    if (!program) return program.status();
    Result<ProgramHandle> handle = device.createProgram(*program.value());
    if (!handle) return handle.status();
    r->program_ = handle.value();
    GraphicsPipelineDesc pd;
    pd.program = r->program_;
    pd.vertexLayout.stride = sizeof(Vertex);
    pd.vertexLayout.attributes = {{0, VertexFormat::Float3, 0}, {1, VertexFormat::Float3, 12}};
    pd.depth = {true, true, CompareOp::Less};
    pd.colorFormats = {Format::RGBA16F, Format::RG16F, albedoFormat};
    pd.depthFormat = Format::D32F;
    pd.debugName = "sample-scene-gbuffer";
    Result<PipelineHandle> pipeline = device.createGraphicsPipeline(pd);
    if (!pipeline) return pipeline.status();
    r->pipeline_ = pipeline.value();
    return r;
}

SceneRenderer::~SceneRenderer() {
    releaseMeshes();
    if (!pipeline_.isNull()) (void)device_.destroyPipeline(pipeline_);
    if (!program_.isNull()) (void)device_.destroyProgram(program_);
}

void SceneRenderer::releaseMeshes() {
    for (GpuMesh& m : meshes_) {
        (void)device_.destroyBuffer(m.vertices);
        (void)device_.destroyBuffer(m.indices);
        (void)device_.destroyBuffer(m.params);
    }
    meshes_.clear();
}

Status SceneRenderer::load(const RasterScene& scene) {
    releaseMeshes();
    // Each buffer joins meshes_ as soon as it exists, so a failure part-way releases it too.
    auto upload = [&]() -> Status {
        for (const Mesh& mesh : scene.meshes) {
            GpuMesh& g = meshes_.emplace_back();
            g.source = &mesh;
            g.indexCount = uint32_t(mesh.indices.size());
            Result<BufferHandle> vb = device_.createBuffer({mesh.vertices.size() * sizeof(Vertex), kBufferVertex, "scene-vertices"});
            if (!vb) return vb.status();
            g.vertices = vb.value();
            Result<BufferHandle> ib = device_.createBuffer({mesh.indices.size() * sizeof(uint32_t), kBufferIndex, "scene-indices"});
            if (!ib) return ib.status();
            g.indices = ib.value();
            Result<BufferHandle> pb = device_.createBuffer({sizeof(RasterParams), kBufferUniform, "scene-params"});
            if (!pb) return pb.status();
            g.params = pb.value();
            SFX_TRY(device_.writeBuffer(g.vertices, 0, mesh.vertices.data(), mesh.vertices.size() * sizeof(Vertex)));
            SFX_TRY(device_.writeBuffer(g.indices, 0, mesh.indices.data(), mesh.indices.size() * sizeof(uint32_t)));
        }
        return Status::ok();
    };
    Status s = upload();
    if (!s) releaseMeshes();  // no half-loaded scene: render() then reports it is not loaded
    return s;
}

Result<GBuffer> SceneRenderer::render(const RasterScene& scene, uint32_t width, uint32_t height, double time) {
    if (meshes_.size() != scene.meshes.size())
        return Status{StatusCode::InvalidArgument, "SceneRenderer::render: scene '" + scene.name + "' is not the loaded one"};
    GBuffer g;
    g.width = width;
    g.height = height;
    Result<CameraProjection> camera = scene.projection(width, height, device_.caps().clipDepth);
    if (!camera) return camera.status();
    g.camera = camera.value();

    // Any failure below releases the G-buffer's textures; the caller gets nothing to free.
    auto record = [&]() -> Status {
        const struct {
            TextureHandle* handle;
            Format format;
            const char* name;
        } targets[] = {{&g.depth, Format::D32F, "scene-depth"},
                       {&g.normals, Format::RGBA16F, "scene-normals"},
                       {&g.velocity, Format::RG16F, "scene-velocity"},
                       {&g.albedo, albedoFormat_, "scene-albedo"}};
        for (const auto& t : targets) {
            Result<TextureHandle> texture = device_.createTexture({width, height, 1, t.format, kTextureSampled | kTextureRenderTarget, t.name});
            if (!texture) return texture.status();
            *t.handle = texture.value();
        }
        std::vector<DrawDesc> draws;
        for (const GpuMesh& m : meshes_) {
            const glm::dmat4 modelView = scene.view(time) * m.source->modelAt(time);
            RasterParams p{};
            store(p.modelView, modelView);
            store(p.projection, g.camera.projection);
            store(p.normalMatrix, glm::transpose(glm::inverse(modelView)));
            store(p.shutterOpenClip, g.camera.projection * scene.view(time - 0.5) * m.source->modelAt(time - 0.5));
            store(p.shutterCloseClip, g.camera.projection * scene.view(time + 0.5) * m.source->modelAt(time + 0.5));
            p.viewportSize[0] = float(width);
            p.viewportSize[1] = float(height);
            for (int c = 0; c < 4; ++c) p.surface[c] = float(m.source->surface[c]);
            SFX_TRY(device_.writeBuffer(m.params, 0, &p, sizeof p));
            DrawDesc d;
            d.pipeline = pipeline_;
            d.vertexBuffer = m.vertices;
            d.indexBuffer = m.indices;
            d.count = m.indexCount;
            d.bindings.uniformBuffers = {BufferBinding{gen::raster_gbuffer::RasterParams, m.params, 0, 0}};
            draws.push_back(d);
        }
        RenderPassDesc pass;
        pass.colors = {ColorAttachment{g.normals, 0, LoadOp::Clear, {0, 0, 0, 0}}, ColorAttachment{g.velocity, 0, LoadOp::Clear, {0, 0, 0, 0}},
                       ColorAttachment{g.albedo, 0, LoadOp::Clear, {0, 0, 0, 0}}};
        pass.depth = DepthAttachment{g.depth, LoadOp::Clear, 1.0f};
        pass.debugName = "scene-gbuffer";
        return device_.renderPass(pass, draws);
    };
    if (Status s = record(); !s) {
        destroy(g);
        return s;
    }
    return g;
}

void SceneRenderer::destroy(GBuffer& g) {
    for (TextureHandle* t : {&g.depth, &g.normals, &g.velocity, &g.albedo}) {
        if (!t->isNull()) (void)device_.destroyTexture(*t);
        *t = {};
    }
}

Result<GBufferContents> readBack(Device& device, const GBuffer& g) {
    Result<TextureDesc> albedo = device.textureDesc(g.albedo);
    if (!albedo) return albedo.status();
    if (albedo->format != Format::RGBA8) return invalidArgument("readBack albedo", toString(albedo->format), "RGBA8");
    GBufferContents c;
    c.width = g.width;
    c.height = g.height;
    const size_t n = size_t(g.width) * g.height;
    c.storedDepth.resize(n);
    c.albedo.resize(n * 4);
    std::vector<uint16_t> normals(n * 4), velocity(n * 2);
    SFX_TRY(device.readTexture(g.depth, 0, c.storedDepth.data(), n * sizeof(float)));
    SFX_TRY(device.readTexture(g.normals, 0, normals.data(), normals.size() * sizeof(uint16_t)));
    SFX_TRY(device.readTexture(g.velocity, 0, velocity.data(), velocity.size() * sizeof(uint16_t)));
    SFX_TRY(device.readTexture(g.albedo, 0, c.albedo.data(), c.albedo.size()));
    c.normals.resize(n);
    c.velocity.resize(n);
    for (size_t i = 0; i < n; ++i) {
        c.normals[i] = {halfToFloat(normals[i * 4]), halfToFloat(normals[i * 4 + 1]), halfToFloat(normals[i * 4 + 2])};
        c.velocity[i] = {halfToFloat(velocity[i * 2]), halfToFloat(velocity[i * 2 + 1])};
    }
    return c;
}

}  // namespace sfx::tools
