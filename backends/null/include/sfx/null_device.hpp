// The null backend: validates every call exactly as a real backend does and keeps texture and
// buffer contents in host memory, but draws nothing. For HAL contract tests on any machine.
#pragma once

#include <memory>

#include "sfx/hal.hpp"

namespace sfx::null {

// `caps` lets a test pose as any device (a ceiling device, one without float targets...).
// Left default, the device claims every capability with generous limits.
std::unique_ptr<Device> createDevice(const DeviceOptions& options = {});
std::unique_ptr<Device> createDevice(const DeviceCaps& caps);
DeviceCaps defaultCaps(CapabilityCeiling ceiling = CapabilityCeiling::None);

}  // namespace sfx::null
