// What the GL driver needs of a platform (EGL, OSMesa, a host's context): a context to make
// current and a way to load entry points. Internal to the GL backend.
#pragma once

#include <memory>
#include <string>

#include "sfx/gl_device.hpp"

namespace sfx::gl {

class GlPlatform {
public:
    virtual ~GlPlatform() = default;  // destroys the context when the platform owns it
    virtual bool makeCurrent() = 0;
    // Leaves no context of this platform current, so that another platform's can be made
    // current: EGL and OSMesa share Mesa's dispatch, so a stale one would take our calls.
    virtual void release() = 0;
    virtual void* getProcAddress(const char* name) = 0;
    virtual const char* name() const = 0;  // "egl", "osmesa", "host"
};

// Each opens a context of `api` (the newest version it can) or says why it cannot.
// `debugContext` asks for a KHR_debug context where the platform has one.
Result<std::unique_ptr<GlPlatform>> openEglPlatform(Api api, bool debugContext);
Result<std::unique_ptr<GlPlatform>> openOsmesaPlatform(Api api);
std::unique_ptr<GlPlatform> hostPlatform(GetProcAddressFn getProcAddress);

}  // namespace sfx::gl
