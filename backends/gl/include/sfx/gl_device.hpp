// The GL backend: GL ES 3.x and desktop GL core through one driver, on the EGL platform
// (surfaceless, no window system) or OSMesa (software, desktop GL only).
#pragma once

#include <memory>

#include "sfx/hal.hpp"

namespace sfx::gl {

enum class Platform { EGL, OSMesa };
enum class Api { GLES, DesktopGL };

// Opens its own context on `platform`. BackendUnavailable (with the reason) when the library,
// display or a context of the asked API cannot be had; OSMesa offers DesktopGL only.
Result<std::unique_ptr<Device>> createDevice(Platform platform, Api api, const DeviceOptions& options);

// A host engine's loader, e.g. eglGetProcAddress or glfwGetProcAddress.
using GetProcAddressFn = void* (*)(const char* name);

// Uses the GL context current on the calling thread, which the host owns: the SDK never makes
// another context current for it and never destroys it. The host keeps it current on this
// thread for every call into the device.
//
// State contract on a host context: after an SDK call the framebuffer binding is 0, no program
// or vertex array is bound, no SDK sampler or texture is left on the units it used, and
// PACK/UNPACK_ALIGNMENT are 1; viewport, blend, depth, cull, scissor and colour-mask state are
// the last pass's. The host re-establishes its own state after calling the SDK. The SDK does
// not install a debug callback on a host context (the host's stays), and GL errors pending from
// the host's own calls are cleared, not reported as the SDK call's failure.
Result<std::unique_ptr<Device>> wrapCurrentContext(GetProcAddressFn getProcAddress, Api api,
                                                   const DeviceOptions& options);

}  // namespace sfx::gl
