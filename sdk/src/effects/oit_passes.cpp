// sfx::Transparency's frame: input checks, the per-draw uniforms, and the passes of each path
// (A-buffer clear / fill / resolve on the high tier, weighted blended accumulate / resolve on
// the current tier).
#include <cmath>
#include <string>

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "sfx/oit.hpp"
#include "sfx/settings_ranges.hpp"
#include "sfx_shaders.hpp"
#include "sfx_shared_oit.h"
#include "sfx_shared_oit_params.h"

namespace sfx {
namespace {

void copyMatrix(float (&out)[16], const glm::mat4& m) {
    const float* p = glm::value_ptr(m);
    for (int i = 0; i < 16; ++i) out[i] = p[i];
}

Status checkDraw(const TransparentDraw& d, size_t i) {
    const std::string at = "TransparencyInputs.draws[" + std::to_string(i) + "].";
    if (d.vertices.isNull()) return invalidArgument(at + "vertices", "null", "a vertex buffer of TransparentVertex");
    if (d.vertexCount == 0 || d.vertexCount % 3 != 0)
        return invalidArgument(at + "vertexCount", std::to_string(d.vertexCount), "a positive multiple of 3");
    SFX_TRY(checkSetting(Setting::OitDrawOpacity, d.opacity, at + "opacity"));
    for (int c = 0; c < 3; ++c)
        if (!(d.color[c] >= 0.0f && d.color[c] <= 1.0e4f))
            return invalidArgument(at + "color", std::to_string(d.color[c]), "each channel in [0, 1e4]");
    if (d.id > shared::SFX_OIT_DRAW_INDEX_MASK) return invalidArgument(at + "id", std::to_string(d.id), "[0, 2^31)");
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(d.model[c][r])) return invalidArgument(at + "model", "a non-finite element", "finite values");
    return Status::ok();
}

}  // namespace

Status Transparency::uploadDraws(const TransparencyInputs& in) {
    while (drawParams_.size() < in.draws.size()) {
        Result<BufferHandle> b = device_.createBuffer({sizeof(shared::OitDrawParams), kBufferUniform, "sfx-oit-draw-params"});
        if (!b) return b.status();
        drawParams_.push_back(b.value());
    }
    for (size_t i = 0; i < in.draws.size(); ++i) {
        const TransparentDraw& d = in.draws[i];
        const glm::mat4 modelView = in.view * d.model;
        shared::OitDrawParams p{};
        copyMatrix(p.modelView, modelView);
        copyMatrix(p.projection, in.projection);
        copyMatrix(p.normalMatrix, glm::inverseTranspose(modelView));
        p.color[0] = d.color.r;
        p.color[1] = d.color.g;
        p.color[2] = d.color.b;
        p.color[3] = d.opacity;
        p.drawId = int32_t(d.id);
        SFX_TRY(device_.writeBuffer(drawParams_[i], 0, &p, sizeof p));
    }
    return Status::ok();
}

// One draw per TransparentDraw with its uniform block at `paramsBinding` and the pass's shared bindings.
std::vector<DrawDesc> Transparency::geometryDraws(const TransparencyInputs& in, PipelineHandle pipeline, uint32_t paramsBinding,
                                                  const BindingSet& shared) const {
    std::vector<DrawDesc> draws(in.draws.size());
    for (size_t i = 0; i < in.draws.size(); ++i) {
        DrawDesc& d = draws[i];
        d.pipeline = pipeline;
        d.vertexBuffer = in.draws[i].vertices;
        d.count = in.draws[i].vertexCount;
        d.bindings = shared;
        d.bindings.uniformBuffers = {{paramsBinding, drawParams_[i]}};
    }
    return draws;
}

Status Transparency::render(const TransparencyInputs& in) {
    if (in.opaqueColor.isNull()) return invalidArgument("TransparencyInputs.opaqueColor", "null", "the opaque colour texture");
    if (in.draws.empty()) {
        output_ = in.opaqueColor;  // nothing to composite
        aoOutput_ = {};            // and no layer to shade: the host's opaque AO stands
        return Status::ok();
    }
    if (in.opaqueDepth.isNull()) return invalidArgument("TransparencyInputs.opaqueDepth", "null", "the opaque depth attachment");
    for (size_t i = 0; i < in.draws.size(); ++i) SFX_TRY(checkDraw(in.draws[i], i));
    SFX_TRY(ensurePrograms());
    SFX_TRY(ensureTargets());
    SFX_TRY(uploadDraws(in));
    output_ = ownedOutput_;
    return abuffer_ ? renderAbuffer(in) : renderWeighted(in);
}

