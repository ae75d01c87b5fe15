// Errors and debug output: every GL() call checks glGetError under options.validation, the
// first error of an HAL call becomes its DeviceError, and KHR_debug errors join the
// validation messages.
#include <cstring>

#include "gl_driver.hpp"

namespace sfx::gl {
namespace {

const char* glErrorName(GLenum e) {
    switch (e) {
        case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
        case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
        case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
        case GL_INVALID_FRAMEBUFFER_OPERATION: return "GL_INVALID_FRAMEBUFFER_OPERATION";
        case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
        default: return "GL error";
    }
}

std::string baseName(const char* path) {
    const char* slash = std::strrchr(path, '/');
    return slash ? slash + 1 : path;
}

}  // namespace

Status GlDevice::takeDeviceError(Status s) {
    if (pendingError_.empty()) return s;
    std::string e;
    e.swap(pendingError_);
    if (!s) return s;
    return {StatusCode::DeviceError, e};
}

void GlDevice::checkError(const char* fn, const char* file, int line) {
    if (!options_.validation) return;
    for (GLenum e; (e = gl_.glGetError()) != GL_NO_ERROR;) {
        std::string m = std::string(fn) + ": " + glErrorName(e) + " at " + baseName(file) + ":" + str(uint64_t(line));
        messages_.push_back(m);
        if (pendingError_.empty()) pendingError_ = m;
    }
}

// A host's context keeps its own debug callback: the SDK does not replace it (nor disable
// debug output when it goes away); it relies on its per-call checks there.
void GlDevice::enableDebugOutput() {
    gl_.glEnable(GL_DEBUG_OUTPUT);
    gl_.glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    gl_.glDebugMessageCallback(&GlDevice::debugCallback, this);
    gl_.glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE, 0, nullptr, GL_TRUE);
    debugOutput_ = true;
}

void APIENTRY GlDevice::debugCallback(GLenum source, GLenum type, GLuint, GLenum, GLsizei, const GLchar* message, const void* user) {
    // Compile and link failures reach the caller as ShaderError with the info log.
    if (type != GL_DEBUG_TYPE_ERROR || source == GL_DEBUG_SOURCE_SHADER_COMPILER) return;
    auto* self = static_cast<GlDevice*>(const_cast<void*>(user));
    self->messages_.push_back(std::string("GL debug: ") + (message ? message : ""));
}

std::vector<std::string> GlDevice::takeValidationMessages() {
    std::vector<std::string> m;
    m.swap(messages_);
    return m;
}

}  // namespace sfx::gl
