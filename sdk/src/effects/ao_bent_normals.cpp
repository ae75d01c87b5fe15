// Bent normals of the horizon technique (AoSettings.bentNormals): the check of the host's target.
// The passes are ao.cpp's and ao_half_res.cpp's, with their programs' bent variants.
#include <string>

#include "ao_internal.hpp"
#include "sfx/ao.hpp"

namespace sfx::detail {

Result<Format> checkBentNormalsInput(Device& device, TextureHandle texture, uint32_t width, uint32_t height) {
    const char* allowed = "RGBA8 (xyz * 0.5 + 0.5), RGBA16F or RGBA32F (signed xyz), renderable on the device";
    if (texture.isNull()) return invalidArgument("AoInputs.bentNormals", "null (AoSettings.bentNormals is on)", std::string("a texture: ") + allowed);
    Result<TextureDesc> d = device.textureDesc(texture);
    if (!d) return invalidArgument("AoInputs.bentNormals", d.status().message(), std::string("a live texture: ") + allowed);
    if (d->width != width || d->height != height)
        return invalidArgument("AoInputs.bentNormals size", std::to_string(d->width) + "x" + std::to_string(d->height),
                               std::to_string(width) + "x" + std::to_string(height) + " (the AO size)");
    const bool formatOk = d->format == Format::RGBA8 || d->format == Format::RGBA16F || d->format == Format::RGBA32F;
    if (!formatOk || !device.caps().renderableFormat[size_t(d->format)])
        return invalidArgument("AoInputs.bentNormals format", toString(d->format), allowed);
    if (!(d->usage & kTextureRenderTarget)) return invalidArgument("AoInputs.bentNormals usage", "without kTextureRenderTarget", "a render target");
    return d->format;
}

}  // namespace sfx::detail
