#version 450
// Hardware depth -> linear eye depth (positive distance along the view axis).
// For any perspective projection, eye depth z = B / (ndc_z + A), with A = P[2][2] and
// B = P[3][2] of the column-major matrix; ndc_z = d * ndcScale + ndcOffset maps the stored
// depth d to the API's clip range. The host folds ndcOffset + A into one constant in double
// precision (LinearizeParams.denomOffset) so the shader does one multiply-add and a divide.
#include "sfx_shared.h"

layout(set = 0, binding = 0) uniform sampler2D uHardwareDepth;
layout(set = 0, binding = 1, std140) uniform LinearizeParams {
    float ndcScale;     // 1 for [0,1] clip depth, 2 for [-1,1]
    float denomOffset;  // ndcOffset + A
    float numerator;    // B
    float maxDepth;     // far plane, or SFX_SKY_DEPTH for an infinite projection
    float linearInput;  // 1: the source already holds linear depth; only the clamp applies
} params;

layout(location = 0) out float outLinearDepth;

void main() {
    float d = texelFetch(uHardwareDepth, ivec2(gl_FragCoord.xy), 0).r;
    float z = d;
    if (params.linearInput == 0.0) {
        float denom = d * params.ndcScale + params.denomOffset;
        z = params.numerator / denom;
    }
    // A non-positive or overflowing quotient is a point at or beyond the far plane.
    outLinearDepth = sfxLinearDepthOrFar(z, params.maxDepth);
}
