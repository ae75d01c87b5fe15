#include "sfx/motion_blur.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "effect_common.hpp"
#include "pass_timers.hpp"
#include "recorded_passes.hpp"
#include "sfx/settings_ranges.hpp"
#include "sfx/validation_errors.hpp"
#include "sfx_shaders.hpp"
#include "sfx_shared.h"
#include "sfx_shared_mb.h"

namespace sfx {
namespace {

using detail::isColorFormat;
using detail::loadProgram;

// The uniform blocks of the mb_*.frag passes, declared once in sfx_shared_mb.h for C++ and GLSL.
using PackParams = shared::MbPackParams;
using ReconstructParams = shared::MbReconstructParams;

bool isVelocityFormat(Format f) { return f == Format::RG16F || f == Format::RG32F || f == Format::RGBA16F || f == Format::RGBA32F; }

std::string num(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

// A value-initialised TierProfile has every count at 0 (no taps, radius 0); it must come from
// tiers::profile() or tiers::choose(), whose values the shaders' loops and tables accept.
Status checkProfile(const TierProfile& p) {
    if (uint32_t(p.tier) >= kTierCount || p.mbTaps < 3 || p.mbTaps > uint32_t(shared::SFX_MB_MAX_TAPS) || p.mbTaps % 2 == 0 ||
        !(p.mbMaxRadiusPx > 0.0f && p.mbMaxRadiusPx <= float(shared::SFX_MB_MAX_RADIUS_LIMIT_PX)) ||
        !(p.mbTilePx >= 1.0f && p.mbTilePx <= float(shared::SFX_MB_MAX_RADIUS_LIMIT_PX)) || (p.mbJitterSize != 2 && p.mbJitterSize != 4))
        return invalidArgument("MotionBlurDesc.profile",
                               "an empty or unknown tier profile (mbTaps " + std::to_string(p.mbTaps) + ", mbMaxRadiusPx " + num(p.mbMaxRadiusPx) +
                                   ", mbTilePx " + num(p.mbTilePx) + ", mbJitterSize " + std::to_string(p.mbJitterSize) + ")",
                               "tiers::profile(tier) or tiers::choose(caps)->profile");
    return Status::ok();
}

uint32_t tilesFor(uint32_t size, uint32_t tile) { return (size + tile - 1) / tile; }

}  // namespace

Result<MotionBlurParams> resolveMotionBlur(const TierProfile& profile, const MotionBlurSettings& s, uint32_t height) {
    SFX_TRY(checkProfile(profile));
    const double limit = double(shared::SFX_MB_MAX_RADIUS_LIMIT_PX);
    if (s.maxRadiusPx) SFX_TRY(checkSetting(Setting::MbMaxRadiusPx, *s.maxRadiusPx));
    SFX_TRY(checkSetting(Setting::MbReferenceRows, s.referenceRows));
    if (s.samples) {
        SFX_TRY(checkSetting(Setting::MbSamples, *s.samples));
        if (*s.samples % 2 == 0)
            return invalidArgument("MotionBlurSettings.samples", std::to_string(*s.samples), "an odd count (centre + mirrored pairs)");
    }
    SFX_TRY(checkSetting(Setting::MbSoftDepthExtent, s.softDepthExtent));
    SFX_TRY(checkSetting(Setting::MbCentreWeight, s.centreWeight));
    SFX_TRY(checkSetting(Setting::MbExposure, s.exposure));
    if (height == 0) return invalidArgument("height", "0", "[1, maxTextureSize]");

    MotionBlurParams p;
    p.taps = s.samples.value_or(profile.mbTaps);
    p.pairs = (p.taps - 1) / 2;
    p.jitterSize = profile.mbJitterSize;
    const double base = double(s.maxRadiusPx.value_or(profile.mbMaxRadiusPx));
    const double scaled = s.referenceRows == 0 ? base : base * double(height) / double(s.referenceRows);
    double radius = std::max(1.0, std::round(scaled));
    // The tier's default is a look defined at referenceRows; at very tall outputs it is held
    // at the shaders' limit rather than refused (the plan names the cap). A radius the
    // caller chose is refused instead, since capping it would change what was asked for.
    if (radius > limit && !s.maxRadiusPx) {
        p.radiusCapped = true;
        p.scaledRadiusPx = radius;
        radius = limit;
    }
    if (radius > limit)
        return invalidArgument("MotionBlurSettings.maxRadiusPx",
                               std::to_string(*s.maxRadiusPx) + " (" + std::to_string(radius) + " px at " + std::to_string(height) + " rows)",
                               "a scaled radius <= 64 px");
    p.radiusPx = uint32_t(radius);
    // The tile: the profile's pixels at referenceRows (both tiers the same), never beyond the
    // radius, and large enough that neighbour max reaches the radius within its limit of tiles.
    const double tileBase = double(profile.mbTilePx);
    const double tile = std::round(s.referenceRows == 0 ? tileBase : tileBase * double(height) / double(s.referenceRows));
    const double fewestTiles = std::ceil(radius / double(shared::SFX_MB_MAX_NEIGHBOR_REACH));
    p.tileSizePx = uint32_t(std::clamp(std::max(tile, fewestTiles), 1.0, radius));
    p.softDepthExtent = s.softDepthExtent;
    p.centreWeight = s.centreWeight;
    p.exposure = s.exposure;
    return p;
}

Result<std::unique_ptr<MotionBlur>> MotionBlur::create(Device& device, const MotionBlurDesc& desc) {
    SFX_TRY(checkProfile(desc.profile));
    SFX_TRY(detail::checkTargetSize(device, desc.width, desc.height, "MotionBlurDesc."));
    if (!isColorFormat(desc.colorFormat))
        return invalidArgument("MotionBlurDesc.colorFormat", toString(desc.colorFormat), "RGBA8, RGBA16F or RGBA32F");
    const DeviceCaps& caps = device.caps();
    for (Format f : {Format::RGBA16F, Format::RG16F, desc.colorFormat})
        if (!caps.renderableFormat[size_t(f)])
            return Status{StatusCode::UnsupportedFormat, std::string("motion blur renders ") + toString(f) + ", which this device cannot render to"};
    std::unique_ptr<MotionBlur> mb(new MotionBlur(device, desc));
    SFX_TRY(mb->allocate());
    return mb;
}

MotionBlur::MotionBlur(Device& device, const MotionBlurDesc& desc)
    : device_(device),
      desc_(desc),
      pipelines_(std::make_unique<detail::PipelineCache>(device)),
      uniforms_(std::make_unique<detail::UniformWrites>()),
      recorded_(std::make_unique<detail::RecordedPasses>(device)),
      passTimers_(std::make_unique<detail::PassTimers>(device)) {}

MotionBlur::~MotionBlur() { release(); }

Status MotionBlur::allocate() {
    Result<std::unique_ptr<LinearDepth>> depth = LinearDepth::create(device_, {desc_.width, desc_.height, desc_.profile.tier, 1, desc_.depthInput});
    if (!depth) return depth.status();
    depth_ = std::move(depth.value());

    Result<BufferHandle> pp = device_.createBuffer({sizeof(PackParams), kBufferUniform, "sfx-mb-pack-params"});
    if (!pp) return pp.status();
    packParams_ = pp.value();
    Result<BufferHandle> rp = device_.createBuffer({sizeof(ReconstructParams), kBufferUniform, "sfx-mb-reconstruct-params"});
    if (!rp) return rp.status();
    reconstructParams_ = rp.value();

    // Programs here; their pipelines at the first dispatch that needs them (the specialisation
    // constants follow the inputs and settings), kept in pipelines_ across resize.
    const std::pair<const char*, ProgramHandle*> programs[] = {
        {gen::mb_pack::kName, &packProgram_},
        {gen::mb_tile_max::kName, &tileProgram_},
        {gen::mb_neighbor_max::kName, &neighborProgram_},
        {gen::mb_reconstruct::kName, &reconstructProgram_},
    };
    for (const auto& [name, out] : programs) {
        Result<ProgramHandle> prog = loadProgram(device_, name, desc_.profile.tier);
        if (!prog) return prog.status();
        *out = prog.value();
    }
    return allocateTargets();
}

// The size-dependent part: the packed and output textures (the tiles follow at dispatch).
Status MotionBlur::allocateTargets() {
    const uint32_t rt = kTextureSampled | kTextureRenderTarget;
    Result<TextureHandle> packed = device_.createTexture({desc_.width, desc_.height, 1, Format::RGBA16F, rt, "sfx-mb-packed"});
    if (!packed) return packed.status();
    packed_ = packed.value();
    Result<TextureHandle> out = device_.createTexture({desc_.width, desc_.height, 1, desc_.colorFormat, rt, "sfx-mb-output"});
    if (!out) return out.status();
    output_ = out.value();
    return Status::ok();
}

void MotionBlur::releaseTargets() {
    releaseTiles();
    for (TextureHandle* t : {&packed_, &output_}) {
        if (!t->isNull()) (void)device_.destroyTexture(*t);
        *t = {};
    }
}

Status MotionBlur::allocateTiles(uint32_t tileSizePx) {
    if (tileSizePx == tileSize_ && !tileMax_.isNull()) return Status::ok();
    releaseTiles();
    const uint32_t rt = kTextureSampled | kTextureRenderTarget;
    const uint32_t tw = tilesFor(desc_.width, tileSizePx), th = tilesFor(desc_.height, tileSizePx);
    Result<TextureHandle> tile = device_.createTexture({tw, th, 1, Format::RG16F, rt, "sfx-mb-tile-max"});
    if (!tile) return tile.status();
    tileMax_ = tile.value();
    Result<TextureHandle> neighbor = device_.createTexture({tw, th, 1, Format::RG16F, rt, "sfx-mb-neighbor-max"});
    if (!neighbor) return neighbor.status();
    neighborMax_ = neighbor.value();
    tileSize_ = tileSizePx;
    return Status::ok();
}

void MotionBlur::releaseTiles() {
    if (!tileMax_.isNull()) (void)device_.destroyTexture(tileMax_);
    if (!neighborMax_.isNull()) (void)device_.destroyTexture(neighborMax_);
    tileMax_ = {};
    neighborMax_ = {};
    tileSize_ = 0;
}

void MotionBlur::release() {
    // Destroy calls on null handles report InvalidHandle; there is nothing to release then.
    recorded_->clear();
    pipelines_->clear();
    for (ProgramHandle* p : {&packProgram_, &tileProgram_, &neighborProgram_, &reconstructProgram_}) {
        if (!p->isNull()) (void)device_.destroyProgram(*p);
        *p = {};
    }
    for (BufferHandle* b : {&packParams_, &reconstructParams_}) {
        if (!b->isNull()) (void)device_.destroyBuffer(*b);
        *b = {};
    }
    releaseTargets();
    passTimers_->clear();
    depth_.reset();
}

Status MotionBlur::resize(uint32_t width, uint32_t height) {
    SFX_TRY(detail::checkTargetSize(device_, width, height, ""));
    if (width == desc_.width && height == desc_.height && !output_.isNull()) return Status::ok();
    desc_.width = width;
    desc_.height = height;
    if (!depth_ || packProgram_.isNull()) {
        release();
        return allocate();
    }
    // Only textures follow the size; programs and pipelines stay. (The tile size is the blur
    // radius, which scales with the height when referenceRows is set: a dispatch at a new radius
    // compiles that tile-max pipeline once, the cache keeps it.)
    releaseTargets();
    Status s = depth_->resize(width, height);
    if (s) s = allocateTargets();
    if (!s) release();  // dispatch then reports the failed resize
    return s;
}

Status MotionBlur::dispatch(const MotionBlurInputs& in, const MotionBlurSettings& settings) {
    if (output_.isNull() || !depth_) return {StatusCode::InvalidHandle, "MotionBlur: resources were not created (failed resize?)"};
    Result<MotionBlurParams> resolved = resolveMotionBlur(desc_.profile, settings, desc_.height);
    if (!resolved) return resolved.status();
    const MotionBlurParams& p = resolved.value();
    // Spelled out only for a message (a steady frame builds no string).
    auto expectedSize = [&] { return std::to_string(desc_.width) + "x" + std::to_string(desc_.height) + " (the MotionBlur size)"; };

    Result<TextureDesc> color = device_.textureDesc(in.color);
    if (!color) return Status{color.status().code(), "MotionBlurInputs.color: " + color.status().message()};
    if (color->width != desc_.width || color->height != desc_.height)
        return invalidArgument("MotionBlurInputs.color size", std::to_string(color->width) + "x" + std::to_string(color->height), expectedSize());
    if (color->format != desc_.colorFormat)
        return {StatusCode::UnsupportedFormat,
                std::string("MotionBlurInputs.color format ") + toString(color->format) + " differs from MotionBlurDesc.colorFormat " +
                    toString(desc_.colorFormat)};
    if (!(color->usage & kTextureSampled)) return invalidArgument("MotionBlurInputs.color usage", "without kTextureSampled", "a sampled texture");

    // The host's output, or the effect's own (checked at creation).
    const TextureHandle target = in.output.isNull() ? output_ : in.output;
    if (!in.output.isNull()) {
        Result<TextureDesc> out = device_.textureDesc(in.output);
        if (!out) return Status{out.status().code(), "MotionBlurInputs.output: " + out.status().message()};
        if (out->width != desc_.width || out->height != desc_.height)
            return validation::fail(
                validation::Error::MotionBlurOutputSize,
                {std::to_string(out->width), std::to_string(out->height), std::to_string(desc_.width), std::to_string(desc_.height)});
        if (out->format != desc_.colorFormat)
            return validation::fail(validation::Error::MotionBlurOutputFormat, {toString(out->format), toString(desc_.colorFormat)});
        if (!(out->usage & kTextureRenderTarget))
            return validation::fail(validation::Error::MotionBlurOutputUsage, {validation::textureUsageNames(out->usage)});
    }

    const bool cameraOnly = in.velocity.isNull();
    if (!cameraOnly) {
        Result<TextureDesc> vel = device_.textureDesc(in.velocity);
        if (!vel) return Status{vel.status().code(), "MotionBlurInputs.velocity: " + vel.status().message()};
        if (vel->width != desc_.width || vel->height != desc_.height)
            return invalidArgument("MotionBlurInputs.velocity size", std::to_string(vel->width) + "x" + std::to_string(vel->height), expectedSize());
        if (!isVelocityFormat(vel->format))
            return {StatusCode::UnsupportedFormat,
                    std::string("MotionBlurInputs.velocity format ") + toString(vel->format) + "; allowed RG16F, RG32F, RGBA16F, RGBA32F"};
        if (!(vel->usage & kTextureSampled))
            return invalidArgument("MotionBlurInputs.velocity usage", "without kTextureSampled", "a sampled texture");
    }

    // Before the passes: a new tile size makes textures, which no recording may span.
    SFX_TRY(allocateTiles(p.tileSizePx));
    if (profiling_) {
        profiledSettings_ = settings;
        SFX_TRY(passTimers_->reserve(plan(settings).passes.size()));
        return recordPasses(in, p, target);
    }
    const uint64_t key = detail::RecordedPasses::key({in.color.bits, in.depth.texture.bits, in.velocity.bits, target.bits});
    return recorded_->run(key, [&] { return recordPasses(in, p, target); });
}

Status MotionBlur::recordPasses(const MotionBlurInputs& in, const MotionBlurParams& p, TextureHandle target) {
    const bool cameraOnly = in.velocity.isNull();
    // Profiling: the depth passes take the first timers, then one per pass in plan() order.
    // plan() builds strings: asked only when profiling.
    const std::span<const TimerHandle> timers = passTimers_->handles();
    const size_t depthPasses = profiling_ ? depth_->plan().passes.size() : 0;
    SFX_TRY(depth_->dispatch(in.depth, timers.first(std::min(depthPasses, timers.size()))));
    size_t passIndex = depthPasses;

    PackParams pack{};
    const glm::dmat4 reprojection = in.camera.previousViewProjection * glm::inverse(in.camera.currentViewProjection);
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) pack.reprojection[c * 4 + r] = float(reprojection[c][r]);
    if (cameraOnly) {
        for (int i = 0; i < 16; ++i)
            if (!std::isfinite(pack.reprojection[i]))
                return invalidArgument("MotionBlurInputs.camera", "a singular or non-finite view-projection", "invertible finite matrices");
    }
    const glm::dmat4& proj = in.depth.camera.projection;
    pack.clipFromView[0] = float(proj[2][2]);
    pack.clipFromView[1] = float(proj[3][2]);
    pack.clipFromView[2] = 2.0f / float(desc_.width);
    pack.clipFromView[3] = 2.0f / float(desc_.height);
    pack.target[0] = float(desc_.width);
    pack.target[1] = float(desc_.height);
    pack.radius = float(p.radiusPx);
    pack.velocityScale = float(0.5 * p.exposure);
    pack.maxDepth = float(depth_->reconstruction().maxDepth);
    SFX_TRY(uniforms_->write(device_, packParams_, pack));
    ReconstructParams rec{};
    rec.softExtent = float(p.softDepthExtent);
    rec.centreWeight = float(p.centreWeight);
    rec.radius = float(p.radiusPx);
    rec.tileSize = int32_t(p.tileSizePx);
    SFX_TRY(uniforms_->write(device_, reconstructParams_, rec));

