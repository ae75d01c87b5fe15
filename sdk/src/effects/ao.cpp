// The AmbientObscurance effect: linear depth (+ MIP for high-tier Scalable AO), one obscurance
// pass of the chosen technique, and a two-pass separable bilateral blur into the host's output;
// at half resolution both at half size and a depth-aware upsample last (ao_half_res.cpp).
#include <algorithm>
#include <cmath>
#include <string>

#include "ao_internal.hpp"
#include "effect_common.hpp"
#include "pass_timers.hpp"
#include "recorded_passes.hpp"
#include "sfx/ao.hpp"
#include "sfx_shaders.hpp"
#include "sfx_shared_ao.h"

namespace sfx {
namespace {

using detail::loadProgram;

// The uniform blocks of the AO passes, declared once in sfx_shared_ao.h for C++ and GLSL.
using shared::AoParams;
using shared::BlurParams;
using shared::UpsampleParams;

const char* programName(AoTechnique t) {
    switch (t) {
        case AoTechnique::Alchemy: return gen::ao_alchemy::kName;
        case AoTechnique::Scalable: return gen::ao_scalable::kName;
        case AoTechnique::Crease: return gen::ao_crease::kName;
        case AoTechnique::Horizon: return gen::ao_horizon::kName;
    }
    return gen::ao_scalable::kName;
}

bool isOutputFormat(Format f) {
    return f == Format::R8 || f == Format::RGBA8 || f == Format::R16F || f == Format::RG16F || f == Format::RGBA16F || f == Format::R32F ||
        f == Format::RGBA32F;
}

}  // namespace

Result<std::unique_ptr<AmbientObscurance>> AmbientObscurance::create(Device& device, const AoDesc& desc) {
    if (uint32_t(desc.profile.tier) >= kTierCount)
        return invalidArgument("AoDesc.profile.tier", std::to_string(uint32_t(desc.profile.tier)), tierNameList());
    SFX_TRY(detail::checkTargetSize(device, desc.width, desc.height, "AoDesc."));
    SFX_TRY(validateAoSettings(desc.settings, desc.profile));
    std::unique_ptr<AmbientObscurance> ao(new AmbientObscurance(device, desc));
    SFX_TRY(ao->allocate());
    return ao;
}

AmbientObscurance::AmbientObscurance(Device& device, const AoDesc& desc)
    : device_(device),
      desc_(desc),
      pipelines_(std::make_unique<detail::PipelineCache>(device)),
      uniforms_(std::make_unique<detail::UniformWrites>()),
      recorded_(std::make_unique<detail::RecordedPasses>(device)),
      passTimers_(std::make_unique<detail::PassTimers>(device)) {}

AmbientObscurance::~AmbientObscurance() { release(); }

Status AmbientObscurance::allocate() {
    Result<AoConfig> config = resolveAoConfig(desc_.settings, desc_.profile, maxMipLevels(desc_.width, desc_.height), desc_.height);
    if (!config) return config.status();
    config_ = config.value();
    const Tier tier = desc_.profile.tier;

    LinearDepthDesc dd{desc_.width, desc_.height, tier, config_.depthMipLevels, desc_.depthInput};
    // At half resolution no pass reads the full-size linear depth: the upsample fetches each
    // full-size depth once and linearizes it as it does. High-tier Scalable's pyramid starts at
    // half size (its level 0 is what level 1 of a full-size one would be); without a pyramid the
    // half-size depth pass linearizes as it fetches too. Either way the full-size linearisation
    // pass (about two copy passes on a CPU rasteriser) and its texture are not made.
    dd.halfSizeBase = halfDepthFromMip();
    dd.readersLinearize = config_.halfResolution && config_.depthMipLevels == 1;
    Result<std::unique_ptr<LinearDepth>> depth = LinearDepth::create(device_, dd);
    if (!depth) return depth.status();
    depth_ = std::move(depth.value());

    Result<BufferHandle> params = device_.createBuffer({sizeof(AoParams), kBufferUniform, "sfx-ao-params"});
    if (!params) return params.status();
    aoParams_ = params.value();
    // Bent normals are a second attachment of their own program variants: a pipeline without it
    // must not meet a shader writing it.
    const bool bent = config_.bentNormals;
    if (bent) {
        if (device_.caps().limits.maxColorAttachments < 2)
            return {StatusCode::UnsupportedFeature,
                    "AoSettings.bentNormals needs 2 colour attachments; the device has " + std::to_string(device_.caps().limits.maxColorAttachments)};
        if (!device_.caps().renderableFormat[size_t(detail::aoBentTargetFormat(desc_.profile))])
            return {StatusCode::UnsupportedFormat,
                    std::string("bent normal target format ") + toString(detail::aoBentTargetFormat(desc_.profile)) +
                        " is not renderable on this device"};
    }
    Result<ProgramHandle> program = loadProgram(device_, bent ? gen::ao_horizon_bent::kName : programName(config_.technique), tier);
    if (!program) return program.status();
    aoProgram_ = program.value();

    if (config_.blurRadius > 0 || config_.halfResolution) {
        targetFormat_ = detail::aoTargetFormat(desc_.profile, config_.technique);
        if (!device_.caps().renderableFormat[size_t(targetFormat_)])
            return {StatusCode::UnsupportedFormat, std::string("AO target format ") + toString(targetFormat_) + " is not renderable on this device"};
        SFX_TRY(allocateTargets());
    }
    if (config_.halfResolution) SFX_TRY(allocateHalfRes());
    if (config_.blurRadius > 0) {
        for (BufferHandle* b : {&blurParamsH_, &blurParamsV_}) {
            Result<BufferHandle> buf = device_.createBuffer({sizeof(BlurParams), kBufferUniform, "sfx-ao-blur-params"});
            if (!buf) return buf.status();
            *b = buf.value();
        }
        Result<ProgramHandle> blur = loadProgram(device_, bent ? gen::ao_blur_bent::kName : gen::ao_blur::kName, tier);
        if (!blur) return blur.status();
        blurProgram_ = blur.value();
    }
    // The pass count follows the settings (MIP levels, blur), so timers follow each allocation.
    if (profiling_) SFX_TRY(createPassTimers());
    return Status::ok();
}

// The size-dependent part, at the pass's size: the raw AO target (with blur or at half
// resolution), the blur intermediate (with blur), the half-size depth (half resolution
// without a depth MIP), and with bent normals their own raw and blur targets beside the AO's.
// Full resolution without blur needs none.
Status AmbientObscurance::allocateTargets() {
    const bool half = config_.halfResolution, blur = config_.blurRadius > 0;
    struct Wanted {
        TextureHandle* texture;
        bool needed;
        Format format;
        const char* name;
    };
    const bool bent = config_.bentNormals;
    const Format bentFormat = detail::aoBentTargetFormat(desc_.profile);
    for (const Wanted& w : {Wanted{&aoTarget_, blur || half, targetFormat_, "sfx-ao-raw"}, Wanted{&blurTarget_, blur, targetFormat_, "sfx-ao-blur"},
                            Wanted{&halfDepth_, half && !halfDepthFromMip(), Format::R32F, "sfx-ao-half-depth"},
                            Wanted{&bentTarget_, bent && (blur || half), bentFormat, "sfx-ao-bent-raw"},
                            Wanted{&bentBlurTarget_, bent && blur, bentFormat, "sfx-ao-bent-blur"}}) {
        if (!w.needed) continue;
        TextureDesc td{passWidth(), passHeight(), 1, w.format, kTextureSampled | kTextureRenderTarget, w.name};
        Result<TextureHandle> tex = device_.createTexture(td);
        if (!tex) return tex.status();
        *w.texture = tex.value();
    }
    return Status::ok();
}

void AmbientObscurance::releaseTargets() {
    for (TextureHandle* t : {&aoTarget_, &blurTarget_, &halfDepth_, &bentTarget_, &bentBlurTarget_}) {
        if (!t->isNull()) (void)device_.destroyTexture(*t);
        *t = {};
    }
}

Status AmbientObscurance::createPassTimers() {
    passTimers_->clear();
    Status s = passTimers_->reserve(plan().passes.size());
    if (!s) passTimers_->clear();
    return s;
}

Status AmbientObscurance::setProfiling(bool enabled) {
    if (enabled == profiling_) return Status::ok();
    profiling_ = enabled;
    if (!enabled) {
        passTimers_->clear();
        return Status::ok();
    }
    Status s = depth_ ? createPassTimers() : Status::ok();  // without resources, allocate() creates them
    if (!s) profiling_ = false;
    return s;
}

Result<std::vector<PassTiming>> AmbientObscurance::passTimings() {
    if (!profiling_)
        return Status{StatusCode::InvalidArgument, "AmbientObscurance::passTimings: profiling is off (call setProfiling(true) before dispatch)"};
    return passTimers_->read(plan(), "AmbientObscurance");
}

void AmbientObscurance::release() {
    // Destroy calls on null handles report InvalidHandle; there is nothing to release then.
    recorded_->clear();
    pipelines_->clear();
    for (ProgramHandle* p : {&aoProgram_, &blurProgram_, &halfDepthProgram_, &upsampleProgram_}) {
        if (!p->isNull()) (void)device_.destroyProgram(*p);
        *p = {};
    }
    for (BufferHandle* b : {&aoParams_, &blurParamsH_, &blurParamsV_, &upsampleParams_}) {
        if (!b->isNull()) (void)device_.destroyBuffer(*b);
        *b = {};
    }
    releaseTargets();
    targetFormat_ = Format::Undefined;
    passTimers_->clear();
    depth_.reset();
}

Status AmbientObscurance::resize(uint32_t width, uint32_t height) {
    SFX_TRY(detail::checkTargetSize(device_, width, height, ""));
    if (width == desc_.width && height == desc_.height && depth_) return Status::ok();
    Result<AoConfig> config = resolveAoConfig(desc_.settings, desc_.profile, maxMipLevels(width, height), height);
    if (!config) return config.status();
    // The MIP level count follows the size only below 2^levels pixels, and with it whether MIP
    // level 1 is the half-size depth; then everything is rebuilt.
    const bool mipHalfDepthChanged = detail::mipGivesHalfDepth(config.value(), desc_.profile, width, height) != halfDepthFromMip();
    if (!depth_ || config->depthMipLevels != config_.depthMipLevels || mipHalfDepthChanged) {
        desc_.width = width;
        desc_.height = height;
        release();
        return allocate();
    }
    // Otherwise only textures follow the size: programs and pipelines (their constants do not
    // depend on it) stay, and the size-dependent uniforms are written at every dispatch, from the
    // config of the new size (the clamp and crease's stride follow the rows).
    desc_.width = width;
    desc_.height = height;
    config_ = config.value();
    releaseTargets();
    Status s = depth_->resize(width, height);
    if (s) s = allocateTargets();
    if (!s) release();  // dispatch then reports the failed resize
    return s;
}

Status AmbientObscurance::setSettings(const AoSettings& settings) {
    SFX_TRY(validateAoSettings(settings, desc_.profile));
    Result<AoConfig> config = resolveAoConfig(settings, desc_.profile, maxMipLevels(desc_.width, desc_.height), desc_.height);
    if (!config) return config.status();
    desc_.settings = settings;
    // Looks, counts and radii are uniforms and specialisation constants: a dispatch compiles the
    // pipeline a changed constant needs (the pipeline cache keeps the others). Only a technique,
    // MIP level count or blur on/off change reallocates programs and textures.
    if (depth_ && config->technique == config_.technique && config->depthMipLevels == config_.depthMipLevels &&
        (config->blurRadius > 0) == (config_.blurRadius > 0) && config->halfResolution == config_.halfResolution &&
        config->bentNormals == config_.bentNormals) {
        config_ = config.value();
        return Status::ok();
    }
    release();
    return allocate();
}

Status AmbientObscurance::dispatch(const AoInputs& in) {
    if (!depth_ || aoProgram_.isNull()) return {StatusCode::InvalidHandle, "AmbientObscurance: resources were not created (failed resize?)"};
    Result<TextureDesc> out = device_.textureDesc(in.output);
    if (!out) return Status{out.status().code(), "AoInputs.output: " + out.status().message()};
    if (out->width != desc_.width || out->height != desc_.height)
        return invalidArgument("AoInputs.output size", std::to_string(out->width) + "x" + std::to_string(out->height),
                               std::to_string(desc_.width) + "x" + std::to_string(desc_.height) + " (the AO size)");
    if (!isOutputFormat(out->format) || !device_.caps().renderableFormat[size_t(out->format)])
        return {StatusCode::UnsupportedFormat,
                std::string("AoInputs.output format ") + toString(out->format) +
                    " is not allowed; R8, RGBA8, R16F, RG16F, RGBA16F, R32F or RGBA32F renderable on the device"};
    if (!(out->usage & kTextureRenderTarget)) return invalidArgument("AoInputs.output usage", "without kTextureRenderTarget", "a render target");
    int32_t normalSource = 0;
    if (config_.normals == AoNormals::FromTexture) {
        Result<TextureDesc> nd = device_.textureDesc(in.normals);
        if (!nd) return Status{nd.status().code(), "AoInputs.normals (AoSettings.normals is FromTexture): " + nd.status().message()};
        if (nd->width != desc_.width || nd->height != desc_.height)
            return invalidArgument("AoInputs.normals size", std::to_string(nd->width) + "x" + std::to_string(nd->height),
                                   std::to_string(desc_.width) + "x" + std::to_string(desc_.height) + " (the AO size)");
        if (nd->format == Format::RGBA8)
            normalSource = 2;
        else if (nd->format == Format::RGBA16F || nd->format == Format::RGBA32F)
            normalSource = 1;
        else
            return {
                StatusCode::UnsupportedFormat,
                std::string("AoInputs.normals format ") + toString(nd->format) + "; allowed RGBA16F/RGBA32F (signed xyz) or RGBA8 (xyz * 0.5 + 0.5)"};
    }
    SFX_TRY(detail::checkDepthLayers(device_, in, config_, desc_.width, desc_.height));
    Format bentFormat = Format::Undefined;
    if (config_.bentNormals) {
        Result<Format> f = detail::checkBentNormalsInput(device_, in.bentNormals, desc_.width, desc_.height);
        if (!f) return f.status();
        bentFormat = f.value();
    }
    // Pass timers make a recording single-use: profiling records every frame.
    if (profiling_) return recordPasses(in, out.value(), normalSource, bentFormat);
    const uint64_t key = detail::RecordedPasses::key({in.depth.texture.bits, in.normals.bits, in.output.bits, in.depthLayers[0].bits,
                                                      in.depthLayers[1].bits, in.depthLayers[2].bits, in.bentNormals.bits});
    return recorded_->run(key, [&] { return recordPasses(in, out.value(), normalSource, bentFormat); });
}

Status AmbientObscurance::recordPasses(const AoInputs& in, const TextureDesc& out, int32_t normalSource, Format bentFormat) {
    // Profiling: plan() order is the depth passes (linearize + one per MIP level past 0), at half
    // resolution the half-size depth unless MIP level 1 is it, the obscurance pass, blur h and v,
    // at half resolution the upsample. timed() records a pass bare when profiling is off.
    const std::span<const TimerHandle> timers = passTimers_->handles();
    // plan() builds strings: asked only when profiling (timed() ignores the index otherwise).
    const size_t depthPasses = timers.empty() ? 0 : depth_->plan().passes.size();  // none when passing linear depth through
    SFX_TRY(depth_->dispatch(in.depth, timers.empty() ? timers : timers.first(depthPasses)));
    size_t passIndex = depthPasses;
    const bool half = config_.halfResolution;
    if (half && !halfDepthFromMip()) SFX_TRY(recordHalfDepth(passIndex++));
    const DepthReconstruction& rec = depth_->reconstruction();
    const bool blur = config_.blurRadius > 0;
    const float keyBase = float(shared::aoDepthKeyBase(rec.nearDepth));
    // The depth the obscurance and blur passes read, and its MIP levels past their own size.
    const TextureHandle passDepth = half ? halfDepthTexture() : depth_->texture();

    AoParams p{};
    for (int i = 0; i < 4; ++i) p.projInfo[i] = float(rec.projInfo[i]);
    p.radius = float(config_.radius);
    p.intensity = float(config_.intensity);
    p.contrast = float(config_.contrast);
    p.bias = float(config_.bias);
    p.epsilon = float(config_.epsilon);
    // Screen radii are in the pass's pixels: half as many per unit at half size.
    p.pixelsPerUnit = float(rec.pixelsPerUnitAtUnitDepth * (half ? 0.5 : 1.0));
    p.maxRadiusPx = float(config_.maxRadiusPx);
    p.maxDepth = float(rec.maxDepth);
    p.fullWidth = int32_t(desc_.width);
    p.fullHeight = int32_t(desc_.height);
    p.spiralHalfStepQ16 = shared::aoSpiralHalfStepQ16(config_.spiralTurns, config_.samples, config_.mirrored);
    p.sumExponent = float(config_.sumExponent);
    p.keyBase = keyBase;
    p.creaseRange = config_.crease.range;
    p.creaseBias = config_.crease.bias;
    p.creaseAverager = config_.crease.averager;
    p.creaseMinimum = config_.crease.minimumCrease;
    p.fadeStart = config_.crease.fadeStart;
    p.invFadeRange = std::isinf(config_.crease.fadeEnd) ? 0.0f : float(1.0 / (double(config_.crease.fadeEnd) - config_.crease.fadeStart));
    p.horizonThickness = float(config_.horizon.thickness);
    p.horizonInvFalloffWidth = float(1.0 / (config_.horizon.falloff * config_.radius));
    SFX_TRY(uniforms_->write(device_, aoParams_, p));

    // Obscurance: straight into the output at full resolution without blur.
    const bool direct = !blur && !half;
    const TextureHandle aoDest = direct ? in.output : aoTarget_;
    const bool bent = config_.bentNormals;
    const Format bentTargetFormat = detail::aoBentTargetFormat(desc_.profile);
    const Format bentDestFormat = direct ? bentFormat : bentTargetFormat;
    const SpecializationConstant aoConstants[] = {
        {SFX_AO_SC_SAMPLES, int32_t(config_.samples)},
        {SFX_AO_SC_MIRRORED, config_.mirrored ? 1 : 0},
        {SFX_AO_SC_MIP_LEVELS, int32_t(config_.depthMipLevels)},
        {SFX_AO_SC_NORMAL_SOURCE, normalSource},
        {SFX_AO_SC_PACK_DEPTH, detail::aoDepthInTarget(desc_.profile, config_.technique, blur, half)},
        {SFX_AO_SC_CLAMP_RADIUS, config_.maxRadiusPx > 0.0 ? 1 : 0},
        {SFX_AO_SC_HALF_RES, half ? 1 : 0},
        {SFX_AO_SC_DEPTH_LAYERS, int32_t(config_.depthLayers)},
        {SFX_AO_SC_HORIZON_STEPS, int32_t(config_.horizon.steps)},
        {SFX_AO_SC_BENT_UNORM, bentDestFormat == Format::RGBA8 ? 1 : 0},
    };
    // The bent variant alone declares the last constant.
    const std::span<const SpecializationConstant> aoConstantSpan(aoConstants, std::size(aoConstants) - (bent ? 0 : 1));
    Result<PipelineHandle> aoPipeline = pipelines_->get(aoProgram_, direct ? out.format : targetFormat_, aoConstantSpan, "sfx-ao",
                                                        bent ? bentDestFormat : Format::Undefined);
    if (!aoPipeline) return aoPipeline.status();
    RenderPassDesc pass;
    pass.colors = {ColorAttachment{aoDest, 0, LoadOp::DontCare, {}}};
    if (bent) pass.colors.push_back(ColorAttachment{direct ? in.bentNormals : bentTarget_, 0, LoadOp::DontCare, {}});
    pass.debugName = "sfx-ao";
    DrawDesc draw;
    draw.pipeline = aoPipeline.value();
    // Without host normals the normals binding gets the pass's depth, with the same mip range
    // (GL keeps one range per texture): the shader never reads it then, but every declared
    // sampler needs a valid texture.
    const TextureBinding depthBinding{gen::ao_scalable::uDepth, passDepth, 0, config_.depthMipLevels, {}};
    TextureBinding normalBinding = depthBinding;
    normalBinding.binding = gen::ao_scalable::uNormals;
    if (normalSource) normalBinding = TextureBinding{gen::ao_scalable::uNormals, in.normals, 0, 1, {}};
    draw.bindings.textures = {depthBinding, normalBinding};
    detail::appendDepthLayerBindings(draw.bindings.textures, in, config_, desc_.profile, depthBinding);
    draw.bindings.uniformBuffers = {BufferBinding{gen::ao_scalable::AoParams, aoParams_, 0, 0}};
    SFX_TRY(timed(passIndex++, [&] { return device_.renderPass(pass, std::span<const DrawDesc>(&draw, 1)); }));

    if (blur) {
        const int radius = int(config_.blurRadius);
        for (int blurPass = 0; blurPass < 2; ++blurPass) {
            BlurParams b{};
            b.direction[0] = blurPass == 0 ? 1 : 0;
            b.direction[1] = blurPass == 0 ? 0 : 1;
            b.maxDepth = float(rec.maxDepth);
            b.keyBase = keyBase;
            const BufferHandle buffer = blurPass == 0 ? blurParamsH_ : blurParamsV_;
            SFX_TRY(uniforms_->write(device_, buffer, b));
            // At half resolution the second pass goes back into the raw target, for the upsample.
            const TextureHandle src = blurPass == 0 ? aoTarget_ : blurTarget_;
            const TextureHandle dst = blurPass == 0 ? blurTarget_ : half ? aoTarget_ : in.output;
            // The bent normals follow the same way through their own targets.
            const TextureHandle bentSrc = blurPass == 0 ? bentTarget_ : bentBlurTarget_;
            const TextureHandle bentDst = blurPass == 0 ? bentBlurTarget_ : half ? bentTarget_ : in.bentNormals;
            const Format bentDstFormat = blurPass == 0 || half ? bentTargetFormat : bentFormat;
            const SpecializationConstant blurConstants[] = {
                {SFX_AO_SC_BLUR_RADIUS, radius},
                {SFX_AO_SC_BLUR_MODERATE_RADIUS, std::max(1, radius / 2)},
                {SFX_AO_SC_BLUR_CREASE, config_.technique == AoTechnique::Crease ? 1 : 0},
                {SFX_AO_SC_BLUR_FINAL_PASS, blurPass},
                {SFX_AO_SC_BLUR_KEEP_DEPTH, half ? 1 : 0},
                {SFX_AO_SC_BLUR_BENT_UNORM, bentDstFormat == Format::RGBA8 ? 1 : 0},
            };
            const std::span<const SpecializationConstant> blurConstantSpan(blurConstants, std::size(blurConstants) - (bent ? 0 : 1));
            Result<PipelineHandle> bp = pipelines_->get(blurProgram_, blurPass == 0 || half ? targetFormat_ : out.format, blurConstantSpan,
                                                        blurPass == 0 ? "sfx-ao-blur-h" : "sfx-ao-blur-v", bent ? bentDstFormat : Format::Undefined);
            if (!bp) return bp.status();
            RenderPassDesc bpass;
            bpass.colors = {ColorAttachment{dst, 0, LoadOp::DontCare, {}}};
            if (bent) bpass.colors.push_back(ColorAttachment{bentDst, 0, LoadOp::DontCare, {}});
            bpass.debugName = blurPass == 0 ? "sfx-ao-blur-h" : "sfx-ao-blur-v";
            DrawDesc bdraw;
            bdraw.pipeline = bp.value();
            // The depth comes with each texel of the source (the target's layout): one binding.
            bdraw.bindings.textures = {TextureBinding{gen::ao_blur::uSource, src, 0, 1, {}}};
            if (bent) bdraw.bindings.textures.push_back(TextureBinding{gen::ao_blur_bent::uBentSource, bentSrc, 0, 1, {}});
            bdraw.bindings.uniformBuffers = {BufferBinding{gen::ao_blur::BlurParams, buffer, 0, 0}};
            SFX_TRY(timed(passIndex++, [&] { return device_.renderPass(bpass, std::span<const DrawDesc>(&bdraw, 1)); }));
        }
    }
    if (half) SFX_TRY(recordUpsample(in, out.format, bentFormat, aoTarget_, passIndex++));
    return Status::ok();
}

EffectPlan AmbientObscurance::plan() const {
    EffectPlan plan;
    if (depth_) plan = depth_->plan();
    const bool half = config_.halfResolution, blur = config_.blurRadius > 0;
    const uint32_t w = passWidth(), h = passHeight();
    const std::string atHalf = half ? " at half size" : "";
    if (half && !halfDepthFromMip()) plan.passes.push_back({"ao", "half-size depth (AO at half resolution; no depth MIP level 1 to reuse)", w, h});
    const std::string layers = config_.depthLayers > 1 ? ", taps test " + std::to_string(config_.depthLayers) + " depth layers" : "";
    const std::string bentNote = config_.bentNormals ? ", + bent normals" : "";
    plan.passes.push_back({"ao", std::string("obscurance (") + toString(config_.technique) + layers + bentNote + ")" + atHalf, w, h});
    plan.resources.push_back({"ao", "ao params", Format::Undefined, 0, 0, 1, sizeof(AoParams)});
    if (blur) {
        plan.passes.push_back({"ao", "bilateral blur h" + atHalf, w, h});
        plan.passes.push_back({"ao", "bilateral blur v" + atHalf, w, h});
    }
    if (half) plan.passes.push_back({"ao", "depth-aware upsample to full size (AO at half resolution)", desc_.width, desc_.height});
    const Format targetFormat = detail::aoTargetFormat(desc_.profile, config_.technique);
    const TextureDesc td{w, h, 1, targetFormat, kTextureSampled | kTextureRenderTarget};
    const std::string raw = desc_.profile.aoPackedDepthTarget && blur ? "raw AO + packed depth key (RGBA8)"
        : desc_.profile.aoPackedDepthTarget
        ? "raw AO (RGBA8)"
        : std::string("raw AO + linear depth (") + toString(targetFormat) + "): the blur and upsample read one texel per tap";
    if (blur || half) plan.resources.push_back(plannedTexture("ao", raw + (half ? ", half size: the upsample's source" : ""), td));
    if (blur) {
        plan.resources.push_back(plannedTexture("ao", "blur intermediate" + atHalf, td));
        plan.resources.push_back({"ao", "blur params", Format::Undefined, 0, 0, 1, 2 * sizeof(BlurParams)});
    }
    if (half && !halfDepthFromMip())
        plan.resources.push_back(plannedTexture("ao", "half-size depth (R32F): what obscurance, blur and upsample weights read at half size",
                                                TextureDesc{w, h, 1, Format::R32F, kTextureSampled | kTextureRenderTarget}));
    if (half) plan.resources.push_back({"ao", "upsample params", Format::Undefined, 0, 0, 1, sizeof(UpsampleParams)});
    if (config_.bentNormals) {
        const Format bentFormat = detail::aoBentTargetFormat(desc_.profile);
        const TextureDesc bd{w, h, 1, bentFormat, kTextureSampled | kTextureRenderTarget};
        const std::string f = std::string(" (") + toString(bentFormat) + ")";
        if (blur || half) plan.resources.push_back(plannedTexture("ao", "raw bent normals" + f + atHalf, bd));
        if (blur) plan.resources.push_back(plannedTexture("ao", "bent normal blur intermediate" + f + atHalf, bd));
    }
    return plan;
}

}  // namespace sfx
