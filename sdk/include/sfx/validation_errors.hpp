// The one table of the HAL's validation errors: every refusal a backend (Vulkan, GL, null) or the
// shared validation gives for a bad argument has its code and its message template here, so a
// bad call reads the same on every backend. The table itself is in sdk/src/validation_messages.cpp;
// tests read it to check that every rule has a case.
#pragma once

#include <cstdint>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

#include "sfx/status.hpp"

namespace sfx::validation {

enum class Error : uint32_t {
    // Handles (HandlePool::check).
    HandleNull,
    HandleForeign,
    HandleUnknown,
    HandleStale,
    // Descriptions of resources.
    TextureWidth,
    TextureHeight,
    TextureRenderTargetSize,
    TextureMipLevels,
    TextureFormatUnknown,
    TextureUsage,
    TextureFormatNotSampled,
    TextureFormatNotRenderable,
    TextureStorageUnsupported,
    TextureStorageDepth,
    TextureFormatNotStorage,
    BufferSize,
    BufferUsage,
    BufferStorageUnsupported,
    BufferUniformSize,
    SamplerFilter,
    SamplerAddress,
    // Programs.
    ProgramNoStages,
    ProgramMixedStages,
    ProgramMissingStage,
    ProgramComputeUnsupported,
    ProgramStorageBufferUnsupported,
    ProgramStorageImageUnsupported,
    ProgramFragmentStorageUnsupported,
    ProgramNoSpirv,
    ProgramTierDialect,
    ProgramNoSource,
    // Pipelines.
    PipelineProgramCompute,
    PipelineProgramGraphics,
    PipelineColorCount,
    PipelineColorFormat,
    PipelineDepthFormat,
    PipelineNoAttachments,
    VertexStrideAttributes,
    VertexStrideMax,
    VertexAttributeFormat,
    VertexAttributeLocation,
    VertexAttributeLocationTwice,
    VertexAttributeOffset,
    PipelineCull,
    PipelineDepthCompare,
    PipelineBlendFactor,
    PipelineBlendInteger,
    PipelineBlendFormat,
    SpecializationConstantIdTwice,
    // Reads and writes.
    MipOutOfRange,
    TextureBytes,
    BufferRange,
    NullPointer,
    // Timers.
    TimerNotBegun,
    TimerNoMeasurement,
    // Render passes.
    PassNoAttachments,
    PassColorCount,
    PassColorTarget,
    PassDepthTarget,
    PassLoadOp,
    PassSize,
    // Draws and dispatches.
    DrawPipelineCompute,
    DispatchPipelineGraphics,
    DrawPipelineFormats,
    DrawInstanceCount,
    DrawVertexBufferMissing,
    DrawVertexBufferUnused,
    DrawIndexCount,
    DrawVertexCount,
    DispatchUnsupported,
    DispatchGroups,
    // Bindings against the program's reflection and the bound resources.
    BindingTwice,
    BindingUnknown,
    BindingKind,
    BindingMissing,
    BindingMips,
    BindingNotFilterable,
    ResourceUsage,
    BufferBindingAlignment,
    BufferBindingMaxRange,
    BufferBindingBlockSize,
    FeedbackLoop,
    MipUsedTwoWays,
    // Effect inputs the host hands over.
    MotionBlurOutputSize,
    MotionBlurOutputFormat,
    MotionBlurOutputUsage,
    // Checks only some APIs make (see the comment at each use).
    ShaderInvalidSpirv,
    ShaderCompile,
    ShaderLink,
    HostCommandBufferRead,
    ProgramTextureUnit,
    TimerPoolFull,
    TimerHostPending,
    // The host-integration entry points (sfx/vulkan_device.hpp, sfx/gl_device.hpp).
    ExternalObjectNull,
    ExternalQueueFamily,
    ExternalQueueFamilyFlags,
    ExternalApiVersion,
    ExternalSynchronization2,
    DeviceWrongApi,
    HostCommandBufferOwnDevice,
    GlNoCurrentContext,
    Count
};

struct ErrorEntry {
    Error error;
    StatusCode code;
    const char* name;     // "BindingUnknown", for tests and logs
    const char* message;  // a sentence; each "{}" takes the next argument, in order
};

// The row of `error` in the table.
const ErrorEntry& entry(Error error);
// The Status of `error` with its template filled from `args` ("{}" in order).
Status fail(Error error, std::initializer_list<std::string_view> args);

// Words for values that messages print: usage bits as names ("sampled | render-target", "none",
// unknown bits as hex), and a list of names joined as "a, b or c".
std::string textureUsageNames(uint32_t usage);
std::string bufferUsageNames(uint32_t usage);
std::string orList(const std::vector<std::string>& names);

}  // namespace sfx::validation
