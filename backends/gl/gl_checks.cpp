// The checks only the GL backend makes; every other check of a GL call is the shared
// sfx::validation, which Device's front end runs before the hook. Each is here because of how GL works, not what the HAL says:
//   checkTextureUnits  GL uses a sampled texture's binding number as its texture unit, so a
//                      binding at or past GL_MAX_TEXTURE_IMAGE_UNITS cannot be bound at all. On
//                      Vulkan a binding number is only a descriptor slot, with no such limit.
#include "gl_driver.hpp"

namespace sfx::gl {

Status GlDevice::checkTextureUnits(const CompiledProgram& program) const {
    for (const ShaderResource& r : program.resources)
        if (r.kind == ResourceKind::SampledTexture && r.binding >= caps_.limits.maxTextureBindings)
            return validation::fail(validation::Error::ProgramTextureUnit,
                                    {program.name, r.name, str(r.binding), str(caps_.limits.maxTextureBindings - 1)});
    return Status::ok();
}

}  // namespace sfx::gl
