// What the benchmarks share around a device: opening it for a tier as the conformance tests do,
// and reading an AO output back.
#pragma once

#include <glm/glm.hpp>

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "sfx/backends.hpp"
#include "sfx/reference/depth_reference.hpp"

namespace sfx::tools {

// A device for `tier` with validation off (it would be timed too): the current tier under the
// GL ES 3.0 ceiling, so its cost is the one a GL ES 3.0 class device would pay for the same
// shaders. UnsupportedTier when the device cannot run the tier.
Result<std::unique_ptr<Device>> openForTier(const BackendConfig& config, Tier tier);

// The compiled backend named `backend` (its BackendConfig's toString, e.g. "vulkan"; never the
// null backend, which draws nothing to measure) opened with openForTier; InvalidArgument when
// no such backend is compiled in.
Result<std::unique_ptr<Device>> openNamedForTier(const std::string& backend, Tier tier);

// Opens every backend (by name, e.g. "vulkan") x tier with openForTier and calls run on each
// device; one that cannot run the tier is skipped with a line on stdout saying why. An unknown
// backend name is InvalidArgument; the first error of run stops the loop, named by backend/tier.
Status forEachDevice(const std::vector<std::string>& backends, const std::vector<Tier>& tiers, const std::string& program,
                     const std::function<Status(Device&, const std::string& backend, Tier)>& run);

// The format an AO output gets on `device`: R32F where renderable, else RGBA8.
Format aoOutputFormat(const Device& device);

// A W x H AO output (R32F, R16F, or RGBA8's red channel) as visibility in [0, 1], row 0 first.
Result<reference::Grid> readVisibility(Device& device, TextureHandle texture, Format format, uint32_t width, uint32_t height);

// A W x H bent-normal output (AoInputs.bentNormals) as signed xyz, row 0 first: RGBA8 holds
// xyz * 0.5 + 0.5, RGBA16F and RGBA32F signed xyz.
Result<std::vector<glm::dvec3>> readBentNormals(Device& device, TextureHandle texture, Format format, uint32_t width, uint32_t height);

}  // namespace sfx::tools
