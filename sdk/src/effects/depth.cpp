#include "sfx/depth.hpp"

#include <array>
#include <string>

#include "effect_common.hpp"
#include "sfx_shaders.hpp"
#include "sfx_shared.h"

namespace sfx {
namespace {

using detail::loadProgram;

// The uniform block of linearize_depth.frag, declared once in sfx_shared.h.
using shared::LinearizeParams;

bool isHardwareDepthFormat(Format f) { return f == Format::D16 || f == Format::D24S8 || f == Format::D32F || f == Format::R32F; }

}  // namespace

Result<std::unique_ptr<LinearDepth>> LinearDepth::create(Device& device, const LinearDepthDesc& desc) {
    if (uint32_t(desc.tier) >= kTierCount) return invalidArgument("LinearDepthDesc.tier", std::to_string(uint32_t(desc.tier)), tierNameList());
    const uint32_t maxLevels = uint32_t(shared::SFX_DEPTH_MIP_MAX_LEVELS);
    if (desc.mipLevels == 0 || desc.mipLevels > maxLevels)
        return invalidArgument("LinearDepthDesc.mipLevels", std::to_string(desc.mipLevels), "[1, " + std::to_string(maxLevels) + "]");
    if (uint32_t(desc.input) > 1) return invalidArgument("LinearDepthDesc.input", std::to_string(uint32_t(desc.input)), "Hardware or Linear");
    // The programs built for the tier (shader_src/programs.txt) say whether it has the MIP pass.
    if (desc.mipLevels > 1 && !shaders::find(gen::depth_mip::kName, desc.tier).isOk())
        return invalidArgument("LinearDepthDesc.mipLevels", std::to_string(desc.mipLevels),
                               std::string("1 on the ") + toString(desc.tier) + " tier (its programs include no depth MIP pass)");
    std::unique_ptr<LinearDepth> depth(new LinearDepth(device, desc));
    SFX_TRY(depth->allocate());
    return depth;
}

LinearDepth::LinearDepth(Device& device, const LinearDepthDesc& desc)
    : device_(device),
      desc_(desc),
      pipelines_(std::make_unique<detail::PipelineCache>(device)),
      uniforms_(std::make_unique<detail::UniformWrites>()) {}

LinearDepth::~LinearDepth() { release(); }

Status LinearDepth::allocate() {
    // Linear input without a pyramid is used where it lies: nothing to allocate. Readers that
    // linearize hardware depth need the constants only.
    if (passThrough() && !(desc_.readersLinearize && desc_.input == DepthKind::Hardware)) return allocateTexture();
    Result<BufferHandle> params = device_.createBuffer({sizeof(LinearizeParams), kBufferUniform, "sfx-linearize-params"});
    if (!params) return params.status();
    params_ = params.value();
    if (passThrough()) return allocateTexture();
    Result<ProgramHandle> lin = loadProgram(device_, gen::linearize_depth::kName, desc_.tier);
    if (!lin) return lin.status();
    linearizeProgram_ = lin.value();
    // The pipeline for the input kind of the desc, made here; a dispatch of the other kind makes its own.
    const std::array<SpecializationConstant, 2> constants = linearizeConstants(desc_.input);
    Result<PipelineHandle> lp = pipelines_->get(linearizeProgram_, Format::R32F, std::span(constants), "sfx-linearize-depth");
    if (!lp) return lp.status();
    if (desc_.mipLevels > 1) {
        Result<ProgramHandle> mip = loadProgram(device_, gen::depth_mip::kName, desc_.tier);
        if (!mip) return mip.status();
        mipProgram_ = mip.value();
        // The MIP pass has one pipeline (no constants): made here, so no dispatch compiles it.
        Result<PipelineHandle> mp = pipelines_->get(mipProgram_, Format::R32F, {}, "sfx-depth-mip");
        if (!mp) return mp.status();
    }
    return allocateTexture();
}

uint32_t LinearDepth::levelZeroWidth() const { return desc_.halfSizeBase ? mipExtent(desc_.width, 1) : desc_.width; }
uint32_t LinearDepth::levelZeroHeight() const { return desc_.halfSizeBase ? mipExtent(desc_.height, 1) : desc_.height; }

std::array<SpecializationConstant, 2> LinearDepth::linearizeConstants(DepthKind kind) const {
    return {SpecializationConstant{SFX_DEPTH_SC_LINEAR_INPUT, kind == DepthKind::Linear ? 1 : 0},
            SpecializationConstant{SFX_DEPTH_SC_HALF_SIZE_BASE, desc_.halfSizeBase ? 1 : 0}};
}

// The size-dependent part: the linear depth texture (programs and pipelines do not depend on it).
Status LinearDepth::allocateTexture() {
    const uint32_t w = levelZeroWidth(), h = levelZeroHeight();
    const uint32_t allowed = maxMipLevels(std::max(w, 1u), std::max(h, 1u));
    if (w > 0 && h > 0 && desc_.mipLevels > allowed)
        return invalidArgument("LinearDepthDesc.mipLevels", std::to_string(desc_.mipLevels),
                               "[1, " + std::to_string(allowed) + "] for " + std::to_string(w) + "x" + std::to_string(h) +
                                   (desc_.halfSizeBase ? " (level 0 at half the source's size)" : ""));
    if (passThrough()) return Status::ok();
    TextureDesc td{w, h, desc_.mipLevels, Format::R32F, kTextureSampled | kTextureRenderTarget, "sfx-linear-depth"};
    Result<TextureHandle> tex = device_.createTexture(td);
    if (!tex) return tex.status();
    texture_ = tex.value();
    return Status::ok();
}

void LinearDepth::release() {
    // Destroy calls on null handles report InvalidHandle; there is nothing to release then.
    pipelines_->clear();
    if (!mipProgram_.isNull()) (void)device_.destroyProgram(mipProgram_);
    if (!linearizeProgram_.isNull()) (void)device_.destroyProgram(linearizeProgram_);
    if (!params_.isNull()) (void)device_.destroyBuffer(params_);
    if (!texture_.isNull()) (void)device_.destroyTexture(texture_);
    mipProgram_ = {};
    linearizeProgram_ = {};
    params_ = {};
    texture_ = {};
    hostTexture_ = {};
}

Status LinearDepth::resize(uint32_t width, uint32_t height) {
    SFX_TRY(detail::checkTargetSize(device_, width, height, ""));
    if (width == desc_.width && height == desc_.height) return Status::ok();
    // Only the texture follows the size; programs and pipelines stay.
    if (!texture_.isNull()) (void)device_.destroyTexture(texture_);
    texture_ = {};
    hostTexture_ = {};
    desc_.width = width;
    desc_.height = height;
    return allocateTexture();
}

Status LinearDepth::dispatch(const DepthSource& source, std::span<const TimerHandle> passTimers) {
    if (texture_.isNull() && !passThrough()) return {StatusCode::InvalidHandle, "LinearDepth: resources were not created (failed resize?)"};
    // One timer per planned pass: linearize, then one per MIP level past 0 (none passing through).
    // plan() builds strings: asked only when profiling.
    const size_t passes = passTimers.empty() ? 0 : plan().passes.size();
    if (!passTimers.empty() && passTimers.size() != passes)
        return invalidArgument("LinearDepth::dispatch passTimers", std::to_string(passTimers.size()) + " timers",
                               "none or " + std::to_string(passes) + " (one per planned pass)");
    Result<TextureDesc> src = device_.textureDesc(source.texture);
    if (!src) return Status{src.status().code(), "DepthSource.texture: " + src.status().message()};
    if (src->width != desc_.width || src->height != desc_.height)
        return invalidArgument("DepthSource.texture size", std::to_string(src->width) + "x" + std::to_string(src->height),
                               std::to_string(desc_.width) + "x" + std::to_string(desc_.height) + " (the LinearDepth size)");
    if (source.kind == DepthKind::Hardware && !isHardwareDepthFormat(src->format))
        return {StatusCode::UnsupportedFormat,
                std::string("DepthSource.texture format ") + toString(src->format) + " is not hardware depth; allowed D16, D24S8, D32F, R32F"};
    if (source.kind == DepthKind::Linear && src->format != Format::R32F)
        return {StatusCode::UnsupportedFormat,
                std::string("DepthSource.texture format ") + toString(src->format) + " is not linear depth; allowed R32F"};
    if (uint32_t(source.kind) > 1) return invalidArgument("DepthSource.kind", std::to_string(uint32_t(source.kind)), "Hardware or Linear");
    if (!(src->usage & kTextureSampled)) return invalidArgument("DepthSource.texture usage", "without kTextureSampled", "a sampled texture");
    if (passThrough() && !desc_.readersLinearize && source.kind != DepthKind::Linear)
        return invalidArgument("DepthSource.kind", "Hardware",
                               "Linear, as LinearDepthDesc.input said at creation (no linearisation pass was planned)");

    Result<DepthReconstruction> rec = makeDepthReconstruction(source.camera, desc_.width, desc_.height);
    if (!rec) return rec.status();
    reconstruction_ = rec.value();
    sourceKind_ = source.kind;
    hostTexture_ = source.texture;
    LinearizeParams p{};
    p.ndcScale = float(reconstruction_.ndcScale);
    p.denomOffset = float(reconstruction_.denomOffset);
    p.numerator = float(reconstruction_.numerator);
    p.maxDepth = float(reconstruction_.maxDepth);
    if (passThrough()) {
        // Readers clamp what they fetch with sfxLinearDepthOrFar (sfx_shared.h), exactly as the
        // linearisation pass would have, or linearize it as that pass would (readersLinearize),
        // so the host's texture serves as it is.
        if (!params_.isNull()) SFX_TRY(uniforms_->write(device_, params_, p));
        return Status::ok();
    }
    SFX_TRY(uniforms_->write(device_, params_, p));
    // The source's kind is a branch of the shader: a specialisation constant (one pipeline each).
    const std::array<SpecializationConstant, 2> constants = linearizeConstants(source.kind);
    Result<PipelineHandle> linearize = pipelines_->get(linearizeProgram_, Format::R32F, std::span(constants), "sfx-linearize-depth");
    if (!linearize) return linearize.status();
    Result<PipelineHandle> mipPipeline = PipelineHandle{};
    if (desc_.mipLevels > 1) {
        mipPipeline = pipelines_->get(mipProgram_, Format::R32F, {}, "sfx-depth-mip");
        if (!mipPipeline) return mipPipeline.status();
    }

    RenderPassDesc pass;
    pass.colors = {ColorAttachment{texture_, 0, LoadOp::DontCare, {}}};
    pass.debugName = "sfx-linearize-depth";
    DrawDesc draw;
    draw.pipeline = linearize.value();
    draw.bindings.textures = {TextureBinding{gen::linearize_depth::uHardwareDepth, source.texture, 0, 1, {}}};
    draw.bindings.uniformBuffers = {BufferBinding{gen::linearize_depth::LinearizeParams, params_, 0, 0}};
    if (!passTimers.empty()) SFX_TRY(device_.beginTimer(passTimers[0]));
    SFX_TRY(device_.renderPass(pass, std::span<const DrawDesc>(&draw, 1)));
    if (!passTimers.empty()) SFX_TRY(device_.endTimer(passTimers[0]));

    for (uint32_t level = 1; level < desc_.mipLevels; ++level) {
        RenderPassDesc mipPass;
        mipPass.colors = {ColorAttachment{texture_, level, LoadOp::DontCare, {}}};
        mipPass.debugName = "sfx-depth-mip";
        DrawDesc mipDraw;
        mipDraw.pipeline = mipPipeline.value();
        mipDraw.bindings.textures = {TextureBinding{gen::depth_mip::uPreviousLevel, texture_, level - 1, 1, {}}};
        if (!passTimers.empty()) SFX_TRY(device_.beginTimer(passTimers[level]));
        SFX_TRY(device_.renderPass(mipPass, std::span<const DrawDesc>(&mipDraw, 1)));
        if (!passTimers.empty()) SFX_TRY(device_.endTimer(passTimers[level]));
    }
    return Status::ok();
}

EffectPlan LinearDepth::plan() const {
    EffectPlan plan;
    if (passThrough()) {
        // The host's depth is read where it lies, linearized by its readers where it is hardware depth.
        if (desc_.readersLinearize && desc_.input == DepthKind::Hardware)
            plan.resources.push_back({"depth", "linearize params (the readers linearize the host's depth as they fetch it: no pass)",
                                      Format::Undefined, 0, 0, 1, sizeof(LinearizeParams)});
        return plan;
    }
    const uint32_t w = levelZeroWidth(), h = levelZeroHeight();
    // The name stays "linearize" at half size (the extent says it): profiles and tables key on it.
    plan.passes.push_back({"depth", "linearize", w, h});
    for (uint32_t level = 1; level < desc_.mipLevels; ++level)
        plan.passes.push_back({"depth", "depth_mip " + std::to_string(level), mipExtent(w, level), mipExtent(h, level)});
    TextureDesc td{w, h, desc_.mipLevels, Format::R32F, kTextureSampled | kTextureRenderTarget};
    const std::string what = desc_.mipLevels > 1 ? "linear depth + MIP pyramid" : "linear depth";
    const std::string from = desc_.halfSizeBase ? " from half size (level 0 holds MIP level 1's samples; no reader needs the full-size level)" : "";
    plan.resources.push_back(plannedTexture("depth", what + from, td));
    plan.resources.push_back({"depth", "linearize params", Format::Undefined, 0, 0, 1, sizeof(LinearizeParams)});
    return plan;
}

}  // namespace sfx