    // Branches and loop counts: specialisation constants, one pipeline per combination seen.
    auto pipeline = [&](ProgramHandle program, Format format, std::initializer_list<SpecializationConstant> constants, const char* name) {
        return pipelines_->get(program, format, constants, name);
    };
    Result<PipelineHandle> packPipeline = pipeline(packProgram_, Format::RGBA16F, {{SFX_MB_SC_CAMERA_ONLY, cameraOnly ? 1 : 0}}, gen::mb_pack::kName);
    if (!packPipeline) return packPipeline.status();
    Result<PipelineHandle> tilePipeline = pipeline(tileProgram_, Format::RG16F, {{SFX_MB_SC_TILE_SIZE, int32_t(p.tileSizePx)}},
                                                   gen::mb_tile_max::kName);
    if (!tilePipeline) return tilePipeline.status();
    Result<PipelineHandle> neighborPipeline = pipeline(neighborProgram_, Format::RG16F,
                                                       {{SFX_MB_SC_TILE_SIZE, int32_t(p.tileSizePx)}, {SFX_MB_SC_RADIUS, int32_t(p.radiusPx)}},
                                                       gen::mb_neighbor_max::kName);
    if (!neighborPipeline) return neighborPipeline.status();
    Result<PipelineHandle> reconstructPipeline = pipeline(reconstructProgram_, desc_.colorFormat,
                                                          {{SFX_MB_SC_PAIRS, int32_t(p.pairs)}, {SFX_MB_SC_JITTER_SIZE, int32_t(p.jitterSize)}},
                                                          gen::mb_reconstruct::kName);
    if (!reconstructPipeline) return reconstructPipeline.status();

