// OSMesa platform: Mesa's off-screen software context, desktop GL core only. It is made
// current on a 1x1 dummy buffer; the driver renders only into framebuffer objects.
#include <GL/osmesa.h>

#include <cstdint>
#include <string>

#include "gl_platform.hpp"

namespace sfx::gl {
namespace {

class OsmesaPlatform final : public GlPlatform {
public:
    explicit OsmesaPlatform(OSMesaContext context) : context_(context) {}
    ~OsmesaPlatform() override {
        if (OSMesaGetCurrentContext() == context_) OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
        OSMesaDestroyContext(context_);
    }
    bool makeCurrent() override { return OSMesaMakeCurrent(context_, dummy_, GL_UNSIGNED_BYTE, 1, 1); }
    void release() override {
        if (OSMesaGetCurrentContext() == context_) OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
    }
    void* getProcAddress(const char* name) override { return reinterpret_cast<void*>(OSMesaGetProcAddress(name)); }
    const char* name() const override { return "osmesa"; }

private:
    OSMesaContext context_;
    uint32_t dummy_[1] = {0};  // the 1x1 RGBA colour buffer OSMesa insists on
};

}  // namespace

Result<std::unique_ptr<GlPlatform>> openOsmesaPlatform(Api api) {
    if (api != Api::DesktopGL) return Status{StatusCode::BackendUnavailable, "OSMesa offers desktop GL only, not GL ES"};
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
        context = OSMesaCreateContextAttribs(attribs, nullptr);
        if (context) break;
    }
    if (!context) return Status{StatusCode::BackendUnavailable, "OSMesa: OSMesaCreateContextAttribs found no core context 3.3+"};
    auto platform = std::make_unique<OsmesaPlatform>(context);
    if (!platform->makeCurrent()) return Status{StatusCode::BackendUnavailable, "OSMesa: OSMesaMakeCurrent failed"};
    return std::unique_ptr<GlPlatform>(std::move(platform));
}

}  // namespace sfx::gl
