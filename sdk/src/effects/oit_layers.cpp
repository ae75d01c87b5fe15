// sfx::Transparency's optional high-tier work on the layers: list compression during the resolve
// and opacity-based AO through the layers (after Bauer et al. 2013, section III). Settings
// checks, their targets, the AO pass and what the plan says about them.
#include <cmath>
#include <string>

#include "sfx/oit.hpp"
#include "sfx/settings_ranges.hpp"
#include "sfx_shaders.hpp"
#include "sfx_shared_oit.h"
#include "sfx_shared_oit_params.h"

namespace sfx {

namespace {

std::string fmt(double v) {
    std::string s = std::to_string(v);
    return s.substr(0, s.find_last_not_of('0') + 1);
}

Status inRange(const char* field, double v, double lo, double hi, bool openLow = false) {
    const bool ok = std::isfinite(v) && (openLow ? v > lo : v >= lo) && v <= hi;
    if (ok) return Status::ok();
    return invalidArgument(std::string("TransparencyDesc.ao.config.") + field, fmt(v), (openLow ? "(" : "[") + fmt(lo) + ", " + fmt(hi) + "]");
}

}  // namespace

Status checkLayerSettings(const TransparencyDesc& desc) {
    SFX_TRY(checkSetting(Setting::OitCompressedNodes, desc.compressedNodes));
    const TransparencyAoDesc& ao = desc.ao;
    if (!ao.enabled) return Status::ok();
    const AoConfig& c = ao.config;
    if (c.technique != AoTechnique::Alchemy && c.technique != AoTechnique::Scalable)
        return invalidArgument("TransparencyDesc.ao.config.technique", toString(c.technique), "Alchemy or Scalable");
    if (uint32_t(ao.occluders) > uint32_t(TransparencyAoOccluders::Compressed))
        return invalidArgument("TransparencyDesc.ao.occluders", std::to_string(uint32_t(ao.occluders)), "BruteForce or Compressed");
    if (ao.occluders == TransparencyAoOccluders::Compressed && desc.compressedNodes == 0)
        return invalidArgument("TransparencyDesc.compressedNodes", "0 with ao.occluders Compressed",
                               "[1, " + std::to_string(shared::SFX_OIT_COMPRESSED_NODES) + "] (the nodes the AO taps read)");
    if (c.samples < 1 || c.samples > uint32_t(shared::SFX_AO_MAX_SAMPLES) || (c.mirrored && c.samples % 2 != 0))
        return invalidArgument("TransparencyDesc.ao.config.samples", std::to_string(c.samples),
                               "[1, " + std::to_string(shared::SFX_AO_MAX_SAMPLES) + "], even when mirrored");
    SFX_TRY(inRange("radius", c.radius, 0.0, 1.0e4, true));
    SFX_TRY(inRange("intensity", c.intensity, 0.0, 1.0e3));
    SFX_TRY(inRange("contrast", c.contrast, 0.0, 100.0));
    SFX_TRY(inRange("bias", c.bias, 0.0, 1.0));
    SFX_TRY(inRange("sumExponent", c.sumExponent, 0.5, 4.0));
    SFX_TRY(inRange("epsilon", c.epsilon, 0.0, 1.0, true));
    SFX_TRY(inRange("spiralTurns", c.spiralTurns, 0.0, 1.0e3));
    SFX_TRY(inRange("maxRadiusPx", c.maxRadiusPx, 0.0, 1.0e5));
    SFX_TRY(checkSetting(Setting::OitAoFilterRadius, ao.filterRadius));
    return Status::ok();
}

Status Transparency::ensureLayerTargets() {
    const uint64_t pixels = uint64_t(desc_.width) * desc_.height;
    if (desc_.compressedNodes > 0 && compressed_.isNull()) {
        Result<BufferHandle> b = device_.createBuffer(
            {pixels * uint64_t(shared::SFX_OIT_COMPRESSED_WORDS) * 4u, kBufferStorage, "sfx-oit-compressed"});
        if (!b) return b.status();
        compressed_ = b.value();
    }
    if (desc_.ao.enabled) {
        if (ownedAo_.isNull()) {
            Result<TextureHandle> t = device_.createTexture(
                {desc_.width, desc_.height, 1, Format::RG16F, kTextureSampled | kTextureRenderTarget, "sfx-oit-ao"});
            if (!t) return t.status();
            ownedAo_ = t.value();
        }
        auto filterTarget = [&](TextureHandle* h, Format f, const char* name) -> Status {
            if (desc_.ao.filterRadius == 0 || !h->isNull()) return Status::ok();
            Result<TextureHandle> t = device_.createTexture({desc_.width, desc_.height, 1, f, kTextureSampled | kTextureRenderTarget, name});
            if (!t) return t.status();
            *h = t.value();
            return Status::ok();
        };
        SFX_TRY(filterTarget(&aoRaw_, Format::RGBA32F, "sfx-oit-ao-raw"));
        SFX_TRY(filterTarget(&aoFiltered_, Format::RG16F, "sfx-oit-ao-filtered-h"));
        if (aoParams_.isNull()) {
            Result<BufferHandle> b = device_.createBuffer({sizeof(shared::OitAoParams), kBufferUniform, "sfx-oit-ao-params"});
            if (!b) return b.status();
            aoParams_ = b.value();
        }
    }
    return Status::ok();
}

Status Transparency::renderLayerAo(const TransparencyInputs& in, const DepthReconstruction& rec) {
    const AoConfig& c = desc_.ao.config;
    shared::OitAoParams p{};
    for (int i = 0; i < 4; ++i) p.projInfo[i] = float(rec.projInfo[i]);
    p.radius = float(c.radius);
    p.intensity = float(c.intensity);
    p.contrast = float(c.contrast);
    p.bias = float(c.bias);
    p.epsilon = float(c.epsilon);
    p.pixelsPerUnit = float(rec.pixelsPerUnitAtUnitDepth);
    p.maxRadiusPx = float(c.maxRadiusPx);
    p.maxDepth = float(rec.maxDepth);
    p.spiralHalfStepQ16 = shared::aoSpiralHalfStepQ16(c.spiralTurns, c.samples, c.mirrored);
    p.sumExponent = float(c.sumExponent);
    p.ndcScale = float(rec.ndcScale);
    p.denomOffset = float(rec.denomOffset);
    p.numerator = float(rec.numerator);
    p.zNear = float(rec.nearDepth);
    p.zFar = float(rec.maxDepth);
    SFX_TRY(device_.writeBuffer(aoParams_, 0, &p, sizeof p));

    const bool compressed = desc_.ao.occluders == TransparencyAoOccluders::Compressed;
    RenderPassDesc pass;
    const bool filtered = desc_.ao.filterRadius > 0;
    pass.colors = {{filtered ? aoRaw_ : ownedAo_, 0, LoadOp::DontCare}};
    pass.debugName = compressed ? "oit ao (compressed nodes)" : "oit ao (brute force)";
    DrawDesc d;
    d.pipeline = aoPipeline_;
    if (compressed) {
        d.bindings.textures = {{gen::oit_ao_compressed::uOpaqueDepth, in.opaqueDepth}};
        d.bindings.uniformBuffers = {{gen::oit_ao_compressed::OitAoParams, aoParams_}};
        d.bindings.storageBuffers = {{gen::oit_ao_compressed::OitPool, pool_}, {gen::oit_ao_compressed::OitCompressed, compressed_}};
        d.bindings.storageImages = {{gen::oit_ao_compressed::uHeads, heads_}};
    } else {
        d.bindings.textures = {{gen::oit_ao::uOpaqueDepth, in.opaqueDepth}};
        d.bindings.uniformBuffers = {{gen::oit_ao::OitAoParams, aoParams_}};
        d.bindings.storageBuffers = {{gen::oit_ao::OitPool, pool_}};
        d.bindings.storageImages = {{gen::oit_ao::uHeads, heads_}};
    }
    SFX_TRY(timed(3, [&] { return device_.renderPass(pass, {&d, 1}); }));
    if (filtered) SFX_TRY(filterLayerAo());
    aoOutput_ = ownedAo_;
    return Status::ok();
}

// The bilateral filter: raw (RGBA32F, keys in b and a) -> horizontal -> vertical into the output.
Status Transparency::filterLayerAo() {
    namespace g = gen::oit_ao_filter;
    const TextureHandle sources[2] = {aoRaw_, aoFiltered_}, targets[2] = {aoFiltered_, ownedAo_};
    for (int vertical = 0; vertical < 2; ++vertical) {
        RenderPassDesc pass;
        pass.colors = {{targets[vertical], 0, LoadOp::DontCare}};
        pass.debugName = vertical ? "oit ao filter (vertical)" : "oit ao filter (horizontal)";
        DrawDesc d;
        d.pipeline = filterPipelines_[vertical];
        d.bindings.textures = {{g::uSource, sources[vertical]}, {g::uKeys, aoRaw_}};
        d.bindings.uniformBuffers = {{g::OitAoParams, aoParams_}};
        SFX_TRY(timed(size_t(4 + vertical), [&] { return device_.renderPass(pass, {&d, 1}); }));
    }
    return Status::ok();
}

void Transparency::planLayerAo(EffectPlan& plan) const {
    const uint32_t w = desc_.width, h = desc_.height;
    if (!abuffer_) {
        // The current tier keeps no layers: AO there is the host's, over the opaque layer only.
        if (desc_.ao.enabled || desc_.compressedNodes > 0)
            plan.passes.push_back({"oit", "no AO through layers or compression on the current tier (AO: opaque layer only)", 0, 0});
        return;
    }
    if (desc_.compressedNodes > 0) {
        const std::string m = std::to_string(desc_.compressedNodes);
        plan.passes.back().name += " + compress lists to " + m + " nodes";
        plan.resources.push_back({"oit", "compressed lists (" + m + " nodes of 16-bit depth + 8-bit opacity, 12 B/px; for AO taps)",
                                  Format::Undefined, w, h, 1, uint64_t(w) * h * uint64_t(shared::SFX_OIT_COMPRESSED_WORDS) * 4u});
    }
    if (desc_.ao.enabled) {
        const bool compressed = desc_.ao.occluders == TransparencyAoOccluders::Compressed;
        plan.passes.push_back({"oit",
                               std::string("AO through layers (") + toString(desc_.ao.config.technique) + ", " +
                                   (compressed ? "taps read the compressed nodes" : "brute force: taps walk the lists") +
                                   "; blended by opacity, separate from colour)",
                               w, h});
        plan.resources.push_back(plannedTexture("oit", "AO through layers (r blended, g opaque surface)",
                                                {w, h, 1, Format::RG16F, kTextureSampled | kTextureRenderTarget}));
        plan.resources.push_back({"oit", "AO uniforms", Format::Undefined, 0, 0, 1, sizeof(shared::OitAoParams)});
        if (desc_.ao.filterRadius > 0) {
            const std::string r = std::to_string(desc_.ao.filterRadius);
            for (const char* dir : {"horizontal", "vertical"})
                plan.passes.push_back({"oit",
                                       std::string("AO bilateral filter, ") + dir + " (" + r +
                                           " taps each side; keys: front depth for blended, opaque depth for opaque)",
                                       w, h});
            plan.resources.push_back(plannedTexture("oit", "raw AO through layers + filter keys (front depth, opaque depth)",
                                                    {w, h, 1, Format::RGBA32F, kTextureSampled | kTextureRenderTarget}));
            plan.resources.push_back(
                plannedTexture("oit", "AO after the horizontal filter pass", {w, h, 1, Format::RG16F, kTextureSampled | kTextureRenderTarget}));
        }
    }
}

}  // namespace sfx
