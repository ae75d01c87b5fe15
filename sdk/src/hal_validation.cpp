// The shared checks of descriptions (textures, buffers, samplers, programs, pipelines) and of
// reads and writes. Codes and messages: validation_messages.cpp.
#include "sfx/hal_validation.hpp"

#include <algorithm>
#include <string>

#include "hal_validation_words.hpp"

namespace sfx::validation {

Status textureDesc(const TextureDesc& d, const DeviceCaps& caps) {
    const uint32_t maxSize = caps.limits.maxTextureSize;
    if (d.width == 0 || d.width > maxSize) return fail(Error::TextureWidth, {str(d.width), str(maxSize)});
    if (d.height == 0 || d.height > maxSize) return fail(Error::TextureHeight, {str(d.height), str(maxSize)});
    if ((d.usage & kTextureRenderTarget) && (d.width > caps.limits.maxRenderTargetWidth || d.height > caps.limits.maxRenderTargetHeight))
        return fail(Error::TextureRenderTargetSize,
                    {str(d.width), str(d.height), str(caps.limits.maxRenderTargetWidth), str(caps.limits.maxRenderTargetHeight)});
    const uint32_t maxLevels = maxMipLevels(d.width, d.height);
    if (d.mipLevels == 0 || d.mipLevels > maxLevels)
        return fail(Error::TextureMipLevels, {str(d.mipLevels), str(maxLevels), str(d.width), str(d.height)});
    if (!knownFormat(d.format) || d.format == Format::Undefined)
        return fail(Error::TextureFormatUnknown, {formatName(d.format), formatList([](Format) { return true; })});
    const uint32_t known = kTextureSampled | kTextureRenderTarget | kTextureStorage;
    if (d.usage == 0 || (d.usage & ~known) != 0) return fail(Error::TextureUsage, {textureUsageNames(d.usage)});
    if ((d.usage & kTextureSampled) && !caps.sampledFormat[size_t(d.format)])
        return fail(Error::TextureFormatNotSampled, {toString(d.format), formatList([&](Format f) { return caps.sampledFormat[size_t(f)]; })});
    if ((d.usage & kTextureRenderTarget) && !caps.renderableFormat[size_t(d.format)])
        return fail(Error::TextureFormatNotRenderable, {toString(d.format), formatList([&](Format f) { return caps.renderableFormat[size_t(f)]; })});
    if (d.usage & kTextureStorage) {
        if (!caps.storageImages) return fail(Error::TextureStorageUnsupported, {underCeiling(caps)});
        if (isDepthFormat(d.format)) return fail(Error::TextureStorageDepth, {toString(d.format)});
        if (!caps.storageFormat[size_t(d.format)])
            return fail(Error::TextureFormatNotStorage, {toString(d.format), formatList([&](Format f) { return caps.storageFormat[size_t(f)]; })});
    }
    return Status::ok();
}

Status bufferDesc(const BufferDesc& d, const DeviceCaps& caps) {
    if (d.size == 0 || d.size > caps.limits.maxBufferSize) return fail(Error::BufferSize, {str(d.size), str(caps.limits.maxBufferSize)});
    const uint32_t known = kBufferUniform | kBufferStorage | kBufferVertex | kBufferIndex;
    if (d.usage == 0 || (d.usage & ~known) != 0) return fail(Error::BufferUsage, {bufferUsageNames(d.usage)});
    if ((d.usage & kBufferStorage) && !caps.storageBuffers) return fail(Error::BufferStorageUnsupported, {underCeiling(caps)});
    if ((d.usage & kBufferUniform) && d.size > caps.limits.maxUniformBlockSize)
        return fail(Error::BufferUniformSize, {str(d.size), str(caps.limits.maxUniformBlockSize)});
    return Status::ok();
}

Status samplerDesc(const SamplerDesc& d) {
    const std::pair<const char*, Filter> filters[] = {{"minFilter", d.minFilter}, {"magFilter", d.magFilter}, {"mipFilter", d.mipFilter}};
    for (const auto& [field, filter] : filters)
        if (uint32_t(filter) > uint32_t(Filter::Linear)) return fail(Error::SamplerFilter, {field, str(uint32_t(filter))});
    if (uint32_t(d.address) > uint32_t(AddressMode::MirroredRepeat)) return fail(Error::SamplerAddress, {str(uint32_t(d.address))});
    return Status::ok();
}

Status program(const CompiledProgram& p, const DeviceCaps& caps) {
    if (p.stages.empty()) return fail(Error::ProgramNoStages, {p.name});
    bool hasVertex = false, hasFragment = false, hasCompute = false;
    for (const StageCode& s : p.stages) {
        hasVertex |= s.stage == ShaderStage::Vertex;
        hasFragment |= s.stage == ShaderStage::Fragment;
        hasCompute |= s.stage == ShaderStage::Compute;
    }
    if (hasCompute && (hasVertex || hasFragment)) return fail(Error::ProgramMixedStages, {p.name});
    if (!hasCompute && !(hasVertex && hasFragment)) return fail(Error::ProgramMissingStage, {p.name});
    // What the device lacks comes first: under the ceiling a compute or storage program has no
    // ESSL 300 / GLSL 330 text at all, and "unsupported" is the honest answer, not "bad shader".
    const std::string under = underCeiling(caps);
    if (hasCompute && !caps.computeShaders) return fail(Error::ProgramComputeUnsupported, {p.name, under});
    for (const ShaderResource& r : p.resources) {
        if (r.kind == ResourceKind::StorageBuffer && !caps.storageBuffers)
            return fail(Error::ProgramStorageBufferUnsupported, {p.name, r.name, under});
        if (r.kind == ResourceKind::StorageImage && !caps.storageImages) return fail(Error::ProgramStorageImageUnsupported, {p.name, r.name, under});
        const bool storage = r.kind == ResourceKind::StorageBuffer || r.kind == ResourceKind::StorageImage;
        if (storage && (r.stages & stageBit(ShaderStage::Fragment)) && !caps.fragmentStoresAndAtomics)
            return fail(Error::ProgramFragmentStorageUnsupported, {p.name, r.name, under});
    }
    for (const StageCode& s : p.stages) {
        if (caps.dialect == ShaderDialect::Spirv) {
            if (s.spirv.size() < 5 || s.spirv[0] != 0x07230203u) return fail(Error::ProgramNoSpirv, {p.name, toString(s.stage)});
        } else if (s.glsl[size_t(caps.dialect)].empty()) {
            // sfxc leaves out every stage's text for a dialect the program's tier does not target
            // (the tier table's dialects) and keeps the others; a program with no text at all,
            // or one stage missing, is a broken program instead.
            const bool noStageHasIt = std::all_of(p.stages.begin(), p.stages.end(),
                                                  [&](const StageCode& other) { return other.glsl[size_t(caps.dialect)].empty(); });
            const bool otherDialects = std::any_of(p.stages.begin(), p.stages.end(), [](const StageCode& other) {
                return std::any_of(std::begin(other.glsl), std::end(other.glsl), [](const std::string& g) { return !g.empty(); });
            });
            const bool tierLacksDialect = noStageHasIt && otherDialects;
            if (tierLacksDialect) return fail(Error::ProgramTierDialect, {p.name, toString(p.tier), toString(caps.dialect)});
            return fail(Error::ProgramNoSource, {p.name, toString(caps.dialect), toString(s.stage)});
        }
    }
    return Status::ok();
}

Status specializationConstants(const std::vector<SpecializationConstant>& constants, const char* where) {
    for (size_t i = 0; i < constants.size(); ++i)
        for (size_t j = 0; j < i; ++j)
            if (constants[j].id == constants[i].id) return fail(Error::SpecializationConstantIdTwice, {where, str(i), str(constants[i].id), str(j)});
    return Status::ok();
}

ProgramInfo programInfo(const CompiledProgram& program) { return {program.name, program.isCompute(), program.resources}; }

Status graphicsPipelineShape(const GraphicsPipelineDesc& d, const DeviceCaps& caps) {
    SFX_TRY(specializationConstants(d.constants, "GraphicsPipelineDesc"));
    if (d.colorFormats.size() > caps.limits.maxColorAttachments)
        return fail(Error::PipelineColorCount, {str(d.colorFormats.size()), str(caps.limits.maxColorAttachments)});
    for (size_t i = 0; i < d.colorFormats.size(); ++i) {
        const Format f = d.colorFormats[i];
        if (!knownFormat(f) || f == Format::Undefined || isDepthFormat(f) || !caps.renderableFormat[size_t(f)])
            return fail(Error::PipelineColorFormat,
                        {str(i), formatName(f), formatList([&](Format g) { return !isDepthFormat(g) && caps.renderableFormat[size_t(g)]; })});
    }
    if (d.depthFormat != Format::Undefined && (!knownFormat(d.depthFormat) || !isDepthFormat(d.depthFormat)))
        return fail(Error::PipelineDepthFormat, {formatName(d.depthFormat)});
    if (d.colorFormats.empty() && d.depthFormat == Format::Undefined) return fail(Error::PipelineNoAttachments, {});
    const VertexLayout& layout = d.vertexLayout;
    if ((layout.stride == 0) != layout.attributes.empty())
        return fail(Error::VertexStrideAttributes, {str(layout.stride), str(layout.attributes.size())});
    if (layout.stride > kMaxVertexStride) return fail(Error::VertexStrideMax, {str(layout.stride), str(kMaxVertexStride)});
    for (size_t i = 0; i < layout.attributes.size(); ++i) {
        const VertexAttribute& a = layout.attributes[i];
        const uint32_t size = vertexFormatBytes(a.format);
        if (size == 0) return fail(Error::VertexAttributeFormat, {str(i), str(uint32_t(a.format))});
        if (a.location >= kMaxVertexAttributes) return fail(Error::VertexAttributeLocation, {str(i), str(a.location), str(kMaxVertexAttributes - 1)});
        for (size_t j = 0; j < i; ++j)
            if (layout.attributes[j].location == a.location) return fail(Error::VertexAttributeLocationTwice, {str(i), str(a.location), str(j)});
        // 64-bit: offset 0xFFFFFFFC + 16 must not wrap to 12 and pass.
        if (uint64_t(a.offset) + size > layout.stride)
            return fail(Error::VertexAttributeOffset,
                        {str(i), str(a.offset), str(layout.stride >= size ? layout.stride - size : 0), str(size), str(layout.stride)});
    }
    return Status::ok();
}

Status graphicsPipelineState(const GraphicsPipelineDesc& d, const DeviceCaps& caps) {
    if (uint32_t(d.cull) > uint32_t(CullMode::Front)) return fail(Error::PipelineCull, {str(uint32_t(d.cull))});
    if (uint32_t(d.depth.compare) > uint32_t(CompareOp::Always)) return fail(Error::PipelineDepthCompare, {str(uint32_t(d.depth.compare))});
    if (uint32_t(d.blend.src) > uint32_t(BlendFactor::OneMinusDstAlpha)) return fail(Error::PipelineBlendFactor, {"src", str(uint32_t(d.blend.src))});
    if (uint32_t(d.blend.dst) > uint32_t(BlendFactor::OneMinusDstAlpha)) return fail(Error::PipelineBlendFactor, {"dst", str(uint32_t(d.blend.dst))});
    if (d.blend.separateAlpha && uint32_t(d.blend.srcAlpha) > uint32_t(BlendFactor::OneMinusDstAlpha))
        return fail(Error::PipelineBlendFactor, {"srcAlpha", str(uint32_t(d.blend.srcAlpha))});
    if (d.blend.separateAlpha && uint32_t(d.blend.dstAlpha) > uint32_t(BlendFactor::OneMinusDstAlpha))
        return fail(Error::PipelineBlendFactor, {"dstAlpha", str(uint32_t(d.blend.dstAlpha))});
    // Integer attachments do not blend: Vulkan's validation refuses it, GL ignores it silently.
    if (d.blend.enable)
        for (size_t i = 0; i < d.colorFormats.size(); ++i)
            if (knownFormat(d.colorFormats[i]) && isIntegerFormat(d.colorFormats[i]))
                return fail(Error::PipelineBlendInteger, {toString(d.colorFormats[i]), str(i)});
    if (d.blend.enable)
        for (size_t i = 0; i < d.colorFormats.size(); ++i)
            if (knownFormat(d.colorFormats[i]) && !caps.blendableFormat[size_t(d.colorFormats[i])])
                return fail(Error::PipelineBlendFormat,
                            {str(i), toString(d.colorFormats[i]), formatList([&](Format f) { return caps.blendableFormat[size_t(f)]; })});
    return Status::ok();
}

Result<PipelineInfo> graphicsPipeline(const GraphicsPipelineDesc& desc, const ProgramInfo& program, const DeviceCaps& caps) {
    if (program.compute) return fail(Error::PipelineProgramCompute, {program.name});
    SFX_TRY(graphicsPipelineShape(desc, caps));
    SFX_TRY(graphicsPipelineState(desc, caps));
    return PipelineInfo{false, program.name, program.resources, desc.colorFormats, desc.depthFormat, desc.vertexLayout};
}

Result<PipelineInfo> computePipeline(const ComputePipelineDesc& desc, const ProgramInfo& program) {
    if (!program.compute) return fail(Error::PipelineProgramGraphics, {program.name});
    SFX_TRY(specializationConstants(desc.constants, "ComputePipelineDesc"));
    return PipelineInfo{true, program.name, program.resources, {}, Format::Undefined, {}};
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
    for (const VertexAttribute& a : layout.attributes) end = std::max(end, uint64_t(a.offset) + vertexFormatBytes(a.format));
    return end;
}

Status mipRange(const TextureDesc& d, uint32_t mip, std::string_view argument) {
    if (mip >= d.mipLevels) return fail(Error::MipOutOfRange, {argument, str(mip), str(d.mipLevels - 1)});
    return Status::ok();
}

Status textureBytes(const TextureDesc& d, uint32_t mip, size_t bytes, std::string_view argument) {
    SFX_TRY(mipRange(d, mip, "mip"));
    const uint64_t want = mipLevelBytes(d, mip);
    if (bytes != want) return fail(Error::TextureBytes, {argument, str(bytes), str(want), str(mip), str(d.width), str(d.height), toString(d.format)});
    return Status::ok();
}

Status bufferRange(const BufferDesc& d, uint64_t offset, uint64_t bytes, std::string_view argument) {
    if (bytes == 0 || offset > d.size || bytes > d.size - offset) return fail(Error::BufferRange, {argument, str(offset), str(bytes), str(d.size)});
    return Status::ok();
}

Status pointer(const void* p, std::string_view argument, std::string_view what) {
    if (!p) return fail(Error::NullPointer, {argument, what});
    return Status::ok();
}

uint64_t boundSize(const BufferBinding& bb, const BufferDesc& d) { return bb.size ? bb.size : (bb.offset < d.size ? d.size - bb.offset : 0); }

}  // namespace sfx::validation
