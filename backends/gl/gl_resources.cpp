// Textures, buffers and samplers: creation, upload and destruction. New buffers are zero-filled
// like every backend's; textures and samplers get the state the commands rely on.
#include <algorithm>

#include "gl_driver.hpp"
#include "gl_formats.hpp"

namespace sfx::gl {

Result<TextureHandle> GlDevice::doCreateTexture(const TextureDesc& desc) {
    SFX_TRY(enter());
    const GlFormat f = glFormat(desc.format);
    GlTexture t{desc, 0};
    GL(glGenTextures, 1, &t.name);
    GL(glBindTexture, GL_TEXTURE_2D, t.name);
    GL(glTexStorage2D, GL_TEXTURE_2D, GLsizei(desc.mipLevels), f.internalFormat, GLsizei(desc.width), GLsizei(desc.height));
    // Depth is read as a value in shaders (texelFetch), never compared.
    if (isDepthFormat(desc.format)) GL(glTexParameteri, GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_NONE);
    GL(glTexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
    GL(glTexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    GL(glBindTexture, GL_TEXTURE_2D, 0);
    Status s = takeDeviceError(Status::ok());
    if (!s) {
        gl_.glDeleteTextures(1, &t.name);
        return s;
    }
    storage_.add();
    bytesHeld_ += textureBytes(desc);
    return textures_.insert(t);
}

Status GlDevice::doDestroyTexture(TextureHandle h) {
    SFX_TRY(enter());
    GlTexture t = textures_.remove(h);
    forgetFbosOf(t.name);
    if (t.external) return takeDeviceError(Status::ok());  // the host's to delete
    storage_.remove();
    bytesHeld_ -= textureBytes(t.desc);
    GL(glDeleteTextures, 1, &t.name);
    return takeDeviceError(Status::ok());
}

Status GlDevice::doWriteTexture(TextureHandle h, uint32_t mip, const void* data, size_t /*the whole level*/) {
    const GlTexture& t = textures_.get(h);
    SFX_TRY(enter());
    const GlFormat f = glFormat(t.desc.format);
    GL(glBindBuffer, GL_PIXEL_UNPACK_BUFFER, 0);
    GL(glActiveTexture, GL_TEXTURE0);
    GL(glBindTexture, GL_TEXTURE_2D, t.name);
    GL(glTexSubImage2D, GL_TEXTURE_2D, GLint(mip), 0, 0, GLsizei(mipExtent(t.desc.width, mip)), GLsizei(mipExtent(t.desc.height, mip)), f.format,
       f.type, data);
    GL(glBindTexture, GL_TEXTURE_2D, 0);
    return takeDeviceError(Status::ok());
}

Result<BufferHandle> GlDevice::doCreateBuffer(const BufferDesc& desc) {
    SFX_TRY(enter());
    GlBuffer b{desc, 0};
    GL(glGenBuffers, 1, &b.name);
    GL(glBindBuffer, GL_COPY_WRITE_BUFFER, b.name);
    // Zero-filled like every backend's new buffer, from a small block rather than a host
    // copy of the whole buffer (which may be up to maxBufferSize).
    GL(glBufferData, GL_COPY_WRITE_BUFFER, GLsizeiptr(desc.size), nullptr, GL_DYNAMIC_DRAW);
    static const std::vector<uint8_t> kZeros(64 * 1024, 0);
    for (uint64_t offset = 0; offset < desc.size; offset += kZeros.size())
        GL(glBufferSubData, GL_COPY_WRITE_BUFFER, GLintptr(offset), GLsizeiptr(std::min<uint64_t>(kZeros.size(), desc.size - offset)), kZeros.data());
    GL(glBindBuffer, GL_COPY_WRITE_BUFFER, 0);
    Status s = takeDeviceError(Status::ok());
    if (!s) {
        gl_.glDeleteBuffers(1, &b.name);
        return s;
    }
    storage_.add();
    bytesHeld_ += desc.size;
    return buffers_.insert(b);
}

Status GlDevice::doDestroyBuffer(BufferHandle h) {
    SFX_TRY(enter());
    GlBuffer b = buffers_.remove(h);
    storage_.remove();
    bytesHeld_ -= b.desc.size;
    GL(glDeleteBuffers, 1, &b.name);
    return takeDeviceError(Status::ok());
}

Status GlDevice::doWriteBuffer(BufferHandle h, uint64_t offset, const void* data, size_t bytes) {
    const GlBuffer& b = buffers_.get(h);
    SFX_TRY(enter());
    GL(glBindBuffer, GL_COPY_WRITE_BUFFER, b.name);
    GL(glBufferSubData, GL_COPY_WRITE_BUFFER, GLintptr(offset), GLsizeiptr(bytes), data);
    GL(glBindBuffer, GL_COPY_WRITE_BUFFER, 0);
    return takeDeviceError(Status::ok());
}

Result<SamplerHandle> GlDevice::doCreateSampler(const SamplerDesc& desc) {
    SFX_TRY(enter());
    GlSampler s{desc, 0};
    GL(glGenSamplers, 1, &s.name);
    setSamplerState(s.name, desc);
    Status st = takeDeviceError(Status::ok());
    if (!st) return st;
    return samplers_.insert(s);
}

Status GlDevice::doDestroySampler(SamplerHandle h) {
    SFX_TRY(enter());
    GlSampler s = samplers_.remove(h);
    GL(glDeleteSamplers, 1, &s.name);
    return takeDeviceError(Status::ok());
}

void GlDevice::setSamplerState(GLuint s, const SamplerDesc& d) {
    // Always a mipmapped min filter, so lods past the binding's base are reachable.
    GLenum minFilter;
    if (d.minFilter == Filter::Nearest)
        minFilter = d.mipFilter == Filter::Nearest ? GL_NEAREST_MIPMAP_NEAREST : GL_NEAREST_MIPMAP_LINEAR;
    else
        minFilter = d.mipFilter == Filter::Nearest ? GL_LINEAR_MIPMAP_NEAREST : GL_LINEAR_MIPMAP_LINEAR;
    GL(glSamplerParameteri, s, GL_TEXTURE_MIN_FILTER, GLint(minFilter));
    GL(glSamplerParameteri, s, GL_TEXTURE_MAG_FILTER, d.magFilter == Filter::Nearest ? GL_NEAREST : GL_LINEAR);
    GL(glSamplerParameteri, s, GL_TEXTURE_WRAP_S, GLint(wrapMode(d.address)));
    GL(glSamplerParameteri, s, GL_TEXTURE_WRAP_T, GLint(wrapMode(d.address)));
    GL(glSamplerParameteri, s, GL_TEXTURE_COMPARE_MODE, GL_NONE);
}

DeviceStats GlDevice::stats() const {
    DeviceStats s = halObjectStats(textures_, buffers_, samplers_, programs_, pipelines_, timers_);
    s.memoryAllocations = storage_;
    s.stagingBuffers = readbackCopies_;
    s.framebuffers = framebufferCount_;
    s.deviceMemoryBytes = bytesHeld_;
    return s;
}

}  // namespace sfx::gl
