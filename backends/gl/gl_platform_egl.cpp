// EGL platform: a surfaceless display (EGL_MESA_platform_surfaceless) and a context with no
// surface (EGL_KHR_surfaceless_context); the driver renders only into framebuffer objects.
#define EGL_NO_X11 1
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstring>
#include <mutex>
#include <string>

#include "gl_platform.hpp"

namespace sfx::gl {
namespace {

std::string eglErrorText(const char* what) {
    char hex[16];
    std::snprintf(hex, sizeof(hex), "0x%04x", unsigned(eglGetError()));
    return std::string(what) + " failed (EGL error " + hex + ")";
}

bool hasExtension(const char* list, const char* name) {
    if (!list) return false;
    const size_t n = std::strlen(name);
    for (const char* p = list; (p = std::strstr(p, name)) != nullptr; p += n)
        if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
    return false;
}

// Every surfaceless display handle is the same object, so eglTerminate would end the other
// devices' contexts too: count the users and terminate with the last one.
std::mutex gDisplayMutex;
int gDisplayUsers = 0;

void releaseDisplay(EGLDisplay display) {
    std::lock_guard<std::mutex> lock(gDisplayMutex);
    if (--gDisplayUsers == 0) eglTerminate(display);
}

class EglPlatform final : public GlPlatform {
public:
    EglPlatform(EGLDisplay display, EGLContext context, EGLenum api) : display_(display), context_(context), api_(api) {}
    ~EglPlatform() override {
        eglBindAPI(api_);
        if (eglGetCurrentContext() == context_) eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(display_, context_);
        releaseDisplay(display_);
    }
    bool makeCurrent() override {
        // The current context is per client API in EGL; bind ours before making it current.
        return eglBindAPI(api_) && eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_);
    }
    void release() override {
        eglBindAPI(api_);
        eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    }
    void* getProcAddress(const char* name) override { return reinterpret_cast<void*>(eglGetProcAddress(name)); }
    const char* name() const override { return "egl"; }

private:
    EGLDisplay display_;
    EGLContext context_;
    EGLenum api_;
};

struct Version {
    int major, minor;
};

}  // namespace

Result<std::unique_ptr<GlPlatform>> openEglPlatform(Api api, bool debugContext) {
    const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (!hasExtension(clientExtensions, "EGL_MESA_platform_surfaceless"))
        return Status{StatusCode::BackendUnavailable, "EGL: the client has no EGL_MESA_platform_surfaceless"};
    auto getPlatformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (!getPlatformDisplay) return Status{StatusCode::BackendUnavailable, "EGL: no eglGetPlatformDisplayEXT"};
    EGLDisplay display = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (display == EGL_NO_DISPLAY) return Status{StatusCode::BackendUnavailable, "EGL: " + eglErrorText("eglGetPlatformDisplayEXT(surfaceless)")};
    {
        std::lock_guard<std::mutex> lock(gDisplayMutex);
        EGLint major = 0, minor = 0;
        if (!eglInitialize(display, &major, &minor)) return Status{StatusCode::BackendUnavailable, "EGL: " + eglErrorText("eglInitialize")};
        ++gDisplayUsers;
    }
    auto fail = [&](const std::string& why) -> Result<std::unique_ptr<GlPlatform>> {
        releaseDisplay(display);
        return Status{StatusCode::BackendUnavailable, "EGL: " + why};
    };
    const char* displayExtensions = eglQueryString(display, EGL_EXTENSIONS);
    if (!hasExtension(displayExtensions, "EGL_KHR_surfaceless_context")) return fail("the display has no EGL_KHR_surfaceless_context");

    const bool es = api == Api::GLES;
    const EGLenum eglApi = es ? EGL_OPENGL_ES_API : EGL_OPENGL_API;
    if (!eglBindAPI(eglApi)) return fail(eglErrorText(es ? "eglBindAPI(EGL_OPENGL_ES_API)" : "eglBindAPI(EGL_OPENGL_API)"));

    // A pbuffer-capable config where there is one; surfaceless Mesa may offer configs of no
    // surface type, and EGL_KHR_no_config_context needs none at all.
    const EGLint renderable = es ? EGL_OPENGL_ES3_BIT : EGL_OPENGL_BIT;
    EGLConfig config = nullptr;
    EGLint count = 0;
    const EGLint withPbuffer[] = {EGL_RENDERABLE_TYPE, renderable, EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_NONE};
    const EGLint anySurface[] = {EGL_RENDERABLE_TYPE, renderable, EGL_SURFACE_TYPE, EGL_DONT_CARE, EGL_NONE};
    if (!eglChooseConfig(display, withPbuffer, &config, 1, &count) || count == 0) {
        count = 0;
        if (!eglChooseConfig(display, anySurface, &config, 1, &count) || count == 0) {
            if (!hasExtension(displayExtensions, "EGL_KHR_no_config_context"))
                return fail(std::string("no config renders ") + (es ? "GL ES 3" : "desktop GL"));
            config = EGL_NO_CONFIG_KHR;
        }
    }

    // Newest first: the ceiling only narrows what the driver reports, the context stays modern.
    const Version esVersions[] = {{3, 2}, {3, 1}, {3, 0}};
    const Version glVersions[] = {{4, 6}, {4, 5}, {4, 3}, {3, 3}};
    const Version* versions = es ? esVersions : glVersions;
    const size_t versionCount = es ? std::size(esVersions) : std::size(glVersions);
    EGLContext context = EGL_NO_CONTEXT;
    // A driver may refuse debug contexts: then take a plain one (only KHR_debug output is lost).
    for (size_t attempt = 0; attempt < versionCount * 2 && context == EGL_NO_CONTEXT; ++attempt) {
        const size_t i = attempt % versionCount;
        const bool debug = debugContext && attempt < versionCount;
        if (attempt >= versionCount && !debugContext) break;
        EGLint attribs[16];
        int n = 0;
        attribs[n++] = EGL_CONTEXT_MAJOR_VERSION;
        attribs[n++] = versions[i].major;
        attribs[n++] = EGL_CONTEXT_MINOR_VERSION;
        attribs[n++] = versions[i].minor;
        if (!es) {
            attribs[n++] = EGL_CONTEXT_OPENGL_PROFILE_MASK;
            attribs[n++] = EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT;
        }
        if (debug) {
            attribs[n++] = EGL_CONTEXT_OPENGL_DEBUG;
            attribs[n++] = EGL_TRUE;
        }
        attribs[n++] = EGL_NONE;
        context = eglCreateContext(display, config, EGL_NO_CONTEXT, attribs);
    }
    if (context == EGL_NO_CONTEXT) return fail(eglErrorText(es ? "eglCreateContext(GL ES 3.x)" : "eglCreateContext(desktop GL core 3.3+)"));
    if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
        std::string why = eglErrorText("eglMakeCurrent(surfaceless)");
        eglDestroyContext(display, context);
        return fail(why);
    }
    return std::unique_ptr<GlPlatform>(new EglPlatform(display, context, eglApi));
}

}  // namespace sfx::gl
