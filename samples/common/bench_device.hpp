// What the benchmarks share around a device: opening it for a tier as the conformance tests do,
// and reading an AO output back.
#pragma once

#include <memory>

#include "sfx/backends.hpp"
#include "sfx/reference/depth_reference.hpp"

namespace sfx::samples {

// A device for `tier` with validation off (it would be timed too): the current tier under the
// GL ES 3.0 ceiling, so its cost is the one a GL ES 3.0 class device would pay for the same
// shaders. UnsupportedTier when the device cannot run the tier.
Result<std::unique_ptr<Device>> openForTier(const BackendConfig& config, Tier tier);

// The format an AO output gets on `device`: R32F where renderable, else RGBA8.
Format aoOutputFormat(const Device& device);

// A W x H AO output (R32F, or RGBA8's red channel) as visibility in [0, 1], row 0 first.
Result<reference::Grid> readVisibility(Device& device, TextureHandle texture, Format format, uint32_t width, uint32_t height);

}  // namespace sfx::samples
