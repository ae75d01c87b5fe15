#version 450
// The host's last pass: the motion-blurred colour, clamped and gamma-encoded into RGBA8.
layout(set = 0, binding = 0) uniform sampler2D blurredTex;
layout(location = 0) out vec4 outColour;

void main() {
    vec3 c = clamp(texelFetch(blurredTex, ivec2(gl_FragCoord.xy), 0).rgb, 0.0, 1.0);
    outColour = vec4(pow(c, vec3(1.0 / 2.2)), 1.0);
}
