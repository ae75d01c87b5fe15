#version 450
// Motion blur pass 1: the velocity the reconstruction will use, packed with depth.
// Output RGBA16F: xy = velocity radius in [-k, k] px on fp16's grid (mbQuantizeVelocity); zw = linear depth as an
// fp16 hi/lo pair (hi = z to 11 significant bits, lo = z - hi), so one fetch gives both at ~22 bits of depth.
// The velocity is the host's (pixels across the shutter interval) or, in camera-only mode,
// the reprojection of this pixel's depth by the previous view-projection.
#define SFX_WANT_MB_PACK_PARAMS 1
#include "sfx_shared.h"
#include "sfx_shared_mb.h"

layout(set = 0, binding = 0) uniform sampler2D uLinearDepth;
layout(set = 0, binding = 1) uniform sampler2D uVelocity;  // unused in camera-only mode
// params: the uniform block declared in sfx_shared_mb.h.

layout(location = 0) out vec4 outPacked;
layout(constant_id = SFX_MB_SC_CAMERA_ONLY) const int kCameraOnly = 0;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    // uLinearDepth may be the host's linear depth itself (LinearDepth passing through).
    float z = sfxLinearDepthOrFar(sfxTexel(uLinearDepth, p, 0).r, params.maxDepth);
    vec2 v;
    if (kCameraOnly != 0) {
        v = mbCameraVelocity(gl_FragCoord.xy, params.clipFromView.zw, params.target.xy, z, params.clipFromView.x,
                             params.clipFromView.y, params.reprojection);
    } else {
        v = sfxTexel(uVelocity, p, 0).xy;
    }
    // Non-finite, infinite and huge velocities: the rule of sfx_shared_mb.h (mbClampVelocity).
    v = mbClampVelocity(v * params.velocityScale, params.radius);
    // On the fp16-exact grid of sfx_shared_mb.h: the target's own rounding never changes it.
    vec2 stored = vec2(mbQuantizeVelocity(v.x), mbQuantizeVelocity(v.y));
    float zc = min(z, SFX_MB_MAX_PACKED_DEPTH);
    // hi keeps the top 11 significant bits of z, which fp16 stores exactly; lo the rest.
    // (Computed by hand: packHalf2x16 is missing from GLSL 330, the desktop current tier.)
    uint exponent = max(floatBitsToUint(zc) & 0x7F800000u, 0x38800000u);  // 2^floor(log2 z), at least 2^-14
    float step = uintBitsToFloat(exponent - (10u << 23));                   // that over 1024
    float hi = floor(zc / step) * step;
    outPacked = vec4(stored, hi, zc - hi);
}
