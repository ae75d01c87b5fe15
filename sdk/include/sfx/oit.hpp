// Order-independent transparency (docs/oit.md): translucent draws composited over the host's
// opaque colour, whatever order they are drawn in.
//
// High tier (TierProfile::abufferOit and caps.fragmentStoresAndAtomics): an A-buffer (Bauer et
// al. 2013): clear, fill (one depth-tested geometry pass; each fragment takes a pool node with one
// atomic, no locks or waits), resolve (per pixel the nearest K fragments by (depth, draw id,
// primitive id) exact, the rest folded into one tail layer, over the opaque colour). The output
// never depends on draw order. Optional: list compression to M <= 4 nodes per pixel, and
// opacity-based AO through the layers into aoOutput().
//
// Current tier: weighted blended OIT (McGuire and Bavoil 2013), an approximation for view depths
// of about 0.1 to 500 units (docs/oit.md gives the measured error); no AO through the layers.
//
// The pool follows the scene: each render() resizes it from the previous frame's fragment count
// times kOitPoolHeadroom. A frame that overflows it stores `capacity` fragments, counts the rest
// (TransparencyStats::dropped), never reads or writes outside it, and the next render() grows it.
// Nothing is allocated until a render() has a transparent draw; with none, output() is the
// opaque colour itself.
#pragma once

#include <glm/glm.hpp>

#include <functional>
#include <memory>
#include <optional>
#include <span>

#include "sfx/ao.hpp"
#include "sfx/camera.hpp"
#include "sfx/hal.hpp"
#include "sfx/plan.hpp"
#include "sfx/tier.hpp"

namespace sfx {

// The pool holds this many times the fragments the scene last produced.
inline constexpr double kOitPoolHeadroom = 1.5;
// Nodes per pixel of the first frame's pool, before any count is known.
inline constexpr uint32_t kOitInitialNodesPerPixel = 4;
// Bytes per A-buffer node (sfx_shared_oit.h's 8 words).
inline constexpr uint32_t kOitNodeBytes = 32;

// One vertex of a transparent mesh: object-space position and normal (12 + 12 bytes).
struct TransparentVertex {
    float position[3];
    float normal[3];
};

// One transparent draw: a non-indexed triangle list of TransparentVertex.
struct TransparentDraw {
    BufferHandle vertices;     // kBufferVertex
    uint32_t vertexCount = 0;  // a positive multiple of 3
    glm::mat4 model{1.0f};     // object to world
    glm::vec3 color{1.0f};     // straight linear RGB, each in [0, 1e4]
    float opacity = 1.0f;      // [0, 1]
    // Orders this draw's fragments against other draws' at exactly equal depth; give every
    // draw its own id, stable from frame to frame, so the result ignores draw order. [0, 2^31)
    uint32_t id = 0;
};

struct TransparencyInputs {
    TextureHandle opaqueColor;  // the desc's colorFormat, sampled, output size
    // The opaque pass's depth attachment (the desc's depthFormat, kTextureRenderTarget), output
    // size: tested against, never written.
    TextureHandle opaqueDepth;
    glm::mat4 view{1.0f};        // world to view (camera looks down -z)
    glm::mat4 projection{1.0f};  // the same projection the opaque pass used
    std::span<const TransparentDraw> draws;
};

enum class TransparencyQuality : uint32_t {
    Standard,  // K = 16 fragments per pixel kept exactly
    High,      // K = 32
};

// Where the AO taps find their occluders.
enum class TransparencyAoOccluders : uint32_t {
    BruteForce,  // every fragment of the tap pixel's list, and its opaque surface
    Compressed,  // the tap pixel's M compressed nodes (needs TransparencyDesc::compressedNodes)
};

// Opacity-based AO through the layers (high tier; ignored on the current tier).
struct TransparencyAoDesc {
    bool enabled = false;
    // technique Alchemy or Scalable; radius (0, 1e4], intensity [0, 1e3], contrast [0, 100], bias
    // [0, 1], epsilon (0, 1], samples [1, 64], mirrored, spiralTurns, maxRadiusPx >= 0 are used;
    // depthMipLevels, blurRadius, normals and crease are not (lists have no MIP; the output is
    // raw, for the host to filter; the opaque normal comes from depth).
    AoConfig config;
    TransparencyAoOccluders occluders = TransparencyAoOccluders::BruteForce;
    // Bilateral (depth-aware) filter of the AO, taps each side of a separable blur with the opaque
    // AO blur's weights, [0, 8]; 0 = the raw AO. The blended visibility is keyed by each pixel's
    // front depth, the opaque one by the opaque depth. Needs RGBA32F render targets (the keys).
    uint32_t filterRadius = 0;
};

struct TransparencyDesc {
    uint32_t width = 0, height = 0;        // [1, caps.limits.maxTextureSize]
    TierProfile profile;                   // tiers::profile(tier) or tiers::choose(caps)->profile
    Format colorFormat = Format::RGBA16F;  // RGBA8, RGBA16F or RGBA32F: opaque colour and output
    Format depthFormat = Format::D32F;     // D16, D24S8 or D32F: the opaque depth
    TransparencyQuality quality = TransparencyQuality::Standard;
    // K itself, overriding quality's (unset: quality's K). Fewer kept layers cost less in the
    // resolve and fold more of a deep pixel into its tail.
    std::optional<uint32_t> maxLayers;
    // Nodes of the first frame's pool, before any count is known (unset:
    // kOitInitialNodesPerPixel per pixel); later frames size it from the scene.
    std::optional<uint64_t> initialPoolNodes;
    // M: nodes per compressed list (high tier); 0 = no compression.
    uint32_t compressedNodes = 0;
    bool compressBackHalfOnly = true;  // drop only from the back half: the front half is kept
    TransparencyAoDesc ao;
};

// What the last flushed frame did (high tier; zeros on the current tier, which has no pool).
struct TransparencyStats {
    uint64_t fragments = 0;  // that passed the depth test (stored + dropped)
    uint64_t stored = 0;
    uint64_t dropped = 0;
    uint64_t poolNodes = 0;  // the pool's capacity that frame
    uint64_t poolBytes = 0;
};

uint32_t keptLayers(TransparencyQuality quality);   // K: 16 or 32
uint32_t keptLayers(const TransparencyDesc& desc);  // desc.maxLayers, or its quality's K

class Transparency {
public:
    // UnsupportedFeature when the profile asks for the A-buffer and the device has no fragment
    // stores and atomics; UnsupportedFormat when the current tier's RGBA16F targets or
    // colorFormat cannot be rendered.
    static Result<std::unique_ptr<Transparency>> create(Device& device, const TransparencyDesc& desc);
    ~Transparency();
    Transparency(const Transparency&) = delete;
    Transparency& operator=(const Transparency&) = delete;

