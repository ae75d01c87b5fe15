// Internal helpers shared by the effect contexts in sdk/src/effects/ (not installed).
#pragma once

#include "sfx/hal.hpp"
#include "sfx/tier.hpp"
#include "sfx_shaders.hpp"

namespace sfx::detail {

// The generated program `name` for `tier`, created on `device`; shaders::find's status when
// this build has no such program. One definition for every effect context.
inline Result<ProgramHandle> loadProgram(Device& device, const char* name, Tier tier) {
    Result<const CompiledProgram*> program = shaders::find(name, tier);
    if (!program) return program.status();
    return device.createProgram(*program.value());
}

}  // namespace sfx::detail
