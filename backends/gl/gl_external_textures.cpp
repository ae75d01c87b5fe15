// Host textures in, SDK textures out: importTexture wraps a host GL texture as a texture the SDK
// never deletes, nativeTexture gives the GL name of any texture. GL orders the SDK's passes
// after the host's commands by itself, so the state contract of an imported texture is only
// what the SDK changes on it (docs/integration.md, "Host images and the state contract").
#include <string>

#include "gl_driver.hpp"
#include "gl_formats.hpp"

#include "sfx/validation_errors.hpp"

namespace sfx::gl {
namespace {

constexpr uint32_t kTexture2D = 0x0DE1;  // GL_TEXTURE_2D
constexpr const char* kInternalFormats =
    "GL_R8, GL_RGBA8, GL_R16F, GL_RG16F, GL_RGBA16F, GL_R32F, GL_RG32F, GL_RGBA32F, GL_R32UI, "
    "GL_DEPTH_COMPONENT16, GL_DEPTH24_STENCIL8, GL_DEPTH_COMPONENT32F";

Result<Format> resolveFormat(const ExternalTexture& e) {
    if (e.internalFormat == 0) {
        if (e.format == Format::Undefined || uint32_t(e.format) >= uint32_t(Format::Count))
            return invalidArgument("ExternalTexture.format",
                                   e.format == Format::Undefined ? "Undefined (and internalFormat 0)" : std::to_string(uint32_t(e.format)),
                                   std::string("an sfx::Format other than Undefined, or internalFormat one of ") + kInternalFormats);
        return e.format;
    }
    Format mapped = Format::Undefined;
    for (uint32_t i = 1; i < uint32_t(Format::Count); ++i)
        if (glFormat(Format(i)).internalFormat == e.internalFormat) mapped = Format(i);
    if (mapped == Format::Undefined)
        return invalidArgument("ExternalTexture.internalFormat", "GLenum " + std::to_string(e.internalFormat), kInternalFormats);
    if (e.format != Format::Undefined && e.format != mapped)
        return invalidArgument("ExternalTexture.format", toString(e.format),
                               std::string("Undefined or the format of internalFormat (") + toString(mapped) + ")");
    return mapped;
}

GlDevice* glDevice(Device& device) { return dynamic_cast<GlDevice*>(&device); }

Status notGl(const char* call, const Device& device) {
    return validation::fail(validation::Error::DeviceWrongApi, {call, toString(device.caps().backend), "GL or GL ES"});
}

}  // namespace

Result<TextureHandle> GlDevice::importExternal(const ExternalTexture& e) {
    if (e.name == 0) return invalidArgument("ExternalTexture.name", "0", "the host's GL texture name");
    if (e.target != kTexture2D) return invalidArgument("ExternalTexture.target", "GLenum " + std::to_string(e.target), "GL_TEXTURE_2D (0x0DE1)");
    Result<Format> format = resolveFormat(e);
    if (!format) return format.status();
    TextureDesc desc{e.width, e.height, e.mipLevels, format.value(), e.usage, e.debugName ? e.debugName : ""};
    if (Status s = validation::textureDesc(desc, caps_); !s)
        return Status{s.code(), "importTexture (ExternalTexture as a TextureDesc): " + s.message()};
    SFX_TRY(enter());
    if (!gl_.glIsTexture(e.name))
        return invalidArgument("ExternalTexture.name", std::to_string(e.name),
                               "a texture of this context (or one sharing with it) that has been bound once");
    SFX_TRY(takeDeviceError(Status::ok()));
    return textures_.insert(GlTexture{desc, e.name, true});
}

Result<NativeTexture> GlDevice::native(TextureHandle h) const {
    SFX_TRY(textures_.check(h, "texture"));
    const GlTexture& t = textures_.get(h);
    return NativeTexture{t.name, kTexture2D, uint32_t(glFormat(t.desc.format).internalFormat)};
}

Result<TextureHandle> importTexture(Device& device, const ExternalTexture& texture) {
    GlDevice* gl = glDevice(device);
    if (!gl) return notGl("importTexture", device);
    return gl->importExternal(texture);
}

Result<NativeTexture> nativeTexture(Device& device, TextureHandle texture) {
    GlDevice* gl = glDevice(device);
    if (!gl) return notGl("nativeTexture", device);
    return gl->native(texture);
}

}  // namespace sfx::gl
