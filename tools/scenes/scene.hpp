// Sample scenes for the demo, the benchmarks and the tests: procedural ones built to exercise
// AO (corners, steps, columns, contact) and the Stanford bunny from Debian's glmark2-data,
// rasterised through the HAL into hardware depth and view-space normals.
#pragma once

#include <glm/glm.hpp>

#include <string>
#include <vector>

#include "sfx/camera.hpp"
#include "sfx/hal.hpp"
#include "sfx/mesh_primitives.hpp"
#include "sfx/scene_file.hpp"

namespace sfx::tools {

using Vertex = scene::Vertex;

// Triangles (vertices, indices) placed in the world, possibly moving.
struct Mesh : scene::TriangleMesh {
    Mesh() = default;
    Mesh(scene::TriangleMesh triangles) : scene::TriangleMesh(std::move(triangles)) {}
    glm::dmat4 model{1.0};
    glm::dvec3 velocity{0.0};  // world units per shutter interval (for moving-object demos)
    // Turning: radians per shutter interval about the world axis `spinAxis` through the world
    // point `spinCentre`, applied after `model` and before the translation by `velocity`.
    double spinRadians = 0.0;
    glm::dvec3 spinAxis{0, 1, 0};
    glm::dvec3 spinCentre{0.0};
    // Object to world at `time` shutter intervals from t = 0 (model itself at t = 0).
    glm::dmat4 modelAt(double time) const;
    // RasterParams.surface: rgb linear colour, a the shading code (SFX_RASTER_SHADING_*);
    // a = 0 draws the samples' checkered albedo.
    glm::dvec4 surface{0.0};
};

struct RasterScene {
    std::string name;
    std::vector<Mesh> meshes;
    glm::dvec3 eye{0, 1.5, 5};
    glm::dvec3 target{0, 0.5, 0};
    glm::dvec3 up{0, 1, 0};
    glm::dvec3 eyeVelocity{0.0};  // world units per shutter interval (camera motion blur)
    double fovYDegrees = 60.0;
    double nearPlane = 0.1;
    double farPlane = 100.0;
    glm::dmat4 view(double time = 0.0) const;  // camera at `time` shutter intervals from t = 0
    // The projection render() draws a width x height picture with (row 0 = top).
    Result<CameraProjection> projection(uint32_t width, uint32_t height, ClipDepthRange clipDepth) const;
};

// "corner", "steps", "columns", "contact", "bunny". FileError when the bunny's OBJ is missing
// (package glmark2-data), InvalidArgument naming the known scenes for anything else.
Result<RasterScene> makeScene(const std::string& name);
std::vector<std::string> sceneNames();
// The opaque objects of a scene file as the raster pass draws them (what `sfx render`, its
// depth peel and the truth see): one mesh per object, placed by its world matrix, with its
// colour and shading code; the file's camera.
RasterScene opaqueScene(const scene::Scene& file);

// A G-buffer rendered by the device at mid-shutter, row 0 = top of the picture.
struct GBuffer {
    uint32_t width = 0, height = 0;
    TextureHandle depth;     // D32F hardware depth in the device's clip convention
    TextureHandle normals;   // RGBA16F view-space unit normals (x right, y up, looking down -z); a = 0: nothing drawn
    TextureHandle velocity;  // RG16F pixels across the shutter interval (sfx/motion_blur.hpp convention)
    TextureHandle albedo;    // albedo (Mesh::surface or a checker), a = shading code; a = 0: nothing drawn
    CameraProjection camera;
};

// A G-buffer copied back to the host and decoded, row 0 first: what the CPU references,
// the benchmarks' CPU shading and the demo's pictures read.
struct GBufferContents {
    uint32_t width = 0, height = 0;
    std::vector<float> storedDepth;   // the D32F values as rasterised
    std::vector<glm::vec3> normals;   // view space, from the RGBA16F halves (exact)
    std::vector<glm::vec2> velocity;  // pixels across the shutter interval, from RG16F (exact)
    std::vector<uint8_t> albedo;      // RGBA8 (readBack needs the RGBA8 albedo format)
    bool drawn(size_t i) const { return albedo[i * 4 + 3] != 0; }
};
Result<GBufferContents> readBack(Device& device, const GBuffer& gbuffer);

class SceneRenderer {
public:
    // albedoFormat: RGBA8 (the samples) or RGBA16F (scene files: linear colours kept exact).
    static Result<std::unique_ptr<SceneRenderer>> create(Device& device, Tier tier, Format albedoFormat = Format::RGBA8);
    ~SceneRenderer();
    // Uploads the scene's meshes (replacing the previous scene's); render() draws them.
    Status load(const RasterScene& scene);
    // Renders the loaded scene with its objects moved by `time` * velocity (time in shutter
    // intervals); `scene` supplies the camera and must be the one loaded.
    Result<GBuffer> render(const RasterScene& scene, uint32_t width, uint32_t height, double time = 0.0);
    void destroy(GBuffer& gbuffer);

private:
    SceneRenderer(Device& device, Format albedoFormat) : device_(device), albedoFormat_(albedoFormat) {}
    Device& device_;
    Format albedoFormat_;
    ProgramHandle program_;
    PipelineHandle pipeline_;
    struct GpuMesh {
        const Mesh* source = nullptr;
        BufferHandle vertices, indices, params;  // params: this mesh's RasterParams
        uint32_t indexCount = 0;
    };
    std::vector<GpuMesh> meshes_;
    void releaseMeshes();
};

}  // namespace sfx::tools
