// The host's own EGL display and context: a surfaceless display (EGL_MESA_platform_surfaceless)
// and a context without a surface (EGL_KHR_surfaceless_context); the renderer draws only into
// its own framebuffer objects. GL ES 3.x, or desktop GL 3.3+ core through EGL_OPENGL_API.
#pragma once

#include <memory>
#include <string>

#include "sfx/status.hpp"

namespace engine_gl {

enum class ContextApi { GLES, DesktopGL };
const char* toString(ContextApi api);  // "gles", "gl"

class EglContext {
public:
    // BackendUnavailable with the reason when there is no EGL, no surfaceless platform, or no
    // context of the API (the test skips on it).
    static sfx::Result<std::unique_ptr<EglContext>> open(ContextApi api);
    ~EglContext();
    EglContext(const EglContext&) = delete;
    EglContext& operator=(const EglContext&) = delete;

    // Makes the context current on the calling thread (again, after another context was).
    bool makeCurrent();
    ContextApi api() const { return api_; }
    // eglGetProcAddress: the loader both the renderer and sfx::gl::wrapCurrentContext use.
    static void* getProcAddress(const char* name);

private:
    EglContext(void* display, void* context, ContextApi api) : display_(display), context_(context), api_(api) {}
    void* display_;
    void* context_;
    ContextApi api_;
};

}  // namespace engine_gl
