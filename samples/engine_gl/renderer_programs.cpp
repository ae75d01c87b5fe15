#include "renderer_programs.hpp"

#include <string>

namespace engine_gl {
namespace {

// Outputs: 0 = view-space unit normal (x right, y up, looking down -z), the SDK's AoNormals
// convention; 1 = velocity in pixels since the previous frame (x toward increasing column, y
// toward increasing texel row: sfx/motion_blur.hpp's convention with one frame as the shutter
// interval); 2 = albedo, alpha 1 where something was drawn.
const char* kGBufferVertex = R"(
in vec3 aPosition;
in vec3 aNormal;
uniform mat4 uModelView;
uniform mat4 uProjection;
uniform mat3 uNormalMatrix;
uniform mat4 uPreviousClip;  // previous frame's projection * view * model
out vec3 vNormal;
out vec3 vView;
out vec4 vClip;
out vec4 vPreviousClip;
out vec3 vObject;
void main() {
    vec4 view = uModelView * vec4(aPosition, 1.0);
    vView = view.xyz;
    vNormal = uNormalMatrix * aNormal;
    vClip = uProjection * view;
    vPreviousClip = uPreviousClip * vec4(aPosition, 1.0);
    vObject = aPosition;
    gl_Position = vClip;
}
)";

const char* kGBufferFragment = R"(
in vec3 vNormal;
in vec3 vView;
in vec4 vClip;
in vec4 vPreviousClip;
in vec3 vObject;
uniform vec2 uViewport;
uniform vec3 uColour;
layout(location = 0) out vec4 outNormal;
layout(location = 1) out vec2 outVelocity;
layout(location = 2) out vec4 outAlbedo;
void main() {
    vec3 n = normalize(vNormal);
    // Face the viewer: the projection flips y (texel row 0 = top), which swaps the winding.
    if (dot(n, vView) > 0.0) n = -n;
    outNormal = vec4(n, 1.0);
    // Clip y = -1 is texel row 0, so a pixel position is (ndc * 0.5 + 0.5) * size.
    vec2 now = (vClip.xy / vClip.w * 0.5 + 0.5) * uViewport;
    vec2 before = (vPreviousClip.xy / vPreviousClip.w * 0.5 + 0.5) * uViewport;
    outVelocity = now - before;
    ivec3 cell = ivec3(floor(vObject * 5.0));
    float check = ((cell.x + cell.y + cell.z) & 1) == 0 ? 1.0 : 0.6;
    outAlbedo = vec4(uColour * check, 1.0);
}
)";

// One triangle covering the target; no vertex buffer.
const char* kFullScreenVertex = R"(
void main() {
    vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
    gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
}
)";

// Ambient light is scaled by the SDK's visibility; the sun is not (AO models only what the
// ambient term misses). Sky where nothing was drawn.
const char* kCompositeFragment = R"(
uniform sampler2D uAlbedo;
uniform sampler2D uNormals;
uniform sampler2D uAo;
uniform vec3 uSunView;  // unit, view space
out vec4 outColour;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec4 albedo = texelFetch(uAlbedo, p, 0);
    if (albedo.a == 0.0) {
        outColour = vec4(0.55, 0.66, 0.82, 1.0);
        return;
    }
    vec3 n = texelFetch(uNormals, p, 0).xyz;
    float visibility = texelFetch(uAo, p, 0).r;
    float sun = max(dot(n, uSunView), 0.0);
    outColour = vec4(albedo.rgb * (0.55 * visibility + 0.75 * sun), 1.0);
}
)";

const char* kPresentFragment = R"(
uniform sampler2D uBlurred;
out vec4 outColour;
void main() {
    vec3 c = clamp(texelFetch(uBlurred, ivec2(gl_FragCoord.xy), 0).rgb, 0.0, 1.0);
    outColour = vec4(pow(c, vec3(1.0 / 2.2)), 1.0);
}
)";

