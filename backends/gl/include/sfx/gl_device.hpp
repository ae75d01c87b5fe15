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
Result<std::unique_ptr<Device>> wrapCurrentContext(GetProcAddressFn getProcAddress, Api api, const DeviceOptions& options);

// ---- Host textures in, SDK textures out (docs/integration.md, "Host images and the state contract")

// A host GL texture the SDK may read or write as a texture: depth, normals, colour, velocity or
// an effect's output. It must be a complete GL_TEXTURE_2D of the device's context (or one
// sharing with it), with immutable storage (glTexStorage2D) of `mipLevels` levels or more.
struct ExternalTexture {
    uint32_t name = 0;         // the GL texture name
    uint32_t target = 0x0DE1;  // GL_TEXTURE_2D, the only target the SDK binds
    // Its format: either as sfx::Format or as the sized internal format it was made with (the
    // GL formats of the Formats: GL_R8, GL_RGBA8, GL_R16F, GL_RG16F, GL_RGBA16F, GL_R32F,
    // GL_RG32F, GL_RGBA32F, GL_R32UI, GL_DEPTH_COMPONENT16, GL_DEPTH24_STENCIL8,
    // GL_DEPTH_COMPONENT32F); when both are set they must name the same format.
    Format format = Format::Undefined;
    uint32_t internalFormat = 0;
    uint32_t width = 0, height = 0;    // of level 0
    uint32_t mipLevels = 1;            // the SDK uses levels [0, mipLevels)
    uint32_t usage = kTextureSampled;  // TextureUsage bits: what the SDK may do with it
    const char* debugName = "";
};

// A texture of the device for the host's GL texture. The SDK never deletes it: destroyTexture
// forgets it (and the framebuffers the SDK made with it). InvalidArgument naming the field and
// its allowed values for name 0 or not a texture, another target, a format outside the list, a
// size or usage the device cannot hold; InvalidArgument when `device` is not GL or GL ES.
Result<TextureHandle> importTexture(Device& device, const ExternalTexture& texture);

// The GL objects of a texture, imported or the SDK's own.
struct NativeTexture {
    uint32_t name = 0;
    uint32_t target = 0x0DE1;  // GL_TEXTURE_2D
    uint32_t internalFormat = 0;
};
Result<NativeTexture> nativeTexture(Device& device, TextureHandle texture);

}  // namespace sfx::gl
