// The host renderer's own GLSL (ES 3.00, or 3.30 core on desktop GL): host code, not SDK shader
// code. Three programs: the G-buffer raster pass, the composite (albedo lit with the SDK's AO)
// and the present pass (the motion-blurred colour the SDK wrote into the host's texture, to
// display-referred RGBA8).
#pragma once

#include "egl_context.hpp"
#include "host_gl.hpp"
#include "sfx/status.hpp"

namespace engine_gl {

// G-buffer pass attribute locations and fragment outputs.
constexpr GLuint kAttribPosition = 0, kAttribNormal = 1;
constexpr GLenum kGBufferNormals = 0, kGBufferVelocity = 1, kGBufferAlbedo = 2;  // colour attachment indices
// Composite and present texture units (the host's choice; it rebinds them every pass).
constexpr GLint kUnitAlbedo = 0, kUnitNormals = 1, kUnitAo = 2, kUnitBlurred = 0;

struct HostPrograms {
    GLuint gbuffer = 0, composite = 0, present = 0;
};

// Compiles and links the three; ShaderError carrying the GL info log when one fails.
sfx::Result<HostPrograms> buildPrograms(HostGl& gl, ContextApi api);
void destroyPrograms(HostGl& gl, HostPrograms& programs);

}  // namespace engine_gl
