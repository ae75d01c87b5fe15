#include "host_gl.hpp"

#include <cstdio>

namespace engine_gl {

std::string HostGl::load(GetProcAddress loader) {
    std::string missing;
// clang-format off
#define ENGINE_GL_LOAD(type, name)                                                  \
    name = reinterpret_cast<type>(loader("gl" #name));                              \
    if (!name) missing += (missing.empty() ? "gl" : ", gl") + std::string(#name);
    // clang-format on
    ENGINE_GL_STATE_FUNCTIONS(ENGINE_GL_LOAD)
    ENGINE_GL_COUNTED_FUNCTIONS(ENGINE_GL_LOAD)
#undef ENGINE_GL_LOAD
    return missing;
}

void HostGl::checkErrors(const char* where) {
    for (GLenum e = GetError(); e != GL_NO_ERROR; e = GetError()) {
        char hex[16];
        std::snprintf(hex, sizeof hex, "0x%04x", unsigned(e));
        errors_ += std::string(errors_.empty() ? "" : "; ") + where + ": GL error " + hex;
    }
}

std::string HostGl::takeErrors() {
    std::string out;
    out.swap(errors_);
    return out;
}

}  // namespace engine_gl
