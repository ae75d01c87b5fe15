// Depth linearisation and the depth MIP pyramid: the first passes every effect builds on.
// Shape shared by every effect: create / dispatch / resize / destroy (RAII), a description
// struct, status returns, and a plan of the passes and bytes it holds.
#pragma once

#include <array>
#include <memory>

#include "sfx/camera.hpp"
#include "sfx/hal.hpp"
#include "sfx/plan.hpp"
#include "sfx/tier.hpp"

namespace sfx {

namespace detail {
class PipelineCache;   // the effects' pipelines by specialisation constants (internal)
class UniformWrites;   // the effects' uniform buffers, written when their bytes change (internal)
class RecordedPasses;  // the effects' passes recorded once and replayed (internal)
class PassTimers;      // the effects' per-pass timers while profiling (internal)
}  // namespace detail

enum class DepthKind : uint32_t {
    Hardware,  // the depth buffer as rendered (D16, D24S8, D32F), mapped by the camera's projection
    Linear,    // already positive eye-space distance along the view axis, R32F
};

// Where an effect reads the scene's depth.
struct DepthSource {
    TextureHandle texture;
    DepthKind kind = DepthKind::Hardware;
    CameraProjection camera;
};

struct LinearDepthDesc {
    uint32_t width = 0;  // [1, caps.limits.maxTextureSize]
    uint32_t height = 0;
    Tier tier = Tier::Current;
    // Levels of the rotated-grid depth pyramid, level 0 included: 1 = linear depth only (the
    // current tier never needs more); [1, SFX_DEPTH_MIP_MAX_LEVELS] and at most what the size allows.
    uint32_t mipLevels = 1;
    // The DepthSource.kind dispatch will get, said up front so that plan() is known before the
    // first dispatch. Linear with mipLevels 1 needs no pass at all: no texture is allocated and
    // texture() is the host's own R32F texture (dispatching Hardware depth to it is then
    // InvalidArgument). Hardware accepts either kind (linear input is copied).
    DepthKind input = DepthKind::Hardware;
    // With mipLevels 1: the effect reading the depth linearizes hardware depth itself on every
    // fetch (sfxLinearizeDepth, the pass's own formula), so there is neither pass nor texture:
    // texture() is the host's texture of either kind, sourceKind() says which, and
    // linearizeParams() holds the constants. Worth it where each pixel is fetched once or twice
    // (AO at half resolution), not where a pass reads it many times.
    bool readersLinearize = false;
    // Level 0 at half size (MIP level 1's extent): texel q takes the source's depth at
    // depthMipSource(q), linearized as it is fetched, which is what level 1 of the full-size
    // pyramid holds, and the levels above continue from it. For readers that never need the
    // full-size level (AO at half resolution): its pass, about two copy passes on a CPU
    // rasteriser, and its texture are not made. sourceTexture() is the full-size depth.
    bool halfSizeBase = false;
};

// Owns an R32F texture of linear depth (and its MIP pyramid when mipLevels > 1).
class LinearDepth {
public:
    static Result<std::unique_ptr<LinearDepth>> create(Device& device, const LinearDepthDesc& desc);
    ~LinearDepth();
    LinearDepth(const LinearDepth&) = delete;
    LinearDepth& operator=(const LinearDepth&) = delete;

    // Records linearisation (or a copy for linear input) and the pyramid levels.
    // The source must match the size given at creation. passTimers: empty (no timing), or one
    // timer per plan() pass, each begun just before and ended just after its pass (profiling).
    Status dispatch(const DepthSource& source, std::span<const TimerHandle> passTimers = {});
    Status resize(uint32_t width, uint32_t height);

    // R32F, mipLevels levels. Without a pass (passThrough()), the host's texture of the last
    // dispatch (null before the first).
    TextureHandle texture() const { return passThrough() ? hostTexture_ : texture_; }
    // The DepthSource.texture of the last dispatch (null before the first).
    TextureHandle sourceTexture() const { return hostTexture_; }
    // True when no pyramid is built and the input is linear or the readers linearize: dispatch
    // records nothing.
    bool passThrough() const { return desc_.mipLevels == 1 && !desc_.halfSizeBase && (desc_.input == DepthKind::Linear || desc_.readersLinearize); }
    // The kind of the last dispatched source (what texture() holds when passing through).
    DepthKind sourceKind() const { return sourceKind_; }
    // LinearizeParams (sfx_shared.h) of the last dispatch; with readersLinearize, for the readers
    // (null when the desc's input is Linear: nothing to linearize).
    BufferHandle linearizeParams() const { return params_; }
    const LinearDepthDesc& desc() const { return desc_; }
    // Reconstruction constants of the last dispatched camera (valid after dispatch).
    const DepthReconstruction& reconstruction() const { return reconstruction_; }
    EffectPlan plan() const;

private:
    LinearDepth(Device& device, const LinearDepthDesc& desc);
    Status allocate();
    Status allocateTexture();
    void release();
    uint32_t levelZeroWidth() const;  // the texture's size: half the source's with halfSizeBase
    uint32_t levelZeroHeight() const;
    std::array<SpecializationConstant, 2> linearizeConstants(DepthKind kind) const;

    Device& device_;
    LinearDepthDesc desc_;
    TextureHandle texture_;
    TextureHandle hostTexture_;  // the source of the last dispatch
    BufferHandle params_;
    ProgramHandle linearizeProgram_, mipProgram_;
    // Linearisation (one per DepthKind seen) and MIP pipelines; kept across resize.
    std::unique_ptr<detail::PipelineCache> pipelines_;
    std::unique_ptr<detail::UniformWrites> uniforms_;
    DepthReconstruction reconstruction_;
    DepthKind sourceKind_ = DepthKind::Hardware;
};

}  // namespace sfx
