#include "sfx/status.hpp"

namespace sfx {

const char* toString(StatusCode code) {
    switch (code) {
        case StatusCode::Ok: return "Ok";
        case StatusCode::InvalidArgument: return "InvalidArgument";
        case StatusCode::UnsupportedFormat: return "UnsupportedFormat";
        case StatusCode::UnsupportedFeature: return "UnsupportedFeature";
        case StatusCode::UnsupportedTier: return "UnsupportedTier";
        case StatusCode::InvalidHandle: return "InvalidHandle";
        case StatusCode::StaleHandle: return "StaleHandle";
        case StatusCode::ForeignHandle: return "ForeignHandle";
        case StatusCode::ShaderError: return "ShaderError";
        case StatusCode::BackendUnavailable: return "BackendUnavailable";
        case StatusCode::DeviceError: return "DeviceError";
        case StatusCode::FileError: return "FileError";
        case StatusCode::OverBudget: return "OverBudget";
    }
    return "Unknown";
}

std::string Status::toString() const {
    if (isOk()) return "Ok";
    return std::string(sfx::toString(code_)) + ": " + message_;
}

Status invalidArgument(const std::string& argument, const std::string& got, const std::string& allowed) {
    return {StatusCode::InvalidArgument, argument + " is " + got + "; allowed " + allowed};
}

}  // namespace sfx
