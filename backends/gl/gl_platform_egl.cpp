// EGL platform: a display with no window system and a context with no surface
// (EGL_KHR_surfaceless_context); the driver renders only into framebuffer objects. The display
// is the first of these that gives such a context:
//   - surfaceless: EGL_MESA_platform_surfaceless (Mesa, every driver this project is tested on);
//   - device: the first EGL device (EGL_EXT_platform_device), how NVIDIA's drivers run headless,
//     with no surfaceless platform;
//   - default: eglGetDisplay(EGL_DEFAULT_DISPLAY), the one display of Android and similar systems.
// SFX_EGL_PLATFORM=surfaceless|device|default in the environment tries that one alone.
#define EGL_NO_X11 1
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdlib>
#include <cstring>
#include <map>
#include <mutex>
#include <string>
#include <vector>

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

// Every display handle of a kind is the same object, so eglTerminate would end the other
// devices' contexts too: count each display's users and terminate with the last one.
std::mutex gDisplayMutex;
std::map<EGLDisplay, int> gDisplayUsers;

void releaseDisplay(EGLDisplay display) {
    std::lock_guard<std::mutex> lock(gDisplayMutex);
    if (--gDisplayUsers[display] == 0) {
        gDisplayUsers.erase(display);
        eglTerminate(display);
    }
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

enum class DisplayKind { Surfaceless, Device, Default };
constexpr DisplayKind kDisplayKinds[] = {DisplayKind::Surfaceless, DisplayKind::Device, DisplayKind::Default};

const char* toString(DisplayKind kind) {
    switch (kind) {
        case DisplayKind::Surfaceless: return "surfaceless";
        case DisplayKind::Device: return "device";
        case DisplayKind::Default: return "default";
    }
    return "?";
}

Status unavailable(const std::string& why) { return Status{StatusCode::BackendUnavailable, why}; }

// The display of `kind`, not yet initialised, or why there is none.
Result<EGLDisplay> findDisplay(DisplayKind kind) {
    const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    auto getPlatformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
    EGLDisplay display = EGL_NO_DISPLAY;
    switch (kind) {
        case DisplayKind::Surfaceless:
            if (!hasExtension(clientExtensions, "EGL_MESA_platform_surfaceless"))
                return unavailable("the client has no EGL_MESA_platform_surfaceless");
            if (!getPlatformDisplay) return unavailable("no eglGetPlatformDisplayEXT");
            display = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
            if (display == EGL_NO_DISPLAY) return unavailable(eglErrorText("eglGetPlatformDisplayEXT(surfaceless)"));
            return display;
        case DisplayKind::Device: {
            if (!hasExtension(clientExtensions, "EGL_EXT_platform_device")) return unavailable("the client has no EGL_EXT_platform_device");
            auto queryDevices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
            if (!queryDevices || !getPlatformDisplay) return unavailable("no eglQueryDevicesEXT or eglGetPlatformDisplayEXT");
            EGLDeviceEXT device = nullptr;
            EGLint count = 0;
            if (!queryDevices(1, &device, &count) || count < 1) return unavailable("eglQueryDevicesEXT found no device");
            display = getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, device, nullptr);
            if (display == EGL_NO_DISPLAY) return unavailable(eglErrorText("eglGetPlatformDisplayEXT(device)"));
            return display;
        }
        case DisplayKind::Default:
            display = eglGetDisplay(EGL_DEFAULT_DISPLAY);
            if (display == EGL_NO_DISPLAY) return unavailable("eglGetDisplay(EGL_DEFAULT_DISPLAY) gave no display");
            return display;
    }
    return unavailable("unknown display kind");
}

// A context of `api` with no surface on the display of `kind`.
Result<std::unique_ptr<GlPlatform>> openOn(DisplayKind kind, Api api, bool debugContext) {
    Result<EGLDisplay> found = findDisplay(kind);
    if (!found) return found.status();
    const EGLDisplay display = found.value();
    {
        std::lock_guard<std::mutex> lock(gDisplayMutex);
        EGLint major = 0, minor = 0;
        if (!eglInitialize(display, &major, &minor)) return unavailable(eglErrorText("eglInitialize"));
        ++gDisplayUsers[display];
    }
    auto fail = [&](const std::string& why) -> Result<std::unique_ptr<GlPlatform>> {
        releaseDisplay(display);
        return unavailable(why);
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

}  // namespace

Result<std::unique_ptr<GlPlatform>> openEglPlatform(Api api, bool debugContext) {
    std::vector<DisplayKind> kinds(std::begin(kDisplayKinds), std::end(kDisplayKinds));
    if (const char* forced = std::getenv("SFX_EGL_PLATFORM"); forced && *forced) {
        kinds.clear();
        for (DisplayKind k : kDisplayKinds)
            if (std::strcmp(forced, toString(k)) == 0) kinds.push_back(k);
        if (kinds.empty())
            return unavailable(std::string("EGL: SFX_EGL_PLATFORM is '") + forced +
                               "'; allowed surfaceless, device, default (or unset: each in turn)");
    }
    std::string reasons;
    for (DisplayKind kind : kinds) {
        Result<std::unique_ptr<GlPlatform>> platform = openOn(kind, api, debugContext);
        if (platform) return platform;
        reasons += (reasons.empty() ? "" : "; ") + std::string(toString(kind)) + " display: " + platform.status().message();
    }
    return unavailable("EGL: " + reasons);
}

}  // namespace sfx::gl
