// Commands: render passes, draws and dispatches that the checks (sfx::validation, gl_checks.cpp) accepted,
// encoded as GL state changes and calls, with the SDK's bindings undone after each.
#include <algorithm>

#include "gl_driver.hpp"
#include "gl_formats.hpp"

namespace sfx::gl {

// Binds resources the shared validation accepted. Textures show the shader only the binding's mips
// (BASE_LEVEL/MAX_LEVEL), which also makes rendering into a mip outside them legal.
void GlDevice::bindResources(const BindingSet& b) {
    for (const TextureBinding& tb : b.textures) {
        const GlTexture& t = textures_.get(tb.texture);
        // The checks refused a Linear filter on a format the device cannot filter
        // (caps.filterableFormat), which would leave the texture incomplete.
        const GLuint sampler = tb.sampler.isNull() ? nearestSampler_ : samplers_.get(tb.sampler).name;
        GL(glActiveTexture, GL_TEXTURE0 + tb.binding);
        GL(glBindTexture, GL_TEXTURE_2D, t.name);
        GL(glTexParameteri, GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, GLint(tb.baseMip));
        GL(glTexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, GLint(tb.baseMip + tb.mipCount - 1));
        GL(glBindSampler, tb.binding, sampler);
    }
    GL(glActiveTexture, GL_TEXTURE0);
    auto bindRange = [&](GLenum target, const BufferBinding& bb) {
        const GlBuffer& buf = buffers_.get(bb.buffer);
        GL(glBindBufferRange, target, bb.binding, buf.name, GLintptr(bb.offset), GLsizeiptr(validation::boundSize(bb, buf.desc)));
    };
    for (const BufferBinding& bb : b.uniformBuffers) bindRange(GL_UNIFORM_BUFFER, bb);
    for (const BufferBinding& bb : b.storageBuffers) bindRange(GL_SHADER_STORAGE_BUFFER, bb);
    for (const StorageImageBinding& ib : b.storageImages) {
        const GlTexture& t = textures_.get(ib.texture);
        GL(glBindImageTexture, ib.binding, t.name, GLint(ib.mip), GL_FALSE, 0, GL_READ_WRITE, glFormat(t.desc.format).internalFormat);
    }
}

// Leaves no SDK sampler or texture bound on the units a draw used: a sampler object left
// bound would silently override the filtering of whatever the host binds there next.
void GlDevice::unbindResources(const BindingSet& b) {
    for (const TextureBinding& tb : b.textures) {
        GL(glBindSampler, tb.binding, 0);
        GL(glActiveTexture, GL_TEXTURE0 + tb.binding);
        GL(glBindTexture, GL_TEXTURE_2D, 0);
    }
    GL(glActiveTexture, GL_TEXTURE0);
}

void GlDevice::passTargets(const RenderPassDesc& pass, PassTargets& out) const {
    out.colors.clear();
    out.depth = nullptr;
    out.width = out.height = 0;
    for (const ColorAttachment& ca : pass.colors) {
        const GlTexture& t = textures_.get(ca.texture);
        if (out.width == 0) {
            out.width = mipExtent(t.desc.width, ca.mip);
            out.height = mipExtent(t.desc.height, ca.mip);
        }
        out.colors.push_back({&t, ca.mip});
    }
    if (!pass.depth.texture.isNull()) {
        out.depth = &textures_.get(pass.depth.texture);
        if (out.width == 0) {
            out.width = out.depth->desc.width;
            out.height = out.depth->desc.height;
        }
    }
}

// Clears the attachments as their load ops ask, then runs the draws in order.
Status GlDevice::encodeRenderPass(const RenderPassDesc& pass, std::span<const DrawDesc> draws, const PassTargets& targets) {
    Result<GLuint> fbo = framebuffer(targets.colors, targets.depth, 0);
    if (!fbo) return fbo.status();
    GL(glViewport, 0, 0, GLsizei(targets.width), GLsizei(targets.height));
    GL(glDisable, GL_SCISSOR_TEST);
    GL(glDisable, GL_BLEND);
    GL(glColorMask, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    for (size_t i = 0; i < pass.colors.size(); ++i) {
        const ColorAttachment& ca = pass.colors[i];
        if (ca.load != LoadOp::Clear) continue;
        if (isIntegerFormat(targets.colors[i].first->desc.format)) {
            GLuint v[4];
            for (int c = 0; c < 4; ++c) v[c] = GLuint(std::max(0.0f, ca.clearColor[size_t(c)]));
            GL(glClearBufferuiv, GL_COLOR, GLint(i), v);
        } else {
            GL(glClearBufferfv, GL_COLOR, GLint(i), ca.clearColor.data());
        }
    }
    if (const GlTexture* depth = targets.depth; depth && pass.depth.load == LoadOp::Clear) {
        GL(glDepthMask, GL_TRUE);
        if (depth->desc.format == Format::D24S8)
            GL(glClearBufferfi, GL_DEPTH_STENCIL, 0, pass.depth.clearDepth, 0);
        else
            GL(glClearBufferfv, GL_DEPTH, 0, &pass.depth.clearDepth);
    }
    // Draws with storage side effects (fragment stores and atomics): earlier writes visible to
    // them, and theirs to every later pass or dispatch, as Vulkan's barrier between commands does.
    const bool storage = std::any_of(draws.begin(), draws.end(),
                                     [](const DrawDesc& d) { return !d.bindings.storageBuffers.empty() || !d.bindings.storageImages.empty(); });
    if (storage) GL(glMemoryBarrier, GL_ALL_BARRIER_BITS);
    for (const DrawDesc& d : draws) encodeDraw(d);
    if (storage) GL(glMemoryBarrier, GL_ALL_BARRIER_BITS);
    GL(glBindVertexArray, 0);
    GL(glUseProgram, 0);
    GL(glBindFramebuffer, GL_FRAMEBUFFER, 0);
    return Status::ok();
}

void GlDevice::encodeDraw(const DrawDesc& d) {
    const GlPipeline& p = pipelines_.get(d.pipeline);
    const GraphicsPipelineDesc& pd = p.desc;
    GL(glUseProgram, programOf(p));
    bindResources(d.bindings);

    if (pd.depth.test || pd.depth.write) {
        // GL skips depth writes with the test off; ALWAYS keeps a write-only pipeline writing.
        GL(glEnable, GL_DEPTH_TEST);
        GL(glDepthFunc, pd.depth.test ? compareFunc(pd.depth.compare) : GL_ALWAYS);
    } else {
        GL(glDisable, GL_DEPTH_TEST);
    }
    GL(glDepthMask, pd.depth.write ? GL_TRUE : GL_FALSE);
    if (pd.blend.enable) {
        GL(glEnable, GL_BLEND);
        const BlendState& b = pd.blend;
        GL(glBlendFuncSeparate, blendFactor(b.src), blendFactor(b.dst), blendFactor(b.separateAlpha ? b.srcAlpha : b.src),
           blendFactor(b.separateAlpha ? b.dstAlpha : b.dst));
    } else {
        GL(glDisable, GL_BLEND);
    }
    // NDC y = -1 is memory row 0 and GL's window y grows with the row, so GL's own CCW is
    // counter-clockwise in memory rows.
    GL(glFrontFace, GL_CCW);
    if (pd.cull == CullMode::None) {
        GL(glDisable, GL_CULL_FACE);
    } else {
        GL(glEnable, GL_CULL_FACE);
        GL(glCullFace, pd.cull == CullMode::Back ? GL_BACK : GL_FRONT);
    }

    GL(glBindVertexArray, p.vao);
    if (!pd.vertexLayout.attributes.empty()) {
        GL(glBindBuffer, GL_ARRAY_BUFFER, buffers_.get(d.vertexBuffer).name);
        for (const VertexAttribute& a : pd.vertexLayout.attributes) {
            const GLint size = a.format == VertexFormat::Float2 ? 2 : a.format == VertexFormat::Float3 ? 3 : 4;
            GL(glVertexAttribPointer, a.location, size, GL_FLOAT, GL_FALSE, GLsizei(pd.vertexLayout.stride),
               reinterpret_cast<const void*>(uintptr_t(a.offset)));
        }
        GL(glBindBuffer, GL_ARRAY_BUFFER, 0);
    }
    if (!d.indexBuffer.isNull()) {
        GL(glBindBuffer, GL_ELEMENT_ARRAY_BUFFER, buffers_.get(d.indexBuffer).name);
        GL(glDrawElementsInstanced, GL_TRIANGLES, GLsizei(d.count), GL_UNSIGNED_INT, nullptr, GLsizei(d.instanceCount));
        GL(glBindBuffer, GL_ELEMENT_ARRAY_BUFFER, 0);
    } else {
        GL(glDrawArraysInstanced, GL_TRIANGLES, 0, GLsizei(d.count), GLsizei(d.instanceCount));
    }
    unbindResources(d.bindings);
}

void GlDevice::encodeDispatch(GLuint program, const DispatchDesc& d) {
    GL(glUseProgram, program);
    bindResources(d.bindings);
    // Earlier passes' writes visible to the dispatch, and its writes to what follows.
    GL(glMemoryBarrier, GL_ALL_BARRIER_BITS);
    GL(glDispatchCompute, d.groupsX, d.groupsY, d.groupsZ);
    GL(glMemoryBarrier, GL_ALL_BARRIER_BITS);
    unbindResources(d.bindings);
    GL(glUseProgram, 0);
}

}  // namespace sfx::gl
