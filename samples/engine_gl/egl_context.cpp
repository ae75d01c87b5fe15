#include "egl_context.hpp"

#define EGL_NO_X11 1
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdio>
#include <cstring>

namespace engine_gl {
namespace {

sfx::Status unavailable(const std::string& why) { return {sfx::StatusCode::BackendUnavailable, "engine_gl EGL: " + why}; }

std::string eglFailed(const char* call) {
    char hex[16];
    std::snprintf(hex, sizeof hex, "0x%04x", unsigned(eglGetError()));
    return std::string(call) + " failed (EGL error " + hex + ")";
}

bool hasExtension(const char* list, const char* name) {
    if (!list) return false;
    const size_t n = std::strlen(name);
    for (const char* p = list; (p = std::strstr(p, name)) != nullptr; p += n)
        if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
    return false;
}

EGLenum eglApi(ContextApi api) { return api == ContextApi::GLES ? EGL_OPENGL_ES_API : EGL_OPENGL_API; }

// A display with no window system: Mesa's surfaceless platform where the client has it, else the
// first EGL device (how NVIDIA's drivers run headless). EGL_NO_DISPLAY when neither is there.
EGLDisplay headlessDisplay() {
    const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    auto getPlatformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (!getPlatformDisplay) return EGL_NO_DISPLAY;
    if (hasExtension(client, "EGL_MESA_platform_surfaceless")) return getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    auto queryDevices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
    EGLDeviceEXT first = nullptr;
    EGLint found = 0;
    if (hasExtension(client, "EGL_EXT_platform_device") && queryDevices && queryDevices(1, &first, &found) && found > 0)
        return getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, first, nullptr);
    return EGL_NO_DISPLAY;
}

}  // namespace

const char* toString(ContextApi api) { return api == ContextApi::GLES ? "gles" : "gl"; }

void* EglContext::getProcAddress(const char* name) { return reinterpret_cast<void*>(eglGetProcAddress(name)); }

sfx::Result<std::unique_ptr<EglContext>> EglContext::open(ContextApi api) {
    EGLDisplay display = headlessDisplay();
    if (display == EGL_NO_DISPLAY)
        return unavailable("the EGL client has neither EGL_MESA_platform_surfaceless nor an EGL device (EGL_EXT_platform_device)");
    EGLint major = 0, minor = 0;
    if (!eglInitialize(display, &major, &minor)) return unavailable(eglFailed("eglInitialize"));
    // The display is one object per process: it is not terminated here, so that an SDK device
    // (or anyone else) using it keeps working after this context is gone.
    if (!hasExtension(eglQueryString(display, EGL_EXTENSIONS), "EGL_KHR_surfaceless_context"))
        return unavailable("the display has no EGL_KHR_surfaceless_context");
    if (!eglBindAPI(eglApi(api))) return unavailable(eglFailed("eglBindAPI"));

    const EGLint renderable = api == ContextApi::GLES ? EGL_OPENGL_ES3_BIT : EGL_OPENGL_BIT;
    const EGLint configAttribs[] = {EGL_RENDERABLE_TYPE, renderable, EGL_SURFACE_TYPE, EGL_DONT_CARE, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint count = 0;
    if (!eglChooseConfig(display, configAttribs, &config, 1, &count) || count == 0)
        return unavailable(std::string("no EGL config renders ") + (api == ContextApi::GLES ? "GL ES 3" : "desktop GL"));

    struct Version {
        EGLint major, minor;
    };
    // Newest first: a driver gives the newest it has.
    constexpr size_t kVersions = 3;
    const Version es[kVersions] = {{3, 2}, {3, 1}, {3, 0}};
    const Version desktop[kVersions] = {{4, 5}, {4, 3}, {3, 3}};
    EGLContext context = EGL_NO_CONTEXT;
    for (size_t i = 0; i < kVersions && context == EGL_NO_CONTEXT; ++i) {
        const Version v = api == ContextApi::GLES ? es[i] : desktop[i];
        EGLint attribs[8] = {EGL_CONTEXT_MAJOR_VERSION, v.major, EGL_CONTEXT_MINOR_VERSION, v.minor, EGL_NONE, EGL_NONE, EGL_NONE};
        if (api == ContextApi::DesktopGL) {
            attribs[4] = EGL_CONTEXT_OPENGL_PROFILE_MASK;
            attribs[5] = EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT;
        }
        context = eglCreateContext(display, config, EGL_NO_CONTEXT, attribs);
    }
    if (context == EGL_NO_CONTEXT) return unavailable(eglFailed("eglCreateContext"));
    std::unique_ptr<EglContext> out(new EglContext(display, context, api));
    if (!out->makeCurrent()) return unavailable(eglFailed("eglMakeCurrent(surfaceless)"));
    return out;
}

bool EglContext::makeCurrent() { return eglBindAPI(eglApi(api_)) && eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_); }

EglContext::~EglContext() {
    eglBindAPI(eglApi(api_));
    if (eglGetCurrentContext() == context_) eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display_, context_);
}

}  // namespace engine_gl
