// AO at half resolution: the half-size depth (where no depth MIP level 1 holds it) and the
// depth-aware upsample to the host's full-size output. The obscurance and blur passes are
// ao.cpp's, run at passWidth() x passHeight().
#include <algorithm>
#include <cmath>

#include "ao_internal.hpp"
#include "effect_common.hpp"
#include "sfx/ao.hpp"
#include "sfx_shaders.hpp"
#include "sfx_shared_ao.h"

namespace sfx {

bool AmbientObscurance::halfDepthFromMip() const { return detail::mipGivesHalfDepth(config_, desc_.profile, desc_.width, desc_.height); }

// Half size rounds down as MIP level 1 does (never below 1), so both half-size depths agree.
uint32_t AmbientObscurance::passWidth() const { return config_.halfResolution ? std::max(1u, desc_.width / 2) : desc_.width; }
uint32_t AmbientObscurance::passHeight() const { return config_.halfResolution ? std::max(1u, desc_.height / 2) : desc_.height; }

TextureHandle AmbientObscurance::halfDepthTexture() const { return halfDepthFromMip() ? depth_->texture() : halfDepth_; }

Status AmbientObscurance::allocateHalfRes() {
    const Tier tier = desc_.profile.tier;
    if (!halfDepthFromMip()) {
        Result<ProgramHandle> program = detail::loadProgram(device_, gen::ao_half_depth::kName, tier);
        if (!program) return program.status();
        halfDepthProgram_ = program.value();
    }
    Result<ProgramHandle> upsample = detail::loadProgram(device_, config_.bentNormals ? gen::ao_upsample_bent::kName : gen::ao_upsample::kName, tier);
    if (!upsample) return upsample.status();
    upsampleProgram_ = upsample.value();
    Result<BufferHandle> params = device_.createBuffer({sizeof(shared::UpsampleParams), kBufferUniform, "sfx-ao-upsample-params"});
    if (!params) return params.status();
    upsampleParams_ = params.value();
    return Status::ok();
}

Status AmbientObscurance::recordHalfDepth(size_t passIndex) {
    const int linearize = depth_->passThrough() && depth_->sourceKind() == DepthKind::Hardware ? 1 : 0;
    Result<PipelineHandle> pipeline = pipelines_->get(halfDepthProgram_, Format::R32F, {{SFX_AO_SC_HALF_DEPTH_LINEARIZE, linearize}},
                                                      "sfx-ao-half-depth");
    if (!pipeline) return pipeline.status();
    RenderPassDesc pass;
    pass.colors = {ColorAttachment{halfDepth_, 0, LoadOp::DontCare, {}}};
    pass.debugName = "sfx-ao-half-depth";
    DrawDesc draw;
    draw.pipeline = pipeline.value();
    draw.bindings.textures = {TextureBinding{gen::ao_half_depth::uDepth, depth_->texture(), 0, 1, {}}};
    // Linear input has no constants to linearize by (and the shader does not read them): the
    // declared block still needs a buffer of its size, and the upsample's is one.
    static_assert(sizeof(shared::UpsampleParams) >= sizeof(shared::LinearizeParams));
    const BufferHandle linearizeParams = depth_->linearizeParams().isNull() ? upsampleParams_ : depth_->linearizeParams();
    draw.bindings.uniformBuffers = {BufferBinding{gen::ao_half_depth::LinearizeParams, linearizeParams, 0, 0}};
    return timed(passIndex, [&] { return device_.renderPass(pass, std::span<const DrawDesc>(&draw, 1)); });
}

Status AmbientObscurance::recordUpsample(const AoInputs& in, Format outFormat, Format bentFormat, TextureHandle source, size_t passIndex) {
    shared::UpsampleParams u{};
    const DepthReconstruction& rec = depth_->reconstruction();
    u.maxDepth = float(rec.maxDepth);
    // The key's constants, as the obscurance pass and the blur use them (ao.cpp).
    u.keyBase = float(shared::aoDepthKeyBase(rec.nearDepth));
    u.ndcScale = float(rec.ndcScale);
    u.denomOffset = float(rec.denomOffset);
    u.numerator = float(rec.numerator);
    // The full-size depth is the host's (no pass makes a full-size linear depth at half
    // resolution, ao.cpp): linearized here where it is hardware depth.
    const int linearize = depth_->sourceKind() == DepthKind::Hardware ? 1 : 0;
    SFX_TRY(uniforms_->write(device_, upsampleParams_, u));
    // The half-size depth comes with the AO texel where the target carries it (the float targets
    // of the high tier); else from the half-size depth texture (or level 0 of the half-size pyramid).
    const int depthIn = detail::aoDepthInTarget(desc_.profile, config_.technique, config_.blurRadius > 0, true);
    const int halfDepthSource = depthIn == SFX_AO_DEPTH_IN_FLOAT_G ? SFX_AO_HALF_DEPTH_SOURCE_G
        : depthIn == SFX_AO_DEPTH_IN_FLOAT_B                       ? SFX_AO_HALF_DEPTH_SOURCE_B
        : depthIn == SFX_AO_DEPTH_IN_KEY_BA                        ? SFX_AO_HALF_DEPTH_SOURCE_KEY
                                                                   : SFX_AO_HALF_DEPTH_TEXTURE;
    // With bent normals the upsample's variant writes them too, from the raw bent target the
    // blur's second pass (or the obscurance pass) left, with the visibility's weights.
    const bool bent = config_.bentNormals;
    const SpecializationConstant constants[] = {{SFX_AO_SC_UPSAMPLE_DEPTH, halfDepthSource},
                                                {SFX_AO_SC_UPSAMPLE_LINEARIZE, linearize},
                                                {SFX_AO_SC_UPSAMPLE_BENT_UNORM, bentFormat == Format::RGBA8 ? 1 : 0}};
    Result<PipelineHandle> pipeline = pipelines_->get(upsampleProgram_, outFormat, std::span<const SpecializationConstant>(constants, bent ? 3 : 2),
                                                      "sfx-ao-upsample", bent ? bentFormat : Format::Undefined);
    if (!pipeline) return pipeline.status();
    RenderPassDesc pass;
    pass.colors = {ColorAttachment{in.output, 0, LoadOp::DontCare, {}}};
    if (bent) pass.colors.push_back(ColorAttachment{in.bentNormals, 0, LoadOp::DontCare, {}});
    pass.debugName = "sfx-ao-upsample";
    DrawDesc draw;
    draw.pipeline = pipeline.value();
    draw.bindings.textures = {TextureBinding{gen::ao_upsample::uDepth, depth_->sourceTexture(), 0, 1, {}},
                              TextureBinding{gen::ao_upsample::uHalfDepth, halfDepthTexture(), 0, 1, {}},
                              TextureBinding{gen::ao_upsample::uSource, source, 0, 1, {}}};
    if (bent) draw.bindings.textures.push_back(TextureBinding{gen::ao_upsample_bent::uBentSource, bentTarget_, 0, 1, {}});
    draw.bindings.uniformBuffers = {BufferBinding{gen::ao_upsample::UpsampleParams, upsampleParams_, 0, 0}};
    return timed(passIndex, [&] { return device_.renderPass(pass, std::span<const DrawDesc>(&draw, 1)); });
}

}  // namespace sfx
