// OSMesa platform: Mesa's off-screen software context, desktop GL core only. It is made
// current on a 1x1 dummy buffer; the driver renders only into framebuffer objects.
// libOSMesa is opened at run time rather than linked, as the Vulkan loader is: an application
// that never asks for this platform does not depend on Mesa's software rasteriser (and its
// LLVM), and its absence is a status.
#include <GL/osmesa.h>
#include <dlfcn.h>

#include <cstdint>
#include <string>

#include "gl_platform.hpp"

namespace sfx::gl {
namespace {

struct OsmesaFunctions {
    decltype(&OSMesaCreateContextAttribs) createContextAttribs = nullptr;
    decltype(&OSMesaDestroyContext) destroyContext = nullptr;
    decltype(&OSMesaMakeCurrent) makeCurrent = nullptr;
    decltype(&OSMesaGetCurrentContext) getCurrentContext = nullptr;
    decltype(&OSMesaGetProcAddress) getProcAddress = nullptr;
    std::string error;  // empty when every entry point was found
};

// The first entry point missing is the one the error names.
template <typename Fn>
void loadSymbol(void* library, const char* name, Fn* out, std::string& error) {
    *out = reinterpret_cast<Fn>(dlsym(library, name));
    if (!*out && error.empty()) error = std::string("OSMesa: libOSMesa.so.8 has no ") + name;
}

// Opened once per process and never closed: contexts made current on any thread keep Mesa's
// state alive, and a function-local static makes the first call thread-safe.
const OsmesaFunctions& osmesa() {
    static const OsmesaFunctions functions = [] {
        OsmesaFunctions f;
        void* library = dlopen("libOSMesa.so.8", RTLD_NOW | RTLD_LOCAL);
        if (!library) {
            const char* why = dlerror();
            f.error = std::string("OSMesa: libOSMesa.so.8 (package libosmesa6) could not be opened: ") + (why ? why : "no reason given");
            return f;
        }
        loadSymbol(library, "OSMesaCreateContextAttribs", &f.createContextAttribs, f.error);
        loadSymbol(library, "OSMesaDestroyContext", &f.destroyContext, f.error);
        loadSymbol(library, "OSMesaMakeCurrent", &f.makeCurrent, f.error);
        loadSymbol(library, "OSMesaGetCurrentContext", &f.getCurrentContext, f.error);
        loadSymbol(library, "OSMesaGetProcAddress", &f.getProcAddress, f.error);
        return f;
    }();
    return functions;
}

class OsmesaPlatform final : public GlPlatform {
public:
    OsmesaPlatform(const OsmesaFunctions& f, OSMesaContext context) : f_(f), context_(context) {}
    ~OsmesaPlatform() override {
        release();
        f_.destroyContext(context_);
    }
    bool makeCurrent() override { return f_.makeCurrent(context_, dummy_, GL_UNSIGNED_BYTE, 1, 1); }
    void release() override {
        if (f_.getCurrentContext() == context_) f_.makeCurrent(nullptr, nullptr, 0, 0, 0);
    }
    void* getProcAddress(const char* name) override { return reinterpret_cast<void*>(f_.getProcAddress(name)); }
    const char* name() const override { return "osmesa"; }

private:
    const OsmesaFunctions& f_;
    OSMesaContext context_;
    uint32_t dummy_[1] = {0};  // the 1x1 RGBA colour buffer OSMesa insists on
};

}  // namespace

Result<std::unique_ptr<GlPlatform>> openOsmesaPlatform(Api api) {
    if (api != Api::DesktopGL) return Status{StatusCode::BackendUnavailable, "OSMesa offers desktop GL only, not GL ES"};
    const OsmesaFunctions& f = osmesa();
    if (!f.error.empty()) return Status{StatusCode::BackendUnavailable, f.error};
    const int versions[][2] = {{4, 5}, {4, 3}, {3, 3}};
    OSMesaContext context = nullptr;
    for (const auto& v : versions) {
        const int attribs[] = {OSMESA_FORMAT,
                               OSMESA_RGBA,
                               OSMESA_DEPTH_BITS,
                               0,
                               OSMESA_STENCIL_BITS,
                               0,
                               OSMESA_ACCUM_BITS,
                               0,
                               OSMESA_PROFILE,
                               OSMESA_CORE_PROFILE,
                               OSMESA_CONTEXT_MAJOR_VERSION,
                               v[0],
                               OSMESA_CONTEXT_MINOR_VERSION,
                               v[1],
                               0};
        context = f.createContextAttribs(attribs, nullptr);
        if (context) break;
    }
    if (!context) return Status{StatusCode::BackendUnavailable, "OSMesa: OSMesaCreateContextAttribs found no core context 3.3+"};
    auto platform = std::make_unique<OsmesaPlatform>(f, context);
    if (!platform->makeCurrent()) return Status{StatusCode::BackendUnavailable, "OSMesa: OSMesaMakeCurrent failed"};
    return std::unique_ptr<GlPlatform>(std::move(platform));
}

}  // namespace sfx::gl
