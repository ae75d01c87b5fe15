// The checks the GL backend makes on its own, beside the shared sfx::validation ones: all in this
// file because they are to move into the shared validation, written once for every backend.
//   Binding against reflection  checkBindingsMatch: every resource the program reflects is bound,
//                               and nothing is bound that the program does not use.
//   Resource bindings           checkResources, checkBufferRange: handles alive, texture units
//                               within maxTextureBindings, buffer offsets aligned, usage flags,
//                               bound range >= the reflected block size, storage features present.
//   Attachments                 checkPass: at least one attachment, colour count within
//                               maxColorAttachments, colour/depth formats and kTextureRenderTarget,
//                               mips in range, one extent for the whole pass.
//   Pipeline against pass       checkDraw: pipeline kind, colour and depth formats as the pass's
//                               attachments, vertex and index buffers present and alive.
//   Feedback                    checkPass: validation::noFeedbackLoop for every draw, before any
//                               GL work, so a refused pass leaves its targets untouched.
//   Dispatch                    checkDispatch: pipeline kind, then bindings as for a draw.
#include <algorithm>

#include "gl_driver.hpp"

namespace sfx::gl {

// Every reflected resource bound, and nothing bound the program lacks, by kind and number.
Status GlDevice::checkBindingsMatch(const GlProgram& program, const BindingSet& b, const char* where) {
    auto has = [&](ResourceKind kind, uint32_t binding) {
        switch (kind) {
        case ResourceKind::SampledTexture:
            return std::any_of(b.textures.begin(), b.textures.end(), [&](const auto& x) { return x.binding == binding; });
        case ResourceKind::UniformBuffer:
            return std::any_of(b.uniformBuffers.begin(), b.uniformBuffers.end(),
                               [&](const auto& x) { return x.binding == binding; });
        case ResourceKind::StorageBuffer:
            return std::any_of(b.storageBuffers.begin(), b.storageBuffers.end(),
                               [&](const auto& x) { return x.binding == binding; });
        case ResourceKind::StorageImage:
            return std::any_of(b.storageImages.begin(), b.storageImages.end(),
                               [&](const auto& x) { return x.binding == binding; });
        }
        return false;
    };
    for (const ShaderResource& r : program.resources)
        if (!has(r.kind, r.binding))
            return {StatusCode::InvalidArgument, std::string(where) + " lacks " + toString(r.kind) + " '" + r.name +
                                                     "' (binding " + str(r.binding) + ") of program '" + program.label + "'"};
    auto uses = [&](ResourceKind kind, uint32_t binding) {
        return std::any_of(program.resources.begin(), program.resources.end(),
                           [&](const ShaderResource& r) { return r.kind == kind && r.binding == binding; });
    };
    auto refuse = [&](ResourceKind kind, uint32_t binding) {
        return Status{StatusCode::InvalidArgument, std::string(where) + " binds a " + toString(kind) + " at binding " +
                                                       str(binding) + ", which program '" + program.label +
                                                       "' does not use"};
    };
    for (const auto& x : b.textures)
        if (!uses(ResourceKind::SampledTexture, x.binding)) return refuse(ResourceKind::SampledTexture, x.binding);
    for (const auto& x : b.uniformBuffers)
        if (!uses(ResourceKind::UniformBuffer, x.binding)) return refuse(ResourceKind::UniformBuffer, x.binding);
    for (const auto& x : b.storageBuffers)
        if (!uses(ResourceKind::StorageBuffer, x.binding)) return refuse(ResourceKind::StorageBuffer, x.binding);
    for (const auto& x : b.storageImages)
        if (!uses(ResourceKind::StorageImage, x.binding)) return refuse(ResourceKind::StorageImage, x.binding);
    return Status::ok();
}

Status GlDevice::checkBufferRange(GLenum target, const BufferBinding& bb, uint32_t alignment, uint32_t minSize,
                                  const ShaderResource* resource) {
    SFX_TRY(buffers_.check(bb.buffer, "BufferBinding.buffer"));
    const GlBuffer& buf = buffers_.get(bb.buffer);
    const uint64_t size = boundSize(bb, buf.desc);
    SFX_TRY(validation::bufferRange(buf.desc, bb.offset, size, "BufferBinding range"));
    if (bb.offset % alignment)
        return invalidArgument("BufferBinding.offset", str(bb.offset), "a multiple of " + str(alignment));
    const uint32_t needUsage = target == GL_UNIFORM_BUFFER ? kBufferUniform : kBufferStorage;
    if (!(buf.desc.usage & needUsage))
        return invalidArgument("BufferBinding.buffer usage", str(buf.desc.usage),
                               target == GL_UNIFORM_BUFFER ? "with kBufferUniform" : "with kBufferStorage");
    if (size < minSize)
        return invalidArgument("BufferBinding size", str(size),
                               ">= " + str(minSize) + " bytes of block '" + (resource ? resource->name : "") + "'");
    return Status::ok();
}

const ShaderResource* GlDevice::findResource(const GlProgram* program, ResourceKind kind, uint32_t binding) {
    if (!program) return nullptr;
    for (const ShaderResource& r : program->resources)
        if (r.kind == kind && r.binding == binding) return &r;
    return nullptr;
}

// Every check of a draw's or dispatch's resources, made before the command does any GL work,
// so a refused command leaves the targets (and the GL state) as they were.
Status GlDevice::checkResources(const BindingSet& b, const GlProgram* program) {
    for (const TextureBinding& tb : b.textures) {
        SFX_TRY(textures_.check(tb.texture, "TextureBinding.texture"));
        SFX_TRY(validation::textureBinding(textures_.get(tb.texture).desc, tb));
        if (tb.binding >= caps_.limits.maxTextureBindings)
            return invalidArgument("TextureBinding.binding", str(tb.binding),
                                   "[0, " + str(caps_.limits.maxTextureBindings - 1) + "]");
        if (!tb.sampler.isNull()) SFX_TRY(samplers_.check(tb.sampler, "TextureBinding.sampler"));
    }
    for (const BufferBinding& bb : b.uniformBuffers) {
        const ShaderResource* r = findResource(program, ResourceKind::UniformBuffer, bb.binding);
        SFX_TRY(checkBufferRange(GL_UNIFORM_BUFFER, bb, uniformOffsetAlignment_, r ? r->blockSize : 0, r));
    }
    for (const BufferBinding& bb : b.storageBuffers) {
        if (!caps_.storageBuffers)
            return {StatusCode::UnsupportedFeature, "BindingSet.storageBuffers: the device has no storage buffers"};
        const ShaderResource* r = findResource(program, ResourceKind::StorageBuffer, bb.binding);
        SFX_TRY(checkBufferRange(GL_SHADER_STORAGE_BUFFER, bb, storageOffsetAlignment_, r ? r->blockSize : 0, r));
    }
    for (const StorageImageBinding& ib : b.storageImages) {
        if (!caps_.storageImages)
            return {StatusCode::UnsupportedFeature, "BindingSet.storageImages: the device has no storage images"};
        SFX_TRY(textures_.check(ib.texture, "StorageImageBinding.texture"));
        const GlTexture& t = textures_.get(ib.texture);
        SFX_TRY(validation::mipRange(t.desc, ib.mip, "StorageImageBinding.mip"));
        if (!(t.desc.usage & kTextureStorage))
            return invalidArgument("StorageImageBinding.texture usage", str(t.desc.usage), "with kTextureStorage");
    }
    return Status::ok();
}

// The pass's attachments, then every draw against them and against feedback loops; `targets`
// receives what the pass renders to.
Status GlDevice::checkPass(const RenderPassDesc& pass, std::span<const DrawDesc> draws, PassTargets* targets) {
    if (pass.colors.empty() && pass.depth.texture.isNull())
        return invalidArgument("RenderPassDesc", "without attachments", "at least one colour or depth attachment");
    if (pass.colors.size() > caps_.limits.maxColorAttachments)
        return invalidArgument("RenderPassDesc.colors.size()", str(pass.colors.size()),
                               "[0, " + str(caps_.limits.maxColorAttachments) + "]");
    ColorTargets& colors = targets->colors;
    uint32_t& width = targets->width;
    uint32_t& height = targets->height;
    auto extentMatches = [&](const TextureDesc& d, uint32_t mip, const char* what) -> Status {
        const uint32_t w = mipExtent(d.width, mip), h = mipExtent(d.height, mip);
        if (width == 0) {
            width = w;
            height = h;
        } else if (w != width || h != height) {
            return invalidArgument(what, str(w) + "x" + str(h), "the pass's extent " + str(width) + "x" + str(height));
        }
        return Status::ok();
    };
    for (const ColorAttachment& ca : pass.colors) {
        SFX_TRY(textures_.check(ca.texture, "RenderPassDesc.colors[].texture"));
        const GlTexture& t = textures_.get(ca.texture);
        SFX_TRY(validation::mipRange(t.desc, ca.mip, "RenderPassDesc.colors[].mip"));
        if (!(t.desc.usage & kTextureRenderTarget) || isDepthFormat(t.desc.format))
            return invalidArgument("RenderPassDesc.colors[].texture", toString(t.desc.format),
                                   "a colour texture with kTextureRenderTarget");
        SFX_TRY(extentMatches(t.desc, ca.mip, "RenderPassDesc.colors[] extent"));
        colors.push_back({&t, ca.mip});
    }
    const GlTexture*& depth = targets->depth;
    if (!pass.depth.texture.isNull()) {
        SFX_TRY(textures_.check(pass.depth.texture, "RenderPassDesc.depth.texture"));
        depth = &textures_.get(pass.depth.texture);
        if (!(depth->desc.usage & kTextureRenderTarget) || !isDepthFormat(depth->desc.format))
            return invalidArgument("RenderPassDesc.depth.texture", toString(depth->desc.format),
                                   "a depth texture with kTextureRenderTarget");
        SFX_TRY(extentMatches(depth->desc, 0, "RenderPassDesc.depth extent"));
    }
    // Check every draw before any GL work, so a bad draw leaves the targets untouched.
    for (const DrawDesc& d : draws) {
        SFX_TRY(checkDraw(d, colors, depth));
        SFX_TRY(validation::noFeedbackLoop(pass, d));
    }
    return Status::ok();
}

Status GlDevice::checkDraw(const DrawDesc& d, const ColorTargets& colors, const GlTexture* depth) {
    SFX_TRY(pipelines_.check(d.pipeline, "DrawDesc.pipeline"));
    const GlPipeline& p = pipelines_.get(d.pipeline);
    if (p.compute) return {StatusCode::InvalidArgument, "DrawDesc.pipeline is a compute pipeline"};
    SFX_TRY(programs_.check(p.program, "DrawDesc.pipeline's program"));
    const GraphicsPipelineDesc& pd = p.desc;
    if (pd.colorFormats.size() != colors.size())
        return invalidArgument("DrawDesc.pipeline colour formats", str(pd.colorFormats.size()),
                               str(colors.size()) + ", the pass's colour attachments");
    for (size_t i = 0; i < colors.size(); ++i)
        if (pd.colorFormats[i] != colors[i].first->desc.format)
            return invalidArgument("DrawDesc.pipeline colorFormats[" + str(i) + "]", toString(pd.colorFormats[i]),
                                   std::string(toString(colors[i].first->desc.format)) + ", the pass's attachment");
    const Format passDepth = depth ? depth->desc.format : Format::Undefined;
    if (pd.depthFormat != passDepth)
        return invalidArgument("DrawDesc.pipeline depthFormat", toString(pd.depthFormat),
                               std::string(toString(passDepth)) + ", the pass's depth attachment");
    SFX_TRY(checkBindingsMatch(programs_.get(p.program), d.bindings, "DrawDesc.bindings"));
    SFX_TRY(checkResources(d.bindings, &programs_.get(p.program)));
    const BufferDesc* vertexBuffer = nullptr;
    const BufferDesc* indexBuffer = nullptr;
    if (!pd.vertexLayout.attributes.empty()) {
        SFX_TRY(buffers_.check(d.vertexBuffer, "DrawDesc.vertexBuffer"));
        vertexBuffer = &buffers_.get(d.vertexBuffer).desc;
    } else if (!d.vertexBuffer.isNull()) {
        return invalidArgument("DrawDesc.vertexBuffer", "set", "null for a pipeline without vertex attributes");
    }
    if (!d.indexBuffer.isNull()) {
        SFX_TRY(buffers_.check(d.indexBuffer, "DrawDesc.indexBuffer"));
        indexBuffer = &buffers_.get(d.indexBuffer).desc;
    }
    return validation::drawRange(d, pd.vertexLayout, vertexBuffer, indexBuffer);
}

Result<const GlProgram*> GlDevice::checkDispatch(const DispatchDesc& d) {
    SFX_TRY(validation::dispatchGroups(d, caps_));
    SFX_TRY(pipelines_.check(d.pipeline, "DispatchDesc.pipeline"));
    const GlPipeline& p = pipelines_.get(d.pipeline);
    if (!p.compute) return Status{StatusCode::InvalidArgument, "DispatchDesc.pipeline is a graphics pipeline"};
    SFX_TRY(programs_.check(p.program, "DispatchDesc.pipeline's program"));
    const GlProgram& program = programs_.get(p.program);
    SFX_TRY(checkBindingsMatch(program, d.bindings, "DispatchDesc.bindings"));
    SFX_TRY(checkResources(d.bindings, &program));
    return &program;
}

}  // namespace sfx::gl
