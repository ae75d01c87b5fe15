// The GL entry points the driver uses, loaded per device through its platform's
// GetProcAddress. glcorearb.h supplies only types, enums and PFN typedefs: nothing links
// against libGL or libGLESv2 (see CMakeLists.txt).
#pragma once

#include <GL/glcorearb.h>

namespace sfx::gl {

// Present in GL ES 3.0 and desktop GL 3.3 core: a device is refused without any of them.
// clang-format off
#define SFX_GL_REQUIRED(X)                                              \
    X(PFNGLGETERRORPROC, glGetError)                                    \
    X(PFNGLGETSTRINGPROC, glGetString)                                  \
    X(PFNGLGETSTRINGIPROC, glGetStringi)                                \
    X(PFNGLGETINTEGERVPROC, glGetIntegerv)                              \
    X(PFNGLGETINTEGER64VPROC, glGetInteger64v)                          \
    X(PFNGLGETINTEGERI_VPROC, glGetIntegeri_v)                          \
    X(PFNGLENABLEPROC, glEnable)                                        \
    X(PFNGLDISABLEPROC, glDisable)                                      \
    X(PFNGLFINISHPROC, glFinish)                                        \
    X(PFNGLGENTEXTURESPROC, glGenTextures)                              \
    X(PFNGLDELETETEXTURESPROC, glDeleteTextures)                        \
    X(PFNGLISTEXTUREPROC, glIsTexture)                                  \
    X(PFNGLBINDTEXTUREPROC, glBindTexture)                              \
    X(PFNGLACTIVETEXTUREPROC, glActiveTexture)                          \
    X(PFNGLTEXSTORAGE2DPROC, glTexStorage2D)                            \
    X(PFNGLTEXSUBIMAGE2DPROC, glTexSubImage2D)                          \
    X(PFNGLTEXPARAMETERIPROC, glTexParameteri)                          \
    X(PFNGLPIXELSTOREIPROC, glPixelStorei)                              \
    X(PFNGLGENFRAMEBUFFERSPROC, glGenFramebuffers)                      \
    X(PFNGLDELETEFRAMEBUFFERSPROC, glDeleteFramebuffers)                \
    X(PFNGLBINDFRAMEBUFFERPROC, glBindFramebuffer)                      \
    X(PFNGLFRAMEBUFFERTEXTURE2DPROC, glFramebufferTexture2D)            \
    X(PFNGLCHECKFRAMEBUFFERSTATUSPROC, glCheckFramebufferStatus)        \
    X(PFNGLDRAWBUFFERSPROC, glDrawBuffers)                              \
    X(PFNGLREADBUFFERPROC, glReadBuffer)                                \
    X(PFNGLREADPIXELSPROC, glReadPixels)                                \
    X(PFNGLVIEWPORTPROC, glViewport)                                    \
    X(PFNGLCOLORMASKPROC, glColorMask)                                  \
    X(PFNGLDEPTHMASKPROC, glDepthMask)                                  \
    X(PFNGLDEPTHFUNCPROC, glDepthFunc)                                  \
    X(PFNGLBLENDFUNCPROC, glBlendFunc)                                  \
    X(PFNGLBLENDFUNCSEPARATEPROC, glBlendFuncSeparate)                  \
    X(PFNGLCULLFACEPROC, glCullFace)                                    \
    X(PFNGLFRONTFACEPROC, glFrontFace)                                  \
    X(PFNGLCLEARBUFFERFVPROC, glClearBufferfv)                          \
    X(PFNGLCLEARBUFFERUIVPROC, glClearBufferuiv)                        \
    X(PFNGLCLEARBUFFERFIPROC, glClearBufferfi)                          \
    X(PFNGLGENBUFFERSPROC, glGenBuffers)                                \
    X(PFNGLDELETEBUFFERSPROC, glDeleteBuffers)                          \
    X(PFNGLBINDBUFFERPROC, glBindBuffer)                                \
    X(PFNGLBUFFERDATAPROC, glBufferData)                                \
    X(PFNGLBUFFERSUBDATAPROC, glBufferSubData)                          \
    X(PFNGLBINDBUFFERRANGEPROC, glBindBufferRange)                      \
    X(PFNGLMAPBUFFERRANGEPROC, glMapBufferRange)                        \
    X(PFNGLUNMAPBUFFERPROC, glUnmapBuffer)                              \
    X(PFNGLGENSAMPLERSPROC, glGenSamplers)                              \
    X(PFNGLDELETESAMPLERSPROC, glDeleteSamplers)                        \
    X(PFNGLSAMPLERPARAMETERIPROC, glSamplerParameteri)                  \
    X(PFNGLBINDSAMPLERPROC, glBindSampler)                              \
    X(PFNGLCREATESHADERPROC, glCreateShader)                            \
    X(PFNGLSHADERSOURCEPROC, glShaderSource)                            \
    X(PFNGLCOMPILESHADERPROC, glCompileShader)                          \
    X(PFNGLGETSHADERIVPROC, glGetShaderiv)                              \
    X(PFNGLGETSHADERINFOLOGPROC, glGetShaderInfoLog)                    \
    X(PFNGLDELETESHADERPROC, glDeleteShader)                            \
    X(PFNGLCREATEPROGRAMPROC, glCreateProgram)                          \
    X(PFNGLATTACHSHADERPROC, glAttachShader)                            \
    X(PFNGLLINKPROGRAMPROC, glLinkProgram)                              \
    X(PFNGLGETPROGRAMIVPROC, glGetProgramiv)                            \
    X(PFNGLGETPROGRAMINFOLOGPROC, glGetProgramInfoLog)                  \
    X(PFNGLDELETEPROGRAMPROC, glDeleteProgram)                          \
    X(PFNGLUSEPROGRAMPROC, glUseProgram)                                \
    X(PFNGLGETUNIFORMLOCATIONPROC, glGetUniformLocation)                \
    X(PFNGLUNIFORM1IPROC, glUniform1i)                                  \
    X(PFNGLGETUNIFORMBLOCKINDEXPROC, glGetUniformBlockIndex)            \
    X(PFNGLUNIFORMBLOCKBINDINGPROC, glUniformBlockBinding)              \
    X(PFNGLGENVERTEXARRAYSPROC, glGenVertexArrays)                      \
    X(PFNGLDELETEVERTEXARRAYSPROC, glDeleteVertexArrays)                \
    X(PFNGLBINDVERTEXARRAYPROC, glBindVertexArray)                      \
    X(PFNGLENABLEVERTEXATTRIBARRAYPROC, glEnableVertexAttribArray)      \
    X(PFNGLVERTEXATTRIBPOINTERPROC, glVertexAttribPointer)              \
    X(PFNGLDRAWARRAYSINSTANCEDPROC, glDrawArraysInstanced)              \
    X(PFNGLDRAWELEMENTSINSTANCEDPROC, glDrawElementsInstanced)
// clang-format on

// GL ES 3.1 / desktop GL 4.3 (compute, storage) and KHR_debug: used only when the version or
// extension says so, since glvnd's eglGetProcAddress returns a stub for any name.
// clang-format off
#define SFX_GL_OPTIONAL(X)                                              \
    X(PFNGLDISPATCHCOMPUTEPROC, glDispatchCompute)                      \
    X(PFNGLMEMORYBARRIERPROC, glMemoryBarrier)                          \
    X(PFNGLBINDIMAGETEXTUREPROC, glBindImageTexture)                    \
    X(PFNGLGETPROGRAMRESOURCEINDEXPROC, glGetProgramResourceIndex)      \
    X(PFNGLSHADERSTORAGEBLOCKBINDINGPROC, glShaderStorageBlockBinding)  \
    X(PFNGLDEBUGMESSAGECALLBACKPROC, glDebugMessageCallback)            \
    X(PFNGLDEBUGMESSAGECONTROLPROC, glDebugMessageControl)
// clang-format on

struct GlFunctions {
#define SFX_GL_MEMBER(type, name) type name = nullptr;
    SFX_GL_REQUIRED(SFX_GL_MEMBER)
    SFX_GL_OPTIONAL(SFX_GL_MEMBER)
#undef SFX_GL_MEMBER
};

}  // namespace sfx::gl