    auto run = [&](TextureHandle target, const char* name, PipelineHandle pipeline, BindingSet bindings) -> Status {
        RenderPassDesc pass;
        pass.colors = {ColorAttachment{target, 0, LoadOp::DontCare, {}}};
        pass.debugName = name;
        DrawDesc draw;
        draw.pipeline = pipeline;
        draw.bindings = std::move(bindings);
        auto record = [&] { return device_.renderPass(pass, std::span<const DrawDesc>(&draw, 1)); };
        return profiling_ ? passTimers_->timed(passIndex++, record) : record();
    };

    BindingSet packBind;
    // Camera-only mode reads no velocity; the depth texture fills the unused slot.
    packBind.textures = {TextureBinding{gen::mb_pack::uLinearDepth, depth_->texture(), 0, 1, {}},
                         TextureBinding{gen::mb_pack::uVelocity, cameraOnly ? depth_->texture() : in.velocity, 0, 1, {}}};
    packBind.uniformBuffers = {BufferBinding{gen::mb_pack::MbPackParams, packParams_, 0, 0}};
    SFX_TRY(run(packed_, "sfx-mb-pack", packPipeline.value(), packBind));

    BindingSet tileBind;
    tileBind.textures = {TextureBinding{gen::mb_tile_max::uPacked, packed_, 0, 1, {}}};
    SFX_TRY(run(tileMax_, "sfx-mb-tile-max", tilePipeline.value(), tileBind));

