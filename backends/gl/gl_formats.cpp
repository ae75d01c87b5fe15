// The HAL-to-GL enum tables: formats, compare functions, blend factors, wrap modes.
#include "gl_formats.hpp"

namespace sfx::gl {

GlFormat glFormat(Format f) {
    switch (f) {
        case Format::R8: return {GL_R8, GL_RED, GL_UNSIGNED_BYTE};
        case Format::RGBA8: return {GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE};
        case Format::R16F: return {GL_R16F, GL_RED, GL_HALF_FLOAT};
        case Format::RG16F: return {GL_RG16F, GL_RG, GL_HALF_FLOAT};
        case Format::RGBA16F: return {GL_RGBA16F, GL_RGBA, GL_HALF_FLOAT};
        case Format::R32F: return {GL_R32F, GL_RED, GL_FLOAT};
        case Format::RG32F: return {GL_RG32F, GL_RG, GL_FLOAT};
        case Format::RGBA32F: return {GL_RGBA32F, GL_RGBA, GL_FLOAT};
        case Format::R32UI: return {GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT};
        case Format::D16: return {GL_DEPTH_COMPONENT16, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT};
        case Format::D24S8: return {GL_DEPTH24_STENCIL8, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8};
        case Format::D32F: return {GL_DEPTH_COMPONENT32F, GL_DEPTH_COMPONENT, GL_FLOAT};
        default: return {0, 0, 0};
    }
}

bool isHalfFormat(Format f) { return f == Format::R16F || f == Format::RG16F || f == Format::RGBA16F; }
bool isFloat32Format(Format f) { return f == Format::R32F || f == Format::RG32F || f == Format::RGBA32F; }
bool isEs31ImageFormat(Format f) {
    return f == Format::RGBA32F || f == Format::RGBA16F || f == Format::R32F || f == Format::RGBA8 || f == Format::R32UI;
}

GLenum compareFunc(CompareOp op) {
    switch (op) {
        case CompareOp::Never: return GL_NEVER;
        case CompareOp::Less: return GL_LESS;
        case CompareOp::LessEqual: return GL_LEQUAL;
        case CompareOp::Greater: return GL_GREATER;
        case CompareOp::GreaterEqual: return GL_GEQUAL;
        case CompareOp::Equal: return GL_EQUAL;
        case CompareOp::NotEqual: return GL_NOTEQUAL;
        case CompareOp::Always: return GL_ALWAYS;
    }
    return GL_LESS;
}

GLenum blendFactor(BlendFactor f) {
    switch (f) {
        case BlendFactor::Zero: return GL_ZERO;
        case BlendFactor::One: return GL_ONE;
        case BlendFactor::SrcAlpha: return GL_SRC_ALPHA;
        case BlendFactor::OneMinusSrcAlpha: return GL_ONE_MINUS_SRC_ALPHA;
        case BlendFactor::DstAlpha: return GL_DST_ALPHA;
        case BlendFactor::OneMinusDstAlpha: return GL_ONE_MINUS_DST_ALPHA;
    }
    return GL_ONE;
}

GLenum wrapMode(AddressMode a) {
    switch (a) {
        case AddressMode::ClampToEdge: return GL_CLAMP_TO_EDGE;
        case AddressMode::Repeat: return GL_REPEAT;
        case AddressMode::MirroredRepeat: return GL_MIRRORED_REPEAT;
    }
    return GL_CLAMP_TO_EDGE;
}

}  // namespace sfx::gl
