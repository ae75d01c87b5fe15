// The shared checks of commands: a render pass with its draws, a dispatch, and the bindings of
// either against the pipeline's program reflection and the bound resources. Device's front end
// calls renderPass / dispatch with the backend's ObjectLookup before recording anything, so a
// refused command leaves every target as it was. Codes and messages: validation_messages.cpp.
// These run on every command the effects record, so the success path builds no string and
// allocates nothing once warm: argument names ("DrawDesc.bindings.textures[1].texture") are
// kept as parts (Arg) and spelled out only for a message, and the per-command lists live in
// per-thread scratch vectors that keep their capacity.
#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include "hal_validation_words.hpp"
#include "sfx/hal_validation.hpp"

namespace sfx::validation {
namespace {

// A command argument's name as its parts, e.g. {"DrawDesc", 2} {".bindings"} {".textures", 0}
// for "DrawDesc[2].bindings.textures[0]"; str() spells it out for a message.
class Arg {
public:
    static constexpr size_t kNoIndex = ~size_t(0);
    explicit Arg(const char* root, size_t index = kNoIndex) { push(root, index); }
    Arg then(const char* field, size_t index = kNoIndex) const {
        Arg a = *this;
        a.push(field, index);
        return a;
    }
    std::string str() const {
        std::string out;
        for (uint32_t i = 0; i < count_; ++i) {
            out += parts_[i].name;
            if (parts_[i].index != kNoIndex) out += "[" + validation::str(parts_[i].index) + "]";
        }
        return out;
    }

private:
    struct Part {
        const char* name = "";
        size_t index = kNoIndex;
    };
    void push(const char* name, size_t index) {
        if (count_ < parts_.size()) parts_[count_++] = {name, index};
    }
    std::array<Part, 5> parts_{};
    uint32_t count_ = 0;
};

// Runs `check` (a lookup or range check taking its argument's name) without a name first and,
// only when that fails, again with the name spelled out for the message.
template <class Check>
auto named(const Arg& arg, Check&& check) {
    static const std::string kUnnamed;
    auto r = check(kUnnamed);
    if (r) return r;
    return check(arg.str());
}

// One use of a texture's mips by a command, for the two-ways check.
struct MipUse {
    TextureHandle texture;
    uint32_t baseMip = 0, mipCount = 1;
    const char* as = "";  // "a sampled texture", "a storage image", "a colour attachment"...
    Arg argument;         // who uses it
};

// The per-command lists, reused (cleared, capacity kept) by every command on this thread.
struct Scratch {
    std::vector<MipUse> uses;
    std::vector<Format> colorFormats;
    std::vector<std::pair<uint32_t, Arg>> given;  // ReflectionMatch's claimed bindings
};
Scratch& scratch() {
    thread_local Scratch s;
    return s;
}

const char* bindingSetField(ResourceKind k) {
    switch (k) {
        case ResourceKind::UniformBuffer: return "uniformBuffers";
        case ResourceKind::SampledTexture: return "textures";
        case ResourceKind::StorageBuffer: return "storageBuffers";
        case ResourceKind::StorageImage: return "storageImages";
    }
    return "?";
}

std::string formatsList(const std::vector<Format>& formats) {
    std::string out;
    for (Format f : formats) out += (out.empty() ? "" : ", ") + formatName(f);
    return out;
}

// Binding against reflection: each binding given once, at a binding the program has, of its kind.
class ReflectionMatch {
public:
    ReflectionMatch(const PipelineInfo& pipeline, const Arg& where) : pipeline_(pipeline), where_(where), given_(scratch().given) { given_.clear(); }

    Result<const ShaderResource*> claim(uint32_t binding, ResourceKind kind, const Arg& argument) {
        for (const auto& [b, arg] : given_)
            if (b == binding) return fail(Error::BindingTwice, {argument.str(), str(binding), arg.str()});
        given_.push_back({binding, argument});
        for (const ShaderResource& r : pipeline_.resources)
            if (r.binding == binding) {
                if (r.kind != kind)
                    return fail(Error::BindingKind,
                                {argument.str(), str(binding), pipeline_.programName, toString(r.kind), r.name, bindingSetField(r.kind)});
                return &r;
            }
        std::string bindings;
        for (const ShaderResource& r : pipeline_.resources) bindings += (bindings.empty() ? "" : ", ") + str(r.binding) + " (" + r.name + ")";
        return fail(Error::BindingUnknown, {argument.str(), str(binding), pipeline_.programName, bindings.empty() ? "none" : bindings});
    }

