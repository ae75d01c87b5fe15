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

// Entry points that create GL objects or storage, upload or read back: counted.
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

// How often the host called what it must not call in a steady frame.
struct HostGlCounts {
    uint64_t objectsCreated = 0;   // glGen*, glCreateShader/Program
    uint64_t objectsDeleted = 0;   // glDelete*
    uint64_t allocations = 0;      // glTexStorage2D, glBufferData (new storage)
    uint64_t uploads = 0;          // glTexSubImage2D, glBufferData with data
    uint64_t readbacks = 0;        // glReadPixels
    bool operator==(const HostGlCounts&) const = default;
};

class HostGl {
public:
#define ENGINE_GL_MEMBER(type, name) type name = nullptr;
    ENGINE_GL_STATE_FUNCTIONS(ENGINE_GL_MEMBER)

    // Loads every entry point; empty on success, else the names that are missing.
    std::string load(GetProcAddress loader);

    // The counted calls.
    GLuint genTexture();
    GLuint genSampler();
    GLuint genFramebuffer();
    GLuint genBuffer();
    GLuint genVertexArray();
    GLuint createShader(GLenum type);
    GLuint createProgram();
    void texStorage2D(GLenum target, GLsizei levels, GLenum internalFormat, GLsizei w, GLsizei h);
    void texSubImage2D(GLenum target, GLint level, GLsizei w, GLsizei h, GLenum format, GLenum type, const void* data);
    void bufferData(GLenum target, GLsizeiptr size, const void* data, GLenum usage);
    void readPixels(GLint x, GLint y, GLsizei w, GLsizei h, GLenum format, GLenum type, void* data);
    void deleteTexture(GLuint& name);
    void deleteSampler(GLuint& name);
    void deleteFramebuffer(GLuint& name);
    void deleteBuffer(GLuint& name);
    void deleteVertexArray(GLuint& name);
    void deleteProgram(GLuint& name);

    const HostGlCounts& counts() const { return counts_; }

    // Debug mode: every checkErrors() call that finds a GL error records "<where>: 0x...".
    // The host checks before each call into the SDK, which clears errors left pending.
    void checkErrors(const char* where);
    std::string takeErrors();

private:
    ENGINE_GL_COUNTED_FUNCTIONS(ENGINE_GL_MEMBER)
#undef ENGINE_GL_MEMBER
    HostGlCounts counts_;
    std::string errors_;
};

}  // namespace engine_gl
