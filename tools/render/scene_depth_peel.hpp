// Depth peeling for multilayer AO (`sfx render --ao-layers N`): layer 0 is the raster pass's
// first visible surface, linearised; each of the N - 1 peel passes draws the opaque objects
// again and keeps, per pixel, the nearest fragment strictly behind the layer before
// (raster_depth_peel.frag), writing its linear depth to an R32F texture. The AO effect reads
// layer 0 as its linear depth and the others as AoInputs::depthLayers.
#pragma once

#include <memory>
#include <vector>

#include "scene.hpp"
#include "sfx/depth.hpp"
#include "sfx/scene_render.hpp"

namespace sfx::render {

class DepthPeel {
public:
    // layers: [2, SFX_AO_MAX_DEPTH_LAYERS] (validated by the caller); the tier's programs must
    // have the peel (the high tier's).
    static Result<std::unique_ptr<DepthPeel>> create(Device& device, Tier tier, const tools::RasterScene& scene, uint32_t layers, uint32_t width,
                                                     uint32_t height);
    ~DepthPeel();
    DepthPeel(const DepthPeel&) = delete;
    DepthPeel& operator=(const DepthPeel&) = delete;

    // Linearises the raster pass's depth (layer 0) and records the peel passes.
    Status render(const tools::RasterScene& scene, const DepthSource& hardwareDepth);
    // After render(): layer 0 (R32F linear depth) and layers 1 .. N-1.
    TextureHandle layer0() const { return linear_->texture(); }
    const std::vector<TextureHandle>& peeled() const { return layers_; }
    // The passes and resources, with why, for the renderer's plan.
    std::vector<PlanLine> plan() const;

private:
    DepthPeel(Device& device, uint32_t width, uint32_t height) : device_(device), width_(width), height_(height) {}
    Device& device_;
    uint32_t width_, height_;
    uint32_t triangles_ = 0;
    uint64_t geometryBytes_ = 0;
    std::unique_ptr<LinearDepth> linear_;
    ProgramHandle program_;
    PipelineHandle pipeline_;
    std::vector<TextureHandle> layers_;  // R32F, layers 1 .. N-1
    TextureHandle scratchDepth_;         // D32F: each pass's own nearest-fragment test
    struct GpuMesh {
        BufferHandle vertices, indices, params;
        uint32_t indexCount = 0;
        glm::dmat4 model{1.0};
    };
    std::vector<GpuMesh> meshes_;
};

}  // namespace sfx::render
