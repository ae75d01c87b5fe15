// Readback: buffers through a read mapping, colour levels through glReadPixels in the formats
// GL ES guarantees, and depth directly on desktop GL or through a copy pass on GL ES.
#include <algorithm>
#include <cmath>
#include <cstring>

#include "gl_driver.hpp"
#include "gl_formats.hpp"
#include "sfx/half.hpp"
#include "sfx_shaders.hpp"

namespace sfx::gl {

Status GlDevice::doReadTexture(TextureHandle h, uint32_t mip, void* out, size_t /*the whole level*/) {
    const GlTexture t = textures_.get(h);
    SFX_TRY(enter());
    return takeDeviceError(readLevel(t, mip, out));
}

Status GlDevice::doReadBuffer(BufferHandle h, uint64_t offset, void* out, size_t bytes) {
    const GlBuffer& b = buffers_.get(h);
    SFX_TRY(enter());
    // GL ES has no glGetBufferSubData; mapping for reading works on both APIs.
    GL(glBindBuffer, GL_COPY_READ_BUFFER, b.name);
    const void* mapped = GL(glMapBufferRange, GL_COPY_READ_BUFFER, GLintptr(offset), GLsizeiptr(bytes), GL_MAP_READ_BIT);
    if (mapped) {
        std::memcpy(out, mapped, bytes);
        GL(glUnmapBuffer, GL_COPY_READ_BUFFER);
    }
    GL(glBindBuffer, GL_COPY_READ_BUFFER, 0);
    Status s = takeDeviceError(Status::ok());
    if (s && !mapped) return {StatusCode::DeviceError, "readBuffer: glMapBufferRange returned NULL"};
    return s;
}

Status GlDevice::readLevel(const GlTexture& t, uint32_t mip, void* out) {
    const uint32_t w = mipExtent(t.desc.width, mip), h = mipExtent(t.desc.height, mip);
    const size_t texels = size_t(w) * h;
    const Format f = t.desc.format;
    GL(glBindBuffer, GL_PIXEL_PACK_BUFFER, 0);
    if (isDepthFormat(f)) {
        if (api_ == Api::DesktopGL) {
            // Desktop GL reads depth directly, already in the texture's layout.
            Result<GLuint> fbo = framebuffer({}, &t, mip);
            if (!fbo) return fbo.status();
            const GlFormat gf = glFormat(f);
            GL(glReadPixels, 0, 0, GLsizei(w), GLsizei(h), gf.format, gf.type, out);
            GL(glBindFramebuffer, GL_FRAMEBUFFER, 0);
            return Status::ok();
        }
        std::vector<float> depth(texels);
        SFX_TRY(copyDepthEs(t, mip, w, h, depth.data()));
        for (size_t i = 0; i < texels; ++i) {
            const double d = std::clamp(double(depth[i]), 0.0, 1.0);
            if (f == Format::D16) {
                const uint16_t v = uint16_t(std::lround(d * 65535.0));
                std::memcpy(static_cast<uint8_t*>(out) + i * 2, &v, 2);
            } else if (f == Format::D24S8) {
                // Depth in the high 24 bits as GL's UNSIGNED_INT_24_8; stencil reads as 0 on GL ES.
                const uint32_t v = uint32_t(std::lround(d * 16777215.0)) << 8;
                std::memcpy(static_cast<uint8_t*>(out) + i * 4, &v, 4);
            } else {
                std::memcpy(static_cast<uint8_t*>(out) + i * 4, &depth[i], 4);
            }
        }
        return Status::ok();
    }

    // GL ES guarantees RGBA with UNSIGNED_BYTE, FLOAT or UNSIGNED_INT per target class: read
    // that on both APIs and narrow to the texture's layout here.
    Result<GLuint> fbo = framebuffer({{&t, mip}}, nullptr, 0);
    if (!fbo) return fbo.status();
    const uint32_t channels = channelCount(f);
    if (f == Format::R8 || f == Format::RGBA8) {
        std::vector<uint8_t> rgba(texels * 4);
        GL(glReadPixels, 0, 0, GLsizei(w), GLsizei(h), GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
        auto* o = static_cast<uint8_t*>(out);
        for (size_t i = 0; i < texels; ++i)
            for (uint32_t c = 0; c < channels; ++c) o[i * channels + c] = rgba[i * 4 + c];
    } else if (f == Format::R32UI) {
        std::vector<uint32_t> rgba(texels * 4);
        GL(glReadPixels, 0, 0, GLsizei(w), GLsizei(h), GL_RGBA_INTEGER, GL_UNSIGNED_INT, rgba.data());
        auto* o = static_cast<uint32_t*>(out);
        for (size_t i = 0; i < texels; ++i) o[i] = rgba[i * 4];
    } else {
        std::vector<float> rgba(texels * 4);
        GL(glReadPixels, 0, 0, GLsizei(w), GLsizei(h), GL_RGBA, GL_FLOAT, rgba.data());
        if (isHalfFormat(f)) {
            auto* o = static_cast<uint16_t*>(out);
            for (size_t i = 0; i < texels; ++i)
                for (uint32_t c = 0; c < channels; ++c) o[i * channels + c] = floatToHalf(rgba[i * 4 + c]);
        } else {
            auto* o = static_cast<float*>(out);
            for (size_t i = 0; i < texels; ++i)
                for (uint32_t c = 0; c < channels; ++c) o[i * channels + c] = rgba[i * 4 + c];
        }
    }
    GL(glBindFramebuffer, GL_FRAMEBUFFER, 0);
    return Status::ok();
}

// GL ES cannot glReadPixels depth: draw the level into a temporary R32F target and read that.
Status GlDevice::copyDepthEs(const GlTexture& t, uint32_t mip, uint32_t w, uint32_t h, float* out) {
    if (!extensions_.count("GL_EXT_color_buffer_float") && !(caps_.apiMajor * 10 + caps_.apiMinor >= 32))
        return {StatusCode::UnsupportedFeature, "readTexture of depth on GL ES needs R32F render targets"};
    // The copy pass is shader_src/gl_depth_copy.frag, built for the current tier: it has every
    // GL dialect, so it links under any capability ceiling.
    constexpr uint32_t kDepthUnit = gen::gl_depth_copy::uDepth;
    if (!depthCopyProgram_) {
        Result<const CompiledProgram*> program = shaders::find(gen::gl_depth_copy::kName, Tier::Current);
        if (!program) return program.status();
        Result<GLuint> linked = linkProgram(*program.value());
        if (!linked) return linked.status();
        depthCopyProgram_ = linked.value();
    }
    GlTexture target;
    target.desc = TextureDesc{w, h, 1, Format::R32F, kTextureRenderTarget, "gl_depth_copy"};
    GL(glGenTextures, 1, &target.name);
    GL(glBindTexture, GL_TEXTURE_2D, target.name);
    GL(glTexStorage2D, GL_TEXTURE_2D, 1, GL_R32F, GLsizei(w), GLsizei(h));
    GL(glBindTexture, GL_TEXTURE_2D, 0);
    readbackCopies_.add();
    storage_.add();
    Status s = [&]() -> Status {
        Result<GLuint> fbo = framebuffer({{&target, 0}}, nullptr, 0);
        if (!fbo) return fbo.status();
        GL(glViewport, 0, 0, GLsizei(w), GLsizei(h));
        GL(glDisable, GL_DEPTH_TEST);
        GL(glDisable, GL_BLEND);
        GL(glDisable, GL_CULL_FACE);
        GL(glDisable, GL_SCISSOR_TEST);
        GL(glColorMask, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        GL(glUseProgram, depthCopyProgram_);
        GL(glActiveTexture, GL_TEXTURE0 + kDepthUnit);
        GL(glBindTexture, GL_TEXTURE_2D, t.name);
        GL(glTexParameteri, GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, GLint(mip));
        GL(glTexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, GLint(mip));
        GL(glBindSampler, kDepthUnit, nearestSampler_);
        GL(glBindVertexArray, emptyVao_);
        GL(glDrawArraysInstanced, GL_TRIANGLES, 0, 3, 1);
        GL(glBindSampler, kDepthUnit, 0);
        GL(glBindTexture, GL_TEXTURE_2D, 0);
        GL(glActiveTexture, GL_TEXTURE0);
        GL(glBindVertexArray, 0);
        GL(glUseProgram, 0);
        std::vector<float> rgba(size_t(w) * h * 4);
        GL(glReadPixels, 0, 0, GLsizei(w), GLsizei(h), GL_RGBA, GL_FLOAT, rgba.data());
        for (size_t i = 0; i < size_t(w) * h; ++i) out[i] = rgba[i * 4];
        GL(glBindFramebuffer, GL_FRAMEBUFFER, 0);
        return Status::ok();
    }();
    forgetFbosOf(target.name);
    GL(glDeleteTextures, 1, &target.name);
    readbackCopies_.remove();
    storage_.remove();
    return s;
}

}  // namespace sfx::gl
