// The host renderer's own GL entry points, loaded through its EGL loader (the sample links no GL
// library, as the SDK's GL backend does not). The calls that move pixels between the CPU and the
// GPU or allocate GL storage are reachable only through counting wrappers, so the test can
// assert that the steady frames make none of them.
#pragma once

#define GL_GLES_PROTOTYPES 0
#include <GLES3/gl3.h>

#include <cstdint>
#include <string>

namespace engine_gl {

using GetProcAddress = void* (*)(const char* name);

// Entry points the renderer calls directly: binding, state, draws, program setup.
// clang-format off
#define ENGINE_GL_STATE_FUNCTIONS(X)                                                          \
    X(PFNGLGETERRORPROC, GetError) X(PFNGLGETINTEGERVPROC, GetIntegerv)                       \
    X(PFNGLGETSTRINGPROC, GetString) X(PFNGLENABLEPROC, Enable) X(PFNGLDISABLEPROC, Disable)   \
    X(PFNGLVIEWPORTPROC, Viewport) X(PFNGLDEPTHFUNCPROC, DepthFunc)                           \
    X(PFNGLDEPTHMASKPROC, DepthMask) X(PFNGLCOLORMASKPROC, ColorMask)                         \
    X(PFNGLCLEARBUFFERFVPROC, ClearBufferfv) X(PFNGLFRONTFACEPROC, FrontFace)                 \
    X(PFNGLCULLFACEPROC, CullFace) X(PFNGLPIXELSTOREIPROC, PixelStorei)                        \
    X(PFNGLFINISHPROC, Finish) X(PFNGLBINDTEXTUREPROC, BindTexture)                           \
    X(PFNGLACTIVETEXTUREPROC, ActiveTexture) X(PFNGLTEXPARAMETERIPROC, TexParameteri)          \
    X(PFNGLBINDSAMPLERPROC, BindSampler) X(PFNGLSAMPLERPARAMETERIPROC, SamplerParameteri)      \
    X(PFNGLBINDFRAMEBUFFERPROC, BindFramebuffer)                                              \
    X(PFNGLFRAMEBUFFERTEXTURE2DPROC, FramebufferTexture2D)                                    \
    X(PFNGLCHECKFRAMEBUFFERSTATUSPROC, CheckFramebufferStatus)                                \
    X(PFNGLDRAWBUFFERSPROC, DrawBuffers) X(PFNGLREADBUFFERPROC, ReadBuffer)                    \
    X(PFNGLBINDBUFFERPROC, BindBuffer) X(PFNGLVERTEXATTRIBPOINTERPROC, VertexAttribPointer)    \
    X(PFNGLENABLEVERTEXATTRIBARRAYPROC, EnableVertexAttribArray)                              \
    X(PFNGLBINDVERTEXARRAYPROC, BindVertexArray) X(PFNGLDRAWELEMENTSPROC, DrawElements)        \
    X(PFNGLDRAWARRAYSPROC, DrawArrays) X(PFNGLSHADERSOURCEPROC, ShaderSource)                  \
    X(PFNGLCOMPILESHADERPROC, CompileShader) X(PFNGLGETSHADERIVPROC, GetShaderiv)              \
    X(PFNGLGETSHADERINFOLOGPROC, GetShaderInfoLog) X(PFNGLATTACHSHADERPROC, AttachShader)      \
    X(PFNGLLINKPROGRAMPROC, LinkProgram) X(PFNGLGETPROGRAMIVPROC, GetProgramiv)                \
    X(PFNGLGETPROGRAMINFOLOGPROC, GetProgramInfoLog) X(PFNGLDELETESHADERPROC, DeleteShader)    \
    X(PFNGLUSEPROGRAMPROC, UseProgram) X(PFNGLGETUNIFORMLOCATIONPROC, GetUniformLocation)      \
    X(PFNGLBINDATTRIBLOCATIONPROC, BindAttribLocation) X(PFNGLUNIFORM1IPROC, Uniform1i)        \
    X(PFNGLUNIFORM3FPROC, Uniform3f) X(PFNGLUNIFORM2FPROC, Uniform2f)                          \
    X(PFNGLUNIFORMMATRIX4FVPROC, UniformMatrix4fv) X(PFNGLUNIFORMMATRIX3FVPROC, UniformMatrix3fv)
// clang-format on

// Entry points that create GL objects or storage, upload or read back: counted.
// clang-format off
#define ENGINE_GL_COUNTED_FUNCTIONS(X)                                                        \
    X(PFNGLGENTEXTURESPROC, GenTextures) X(PFNGLTEXSTORAGE2DPROC, TexStorage2D)                \
    X(PFNGLTEXSUBIMAGE2DPROC, TexSubImage2D) X(PFNGLGENSAMPLERSPROC, GenSamplers)              \
    X(PFNGLGENFRAMEBUFFERSPROC, GenFramebuffers) X(PFNGLGENBUFFERSPROC, GenBuffers)            \
    X(PFNGLBUFFERDATAPROC, BufferData) X(PFNGLGENVERTEXARRAYSPROC, GenVertexArrays)            \
    X(PFNGLCREATESHADERPROC, CreateShader) X(PFNGLCREATEPROGRAMPROC, CreateProgram)            \
    X(PFNGLREADPIXELSPROC, ReadPixels)                                                        \
    X(PFNGLDELETETEXTURESPROC, DeleteTextures) X(PFNGLDELETESAMPLERSPROC, DeleteSamplers)      \
    X(PFNGLDELETEFRAMEBUFFERSPROC, DeleteFramebuffers) X(PFNGLDELETEBUFFERSPROC, DeleteBuffers) \
    X(PFNGLDELETEVERTEXARRAYSPROC, DeleteVertexArrays) X(PFNGLDELETEPROGRAMPROC, DeleteProgram)
// clang-format on

// How often the host called what it must not call in a steady frame.
struct HostGlCounts {
    uint64_t objectsCreated = 0;  // glGen*, glCreateShader/Program
    uint64_t objectsDeleted = 0;  // glDelete*
    uint64_t allocations = 0;     // glTexStorage2D, glBufferData (new storage)
    uint64_t uploads = 0;         // glTexSubImage2D, glBufferData with data
    uint64_t readbacks = 0;       // glReadPixels
    bool operator==(const HostGlCounts&) const = default;
};

class HostGl {
public:
#define ENGINE_GL_MEMBER(type, name) type name = nullptr;
    ENGINE_GL_STATE_FUNCTIONS(ENGINE_GL_MEMBER)

