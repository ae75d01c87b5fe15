// The scene renderer's transparency step (private to sfx_render): the scene file's translucent
// objects (opacity < 1) through sfx::Transparency over the composited opaque picture and the
// raster pass's depth attachment. Exists only when the scene has a translucent object and
// --oit is auto; an opaque scene never creates it, so it has no effect, pool or pass.
#pragma once

#include <glm/glm.hpp>

#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "sfx/oit.hpp"
#include "sfx/scene_render.hpp"

namespace sfx::render {

// AO through the translucent layers (high tier, --ao alchemy or scalable): the effect's
// opacity-based AO with taps reading the lists compressed to `nodes` nodes.
struct LayerAoOptions {
    std::optional<AoTechnique> technique;  // nullopt or Crease: none
    float radius = 0.5f;
    uint32_t nodes = 4;         // M, [1, 4]
    uint32_t filterRadius = 2;  // the layer AO's bilateral filter, taps each side (TransparencyAoDesc::filterRadius)
};

class SceneTransparency {
public:
    // `objects`: indices into file.objects, all translucent, in file order. Each is uploaded once
    // as a non-indexed triangle list of TransparentVertex; its draw id is its index in the file,
    // the same every frame whatever the draw order. `drawOrder` permutes the draws (empty: file
    // order). `maxLayers` is 16 or 32 (validateOptions).
    static Result<std::unique_ptr<SceneTransparency>> create(Device& device, const tiers::TierChoice& tier, const scene::Scene& file,
                                                             const std::vector<size_t>& objects, const std::vector<uint32_t>& drawOrder,
                                                             uint32_t width, uint32_t height, uint32_t maxLayers, const LayerAoOptions& layerAo = {});
    ~SceneTransparency();
    SceneTransparency(const SceneTransparency&) = delete;
    SceneTransparency& operator=(const SceneTransparency&) = delete;

    // The effect's passes and resources, and the renderer's own (opaque colour upload, vertex
    // buffers), each with why it is there.
    std::vector<PlanLine> plan() const;

    // Composites the draws over `color` (linear RGB, the opaque picture; replaced by the result),
    // depth-tested against `opaqueDepth` (D32F, kTextureRenderTarget, never written). A frame that
    // drops fragments (the first frame's pool is a guess) is drawn again with the pool the effect
    // grew from its count, at most twice. Fills the transparency fields of `stats`; `uploaded`,
    // when given, receives the opaque colour exactly as the effect read it (half floats).
    // With AO through the layers, `recomposite` is given the AO's opaque-surface visibility (now
    // with the translucent occluders, opacity-weighted) and returns the opaque picture shaded
    // with it, which is composited in one more frame; `layerAo` receives the blended visibility
    // through the layers (what --ao-out writes).
    using Recomposite = std::function<io::Image(const std::vector<float>& opaqueVisibility)>;
    Status render(TextureHandle opaqueDepth, const glm::dmat4& view, const glm::dmat4& projection, io::Image& color, RenderStats& stats,
                  io::Image* uploaded, const Recomposite& recomposite = {}, io::Image* layerAo = nullptr);
    bool aoThroughLayers() const { return effect_->aoThroughLayers(); }

private:
    SceneTransparency(Device& device) : device_(device) {}
    Device& device_;
    uint32_t width_ = 0, height_ = 0;
    std::unique_ptr<Transparency> effect_;
    TextureHandle opaqueColor_;  // RGBA16F: the host composite, uploaded for the effect to read
    struct Object {
        BufferHandle vertices;
        uint32_t vertexCount = 0;
        glm::mat4 model{1.0f};
        glm::vec3 color{1.0f};
        float opacity = 1.0f;
        uint32_t id = 0;
    };
    std::vector<Object> objects_;             // in draw order
    std::vector<BufferHandle> ownedBuffers_;  // one per mesh, shared by the objects drawing it
    uint64_t vertexBytes_ = 0;
    uint32_t triangles_ = 0;
};

}  // namespace sfx::render
