// The framebuffer object cache: one FBO per attachment set, made on first use and deleted when
// one of its textures goes.
#include <algorithm>
#include <cstdio>

#include "gl_driver.hpp"

namespace sfx::gl {

GLenum GlDevice::depthAttachmentPoint(Format f) const { return f == Format::D24S8 ? GL_DEPTH_STENCIL_ATTACHMENT : GL_DEPTH_ATTACHMENT; }

// A framebuffer object per attachment set, made once and kept until a texture goes.
Result<GLuint> GlDevice::framebuffer(const ColorTargets& colors, const GlTexture* depth, uint32_t depthMip) {
    FboKey& key = fboKey_;  // the device's, reused: a found FBO costs no allocation
    key.clear();
    for (const auto& [t, mip] : colors) key.push_back((uint64_t(t->name) << 32) | mip);
    key.push_back(depth ? (uint64_t(depth->name) << 32) | depthMip : ~uint64_t(0));
    auto it = fbos_.find(key);
    if (it != fbos_.end()) {
        GL(glBindFramebuffer, GL_FRAMEBUFFER, it->second);
        return it->second;
    }
    GLuint fbo = 0;
    GL(glGenFramebuffers, 1, &fbo);
    GL(glBindFramebuffer, GL_FRAMEBUFFER, fbo);
    std::vector<GLenum> drawBuffers;
    for (size_t i = 0; i < colors.size(); ++i) {
        GL(glFramebufferTexture2D, GL_FRAMEBUFFER, GLenum(GL_COLOR_ATTACHMENT0 + i), GL_TEXTURE_2D, colors[i].first->name, GLint(colors[i].second));
        drawBuffers.push_back(GLenum(GL_COLOR_ATTACHMENT0 + i));
    }
    if (depth) GL(glFramebufferTexture2D, GL_FRAMEBUFFER, depthAttachmentPoint(depth->desc.format), GL_TEXTURE_2D, depth->name, GLint(depthMip));
    if (drawBuffers.empty()) {
        const GLenum none = GL_NONE;
        GL(glDrawBuffers, 1, &none);
        GL(glReadBuffer, GL_NONE);
    } else {
        GL(glDrawBuffers, GLsizei(drawBuffers.size()), drawBuffers.data());
        GL(glReadBuffer, GL_COLOR_ATTACHMENT0);
    }
    const GLenum status = GL(glCheckFramebufferStatus, GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        GL(glBindFramebuffer, GL_FRAMEBUFFER, 0);
        GL(glDeleteFramebuffers, 1, &fbo);
        char hex[16];
        std::snprintf(hex, sizeof(hex), "0x%04x", unsigned(status));
        return Status{StatusCode::UnsupportedFormat, std::string("the attachments make an incomplete framebuffer (status ") + hex + ")"};
    }
    fbos_[key] = fbo;
    framebufferCount_.add();
    return fbo;
}

void GlDevice::forgetFbosOf(GLuint texture) {
    for (auto it = fbos_.begin(); it != fbos_.end();) {
        const bool uses = std::any_of(it->first.begin(), it->first.end(),
                                      [&](uint64_t k) { return k != ~uint64_t(0) && GLuint(k >> 32) == texture; });
        if (uses) {
            GL(glDeleteFramebuffers, 1, &it->second);
            framebufferCount_.remove();
            it = fbos_.erase(it);
        } else {
            ++it;
        }
    }
}

}  // namespace sfx::gl
