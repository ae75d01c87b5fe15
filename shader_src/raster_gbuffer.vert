#version 450
// Rasterises scene meshes into hardware depth, view-space normals, screen-space velocity and
// a textured albedo (the sample scenes' G-buffer).
layout(set = 0, binding = 0, std140) uniform RasterParams {
    mat4 modelView;
    mat4 projection;
    mat4 normalMatrix;             // inverse transpose of modelView (upper 3x3 used)
    mat4 shutterOpenClip;          // projection * view * model at the start of the shutter interval
    mat4 shutterCloseClip;         // ... and at its end; the frame itself is mid-shutter
    vec4 viewportSize;             // width, height in pixels
} raster;

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 0) out vec3 vNormal;
layout(location = 1) out vec3 vViewPosition;
layout(location = 2) out vec4 vOpenClip;
layout(location = 3) out vec4 vCloseClip;
layout(location = 4) out vec3 vObjectPosition;

void main() {
    vNormal = mat3(raster.normalMatrix) * inNormal;
    vec4 viewPosition = raster.modelView * vec4(inPosition, 1.0);
    vViewPosition = viewPosition.xyz;
    vOpenClip = raster.shutterOpenClip * vec4(inPosition, 1.0);
    vCloseClip = raster.shutterCloseClip * vec4(inPosition, 1.0);
    vObjectPosition = inPosition;
    gl_Position = raster.projection * viewPosition;
}
