#include "host_gl.hpp"

#include <cstdio>

namespace engine_gl {

std::string HostGl::load(GetProcAddress loader) {
    std::string missing;
#define ENGINE_GL_LOAD(type, name)                                                  \
    name = reinterpret_cast<type>(loader("gl" #name));                              \
    if (!name) missing += (missing.empty() ? "gl" : ", gl") + std::string(#name);
    ENGINE_GL_STATE_FUNCTIONS(ENGINE_GL_LOAD)
    ENGINE_GL_COUNTED_FUNCTIONS(ENGINE_GL_LOAD)
#undef ENGINE_GL_LOAD
    return missing;
}

GLuint HostGl::genTexture() {
    GLuint n = 0;
    GenTextures(1, &n);
    ++counts_.objectsCreated;
    return n;
}
GLuint HostGl::genSampler() {
    GLuint n = 0;
    GenSamplers(1, &n);
    ++counts_.objectsCreated;
    return n;
}
GLuint HostGl::genFramebuffer() {
    GLuint n = 0;
    GenFramebuffers(1, &n);
    ++counts_.objectsCreated;
    return n;
}
GLuint HostGl::genBuffer() {
    GLuint n = 0;
    GenBuffers(1, &n);
    ++counts_.objectsCreated;
    return n;
}
GLuint HostGl::genVertexArray() {
    GLuint n = 0;
    GenVertexArrays(1, &n);
    ++counts_.objectsCreated;
    return n;
}
GLuint HostGl::createShader(GLenum type) {
    ++counts_.objectsCreated;
    return CreateShader(type);
}
GLuint HostGl::createProgram() {
    ++counts_.objectsCreated;
    return CreateProgram();
}
void HostGl::texStorage2D(GLenum target, GLsizei levels, GLenum internalFormat, GLsizei w, GLsizei h) {
    ++counts_.allocations;
    TexStorage2D(target, levels, internalFormat, w, h);
}
void HostGl::texSubImage2D(GLenum target, GLint level, GLsizei w, GLsizei h, GLenum format, GLenum type, const void* data) {
    ++counts_.uploads;
    TexSubImage2D(target, level, 0, 0, w, h, format, type, data);
}
void HostGl::bufferData(GLenum target, GLsizeiptr size, const void* data, GLenum usage) {
    ++counts_.allocations;
    if (data) ++counts_.uploads;
    BufferData(target, size, data, usage);
}
void HostGl::readPixels(GLint x, GLint y, GLsizei w, GLsizei h, GLenum format, GLenum type, void* data) {
    ++counts_.readbacks;
    ReadPixels(x, y, w, h, format, type, data);
}

#define ENGINE_GL_DELETE(method, fn)      \
    void HostGl::method(GLuint& name) {   \
        if (name == 0) return;            \
        fn(1, &name);                     \
        ++counts_.objectsDeleted;         \
        name = 0;                         \
    }
ENGINE_GL_DELETE(deleteTexture, DeleteTextures)
ENGINE_GL_DELETE(deleteSampler, DeleteSamplers)
ENGINE_GL_DELETE(deleteFramebuffer, DeleteFramebuffers)
ENGINE_GL_DELETE(deleteBuffer, DeleteBuffers)
ENGINE_GL_DELETE(deleteVertexArray, DeleteVertexArrays)
#undef ENGINE_GL_DELETE

void HostGl::deleteProgram(GLuint& name) {
    if (name == 0) return;
    DeleteProgram(name);
    ++counts_.objectsDeleted;
    name = 0;
}

void HostGl::checkErrors(const char* where) {
    for (GLenum e = GetError(); e != GL_NO_ERROR; e = GetError()) {
        char hex[16];
        std::snprintf(hex, sizeof hex, "0x%04x", unsigned(e));
        errors_ += std::string(errors_.empty() ? "" : "; ") + where + ": GL error " + hex;
    }
}

std::string HostGl::takeErrors() {
    std::string out;
    out.swap(errors_);
    return out;
}

}  // namespace engine_gl
