#version 450
// The host's G-buffer pass: each mesh with this frame's and the previous frame's model-view
// (push constants), the fixed projection and the meshes' colours in a uniform block written once.
layout(push_constant) uniform Draw {
    mat4 modelView;          // this frame
    mat4 previousModelView;  // the previous frame (the same on the first frame: no motion)
} draw;
layout(set = 0, binding = 0) uniform Scene {
    mat4 projection;   // rows 0 = top, clip depth [0, 1]: the CameraProjection the SDK is given
    vec4 viewport;     // width, height, 0, 0
    vec4 colours[8];   // per mesh, indexed by the draw's first instance
} scene;

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 0) out vec3 vNormal;
layout(location = 1) out vec3 vViewPosition;
layout(location = 2) out vec4 vClip;
layout(location = 3) out vec4 vPreviousClip;
layout(location = 4) flat out vec4 vColour;
layout(location = 5) out vec3 vObjectPosition;

void main() {
    vec4 view = draw.modelView * vec4(inPosition, 1.0);
    vNormal = mat3(draw.modelView) * inNormal;  // rigid transforms: no inverse transpose needed
    vViewPosition = view.xyz;
    vClip = scene.projection * view;
    vPreviousClip = scene.projection * (draw.previousModelView * vec4(inPosition, 1.0));
    vColour = scene.colours[gl_InstanceIndex];
    vObjectPosition = inPosition;
    gl_Position = vClip;
}
