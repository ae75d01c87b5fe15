// Multilayer AO's part of the obscurance pass (AoSettings.depthLayers > 1): the checks of the
// host's extra depth layers and their bindings. The taps themselves are the technique's shader
// with the SFX_AO_MULTILAYER loop (sfx_shared_ao.h), which takes the largest per-tap term over
// the layers, as reference::multilayerVisibility does.
#include <string>

#include "ao_internal.hpp"
#include "sfx_shaders.hpp"
#include "sfx_shared_ao.h"

namespace sfx::detail {

Status checkDepthLayers(Device& device, const AoInputs& in, const AoConfig& config, uint32_t width, uint32_t height) {
    for (uint32_t layer = 1; layer < config.depthLayers; ++layer) {
        const std::string field = "AoInputs.depthLayers[" + std::to_string(layer - 1) + "]";
        const std::string why = " (AoSettings.depthLayers is " + std::to_string(config.depthLayers) + ")";
        Result<TextureDesc> d = device.textureDesc(in.depthLayers[layer - 1]);
        if (!d) return Status{d.status().code(), field + why + ": " + d.status().message()};
        if (d->width != width || d->height != height)
            return invalidArgument(field + " size", std::to_string(d->width) + "x" + std::to_string(d->height),
                                   std::to_string(width) + "x" + std::to_string(height) + " (the AO size)");
        if (d->format != Format::R32F)
            return {StatusCode::UnsupportedFormat, field + " format " + toString(d->format) + " is not allowed; R32F linear depth"};
        if (!(d->usage & kTextureSampled)) return invalidArgument(field + " usage", "without kTextureSampled", "a sampled texture");
    }
    return Status::ok();
}

void appendDepthLayerBindings(std::vector<TextureBinding>& bindings, const AoInputs& in, const AoConfig& config, const TierProfile& profile,
                              const TextureBinding& passDepth) {
    if (profile.aoMaxDepthLayers <= 1) return;  // the tier's programs declare no layer bindings
    const uint32_t slots[] = {gen::ao_scalable::uDepthLayer1, gen::ao_scalable::uDepthLayer2, gen::ao_scalable::uDepthLayer3};
    static_assert(sizeof(slots) / sizeof(slots[0]) == size_t(shared::SFX_AO_MAX_DEPTH_LAYERS) - 1);
    for (uint32_t layer = 1; layer < uint32_t(shared::SFX_AO_MAX_DEPTH_LAYERS); ++layer) {
        // Every declared sampler needs a texture: a layer the settings do not use gets the pass's
        // depth with its mip range (GL keeps one range per texture); the shader never reads it.
        TextureBinding b = passDepth;
        if (layer < config.depthLayers) b = TextureBinding{0, in.depthLayers[layer - 1], 0, 1, {}};
        b.binding = slots[layer - 1];
        bindings.push_back(b);
    }
}

}  // namespace sfx::detail