std::string withHeader(ContextApi api, const char* body) {
    return std::string(api == ContextApi::GLES ? "#version 300 es\nprecision highp float;\nprecision highp int;\n" : "#version 330 core\n") + body;
}

sfx::Result<GLuint> compile(HostGl& gl, GLenum stage, const std::string& source, const char* what) {
    GLuint shader = gl.createShader(stage);
    const char* text = source.c_str();
    gl.ShaderSource(shader, 1, &text, nullptr);
    gl.CompileShader(shader);
    GLint ok = 0;
    gl.GetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[2048] = {};
        gl.GetShaderInfoLog(shader, sizeof log, nullptr, log);
        gl.DeleteShader(shader);
        return sfx::Status{sfx::StatusCode::ShaderError, std::string("engine_gl: ") + what + " does not compile: " + log};
    }
    return shader;
}

sfx::Result<GLuint> link(HostGl& gl, ContextApi api, const char* vertex, const char* fragment, const char* what, bool meshAttributes) {
    sfx::Result<GLuint> vs = compile(gl, GL_VERTEX_SHADER, withHeader(api, vertex), what);
    if (!vs) return vs.status();
    sfx::Result<GLuint> fs = compile(gl, GL_FRAGMENT_SHADER, withHeader(api, fragment), what);
    if (!fs) {
        gl.DeleteShader(vs.value());
        return fs.status();
    }
    GLuint program = gl.createProgram();
    gl.AttachShader(program, vs.value());
    gl.AttachShader(program, fs.value());
    if (meshAttributes) {
        gl.BindAttribLocation(program, kAttribPosition, "aPosition");
        gl.BindAttribLocation(program, kAttribNormal, "aNormal");
    }
    gl.LinkProgram(program);
    gl.DeleteShader(vs.value());  // flagged; freed with the program
    gl.DeleteShader(fs.value());
    GLint ok = 0;
    gl.GetProgramiv(program, GL_LINK_STATUS, &ok);
    if (!ok) {
        char log[2048] = {};
        gl.GetProgramInfoLog(program, sizeof log, nullptr, log);
        gl.deleteProgram(program);
        return sfx::Status{sfx::StatusCode::ShaderError, std::string("engine_gl: ") + what + " does not link: " + log};
    }
    return program;
}

// Sampler uniforms name fixed units once; the frame only binds textures to them.
void setUnit(HostGl& gl, GLuint program, const char* name, GLint unit) {
    gl.UseProgram(program);
    gl.Uniform1i(gl.GetUniformLocation(program, name), unit);
    gl.UseProgram(0);
}

}  // namespace

sfx::Result<HostPrograms> buildPrograms(HostGl& gl, ContextApi api) {
    HostPrograms p;
    sfx::Result<GLuint> gbuffer = link(gl, api, kGBufferVertex, kGBufferFragment, "the G-buffer program", true);
    if (!gbuffer) return gbuffer.status();
    p.gbuffer = gbuffer.value();
    sfx::Result<GLuint> composite = link(gl, api, kFullScreenVertex, kCompositeFragment, "the composite program", false);
    if (!composite) {
        destroyPrograms(gl, p);
        return composite.status();
    }
    p.composite = composite.value();
    sfx::Result<GLuint> present = link(gl, api, kFullScreenVertex, kPresentFragment, "the present program", false);
    if (!present) {
        destroyPrograms(gl, p);
        return present.status();
    }
    p.present = present.value();
    setUnit(gl, p.composite, "uAlbedo", kUnitAlbedo);
    setUnit(gl, p.composite, "uNormals", kUnitNormals);
    setUnit(gl, p.composite, "uAo", kUnitAo);
    setUnit(gl, p.present, "uBlurred", kUnitBlurred);
    return p;
}

void destroyPrograms(HostGl& gl, HostPrograms& programs) {
    gl.deleteProgram(programs.gbuffer);
    gl.deleteProgram(programs.composite);
    gl.deleteProgram(programs.present);
}

}  // namespace engine_gl