    BindingSet neighborBind;
    neighborBind.textures = {TextureBinding{gen::mb_neighbor_max::uTileMax, tileMax_, 0, 1, {}}};
    SFX_TRY(run(neighborMax_, "sfx-mb-neighbor-max", neighborPipeline.value(), neighborBind));

    BindingSet recBind;
    recBind.textures = {TextureBinding{gen::mb_reconstruct::uColor, in.color, 0, 1, {}},
                        TextureBinding{gen::mb_reconstruct::uPacked, packed_, 0, 1, {}},
                        TextureBinding{gen::mb_reconstruct::uNeighborMax, neighborMax_, 0, 1, {}}};
    recBind.uniformBuffers = {BufferBinding{gen::mb_reconstruct::MbReconstructParams, reconstructParams_, 0, 0}};
    return run(target, "sfx-mb-reconstruct", reconstructPipeline.value(), recBind);
}

Status MotionBlur::setProfiling(bool enabled) {
    profiling_ = enabled;
    if (!enabled) passTimers_->clear();
    return Status::ok();
}

Result<std::vector<PassTiming>> MotionBlur::passTimings() {
    if (!profiling_)
        return Status{StatusCode::InvalidArgument, "MotionBlur::passTimings: profiling is off (call setProfiling(true) before dispatch)"};
    return passTimers_->read(plan(profiledSettings_), "MotionBlur");
}

EffectPlan MotionBlur::plan(const MotionBlurSettings& settings) const {
    EffectPlan plan;
    if (depth_) plan.append(depth_->plan());
    Result<MotionBlurParams> resolved = resolveMotionBlur(desc_.profile, settings, std::max(desc_.height, 1u));
    const uint32_t tileSize = resolved ? resolved->tileSizePx : 1;
    const uint32_t tw = tilesFor(desc_.width, tileSize), th = tilesFor(desc_.height, tileSize);
    const int span = 2 * shared::mbNeighborReachTiles(int(resolved ? resolved->radiusPx : 1), int(tileSize)) + 1;
    std::string tile = " (" + std::to_string(tileSize) + "x" + std::to_string(tileSize) + " tiles";
    if (resolved && resolved->radiusCapped)
        tile += "; the tier's default radius, " + num(resolved->scaledRadiusPx) + " px at " + std::to_string(desc_.height) +
            " rows, capped at the shaders' 64 px limit";
    tile += ")";
    plan.passes.push_back({"motion_blur", "pack velocity + depth", desc_.width, desc_.height});
    plan.passes.push_back({"motion_blur", "tile max" + tile, tw, th});
    plan.passes.push_back({"motion_blur", "neighbour max " + std::to_string(span) + "x" + std::to_string(span), tw, th});
    plan.passes.push_back({"motion_blur", "reconstruct " + std::to_string(resolved ? resolved->taps : 0) + " taps", desc_.width, desc_.height});
    const uint32_t rt = kTextureSampled | kTextureRenderTarget;
    plan.resources.push_back(plannedTexture("motion_blur", "packed velocity + depth", {desc_.width, desc_.height, 1, Format::RGBA16F, rt}));
    plan.resources.push_back(plannedTexture("motion_blur", "tile max", {tw, th, 1, Format::RG16F, rt}));
    plan.resources.push_back(plannedTexture("motion_blur", "neighbour max", {tw, th, 1, Format::RG16F, rt}));
    plan.resources.push_back(plannedTexture("motion_blur", "output", {desc_.width, desc_.height, 1, desc_.colorFormat, rt}));
    plan.resources.push_back({"motion_blur", "uniforms", Format::Undefined, 0, 0, 1, sizeof(PackParams) + sizeof(ReconstructParams)});
    return plan;
}

}  // namespace sfx
