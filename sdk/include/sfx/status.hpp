// Status and Result: how every public call of the SDK reports success or failure.
// The SDK never aborts the host process; a failure is a code the caller can switch on
// plus a message that names the argument and the allowed range.
#pragma once

#include <cstdint>
#include <string>
#include <type_traits>
#include <utility>

namespace sfx {

enum class StatusCode : uint32_t {
    Ok = 0,
    InvalidArgument,     // an argument is out of its documented range (message names it)
    UnsupportedFormat,   // a texture format the device or the call cannot handle
    UnsupportedFeature,  // the device (or its capability ceiling) lacks a feature the call needs
    UnsupportedTier,     // a tier the device cannot run was asked for
    InvalidHandle,       // a null handle, or one that never existed
    StaleHandle,         // a handle whose object was destroyed
    ForeignHandle,       // a handle made by another device
    ShaderError,         // a shader failed to compile, link or validate
    BackendUnavailable,  // the backend's API, driver or platform is absent on this machine
    DeviceError,         // the graphics API reported a failure
    FileError,           // a file could not be read, written or parsed
    OverBudget,          // nothing fits the cost budget asked for (message states the cheapest cost)
};

const char* toString(StatusCode code);

class [[nodiscard]] Status {
public:
    Status() = default;  // Ok
    Status(StatusCode code, std::string message) : code_(code), message_(std::move(message)) {}

    static Status ok() { return {}; }

    bool isOk() const { return code_ == StatusCode::Ok; }
    explicit operator bool() const { return isOk(); }
    StatusCode code() const { return code_; }
    const std::string& message() const { return message_; }
    // "InvalidArgument: TextureDesc.width is 0; allowed 1..16384"
    std::string toString() const;

private:
    StatusCode code_ = StatusCode::Ok;
    std::string message_;
};

// A value or the Status that explains why there is none.
//
// Reading the value of an error Result is well-defined, never undefined behaviour: value(),
// operator* and operator-> then give a value-initialised T held by this Result (a null
// unique_ptr, a null handle, 0, an empty string), so a forgotten check reads an empty value
// instead of memory that is not there. status() still says why. A Result made from an Ok
// Status (which carries no value) is an error with StatusCode::InvalidArgument.
template <class T>
class [[nodiscard]] Result {
    static_assert(std::is_default_constructible_v<T>, "Result<T> needs a default-constructible T: it is what an error Result's value() gives");

public:
    Result(T value) : value_(std::move(value)) {}
    Result(Status status) : status_(std::move(status)) {
        if (status_.isOk()) status_ = Status{StatusCode::InvalidArgument, "Result<T> was made from an Ok Status, which has no value"};
    }

    bool isOk() const { return status_.isOk(); }
    explicit operator bool() const { return isOk(); }
    const Status& status() const { return status_; }
    T& value() & { return value_; }
    const T& value() const& { return value_; }
    T&& value() && { return std::move(value_); }
    T* operator->() { return &value_; }
    const T* operator->() const { return &value_; }
    T& operator*() { return value_; }
    const T& operator*() const { return value_; }

private:
    T value_{};
    Status status_;
};

// Builds a message such as "AoSettings.radius is -1; allowed (0, 1000]".
Status invalidArgument(const std::string& argument, const std::string& got, const std::string& allowed);

}  // namespace sfx

// Propagates a failed Status to the caller. Used inside functions returning Status or Result<T>.
// clang-format off
#define SFX_TRY(expr)                                   \
    do {                                                \
        ::sfx::Status sfx_try_status_ = (expr);         \
        if (!sfx_try_status_.isOk()) return sfx_try_status_; \
    } while (0)
// clang-format on