Status Transparency::renderAbuffer(const TransparencyInputs& in) {
    // Compression and AO reconstruct linear depth and view positions from the projection.
    const bool layers = desc_.compressedNodes > 0 || desc_.ao.enabled;
    DepthReconstruction rec;
    if (layers) {
        Result<DepthReconstruction> r = makeDepthReconstruction({glm::dmat4(in.projection), device_.caps().clipDepth}, desc_.width, desc_.height);
        if (!r)
            return invalidArgument("TransparencyInputs.projection", "not a perspective projection (" + r.status().message() + ")",
                                   "a finite perspective projection looking down -z (needed by compression and AO)");
        rec = r.value();
        if (!(rec.maxDepth < double(shared::SFX_SKY_DEPTH)))
            return invalidArgument("TransparencyInputs.projection", "an infinite far plane",
                                   "a finite far plane (compressed depths are normalised over [near, far])");
    }
    SFX_TRY(sizePoolFromLastFrame());
    shared::OitResolveParams rp{};
    rp.maxLayers = int32_t(keptLayers(desc_));
    rp.ndcScale = float(rec.ndcScale);
    rp.denomOffset = float(rec.denomOffset);
    rp.numerator = float(rec.numerator);
    rp.maxDepth = float(rec.maxDepth);
    rp.zNear = float(rec.nearDepth);
    rp.zFar = float(rec.maxDepth);
    SFX_TRY(device_.writeBuffer(resolveParams_, 0, &rp, sizeof rp));

    DispatchDesc clear;
    clear.pipeline = clearPipeline_;
    clear.groupsX = (desc_.width + 7) / 8;
    clear.groupsY = (desc_.height + 7) / 8;
    clear.bindings.storageBuffers = {{gen::oit_clear::OitPool, pool_}};
    clear.bindings.storageImages = {{gen::oit_clear::uHeads, heads_}};
    SFX_TRY(timed(0, [&] { return device_.dispatch(clear); }));

    RenderPassDesc fill;
    fill.depth = {in.opaqueDepth, LoadOp::Load};
    fill.debugName = "oit fill";
    BindingSet shared;
    shared.storageBuffers = {{gen::oit_fill::OitPool, pool_}};
    shared.storageImages = {{gen::oit_fill::uHeads, heads_}};
    const std::vector<DrawDesc> draws = geometryDraws(in, fillPipeline_, gen::oit_fill::OitDrawParams, shared);
    SFX_TRY(timed(1, [&] { return device_.renderPass(fill, draws); }));
    poolUsed_ = true;

    RenderPassDesc resolve;
    resolve.colors = {{ownedOutput_, 0, LoadOp::DontCare}};
    resolve.debugName = "oit resolve";
    DrawDesc r;
    r.pipeline = resolvePipeline_;
    if (desc_.compressedNodes > 0) {
        namespace g = gen::oit_resolve_compress;
        r.bindings.textures = {{g::uOpaque, in.opaqueColor}, {g::uOpaqueDepth, in.opaqueDepth}};
        r.bindings.uniformBuffers = {{g::OitResolveParams, resolveParams_}};
        r.bindings.storageBuffers = {{g::OitPool, pool_}, {g::OitCompressed, compressed_}};
        r.bindings.storageImages = {{g::uHeads, heads_}};
    } else {
        r.bindings.textures = {{gen::oit_resolve::uOpaque, in.opaqueColor}};
        r.bindings.uniformBuffers = {{gen::oit_resolve::OitResolveParams, resolveParams_}};
        r.bindings.storageBuffers = {{gen::oit_resolve::OitPool, pool_}};
        r.bindings.storageImages = {{gen::oit_resolve::uHeads, heads_}};
    }
    SFX_TRY(timed(2, [&] { return device_.renderPass(resolve, {&r, 1}); }));
    return desc_.ao.enabled ? renderLayerAo(in, rec) : Status::ok();
}

Status Transparency::renderWeighted(const TransparencyInputs& in) {
    RenderPassDesc accumulate;
    accumulate.colors = {{accum_, 0, LoadOp::Clear, {0, 0, 0, 1}}, {weight_, 0, LoadOp::Clear, {0, 0, 0, 1}}};
    accumulate.depth = {in.opaqueDepth, LoadOp::Load};
    accumulate.debugName = "oit weighted blended accumulate";
    const std::vector<DrawDesc> draws = geometryDraws(in, accumPipeline_, gen::oit_wboit_accumulate::OitDrawParams, {});
    SFX_TRY(timed(0, [&] { return device_.renderPass(accumulate, draws); }));

    RenderPassDesc resolve;
    resolve.colors = {{ownedOutput_, 0, LoadOp::DontCare}};
    resolve.debugName = "oit weighted blended resolve";
    DrawDesc r;
    r.pipeline = weightedResolvePipeline_;
    r.bindings.textures = {
        {gen::oit_wboit_resolve::uOpaque, in.opaqueColor}, {gen::oit_wboit_resolve::uAccum, accum_}, {gen::oit_wboit_resolve::uWeight, weight_}};
    return timed(1, [&] { return device_.renderPass(resolve, {&r, 1}); });
}

}  // namespace sfx
