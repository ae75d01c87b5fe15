#include "sfx/hal_validation.hpp"

#include <algorithm>
#include <string>

namespace sfx::validation {
namespace {
std::string str(uint64_t v) { return std::to_string(v); }
}  // namespace

Status textureDesc(const TextureDesc& d, const DeviceCaps& caps) {
    const uint32_t maxSize = caps.limits.maxTextureSize;
    const std::string range = "[1, " + str(maxSize) + "]";
    if (d.width == 0 || d.width > maxSize) return invalidArgument("TextureDesc.width", str(d.width), range);
    if (d.height == 0 || d.height > maxSize) return invalidArgument("TextureDesc.height", str(d.height), range);
    const uint32_t maxLevels = maxMipLevels(d.width, d.height);
    if (d.mipLevels == 0 || d.mipLevels > maxLevels)
        return invalidArgument("TextureDesc.mipLevels", str(d.mipLevels), "[1, " + str(maxLevels) + "] for " +
                                                                             str(d.width) + "x" + str(d.height));
    if (d.format == Format::Undefined || uint32_t(d.format) >= uint32_t(Format::Count))
        return {StatusCode::UnsupportedFormat,
                "TextureDesc.format is " + std::to_string(uint32_t(d.format)) + ", not a known Format"};
    const uint32_t known = kTextureSampled | kTextureRenderTarget | kTextureStorage;
    if (d.usage == 0 || (d.usage & ~known) != 0)
        return invalidArgument("TextureDesc.usage", str(d.usage), "a non-empty set of TextureUsage bits");
    if ((d.usage & kTextureSampled) && !caps.sampledFormat[size_t(d.format)])
        return {StatusCode::UnsupportedFormat,
                std::string("TextureDesc.format ") + toString(d.format) + " cannot be sampled on this device"};
    if ((d.usage & kTextureRenderTarget) && !caps.renderableFormat[size_t(d.format)])
        return {StatusCode::UnsupportedFormat,
                std::string("TextureDesc.format ") + toString(d.format) + " is not renderable on this device"};
    if (d.usage & kTextureStorage) {
        if (!caps.storageImages)
            return {StatusCode::UnsupportedFeature, "TextureDesc.usage has kTextureStorage; the device has no storage images"};
        if (isDepthFormat(d.format))
            return {StatusCode::UnsupportedFormat, std::string("TextureDesc.format ") + toString(d.format) +
                                                       " cannot be a storage image"};
    }
    return Status::ok();
}

Status bufferDesc(const BufferDesc& d, const DeviceCaps& caps) {
    if (d.size == 0 || d.size > caps.limits.maxBufferSize)
        return invalidArgument("BufferDesc.size", str(d.size), "[1, " + str(caps.limits.maxBufferSize) + "]");
    const uint32_t known = kBufferUniform | kBufferStorage | kBufferVertex | kBufferIndex;
    if (d.usage == 0 || (d.usage & ~known) != 0)
        return invalidArgument("BufferDesc.usage", str(d.usage), "a non-empty set of BufferUsage bits");
    if ((d.usage & kBufferStorage) && !caps.storageBuffers)
        return {StatusCode::UnsupportedFeature, "BufferDesc.usage has kBufferStorage; the device has no storage buffers" +
                                                    std::string(caps.ceiling != CapabilityCeiling::None
                                                                    ? " under its capability ceiling"
                                                                    : "")};
    if ((d.usage & kBufferUniform) && d.size > caps.limits.maxUniformBlockSize)
        return invalidArgument("BufferDesc.size", str(d.size),
                               "[1, " + str(caps.limits.maxUniformBlockSize) + "] for a uniform buffer");
    return Status::ok();
}

Status samplerDesc(const SamplerDesc& d) {
    if (uint32_t(d.minFilter) > 1) return invalidArgument("SamplerDesc.minFilter", str(uint32_t(d.minFilter)), "Nearest or Linear");
    if (uint32_t(d.magFilter) > 1) return invalidArgument("SamplerDesc.magFilter", str(uint32_t(d.magFilter)), "Nearest or Linear");
    if (uint32_t(d.mipFilter) > 1) return invalidArgument("SamplerDesc.mipFilter", str(uint32_t(d.mipFilter)), "Nearest or Linear");
    if (uint32_t(d.address) > 2)
        return invalidArgument("SamplerDesc.address", str(uint32_t(d.address)), "ClampToEdge, Repeat or MirroredRepeat");
    return Status::ok();
}

Status program(const CompiledProgram& p, const DeviceCaps& caps) {
    if (p.stages.empty()) return {StatusCode::ShaderError, "program '" + p.name + "' has no stages"};
    bool hasVertex = false, hasFragment = false, hasCompute = false;
    for (const StageCode& s : p.stages) {
        hasVertex |= s.stage == ShaderStage::Vertex;
        hasFragment |= s.stage == ShaderStage::Fragment;
        hasCompute |= s.stage == ShaderStage::Compute;
    }
    if (hasCompute && (hasVertex || hasFragment))
        return {StatusCode::ShaderError, "program '" + p.name + "' mixes compute with graphics stages"};
    if (!hasCompute && !(hasVertex && hasFragment))
        return {StatusCode::ShaderError, "program '" + p.name + "' needs a vertex and a fragment stage"};
    // What the device lacks comes first: under the ceiling a compute or storage program has no
    // ESSL 300 / GLSL 330 text at all, and "unsupported" is the honest answer, not "bad shader".
    const char* under = caps.ceiling != CapabilityCeiling::None ? " (capability ceiling)" : "";
    if (hasCompute && !caps.computeShaders)
        return {StatusCode::UnsupportedFeature, "program '" + p.name + "' is a compute program; the device has no compute shaders" + under};
    for (const ShaderResource& r : p.resources) {
        if (r.kind == ResourceKind::StorageBuffer && !caps.storageBuffers)
            return {StatusCode::UnsupportedFeature, "program '" + p.name + "' uses storage buffer '" + r.name +
                                                        "'; the device has no storage buffers" + under};
        if (r.kind == ResourceKind::StorageImage && !caps.storageImages)
            return {StatusCode::UnsupportedFeature, "program '" + p.name + "' uses storage image '" + r.name +
                                                        "'; the device has no storage images" + under};
    }
    for (const StageCode& s : p.stages) {
        if (caps.dialect == ShaderDialect::Spirv) {
            if (s.spirv.size() < 5 || s.spirv[0] != 0x07230203u)
                return {StatusCode::ShaderError, "program '" + p.name + "' " + toString(s.stage) +
                                                     " stage has no valid SPIR-V module (bad magic or empty)"};
        } else if (s.glsl[size_t(caps.dialect)].empty()) {
            if (p.tier == Tier::High && (caps.dialect == ShaderDialect::Essl300 || caps.dialect == ShaderDialect::Glsl330))
                return {StatusCode::UnsupportedTier, "program '" + p.name + "' is built for the high tier; a device on " +
                                                         toString(caps.dialect) + " runs only current-tier programs"};
            return {StatusCode::ShaderError, "program '" + p.name + "' " + toString(s.stage) + " stage has no " +
                                                 toString(caps.dialect) + " source"};
        }
    }
    return Status::ok();
}

Status specializationConstants(const std::vector<SpecializationConstant>& constants, const char* where) {
    for (size_t i = 0; i < constants.size(); ++i)
        for (size_t j = 0; j < i; ++j)
            if (constants[j].id == constants[i].id)
                return invalidArgument(std::string(where) + ".constants[" + str(i) + "].id", str(constants[i].id),
                                       "an id not given before (constants[" + str(j) + "] has it)");
    return Status::ok();
}

Status graphicsPipelineShape(const GraphicsPipelineDesc& d, const DeviceCaps& caps) {
    SFX_TRY(specializationConstants(d.constants, "GraphicsPipelineDesc"));
    if (d.colorFormats.size() > caps.limits.maxColorAttachments)
        return invalidArgument("GraphicsPipelineDesc.colorFormats.size()", str(d.colorFormats.size()),
                               "[0, " + str(caps.limits.maxColorAttachments) + "]");
    for (size_t i = 0; i < d.colorFormats.size(); ++i) {
        Format f = d.colorFormats[i];
        if (f == Format::Undefined || uint32_t(f) >= uint32_t(Format::Count) || isDepthFormat(f) ||
            !caps.renderableFormat[size_t(f)])
            return {StatusCode::UnsupportedFormat, "GraphicsPipelineDesc.colorFormats[" + str(i) + "] " +
                                                       (uint32_t(f) < uint32_t(Format::Count) ? toString(f) : "?") +
                                                       " is not a renderable colour format on this device"};
    }
    if (d.depthFormat != Format::Undefined &&
        (uint32_t(d.depthFormat) >= uint32_t(Format::Count) || !isDepthFormat(d.depthFormat)))
        return {StatusCode::UnsupportedFormat, "GraphicsPipelineDesc.depthFormat is not a depth format"};
    if (d.colorFormats.empty() && d.depthFormat == Format::Undefined)
        return invalidArgument("GraphicsPipelineDesc", "without attachments", "at least one colour or depth format");
    const VertexLayout& layout = d.vertexLayout;
    if ((layout.stride == 0) != layout.attributes.empty())
        return invalidArgument("GraphicsPipelineDesc.vertexLayout.stride", str(layout.stride),
                               "> 0 exactly when attributes are given");
    if (layout.stride > kMaxVertexStride)
        return invalidArgument("GraphicsPipelineDesc.vertexLayout.stride", str(layout.stride),
                               "[0, " + str(kMaxVertexStride) + "]");
    for (size_t i = 0; i < layout.attributes.size(); ++i) {
        const VertexAttribute& a = layout.attributes[i];
        const std::string field = "GraphicsPipelineDesc.vertexLayout.attributes[" + str(i) + "]";
        const uint32_t size = vertexFormatBytes(a.format);
        if (size == 0) return invalidArgument(field + ".format", str(uint32_t(a.format)), "Float2, Float3 or Float4");
        if (a.location >= kMaxVertexAttributes)
            return invalidArgument(field + ".location", str(a.location), "[0, " + str(kMaxVertexAttributes - 1) + "]");
        for (size_t j = 0; j < i; ++j)
            if (layout.attributes[j].location == a.location)
                return invalidArgument(field + ".location", str(a.location),
                                       "a location no other attribute uses (attributes[" + str(j) + "] has it)");
        // 64-bit: offset 0xFFFFFFFC + 16 must not wrap to 12 and pass.
        if (uint64_t(a.offset) + size > layout.stride)
            return invalidArgument(field + ".offset", str(a.offset),
                                   "[0, " + str(layout.stride >= size ? layout.stride - size : 0) + "] so that its " +
                                       str(size) + " bytes end within the stride (" + str(layout.stride) + ")");
    }
    return Status::ok();
}

Status graphicsPipelineState(const GraphicsPipelineDesc& d, const DeviceCaps&) {
    if (uint32_t(d.cull) > uint32_t(CullMode::Front))
        return invalidArgument("GraphicsPipelineDesc.cull", str(uint32_t(d.cull)), "None, Back or Front");
    if (uint32_t(d.depth.compare) > uint32_t(CompareOp::Always))
        return invalidArgument("GraphicsPipelineDesc.depth.compare", str(uint32_t(d.depth.compare)),
                               "a CompareOp, [0, " + str(uint32_t(CompareOp::Always)) + "]");
    const std::string factors = "a BlendFactor, [0, " + str(uint32_t(BlendFactor::OneMinusDstAlpha)) + "]";
    if (uint32_t(d.blend.src) > uint32_t(BlendFactor::OneMinusDstAlpha))
        return invalidArgument("GraphicsPipelineDesc.blend.src", str(uint32_t(d.blend.src)), factors);
    if (uint32_t(d.blend.dst) > uint32_t(BlendFactor::OneMinusDstAlpha))
        return invalidArgument("GraphicsPipelineDesc.blend.dst", str(uint32_t(d.blend.dst)), factors);
    // Integer attachments do not blend: Vulkan's validation refuses it, GL ignores it silently.
    if (d.blend.enable)
        for (size_t i = 0; i < d.colorFormats.size(); ++i)
            if (uint32_t(d.colorFormats[i]) < uint32_t(Format::Count) && isIntegerFormat(d.colorFormats[i]))
                return invalidArgument("GraphicsPipelineDesc.blend.enable", "true",
                                       "false with the integer colour format " + std::string(toString(d.colorFormats[i])) +
                                           " (colorFormats[" + str(i) + "])");
    return Status::ok();
}

Status textureBinding(const TextureDesc& t, const TextureBinding& b) {
    // baseMip + mipCount in 32 bits wraps (1 + 0xFFFFFFFF = 0); compare without adding.
    if (b.mipCount == 0 || b.baseMip >= t.mipLevels || b.mipCount > t.mipLevels - b.baseMip)
        return invalidArgument("TextureBinding (binding " + str(b.binding) + ") baseMip+mipCount",
                               str(b.baseMip) + "+" + str(b.mipCount),
                               "a non-empty range inside the texture's " + str(t.mipLevels) + " levels");
    if (!(t.usage & kTextureSampled))
        return invalidArgument("TextureBinding (binding " + str(b.binding) + ").texture", "a texture without kTextureSampled",
                               "a texture with kTextureSampled");
    return Status::ok();
}

uint32_t vertexFormatBytes(VertexFormat f) {
    switch (f) {
    case VertexFormat::Float2: return 8;
    case VertexFormat::Float3: return 12;
    case VertexFormat::Float4: return 16;
    }
    return 0;
}

uint64_t vertexAttributeEnd(const VertexLayout& layout) {
    uint64_t end = 0;
    for (const VertexAttribute& a : layout.attributes)
        end = std::max(end, uint64_t(a.offset) + vertexFormatBytes(a.format));
    return end;
}

Status drawRange(const DrawDesc& draw, const VertexLayout& layout, const BufferDesc* vertexBuffer,
                 const BufferDesc* indexBuffer) {
    if (draw.instanceCount == 0) return invalidArgument("DrawDesc.instanceCount", "0", "[1, 4294967295]");
    if (!layout.attributes.empty()) {
        if (!vertexBuffer)
            return invalidArgument("DrawDesc.vertexBuffer", "null", "a vertex buffer for a pipeline with vertex attributes");
        if (!(vertexBuffer->usage & kBufferVertex))
            return invalidArgument("DrawDesc.vertexBuffer", "a buffer without kBufferVertex", "a buffer with kBufferVertex");
    }
    if (indexBuffer) {
        if (!(indexBuffer->usage & kBufferIndex))
            return invalidArgument("DrawDesc.indexBuffer", "a buffer without kBufferIndex", "a buffer with kBufferIndex");
        // count < 2^32, so count * 4 fits in 64 bits.
        if (uint64_t(draw.count) * 4 > indexBuffer->size)
            return invalidArgument("DrawDesc.count", str(draw.count),
                                   "[0, " + str(indexBuffer->size / 4) + "], the 32-bit indices in DrawDesc.indexBuffer (" +
                                       str(indexBuffer->size) + " bytes)");
        return Status::ok();
    }
    if (layout.attributes.empty() || draw.count == 0) return Status::ok();
    // stride <= kMaxVertexStride and count < 2^32: the product stays far below 2^64.
    const uint64_t end = uint64_t(draw.count - 1) * layout.stride + vertexAttributeEnd(layout);
    if (end > vertexBuffer->size) {
        const uint64_t fit = vertexBuffer->size < vertexAttributeEnd(layout)
                                 ? 0
                                 : (vertexBuffer->size - vertexAttributeEnd(layout)) / layout.stride + 1;
        return invalidArgument("DrawDesc.count", str(draw.count),
                               "[0, " + str(fit) + "], the vertices of stride " + str(layout.stride) +
                                   " in DrawDesc.vertexBuffer (" + str(vertexBuffer->size) + " bytes)");
    }
    return Status::ok();
}

Status mipRange(const TextureDesc& d, uint32_t mip, const char* argument) {
    if (mip >= d.mipLevels) return invalidArgument(argument, str(mip), "[0, " + str(d.mipLevels - 1) + "]");
    return Status::ok();
}

Status textureBytes(const TextureDesc& d, uint32_t mip, size_t bytes, const char* argument) {
    SFX_TRY(mipRange(d, mip, "mip"));
    const uint64_t want = mipLevelBytes(d, mip);
    if (bytes != want)
        return invalidArgument(argument, str(bytes), str(want) + " (mip " + str(mip) + " of a " + str(d.width) + "x" +
                                                         str(d.height) + " " + toString(d.format) + " texture)");
    return Status::ok();
}

Status bufferRange(const BufferDesc& d, uint64_t offset, uint64_t bytes, const char* argument) {
    if (bytes == 0 || offset > d.size || bytes > d.size - offset)
        return invalidArgument(argument, "offset " + str(offset) + " + " + str(bytes) + " bytes",
                               "a non-empty range inside the buffer's " + str(d.size) + " bytes");
    return Status::ok();
}

Status dispatchGroups(const DispatchDesc& d, const DeviceCaps& caps) {
    if (!caps.computeShaders) return {StatusCode::UnsupportedFeature, "dispatch: the device has no compute shaders"};
    const uint32_t kMax = 65535;
    if (d.groupsX == 0 || d.groupsX > kMax) return invalidArgument("DispatchDesc.groupsX", str(d.groupsX), "[1, 65535]");
    if (d.groupsY == 0 || d.groupsY > kMax) return invalidArgument("DispatchDesc.groupsY", str(d.groupsY), "[1, 65535]");
    if (d.groupsZ == 0 || d.groupsZ > kMax) return invalidArgument("DispatchDesc.groupsZ", str(d.groupsZ), "[1, 65535]");
    return Status::ok();
}

Status noFeedbackLoop(const RenderPassDesc& pass, const DrawDesc& draw) {
    for (const TextureBinding& tb : draw.bindings.textures) {
        auto inRange = [&](uint32_t mip) { return mip >= tb.baseMip && mip - tb.baseMip < tb.mipCount; };
        const std::string what = "TextureBinding (binding " + str(tb.binding) + ") mips";
        const std::string got = str(tb.baseMip) + "+" + str(tb.mipCount);
        for (const ColorAttachment& c : pass.colors)
            if (c.texture == tb.texture && inRange(c.mip))
                return invalidArgument(what, got, "a range without mip " + str(c.mip) + ", which the pass renders to");
        if (!pass.depth.texture.isNull() && pass.depth.texture == tb.texture && inRange(0))
            return invalidArgument(what, got, "a range without mip 0 of the pass's depth attachment");
    }
    return Status::ok();
}

}  // namespace sfx::validation
