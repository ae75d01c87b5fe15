#version 450
// Outputs: 0 view-space unit normal (RGBA16F, signed, a = 1 where drawn); 1 screen-space
// velocity (RG16F) in pixels from the previous frame to this one, x toward increasing column,
// y toward increasing row (the SDK's motion blur convention); 2 albedo (RGBA8, a = 1 drawn).
layout(set = 0, binding = 0) uniform Scene {
    mat4 projection;
    vec4 viewport;
    vec4 colours[8];
} scene;

layout(location = 0) in vec3 vNormal;
layout(location = 1) in vec3 vViewPosition;
layout(location = 2) in vec4 vClip;
layout(location = 3) in vec4 vPreviousClip;
layout(location = 4) flat in vec4 vColour;
layout(location = 5) in vec3 vObjectPosition;
layout(location = 0) out vec4 outNormal;
layout(location = 1) out vec2 outVelocity;
layout(location = 2) out vec4 outAlbedo;

void main() {
    vec3 n = normalize(vNormal);
    if (dot(n, vViewPosition) > 0.0) n = -n;  // two-sided: face the viewer
    outNormal = vec4(n, 1.0);
    // Vulkan maps NDC y = -1 to row 0, so pixel = (ndc * 0.5 + 0.5) * size on both axes.
    vec2 pixel = (vClip.xy / vClip.w * 0.5 + 0.5) * scene.viewport.xy;
    vec2 previousPixel = (vPreviousClip.xy / vPreviousClip.w * 0.5 + 0.5) * scene.viewport.xy;
    outVelocity = pixel - previousPixel;
    // A checker on the object's own coordinates, so that motion shows in the picture.
    ivec3 cell = ivec3(floor(vObjectPosition * 4.0));
    float checker = ((cell.x + cell.y + cell.z) & 1) == 0 ? 1.0 : 0.6;
    outAlbedo = vec4(vColour.rgb * checker, 1.0);
}