    // Records the passes; the result is in output() once the device flushes. Reads the previous
    // frame's counter first (a device read, which flushes what was recorded before).
    Status render(const TransparencyInputs& inputs);
    // The composited colour (colorFormat); the opaque colour itself after a frame with no draw.
    TextureHandle output() const { return output_; }
    // AO through the layers (RG16F: r the blended visibility, g the opaque surface's; filtered
    // when desc.ao.filterRadius > 0), when desc.ao is enabled on the high tier and the frame had
    // a draw; null otherwise.
    TextureHandle aoOutput() const { return aoOutput_; }
    // The compressed lists (SFX_OIT_COMPRESSED_WORDS uint32 per pixel, row 0 first; layout in
    // sfx_shared_oit.h / sfx_shared_oit_params.h), when compressedNodes > 0 on the high tier.
    BufferHandle compressedLists() const { return compressed_; }
    bool aoThroughLayers() const { return abuffer_ && desc_.ao.enabled; }
    // The last frame's counts; a device read (flushes).
    Result<TransparencyStats> stats();
    bool usesAbuffer() const { return abuffer_; }
    const TransparencyDesc& desc() const { return desc_; }
    // Passes and resources of a frame with `hasTransparentDraws`, each saying why it exists.
    EffectPlan plan(bool hasTransparentDraws = true) const;
    // Per-pass device timers (off by default, as AmbientObscurance::setProfiling): with profiling
    // on, each render() with a draw times its passes; passTimings() reads them after a flush, in
    // plan(true) order. InvalidArgument when profiling is off or no frame with a draw was timed.
    Status setProfiling(bool enabled);
    Result<std::vector<PassTiming>> passTimings();

private:
    Transparency(Device& device, const TransparencyDesc& desc);
    Status ensurePrograms();
    Status ensureTargets();
    Status ensurePool(uint64_t nodes);
    Status sizePoolFromLastFrame();
    uint64_t maxPoolNodes() const;
    Status uploadDraws(const TransparencyInputs& inputs);
    std::vector<DrawDesc> geometryDraws(const TransparencyInputs& inputs, PipelineHandle pipeline, uint32_t paramsBinding,
                                        const BindingSet& shared) const;
    Status renderAbuffer(const TransparencyInputs& inputs);
    Status renderWeighted(const TransparencyInputs& inputs);
    Status ensureLayerTargets();
    Status renderLayerAo(const TransparencyInputs& inputs, const DepthReconstruction& rec);
    Status filterLayerAo();
    void planLayerAo(EffectPlan& plan) const;
    Result<uint32_t> readCounter();
    // Records `record` inside pass `index`'s timer when profiling (plan(true) order).
    Status timed(size_t index, const std::function<Status()>& record);
    void release();

    Device& device_;
    TransparencyDesc desc_;
    bool abuffer_ = false;
    TextureHandle output_;  // ownedOutput_, or the host's opaque colour after a frame with no draw
    TextureHandle ownedOutput_, heads_, accum_, weight_, aoOutput_, ownedAo_;
    TextureHandle aoRaw_, aoFiltered_;  // with ao.filterRadius: raw AO + keys (RGBA32F), after the h pass (RG16F)
    BufferHandle pool_, resolveParams_, compressed_, aoParams_;
    uint64_t poolNodes_ = 0;
    bool poolUsed_ = false;  // a fill has run since the pool was made: its counter is the scene's
    std::vector<BufferHandle> drawParams_;
    ProgramHandle clearProgram_, fillProgram_, resolveProgram_, accumProgram_, weightedResolveProgram_, aoProgram_, filterProgram_;
    PipelineHandle clearPipeline_, fillPipeline_, resolvePipeline_, accumPipeline_, weightedResolvePipeline_, aoPipeline_;
    PipelineHandle filterPipelines_[2];  // horizontal, vertical
    TransparencyStats last_;
    bool profiling_ = false;
    std::unique_ptr<detail::PassTimers> passTimers_;  // made on first use while profiling
};

}  // namespace sfx