    Status allClaimed() const {
        for (const ShaderResource& r : pipeline_.resources)
            if (std::none_of(given_.begin(), given_.end(), [&](const auto& g) { return g.first == r.binding; }))
                return fail(Error::BindingMissing,
                            {where_.str(), bindingSetField(r.kind), str(r.binding), pipeline_.programName, toString(r.kind), r.name});
        return Status::ok();
    }

private:
    const PipelineInfo& pipeline_;
    const Arg& where_;
    std::vector<std::pair<uint32_t, Arg>>& given_;
};

Status bufferBinding(const BufferBinding& bb, ResourceKind kind, const ShaderResource& block, const Arg& argument, const ObjectLookup& objects,
                     const DeviceCaps& caps) {
    Result<const BufferDesc*> found = named(argument.then(".buffer"), [&](const std::string& name) { return objects.buffer(bb.buffer, name); });
    if (!found) return found.status();
    const BufferDesc& buffer = *found.value();
    const bool uniform = kind == ResourceKind::UniformBuffer;
    const uint32_t usage = uniform ? kBufferUniform : kBufferStorage;
    if (!(buffer.usage & usage))
        return fail(Error::ResourceUsage, {argument.then(".buffer").str(), bufferUsageNames(buffer.usage), "buffer", bufferUsageNames(usage)});
    const uint64_t size = boundSize(bb, buffer);
    SFX_TRY(named(argument, [&](const std::string& name) { return bufferRange(buffer, bb.offset, size, name); }));
    const uint64_t alignment = uniform ? caps.limits.minUniformBufferOffsetAlignment : caps.limits.minStorageBufferOffsetAlignment;
    if (alignment > 1 && bb.offset % alignment != 0)
        return fail(Error::BufferBindingAlignment,
                    {argument.str(), str(bb.offset), str(alignment),
                     uniform ? "caps.limits.minUniformBufferOffsetAlignment" : "caps.limits.minStorageBufferOffsetAlignment"});
    const uint64_t maxRange = uniform ? caps.limits.maxUniformBlockSize : caps.limits.maxStorageBufferSize;
    if (size > maxRange)
        return fail(Error::BufferBindingMaxRange,
                    {argument.str(), str(size), str(maxRange), uniform ? "caps.limits.maxUniformBlockSize" : "caps.limits.maxStorageBufferSize"});
    if (block.blockSize > size) return fail(Error::BufferBindingBlockSize, {argument.str(), str(size), str(block.blockSize), block.name});
    return Status::ok();
}

// A BindingSet against the pipeline's reflection and the bound resources; appends its mip uses.
Status bindings(const BindingSet& set, const PipelineInfo& pipeline, const Arg& where, const ObjectLookup& objects, const DeviceCaps& caps,
                std::vector<MipUse>& uses) {
    ReflectionMatch reflection(pipeline, where);
    for (size_t i = 0; i < set.textures.size(); ++i) {
        const TextureBinding& tb = set.textures[i];
        const Arg arg = where.then(".textures", i);
        Result<const ShaderResource*> r = reflection.claim(tb.binding, ResourceKind::SampledTexture, arg);
        if (!r) return r.status();
        Result<const TextureDesc*> t = named(arg.then(".texture"), [&](const std::string& name) { return objects.texture(tb.texture, name); });
        if (!t) return t.status();
        const SamplerDesc* sampler = nullptr;
        if (!tb.sampler.isNull()) {
            Result<const SamplerDesc*> s = named(arg.then(".sampler"), [&](const std::string& name) { return objects.sampler(tb.sampler, name); });
            if (!s) return s.status();
            sampler = s.value();
        }
        const TextureDesc& desc = *t.value();
        const bool linear = sampler &&
            (sampler->minFilter == Filter::Linear || sampler->magFilter == Filter::Linear || sampler->mipFilter == Filter::Linear);
        if (linear && !caps.filterableFormat[size_t(desc.format)])
            return fail(Error::BindingNotFilterable,
                        {arg.str(), toString(desc.format), formatList([&](Format f) { return caps.filterableFormat[size_t(f)]; })});
        if (!(desc.usage & kTextureSampled))
            return fail(Error::ResourceUsage, {arg.then(".texture").str(), textureUsageNames(desc.usage), "texture", "sampled"});
        // baseMip + mipCount in 32 bits wraps (1 + 0xFFFFFFFF = 0); compare without adding.
        if (tb.mipCount == 0 || tb.baseMip >= desc.mipLevels || tb.mipCount > desc.mipLevels - tb.baseMip)
            return fail(Error::BindingMips, {arg.str(), str(tb.baseMip), str(tb.mipCount), str(desc.mipLevels)});
        uses.push_back({tb.texture, tb.baseMip, tb.mipCount, "a sampled texture", arg});
    }
    for (size_t i = 0; i < set.storageImages.size(); ++i) {
        const StorageImageBinding& ib = set.storageImages[i];
        const Arg arg = where.then(".storageImages", i);
        Result<const ShaderResource*> r = reflection.claim(ib.binding, ResourceKind::StorageImage, arg);
        if (!r) return r.status();
        Result<const TextureDesc*> t = named(arg.then(".texture"), [&](const std::string& name) { return objects.texture(ib.texture, name); });
        if (!t) return t.status();
        if (!(t.value()->usage & kTextureStorage))
            return fail(Error::ResourceUsage, {arg.then(".texture").str(), textureUsageNames(t.value()->usage), "texture", "storage"});
        SFX_TRY(named(arg.then(".mip"), [&](const std::string& name) { return mipRange(*t.value(), ib.mip, name); }));
        uses.push_back({ib.texture, ib.mip, 1, "a storage image", arg});
    }
    const std::pair<const std::vector<BufferBinding>*, ResourceKind> lists[] = {{&set.uniformBuffers, ResourceKind::UniformBuffer},
                                                                                {&set.storageBuffers, ResourceKind::StorageBuffer}};
    for (const auto& [list, kind] : lists)
        for (size_t i = 0; i < list->size(); ++i) {
            const BufferBinding& bb = (*list)[i];
            const Arg arg = where.then(kind == ResourceKind::UniformBuffer ? ".uniformBuffers" : ".storageBuffers", i);
            Result<const ShaderResource*> r = reflection.claim(bb.binding, kind, arg);
            if (!r) return r.status();
            SFX_TRY(bufferBinding(bb, kind, *r.value(), arg, objects, caps));
        }
    return reflection.allClaimed();
}

// A draw may not sample a mip its pass renders to (a feedback loop: undefined on GL, a layout
// conflict on Vulkan).
Status noFeedbackLoop(const RenderPassDesc& pass, const BindingSet& set, const Arg& where) {
    for (size_t i = 0; i < set.textures.size(); ++i) {
        const TextureBinding& tb = set.textures[i];
        auto inRange = [&](uint32_t mip) { return mip >= tb.baseMip && mip - tb.baseMip < tb.mipCount; };
        const Arg arg = where.then(".textures", i);
        for (size_t c = 0; c < pass.colors.size(); ++c)
            if (pass.colors[c].texture == tb.texture && inRange(pass.colors[c].mip))
                return fail(Error::FeedbackLoop,
                            {arg.str(), str(tb.baseMip), str(tb.mipCount), str(pass.colors[c].mip), "RenderPassDesc.colors[" + str(c) + "]"});
        if (!pass.depth.texture.isNull() && pass.depth.texture == tb.texture && inRange(0))
            return fail(Error::FeedbackLoop, {arg.str(), str(tb.baseMip), str(tb.mipCount), "0", "RenderPassDesc.depth"});
    }
    return Status::ok();
}

// One mip in two kinds of use within one command cannot hold on every API (on Vulkan each kind
// is an image layout, and an image subresource has one layout at a time).
Status noMipUsedTwoWays(const std::vector<MipUse>& uses) {
    for (size_t i = 0; i < uses.size(); ++i)
        for (size_t j = 0; j < i; ++j) {
            const MipUse& a = uses[i];
            const MipUse& b = uses[j];
            if (a.texture != b.texture || std::string_view(a.as) == b.as) continue;
            const uint32_t lo = std::max(a.baseMip, b.baseMip);
            if (lo - a.baseMip < a.mipCount && lo - b.baseMip < b.mipCount && lo >= a.baseMip && lo >= b.baseMip)
                return fail(Error::MipUsedTwoWays, {a.argument.str(), str(lo), b.argument.str(), b.as});
        }
    return Status::ok();
}

Status attachment(TextureHandle texture, uint32_t mip, LoadOp load, const Arg& arg, bool depth, size_t index, const ObjectLookup& objects,
                  uint32_t& width, uint32_t& height, std::vector<Format>& colorFormats, Format& depthFormat, std::vector<MipUse>& uses) {
    Result<const TextureDesc*> t = named(arg.then(".texture"), [&](const std::string& name) { return objects.texture(texture, name); });
    if (!t) return t.status();
    const TextureDesc& d = *t.value();
    SFX_TRY(named(arg.then(".mip"), [&](const std::string& name) { return mipRange(d, mip, name); }));
    if (!(d.usage & kTextureRenderTarget) || isDepthFormat(d.format) != depth)
        return depth ? fail(Error::PassDepthTarget, {toString(d.format), textureUsageNames(d.usage)})
                     : fail(Error::PassColorTarget, {str(index), toString(d.format), textureUsageNames(d.usage)});
    if (uint32_t(load) > uint32_t(LoadOp::DontCare)) return fail(Error::PassLoadOp, {arg.then(".load").str(), str(uint32_t(load))});
    const uint32_t w = mipExtent(d.width, mip), h = mipExtent(d.height, mip);
    if (width == 0) {
        width = w;
        height = h;
    } else if (w != width || h != height) {
        return fail(Error::PassSize, {arg.then(".texture").str(), str(w), str(h), str(mip), str(width), str(height)});
    }
    if (depth)
        depthFormat = d.format;
    else
        colorFormats.push_back(d.format);
    uses.push_back({texture, mip, 1, depth ? "the depth attachment" : "a colour attachment", arg});
    return Status::ok();
}

Status drawBuffers(const DrawDesc& draw, const PipelineInfo& pipeline, const Arg& arg, const ObjectLookup& objects) {
    if (draw.instanceCount == 0) return fail(Error::DrawInstanceCount, {arg.str()});
    const VertexLayout& layout = pipeline.vertexLayout;
    const BufferDesc* vertexBuffer = nullptr;
    if (layout.attributes.empty()) {
        if (!draw.vertexBuffer.isNull()) return fail(Error::DrawVertexBufferUnused, {arg.str()});
    } else {
        if (draw.vertexBuffer.isNull()) return fail(Error::DrawVertexBufferMissing, {arg.str()});
        Result<const BufferDesc*> vb = named(arg.then(".vertexBuffer"),
                                             [&](const std::string& name) { return objects.buffer(draw.vertexBuffer, name); });
        if (!vb) return vb.status();
        vertexBuffer = vb.value();
        if (!(vertexBuffer->usage & kBufferVertex))
            return fail(Error::ResourceUsage, {arg.then(".vertexBuffer").str(), bufferUsageNames(vertexBuffer->usage), "buffer", "vertex"});
    }
    if (!draw.indexBuffer.isNull()) {
        Result<const BufferDesc*> ib = named(arg.then(".indexBuffer"),
                                             [&](const std::string& name) { return objects.buffer(draw.indexBuffer, name); });
        if (!ib) return ib.status();
        const BufferDesc& index = *ib.value();
        if (!(index.usage & kBufferIndex))
            return fail(Error::ResourceUsage, {arg.then(".indexBuffer").str(), bufferUsageNames(index.usage), "buffer", "index"});
        // count < 2^32, so count * 4 fits in 64 bits.
        if (uint64_t(draw.count) * 4 > index.size)
            return fail(Error::DrawIndexCount, {arg.str(), str(draw.count), str(index.size / 4), str(index.size)});
        return Status::ok();
    }
    if (!vertexBuffer || draw.count == 0) return Status::ok();
    // stride <= kMaxVertexStride and count < 2^32: the product stays far below 2^64.
    const uint64_t attributeEnd = vertexAttributeEnd(layout);
    const uint64_t end = uint64_t(draw.count - 1) * layout.stride + attributeEnd;
    if (end > vertexBuffer->size) {
        const uint64_t fit = vertexBuffer->size < attributeEnd ? 0 : (vertexBuffer->size - attributeEnd) / layout.stride + 1;
        return fail(Error::DrawVertexCount, {arg.str(), str(draw.count), str(fit), str(layout.stride), str(vertexBuffer->size)});
    }
    return Status::ok();
}

}  // namespace

Status renderPass(const RenderPassDesc& pass, std::span<const DrawDesc> draws, const ObjectLookup& objects, const DeviceCaps& caps) {
    if (pass.colors.empty() && pass.depth.texture.isNull()) return fail(Error::PassNoAttachments, {});
    if (pass.colors.size() > caps.limits.maxColorAttachments)
        return fail(Error::PassColorCount, {str(pass.colors.size()), str(caps.limits.maxColorAttachments)});
    uint32_t width = 0, height = 0;
    Scratch& lists = scratch();
    std::vector<Format>& colorFormats = lists.colorFormats;
    std::vector<MipUse>& uses = lists.uses;
    colorFormats.clear();
    uses.clear();
    Format depthFormat = Format::Undefined;
    for (size_t i = 0; i < pass.colors.size(); ++i) {
        const ColorAttachment& c = pass.colors[i];
        SFX_TRY(
            attachment(c.texture, c.mip, c.load, Arg("RenderPassDesc.colors", i), false, i, objects, width, height, colorFormats, depthFormat, uses));
    }
    if (!pass.depth.texture.isNull())
        SFX_TRY(attachment(pass.depth.texture, 0, pass.depth.load, Arg("RenderPassDesc.depth"), true, 0, objects, width, height, colorFormats,
                           depthFormat, uses));
    for (size_t i = 0; i < draws.size(); ++i) {
        const DrawDesc& d = draws[i];
        const Arg arg = draws.size() == 1 ? Arg("DrawDesc") : Arg("DrawDesc", i);
        Result<const PipelineInfo*> found = named(arg.then(".pipeline"), [&](const std::string& name) { return objects.pipeline(d.pipeline, name); });
        if (!found) return found.status();
        const PipelineInfo& pl = *found.value();
        if (pl.compute) return fail(Error::DrawPipelineCompute, {arg.then(".pipeline").str(), pl.programName});
        if (!std::equal(pl.colorFormats.begin(), pl.colorFormats.end(), colorFormats.begin(), colorFormats.end()) || pl.depthFormat != depthFormat)
            return fail(Error::DrawPipelineFormats,
                        {arg.then(".pipeline").str(), formatsList(pl.colorFormats), formatName(pl.depthFormat), formatsList(colorFormats),
                         formatName(depthFormat)});
        const Arg bindingsArg = arg.then(".bindings");
        SFX_TRY(bindings(d.bindings, pl, bindingsArg, objects, caps, uses));
        SFX_TRY(noFeedbackLoop(pass, d.bindings, bindingsArg));
        SFX_TRY(drawBuffers(d, pl, arg, objects));
    }
    return noMipUsedTwoWays(uses);
}

Status dispatch(const DispatchDesc& d, const ObjectLookup& objects, const DeviceCaps& caps) {
    if (!caps.computeShaders) return fail(Error::DispatchUnsupported, {underCeiling(caps)});
    const std::pair<const char*, uint32_t> groups[] = {{"X", d.groupsX}, {"Y", d.groupsY}, {"Z", d.groupsZ}};
    for (size_t axis = 0; axis < 3; ++axis) {
        const uint32_t count = groups[axis].second, limit = caps.limits.maxComputeWorkGroupCount[axis];
        if (count == 0 || count > limit) return fail(Error::DispatchGroups, {groups[axis].first, str(count), str(limit)});
    }
    Result<const PipelineInfo*> found = named(Arg("DispatchDesc.pipeline"),
                                              [&](const std::string& name) { return objects.pipeline(d.pipeline, name); });
    if (!found) return found.status();
    const PipelineInfo& pl = *found.value();
    if (!pl.compute) return fail(Error::DispatchPipelineGraphics, {pl.programName});
    std::vector<MipUse>& uses = scratch().uses;
    uses.clear();
    SFX_TRY(bindings(d.bindings, pl, Arg("DispatchDesc.bindings"), objects, caps, uses));
    return noMipUsedTwoWays(uses);
}

}  // namespace sfx::validation
