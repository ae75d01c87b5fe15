#version 450
// The host's lighting pass: albedo x (ambient + sun), the ambient term multiplied by the SDK's
// AO (visibility in r). Its output is the colour the SDK's motion blur then blurs.
layout(set = 0, binding = 0) uniform sampler2D albedoTex;
layout(set = 0, binding = 1) uniform sampler2D normalTex;
layout(set = 0, binding = 2) uniform sampler2D aoTex;
layout(location = 0) out vec4 outColour;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec4 albedo = texelFetch(albedoTex, p, 0);
    if (albedo.a == 0.0) {  // nothing drawn: sky
        outColour = vec4(0.45, 0.55, 0.7, 1.0);
        return;
    }
    vec3 n = texelFetch(normalTex, p, 0).xyz;
    float ao = texelFetch(aoTex, p, 0).r;
    vec3 sun = normalize(vec3(0.35, 0.8, 0.5));  // view space: from above, behind the camera
    float diffuse = max(dot(n, sun), 0.0);
    outColour = vec4(albedo.rgb * (0.55 * ao + 0.6 * diffuse * (0.5 + 0.5 * ao)), 1.0);
}
