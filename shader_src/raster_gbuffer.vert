#version 450
// Rasterises scene meshes into hardware depth and view-space normals.
layout(set = 0, binding = 0, std140) uniform RasterParams {
    mat4 modelView;
    mat4 projection;
    mat4 normalMatrix;  // inverse transpose of modelView (upper 3x3 used)
} raster;

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 0) out vec3 vNormal;
layout(location = 1) out vec3 vViewPosition;

void main() {
    vNormal = mat3(raster.normalMatrix) * inNormal;
    vec4 viewPosition = raster.modelView * vec4(inPosition, 1.0);
    vViewPosition = viewPosition.xyz;
    gl_Position = raster.projection * viewPosition;
}