    // Loads every entry point; empty on success, else the names that are missing.
    std::string load(GetProcAddress loader);

    // The counted calls, each one line over the one counting wrapper below.
    GLuint genTexture() { return generate(GenTextures); }
    GLuint genSampler() { return generate(GenSamplers); }
    GLuint genFramebuffer() { return generate(GenFramebuffers); }
    GLuint genBuffer() { return generate(GenBuffers); }
    GLuint genVertexArray() { return generate(GenVertexArrays); }
    GLuint createShader(GLenum type) { return counted(&HostGlCounts::objectsCreated, CreateShader, type); }
    GLuint createProgram() { return counted(&HostGlCounts::objectsCreated, CreateProgram); }
    void texStorage2D(GLenum target, GLsizei levels, GLenum internalFormat, GLsizei w, GLsizei h) {
        counted(&HostGlCounts::allocations, TexStorage2D, target, levels, internalFormat, w, h);
    }
    void texSubImage2D(GLenum target, GLint level, GLsizei w, GLsizei h, GLenum format, GLenum type, const void* data) {
        counted(&HostGlCounts::uploads, TexSubImage2D, target, level, 0, 0, w, h, format, type, data);
    }
    // New storage, and an upload too when it comes with data.
    void bufferData(GLenum target, GLsizeiptr size, const void* data, GLenum usage) {
        if (data) ++counts_.uploads;
        counted(&HostGlCounts::allocations, BufferData, target, size, data, usage);
    }
    void readPixels(GLint x, GLint y, GLsizei w, GLsizei h, GLenum format, GLenum type, void* data) {
        counted(&HostGlCounts::readbacks, ReadPixels, x, y, w, h, format, type, data);
    }
    // Deleting name 0 is no call and no count; the name is 0 afterwards.
    void deleteTexture(GLuint& name) { release(DeleteTextures, name); }
    void deleteSampler(GLuint& name) { release(DeleteSamplers, name); }
    void deleteFramebuffer(GLuint& name) { release(DeleteFramebuffers, name); }
    void deleteBuffer(GLuint& name) { release(DeleteBuffers, name); }
    void deleteVertexArray(GLuint& name) { release(DeleteVertexArrays, name); }
    void deleteProgram(GLuint& name) {
        if (name != 0) counted(&HostGlCounts::objectsDeleted, DeleteProgram, name);
        name = 0;
    }

    const HostGlCounts& counts() const { return counts_; }

    // Debug mode: every checkErrors() call that finds a GL error records "<where>: 0x...".
    // The host checks before each call into the SDK, which clears errors left pending.
    void checkErrors(const char* where);
    std::string takeErrors();

private:
    ENGINE_GL_COUNTED_FUNCTIONS(ENGINE_GL_MEMBER)
#undef ENGINE_GL_MEMBER

    // The one counting wrapper: counts the call in `counter`, then makes it.
    template <class Fn, class... Args>
    auto counted(uint64_t HostGlCounts::*counter, Fn fn, Args... args) -> decltype(fn(args...)) {
        ++(counts_.*counter);
        return fn(args...);
    }
    // glGen* and glDelete* of one name.
    template <class Gen>
    GLuint generate(Gen gen) {
        GLuint name = 0;
        counted(&HostGlCounts::objectsCreated, gen, 1, &name);
        return name;
    }
    template <class Delete>
    void release(Delete del, GLuint& name) {
        if (name != 0) counted(&HostGlCounts::objectsDeleted, del, 1, &name);
        name = 0;
    }

    HostGlCounts counts_;
    std::string errors_;
};

}  // namespace engine_gl
