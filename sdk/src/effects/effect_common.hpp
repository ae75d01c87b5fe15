// Internal helpers shared by the effect contexts in sdk/src/effects/ (not installed).
#pragma once

#include <string>

#include "sfx/hal.hpp"
#include "sfx/tier.hpp"
#include "sfx_shaders.hpp"

namespace sfx::detail {

// The generated program `name` for `tier`, created on `device`; shaders::find's status when
// this build has no such program. One definition for every effect context.
// The colour formats an effect reads and writes as RGBA colour (motion blur, transparency).
inline bool isColorFormat(Format f) { return f == Format::RGBA8 || f == Format::RGBA16F || f == Format::RGBA32F; }

inline Result<ProgramHandle> loadProgram(Device& device, const char* name, Tier tier) {
    Result<const CompiledProgram*> program = shaders::find(name, tier);
    if (!program) return program.status();
    return device.createProgram(*program.value());
}

// A target size inside the device's limits; `what` prefixes the field names in the message
// ("AoDesc" gives "AoDesc.width is 0; allowed [1, 16384]").
inline Status checkTargetSize(const Device& device, uint32_t width, uint32_t height, const std::string& what) {
    const uint32_t maxSize = device.caps().limits.maxTextureSize;
    const std::string range = "[1, " + std::to_string(maxSize) + "]";
    if (width == 0 || width > maxSize) return invalidArgument(what + "width", std::to_string(width), range);
    if (height == 0 || height > maxSize) return invalidArgument(what + "height", std::to_string(height), range);
    return Status::ok();
}

}  // namespace sfx::detail
