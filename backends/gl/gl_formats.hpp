// How the HAL's formats and fixed-function enums map to GL (internal to the GL backend).
#pragma once

#include "gl_functions.hpp"
#include "sfx/hal.hpp"

namespace sfx::gl {

struct GlFormat {
    GLenum internalFormat;
    GLenum format;  // for uploads and desktop depth reads
    GLenum type;
};

GlFormat glFormat(Format f);
bool isHalfFormat(Format f);
bool isFloat32Format(Format f);
// The formats GL ES 3.1 lists for image load/store (rgba32f, rgba16f, r32f, rgba8, r32ui among
// the HAL's); desktop GL 4.2 takes every colour format.
bool isEs31ImageFormat(Format f);

GLenum compareFunc(CompareOp op);
GLenum blendFactor(BlendFactor f);
GLenum wrapMode(AddressMode a);

}  // namespace sfx::gl
