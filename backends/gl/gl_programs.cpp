// Programs and pipelines: the device dialect's text compiled and linked, resources bound by their
// reflected GL names, and pipelines holding the graphics state a draw applies.
#include <algorithm>

#include "gl_driver.hpp"

namespace sfx::gl {

Result<ProgramHandle> GlDevice::doCreateProgram(const CompiledProgram& program) {
    // Here, not in the front end: texture units and the compile and link need the GL context.
    SFX_TRY(checkTextureUnits(program));
    SFX_TRY(enter());
    Result<GLuint> linked = linkProgram(program);
    if (!linked) return takeDeviceError(linked.status());
    const GLuint name = linked.value();
    Status s = takeDeviceError(Status::ok());
    if (!s) {
        gl_.glDeleteProgram(name);
        return s;
    }
    return programs_.insert(GlProgram{validation::programInfo(program), name, sourcesOf(program, caps_.dialect)});
}

Status GlDevice::doDestroyProgram(ProgramHandle h) {
    SFX_TRY(enter());
    GlProgram p = programs_.remove(h);
    releaseProgramObject(p.name, true);
    return takeDeviceError(Status::ok());
}

void GlDevice::releaseProgramObject(GLuint program, bool programDestroyed) {
    if (programDestroyed) destroyedPrograms_.insert(program);
    auto users = programUsers_.find(program);
    if (!programDestroyed && users != programUsers_.end() && --users->second == 0) programUsers_.erase(users);
    if (programUsers_.count(program) || !destroyedPrograms_.count(program)) return;
    destroyedPrograms_.erase(program);
    GL(glDeleteProgram, program);
}

GlSources GlDevice::sourcesOf(const CompiledProgram& program, ShaderDialect dialect) {
    GlSources sources;
    for (const StageCode& s : program.stages) {
        const GLenum type = s.stage == ShaderStage::Vertex ? GL_VERTEX_SHADER
            : s.stage == ShaderStage::Fragment             ? GL_FRAGMENT_SHADER
                                                           : GL_COMPUTE_SHADER;
        sources.push_back({type, s.glsl[size_t(dialect)]});
    }
    return sources;
}

Result<GLuint> GlDevice::linkProgram(const CompiledProgram& program) {
    return linkSources(program.name, sourcesOf(program, caps_.dialect), program.resources);
}

Result<GLuint> GlDevice::linkSources(const std::string& programName, const GlSources& sources, const std::vector<ShaderResource>& resources) {
    Result<GLuint> linked = buildProgram(programName, sources);
    if (!linked) return linked.status();
    bindResourcesByName(linked.value(), resources);
    return linked.value();
}

// SPIRV-Cross writes a specialisation constant as `const int X = SPIRV_CROSS_CONSTANT_ID_<id>;`
// with a default #define that yields to one made before it: the values go right after #version.
Result<GLuint> GlDevice::specialize(const GlProgram& program, const std::vector<SpecializationConstant>& constants) {
    if (constants.empty()) return GLuint(0);
    std::string defines;
    for (const SpecializationConstant& c : constants)
        defines += "#define SPIRV_CROSS_CONSTANT_ID_" + std::to_string(c.id) + " " + std::to_string(c.value) + "\n";
    GlSources sources = program.sources;
    for (auto& [type, text] : sources) {
        const size_t eol = text.find('\n');
        text.insert(eol == std::string::npos ? text.size() : eol + 1, defines);
    }
    return linkSources(program.info.name, sources, program.info.resources);
}

Result<GLuint> GlDevice::compileShader(const std::string& programName, GLenum type, const std::string& source) {
    const GLuint shader = GL(glCreateShader, type);
    const char* text = source.c_str();
    GL(glShaderSource, shader, 1, &text, nullptr);
    GL(glCompileShader, shader);
    GLint ok = 0;
    GL(glGetShaderiv, shader, GL_COMPILE_STATUS, &ok);
    if (ok) return shader;
    GLint length = 0;
    GL(glGetShaderiv, shader, GL_INFO_LOG_LENGTH, &length);
    std::string log(size_t(std::max(length, 1)), '\0');
    GL(glGetShaderInfoLog, shader, GLsizei(log.size()), nullptr, log.data());
    GL(glDeleteShader, shader);
    const char* stage = type == GL_VERTEX_SHADER ? "vertex" : type == GL_FRAGMENT_SHADER ? "fragment" : "compute";
    // GL only: Vulkan consumes SPIR-V, which sfxc validated at build time (vulkan_pipelines.cpp).
    return validation::fail(validation::Error::ShaderCompile, {programName, stage, toString(caps_.dialect), log.c_str()});
}

Result<GLuint> GlDevice::buildProgram(const std::string& programName, const std::vector<std::pair<GLenum, std::string>>& sources) {
    std::vector<GLuint> shaders;
    auto deleteShaders = [&] {
        for (GLuint s : shaders) GL(glDeleteShader, s);
    };
    for (const auto& [type, text] : sources) {
        Result<GLuint> s = compileShader(programName, type, text);
        if (!s) {
            deleteShaders();
            return s.status();
        }
        shaders.push_back(s.value());
    }
    const GLuint program = GL(glCreateProgram);
    for (GLuint s : shaders) GL(glAttachShader, program, s);
    GL(glLinkProgram, program);
    deleteShaders();  // flagged; they go with the program
    GLint ok = 0;
    GL(glGetProgramiv, program, GL_LINK_STATUS, &ok);
    if (ok) return program;
    GLint length = 0;
    GL(glGetProgramiv, program, GL_INFO_LOG_LENGTH, &length);
    std::string log(size_t(std::max(length, 1)), '\0');
    GL(glGetProgramInfoLog, program, GLsizei(log.size()), nullptr, log.data());
    GL(glDeleteProgram, program);
    return validation::fail(validation::Error::ShaderLink, {programName, toString(caps_.dialect), log.c_str()});
}

// SPIR-V to ESSL 300 / GLSL 330 drops binding qualifiers, so bind by the reflected GL name
// (harmless where the qualifier survived). Texture unit = uniform block binding = the
// reflected binding number.
void GlDevice::bindResourcesByName(GLuint program, const std::vector<ShaderResource>& resources) {
    GL(glUseProgram, program);
    for (const ShaderResource& r : resources) {
        switch (r.kind) {
            case ResourceKind::SampledTexture: {
                const GLint loc = GL(glGetUniformLocation, program, r.glName.c_str());
                if (loc >= 0) GL(glUniform1i, loc, GLint(r.binding));
                break;
            }
            case ResourceKind::UniformBuffer: {
                const GLuint index = GL(glGetUniformBlockIndex, program, r.glName.c_str());
                if (index != GL_INVALID_INDEX) GL(glUniformBlockBinding, program, index, r.binding);
                break;
            }
            case ResourceKind::StorageBuffer:
                // GL ES has no glShaderStorageBlockBinding; ESSL 310 keeps binding= instead.
                if (api_ == Api::DesktopGL && gl_.glShaderStorageBlockBinding && gl_.glGetProgramResourceIndex) {
                    const GLuint index = GL(glGetProgramResourceIndex, program, GL_SHADER_STORAGE_BLOCK, r.glName.c_str());
                    if (index != GL_INVALID_INDEX) GL(glShaderStorageBlockBinding, program, index, r.binding);
                }
                break;
            case ResourceKind::StorageImage:
                // Image units cannot be reassigned on GL ES; high-tier dialects keep binding=.
                if (api_ == Api::DesktopGL) {
                    const GLint loc = GL(glGetUniformLocation, program, r.glName.c_str());
                    if (loc >= 0) GL(glUniform1i, loc, GLint(r.binding));
                }
                break;
        }
    }
    GL(glUseProgram, 0);
}

Result<PipelineHandle> GlDevice::doCreateGraphicsPipeline(const GraphicsPipelineDesc& desc, validation::PipelineInfo info) {
    SFX_TRY(enter());
    GlPipeline p;
    p.info = std::move(info);
    p.program = programs_.get(desc.program).name;
    p.desc = desc;
    p.desc.debugName = "";
    Result<GLuint> specialized = specialize(programs_.get(desc.program), desc.constants);
    if (!specialized) return takeDeviceError(specialized.status());
    p.specialized = specialized.value();
    // The VAO holds which attributes are enabled; the buffer is attached per draw.
    GL(glGenVertexArrays, 1, &p.vao);
    GL(glBindVertexArray, p.vao);
    for (const VertexAttribute& a : desc.vertexLayout.attributes) GL(glEnableVertexAttribArray, a.location);
    GL(glBindVertexArray, 0);
    Status s = takeDeviceError(Status::ok());
    if (!s) {
        gl_.glDeleteVertexArrays(1, &p.vao);
        if (p.specialized) gl_.glDeleteProgram(p.specialized);
        return s;
    }
    usePipelineProgram(p.program);
    return pipelines_.insert(std::move(p));
}

Result<PipelineHandle> GlDevice::doCreateComputePipeline(const ComputePipelineDesc& desc, validation::PipelineInfo info) {
    SFX_TRY(enter());
    GlPipeline p;
    p.info = std::move(info);
    p.program = programs_.get(desc.program).name;
    Result<GLuint> specialized = specialize(programs_.get(desc.program), desc.constants);
    if (!specialized) return takeDeviceError(specialized.status());
    p.specialized = specialized.value();
    usePipelineProgram(p.program);
    return pipelines_.insert(std::move(p));
}

Status GlDevice::doDestroyPipeline(PipelineHandle h) {
    SFX_TRY(enter());
    GlPipeline p = pipelines_.remove(h);
    if (p.vao) GL(glDeleteVertexArrays, 1, &p.vao);
    if (p.specialized) GL(glDeleteProgram, p.specialized);
    releaseProgramObject(p.program, false);
    return takeDeviceError(Status::ok());
}

}  // namespace sfx::gl
