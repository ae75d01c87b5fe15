// sfx::Transparency: creation, programs, targets, the pool sized from the scene's last count,
// statistics and the plan (the passes are recorded in oit_passes.cpp).
#include "sfx/oit.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <type_traits>

#include "effect_common.hpp"
#include "pass_timers.hpp"
#include "sfx/settings_ranges.hpp"
#include "sfx_shaders.hpp"
#include "sfx_shared_oit.h"
#include "sfx_shared_oit_params.h"

namespace sfx {

Status checkLayerSettings(const TransparencyDesc& desc);  // oit_layers.cpp

namespace {

using detail::isColorFormat;
using detail::loadProgram;

bool isOpaqueDepthFormat(Format f) { return f == Format::D16 || f == Format::D24S8 || f == Format::D32F; }

Status checkProfile(const TierProfile& p) {
    if (uint32_t(p.tier) >= kTierCount || p.aoScalableTaps == 0)
        return invalidArgument("TransparencyDesc.profile", "an empty or unknown tier profile",
                               "tiers::profile(tier) or tiers::choose(caps)->profile");
    return Status::ok();
}

}  // namespace

uint32_t keptLayers(TransparencyQuality quality) { return quality == TransparencyQuality::High ? 32u : 16u; }
uint32_t keptLayers(const TransparencyDesc& desc) { return desc.maxLayers.value_or(keptLayers(desc.quality)); }

Transparency::Transparency(Device& device, const TransparencyDesc& desc)
    : device_(device), desc_(desc), passTimers_(std::make_unique<detail::PassTimers>(device)) {}

Transparency::~Transparency() { release(); }

Result<std::unique_ptr<Transparency>> Transparency::create(Device& device, const TransparencyDesc& desc) {
    SFX_TRY(detail::checkTargetSize(device, desc.width, desc.height, "TransparencyDesc."));
    SFX_TRY(checkProfile(desc.profile));
    if (!isColorFormat(desc.colorFormat))
        return invalidArgument("TransparencyDesc.colorFormat", toString(desc.colorFormat), "RGBA8, RGBA16F or RGBA32F");
    if (!isOpaqueDepthFormat(desc.depthFormat))
        return invalidArgument("TransparencyDesc.depthFormat", toString(desc.depthFormat), "D16, D24S8 or D32F");
    if (uint32_t(desc.quality) > uint32_t(TransparencyQuality::High))
        return invalidArgument("TransparencyDesc.quality", std::to_string(uint32_t(desc.quality)), "Standard or High");
    if (desc.maxLayers) SFX_TRY(checkSetting(Setting::OitMaxLayers, *desc.maxLayers));
    if (desc.initialPoolNodes == uint64_t(0)) return invalidArgument("TransparencyDesc.initialPoolNodes", "0", "at least 1 node, or unset");
    const DeviceCaps& caps = device.caps();
    if (!caps.renderableFormat[size_t(desc.colorFormat)])
        return Status{StatusCode::UnsupportedFormat,
                      std::string("TransparencyDesc.colorFormat ") + toString(desc.colorFormat) + " is not renderable on this device"};
    SFX_TRY(checkLayerSettings(desc));
    if (desc.profile.abufferOit && desc.ao.enabled && desc.ao.filterRadius > 0 && !caps.renderableFormat[size_t(Format::RGBA32F)])
        return Status{StatusCode::UnsupportedFormat,
                      "TransparencyDesc.ao.filterRadius " + std::to_string(desc.ao.filterRadius) +
                          " needs RGBA32F render targets (the filter's depth keys); the device has none "
                          "(use 0: the raw AO)"};
    std::unique_ptr<Transparency> t(new Transparency(device, desc));
    if (desc.profile.abufferOit) {
        if (!caps.fragmentStoresAndAtomics || !caps.computeShaders)
            return Status{StatusCode::UnsupportedFeature,
                          "TransparencyDesc.profile is the high tier (A-buffer); the device has no fragment stores and atomics "
                          "or no compute shaders (use the current tier's profile)"};
        t->abuffer_ = true;
    } else if (!caps.blendableFormat[size_t(Format::RGBA16F)]) {
        return Status{StatusCode::UnsupportedFormat, "weighted blended OIT needs blendable RGBA16F render targets; the device has none"};
    }
    return t;
}

Status Transparency::setProfiling(bool enabled) {
    profiling_ = enabled;
    if (!enabled) passTimers_->clear();
    return Status::ok();
}

Status Transparency::timed(size_t index, const std::function<Status()>& record) {
    if (!profiling_) return record();
    return passTimers_->timed(index, record);
}

Result<std::vector<PassTiming>> Transparency::passTimings() {
    if (!profiling_)
        return Status{StatusCode::InvalidArgument, "Transparency::passTimings: profiling is off (call setProfiling(true) before render)"};
    return passTimers_->read(plan(true), "Transparency");
}

void Transparency::release() {
    passTimers_->clear();
    // Destroys through `destroy` when set, then clears the handle.
    auto drop = [&](auto& h, Status (Device::*destroy)(std::remove_reference_t<decltype(h)>)) {
        if (!h.isNull()) (void)(device_.*destroy)(h);
        h = {};
    };
    auto texture = [&](TextureHandle& h) { drop(h, &Device::destroyTexture); };
    auto buffer = [&](BufferHandle& h) { drop(h, &Device::destroyBuffer); };
    auto pipeline = [&](PipelineHandle& h) { drop(h, &Device::destroyPipeline); };
    auto program = [&](ProgramHandle& h) { drop(h, &Device::destroyProgram); };
    for (PipelineHandle* p : {&clearPipeline_, &fillPipeline_, &resolvePipeline_, &accumPipeline_, &weightedResolvePipeline_, &aoPipeline_,
                              &filterPipelines_[0], &filterPipelines_[1]})
        pipeline(*p);
    for (ProgramHandle* p : {&clearProgram_, &fillProgram_, &resolveProgram_, &accumProgram_, &weightedResolveProgram_, &aoProgram_, &filterProgram_})
        program(*p);
    for (TextureHandle* t : {&ownedOutput_, &heads_, &accum_, &weight_, &ownedAo_, &aoRaw_, &aoFiltered_}) texture(*t);
    buffer(compressed_);
    buffer(aoParams_);
    aoOutput_ = {};
    for (BufferHandle& b : drawParams_) buffer(b);
    drawParams_.clear();
    buffer(pool_);
    buffer(resolveParams_);
    poolNodes_ = 0;
    output_ = {};
}

// Programs and pipelines on the first frame with a draw: a scene without transparency pays nothing.
Status Transparency::ensurePrograms() {
    const Tier tier = desc_.profile.tier;
    VertexLayout layout;
    layout.stride = sizeof(TransparentVertex);
    layout.attributes = {{0, VertexFormat::Float3, 0}, {1, VertexFormat::Float3, 12}};
    auto graphics = [&](const char* name, ProgramHandle* program, PipelineHandle* pipeline, GraphicsPipelineDesc d) -> Status {
        if (!pipeline->isNull()) return Status::ok();
        Result<ProgramHandle> p = loadProgram(device_, name, tier);
        if (!p) return p.status();
        *program = p.value();
        d.program = *program;
        d.debugName = name;
        Result<PipelineHandle> pl = device_.createGraphicsPipeline(d);
        if (!pl) return pl.status();
        *pipeline = pl.value();
        return Status::ok();
    };
    GraphicsPipelineDesc geometry;
    geometry.vertexLayout = layout;
    geometry.depth = {true, false, CompareOp::Less};
    geometry.depthFormat = desc_.depthFormat;
    GraphicsPipelineDesc fullscreen;
    fullscreen.colorFormats = {desc_.colorFormat};
    if (abuffer_) {
        if (clearPipeline_.isNull()) {
            Result<ProgramHandle> p = loadProgram(device_, gen::oit_clear::kName, tier);
            if (!p) return p.status();
            clearProgram_ = p.value();
            Result<PipelineHandle> pl = device_.createComputePipeline({clearProgram_, "oit_clear"});
            if (!pl) return pl.status();
            clearPipeline_ = pl.value();
        }
        SFX_TRY(graphics(gen::oit_fill::kName, &fillProgram_, &fillPipeline_, geometry));
        // With compression the resolve also writes the compressed lists (M and the drop search are
        // specialisation constants: fixed per effect, compiled once). With layer AO it also stores
        // each node's transmittance in front, so the AO pass need not sort the lists again.
        GraphicsPipelineDesc resolve = fullscreen;
        const int32_t writeTransmittance = desc_.ao.enabled ? 1 : 0;
        if (desc_.compressedNodes > 0)
            resolve.constants = {{SFX_OIT_SC_COMPRESS_NODES, int32_t(desc_.compressedNodes)},
                                 {SFX_OIT_SC_COMPRESS_BACK_HALF, desc_.compressBackHalfOnly ? 1 : 0},
                                 {SFX_OIT_SC_RESOLVE_TRANSMITTANCE, writeTransmittance}};
        else
            resolve.constants = {{SFX_OIT_SC_RESOLVE_TRANSMITTANCE, writeTransmittance}};
        SFX_TRY(graphics(desc_.compressedNodes > 0 ? gen::oit_resolve_compress::kName : gen::oit_resolve::kName, &resolveProgram_, &resolvePipeline_,
                         resolve));
        if (desc_.ao.enabled) {
            const AoConfig& c = desc_.ao.config;
            GraphicsPipelineDesc ao;
            ao.colorFormats = {Format::RG16F};
            ao.constants = {{SFX_OIT_SC_AO_TECHNIQUE, c.technique == AoTechnique::Alchemy ? 0 : 1},
                            {SFX_OIT_SC_AO_SAMPLES, int32_t(c.samples)},
                            {SFX_OIT_SC_AO_MIRRORED, c.mirrored ? 1 : 0}};
            const bool compressed = desc_.ao.occluders == TransparencyAoOccluders::Compressed;
            if (desc_.ao.filterRadius > 0) ao.colorFormats = {Format::RGBA32F};  // the keys in b, a at full precision
            SFX_TRY(graphics(compressed ? gen::oit_ao_compressed::kName : gen::oit_ao::kName, &aoProgram_, &aoPipeline_, ao));
            for (int vertical = 0; vertical < 2 && desc_.ao.filterRadius > 0; ++vertical) {
                GraphicsPipelineDesc f;
                f.colorFormats = {Format::RG16F};
                f.constants = {{SFX_OIT_SC_FILTER_RADIUS, int32_t(desc_.ao.filterRadius)}, {SFX_OIT_SC_FILTER_VERTICAL, vertical}};
                if (vertical == 1) {  // the same program, a second pipeline, made once
                    if (!filterPipelines_[1].isNull()) continue;
                    f.program = filterProgram_;
                    f.debugName = "oit_ao_filter v";
                    Result<PipelineHandle> pl = device_.createGraphicsPipeline(f);
                    if (!pl) return pl.status();
                    filterPipelines_[1] = pl.value();
                } else {
                    SFX_TRY(graphics(gen::oit_ao_filter::kName, &filterProgram_, &filterPipelines_[0], f));
                }
            }
        }
    } else {
        geometry.colorFormats = {Format::RGBA16F, Format::RGBA16F};
        geometry.blend = {true, BlendFactor::One, BlendFactor::One, true, BlendFactor::Zero, BlendFactor::OneMinusSrcAlpha};
        SFX_TRY(graphics(gen::oit_wboit_accumulate::kName, &accumProgram_, &accumPipeline_, geometry));
        SFX_TRY(graphics(gen::oit_wboit_resolve::kName, &weightedResolveProgram_, &weightedResolvePipeline_, fullscreen));
    }
    return Status::ok();
}

Status Transparency::ensureTargets() {
    auto make = [&](TextureHandle* t, Format f, uint32_t usage, const char* name) -> Status {
        if (!t->isNull()) return Status::ok();
        Result<TextureHandle> r = device_.createTexture({desc_.width, desc_.height, 1, f, usage, name});
        if (!r) return r.status();
        *t = r.value();
        return Status::ok();
    };
    const uint32_t rt = kTextureSampled | kTextureRenderTarget;
    SFX_TRY(make(&ownedOutput_, desc_.colorFormat, rt, "sfx-oit-output"));
    if (abuffer_) {
        SFX_TRY(make(&heads_, Format::R32UI, kTextureSampled | kTextureStorage, "sfx-oit-heads"));
        if (resolveParams_.isNull()) {
            Result<BufferHandle> b = device_.createBuffer({sizeof(shared::OitResolveParams), kBufferUniform, "sfx-oit-resolve-params"});
            if (!b) return b.status();
            resolveParams_ = b.value();
        }
        SFX_TRY(ensureLayerTargets());
        if (pool_.isNull()) SFX_TRY(ensurePool(desc_.initialPoolNodes.value_or(uint64_t(kOitInitialNodesPerPixel) * desc_.width * desc_.height)));
    } else {
        SFX_TRY(make(&accum_, Format::RGBA16F, rt, "sfx-oit-wboit-accum"));
        SFX_TRY(make(&weight_, Format::RGBA16F, rt, "sfx-oit-wboit-weight"));
    }
    return Status::ok();
}

uint64_t Transparency::maxPoolNodes() const {
    const DeviceLimits& l = device_.caps().limits;
    const uint64_t bytes = std::min(l.maxStorageBufferSize, l.maxBufferSize);
    const uint64_t nodes = bytes > uint64_t(shared::SFX_OIT_POOL_HEADER_BYTES) ? (bytes - uint64_t(shared::SFX_OIT_POOL_HEADER_BYTES)) / kOitNodeBytes
                                                                               : 0;
    // Node indices are 32-bit, and the end-of-list index is reserved.
    return std::min<uint64_t>(nodes, 0xFFFFFFFEull);
}

Status Transparency::ensurePool(uint64_t nodes) {
    nodes = std::clamp<uint64_t>(nodes, 1, maxPoolNodes());
    if (!pool_.isNull() && nodes == poolNodes_) return Status::ok();
    if (!pool_.isNull()) SFX_TRY(device_.destroyBuffer(pool_));
    pool_ = {};
    poolNodes_ = 0;
    poolUsed_ = false;
    Result<BufferHandle> b = device_.createBuffer(
        {uint64_t(shared::SFX_OIT_POOL_HEADER_BYTES) + nodes * kOitNodeBytes, kBufferStorage, "sfx-oit-pool"});
    if (!b) return b.status();
    pool_ = b.value();
    poolNodes_ = nodes;
    const uint32_t header[4] = {0u, uint32_t(nodes), 0u, 0u};
    return device_.writeBuffer(pool_, 0, header, sizeof header);
}

Result<uint32_t> Transparency::readCounter() {
    uint32_t count = 0;
    SFX_TRY(device_.readBuffer(pool_, 0, &count, sizeof count));
    return count;
}

// The last frame's count decides this frame's pool: grown when it did not fit (with headroom),
// shrunk when it is over four times what the scene needs.
Status Transparency::sizePoolFromLastFrame() {
    if (pool_.isNull() || !poolUsed_) return Status::ok();
    Result<TransparencyStats> s = stats();
    if (!s) return s.status();
    const uint64_t wanted = uint64_t(std::ceil(double(s->fragments) * kOitPoolHeadroom));
    const uint64_t floor = uint64_t(desc_.width) * desc_.height;
    if (wanted > poolNodes_) return ensurePool(wanted);
    if (poolNodes_ > 4 * std::max(wanted, floor)) return ensurePool(std::max(wanted, floor));
    return Status::ok();
}

Result<TransparencyStats> Transparency::stats() {
    if (!abuffer_ || pool_.isNull() || !poolUsed_) return last_;
    Result<uint32_t> count = readCounter();
    if (!count) return count.status();
    TransparencyStats s;
    s.fragments = count.value();
    s.poolNodes = poolNodes_;
    s.stored = std::min<uint64_t>(s.fragments, poolNodes_);
    s.dropped = s.fragments - s.stored;
    s.poolBytes = uint64_t(shared::SFX_OIT_POOL_HEADER_BYTES) + poolNodes_ * kOitNodeBytes;
    last_ = s;
    return s;
}

EffectPlan Transparency::plan(bool hasTransparentDraws) const {
    EffectPlan plan;
    if (!hasTransparentDraws) return plan;  // no pass, no memory: output() is the opaque colour
    const uint32_t w = desc_.width, h = desc_.height;
    const uint32_t rt = kTextureSampled | kTextureRenderTarget;
    const std::string k = std::to_string(keptLayers(desc_));
    if (abuffer_) {
        plan.passes.push_back({"oit", "clear heads + counter (compute; lists start empty)", w, h});
        plan.passes.push_back({"oit", "fill lists (one geometry pass, depth-tested, atomics)", w, h});
        plan.passes.push_back({"oit", "resolve (sort, nearest " + k + " exact + tail, over opaque)", w, h});
        plan.resources.push_back(plannedTexture("oit", "list heads (one node index per pixel)", {w, h, 1, Format::R32UI, kTextureStorage}));
        const uint64_t nodes = poolNodes_ != 0 ? poolNodes_ : desc_.initialPoolNodes.value_or(uint64_t(kOitInitialNodesPerPixel) * w * h);
        plan.resources.push_back(
            {"oit", "node pool (" + std::to_string(nodes) + " nodes: last count x " + std::to_string(kOitPoolHeadroom).substr(0, 3) + ")",
             Format::Undefined, 0, 0, 1, uint64_t(shared::SFX_OIT_POOL_HEADER_BYTES) + nodes * kOitNodeBytes});
        plan.resources.push_back({"oit", "resolve uniforms", Format::Undefined, 0, 0, 1, sizeof(shared::OitResolveParams)});
        planLayerAo(plan);
    } else {
        plan.passes.push_back({"oit", "weighted blended accumulate (one geometry pass, one blend state)", w, h});
        plan.passes.push_back({"oit", "weighted blended resolve (over opaque)", w, h});
        plan.resources.push_back(plannedTexture("oit", "accumulated weighted colour + revealage", {w, h, 1, Format::RGBA16F, rt}));
        plan.resources.push_back(plannedTexture("oit", "accumulated weight", {w, h, 1, Format::RGBA16F, rt}));
        planLayerAo(plan);
    }
    plan.resources.push_back(plannedTexture("oit", "output (composited colour)", {w, h, 1, desc_.colorFormat, rt}));
    plan.resources.push_back(
        {"oit", "draw uniforms (one block per draw)", Format::Undefined, 0, 0, 1, drawParams_.size() * sizeof(shared::OitDrawParams)});
    return plan;
}

}  // namespace sfx
