// The table of validation errors (sfx/validation_errors.hpp): one row per rule, its code and its
// message. Messages name the argument, say what it is and what is allowed, in plain words: usage
// bits by name, enumerators by name, ranges as [min, max].
#include <array>
#include <cstdio>

#include "sfx/validation_errors.hpp"

#include "sfx/hal.hpp"

namespace sfx::validation {
namespace {

using C = StatusCode;
using E = Error;

constexpr ErrorEntry kTable[] = {
    {E::HandleNull, C::InvalidHandle, "HandleNull", "{} is a null {} handle; allowed a {} this device created"},
    {E::HandleForeign, C::ForeignHandle, "HandleForeign", "{} is a {} handle of another device; allowed a {} this device created"},
    {E::HandleUnknown, C::InvalidHandle, "HandleUnknown", "{} is not a {} handle of this device; allowed a {} this device created"},
    {E::HandleStale, C::StaleHandle, "HandleStale", "{} names a destroyed {}; allowed a {} that is still alive"},

    {E::TextureWidth, C::InvalidArgument, "TextureWidth", "TextureDesc.width is {}; allowed [1, {}]"},
    {E::TextureHeight, C::InvalidArgument, "TextureHeight", "TextureDesc.height is {}; allowed [1, {}]"},
    {E::TextureRenderTargetSize, C::InvalidArgument, "TextureRenderTargetSize",
     "TextureDesc is {}x{} with usage render-target; allowed at most {}x{} (the device's framebuffer and viewport limits)"},
    {E::TextureMipLevels, C::InvalidArgument, "TextureMipLevels", "TextureDesc.mipLevels is {}; allowed [1, {}] for {}x{}"},
    {E::TextureFormatUnknown, C::UnsupportedFormat, "TextureFormatUnknown", "TextureDesc.format is {}, not a Format; allowed {}"},
    {E::TextureUsage, C::InvalidArgument, "TextureUsage",
     "TextureDesc.usage is {}; allowed a non-empty combination of sampled, render-target and storage"},
    {E::TextureFormatNotSampled, C::UnsupportedFormat, "TextureFormatNotSampled",
     "TextureDesc.format is {}, which this device cannot sample; allowed with usage sampled: {}"},
    {E::TextureFormatNotRenderable, C::UnsupportedFormat, "TextureFormatNotRenderable",
     "TextureDesc.format is {}, which this device cannot render to; allowed with usage render-target: {}"},
    {E::TextureStorageUnsupported, C::UnsupportedFeature, "TextureStorageUnsupported",
     "TextureDesc.usage includes storage, but this device has no storage images{}"},
    {E::TextureStorageDepth, C::UnsupportedFormat, "TextureStorageDepth",
     "TextureDesc.format is {}, a depth format, which cannot be a storage image; allowed a colour format with usage storage"},
    {E::TextureFormatNotStorage, C::UnsupportedFormat, "TextureFormatNotStorage",
     "TextureDesc.format is {}, which this device cannot use as a storage image; allowed with usage storage: {}"},
    {E::BufferSize, C::InvalidArgument, "BufferSize", "BufferDesc.size is {}; allowed [1, {}]"},
    {E::BufferUsage, C::InvalidArgument, "BufferUsage",
     "BufferDesc.usage is {}; allowed a non-empty combination of uniform, storage, vertex and index"},
    {E::BufferStorageUnsupported, C::UnsupportedFeature, "BufferStorageUnsupported",
     "BufferDesc.usage includes storage, but this device has no storage buffers{}"},
    {E::BufferUniformSize, C::InvalidArgument, "BufferUniformSize", "BufferDesc.size is {}; allowed [1, {}] for a buffer with usage uniform"},
    {E::SamplerFilter, C::InvalidArgument, "SamplerFilter", "SamplerDesc.{} is {}; allowed Nearest or Linear"},
    {E::SamplerAddress, C::InvalidArgument, "SamplerAddress", "SamplerDesc.address is {}; allowed ClampToEdge, Repeat or MirroredRepeat"},

    {E::ProgramNoStages, C::ShaderError, "ProgramNoStages",
     "program '{}' has no stages; allowed a vertex and a fragment stage, or one compute stage"},
    {E::ProgramMixedStages, C::ShaderError, "ProgramMixedStages",
     "program '{}' mixes compute with graphics stages; allowed a vertex and a fragment stage, or one compute stage"},
    {E::ProgramMissingStage, C::ShaderError, "ProgramMissingStage",
     "program '{}' lacks a vertex or a fragment stage; allowed a vertex and a fragment stage, or one compute stage"},
    {E::ProgramComputeUnsupported, C::UnsupportedFeature, "ProgramComputeUnsupported",
     "program '{}' is a compute program, but this device has no compute shaders{}"},
    {E::ProgramStorageBufferUnsupported, C::UnsupportedFeature, "ProgramStorageBufferUnsupported",
     "program '{}' uses storage buffer '{}', but this device has no storage buffers{}"},
    {E::ProgramStorageImageUnsupported, C::UnsupportedFeature, "ProgramStorageImageUnsupported",
     "program '{}' uses storage image '{}', but this device has no storage images{}"},
    {E::ProgramFragmentStorageUnsupported, C::UnsupportedFeature, "ProgramFragmentStorageUnsupported",
     "program '{}' uses '{}' from its fragment stage, but this device has no fragment-stage stores and atomics{}"},
    {E::ProgramNoSpirv, C::ShaderError, "ProgramNoSpirv", "program '{}' has no valid SPIR-V module for its {} stage (empty, or a bad magic number)"},
    {E::ProgramTierDialect, C::UnsupportedTier, "ProgramTierDialect",
     "program '{}' is built for the {} tier, whose dialects do not include {}; allowed a program of a tier that targets it"},
    {E::ProgramNoSource, C::ShaderError, "ProgramNoSource", "program '{}' has no {} source for its {} stage"},

    {E::PipelineProgramCompute, C::InvalidArgument, "PipelineProgramCompute",
     "GraphicsPipelineDesc.program is compute program '{}'; allowed a program with vertex and fragment stages"},
    {E::PipelineProgramGraphics, C::InvalidArgument, "PipelineProgramGraphics",
     "ComputePipelineDesc.program is graphics program '{}'; allowed a compute program"},
    {E::PipelineColorCount, C::InvalidArgument, "PipelineColorCount", "GraphicsPipelineDesc.colorFormats has {} formats; allowed [0, {}]"},
    {E::PipelineColorFormat, C::UnsupportedFormat, "PipelineColorFormat",
     "GraphicsPipelineDesc.colorFormats[{}] is {}; allowed a colour format this device renders to: {}"},
    {E::PipelineDepthFormat, C::UnsupportedFormat, "PipelineDepthFormat",
     "GraphicsPipelineDesc.depthFormat is {}; allowed Undefined, D16, D24S8 or D32F"},
    {E::PipelineNoAttachments, C::InvalidArgument, "PipelineNoAttachments",
     "GraphicsPipelineDesc has no colour format and no depth format; allowed at least one of them"},
    {E::VertexStrideAttributes, C::InvalidArgument, "VertexStrideAttributes",
     "GraphicsPipelineDesc.vertexLayout.stride is {} with {} attributes; allowed a stride above 0 exactly when attributes are given"},
    {E::VertexStrideMax, C::InvalidArgument, "VertexStrideMax", "GraphicsPipelineDesc.vertexLayout.stride is {}; allowed [0, {}]"},
    {E::VertexAttributeFormat, C::InvalidArgument, "VertexAttributeFormat",
     "GraphicsPipelineDesc.vertexLayout.attributes[{}].format is {}; allowed Float2, Float3 or Float4"},
    {E::VertexAttributeLocation, C::InvalidArgument, "VertexAttributeLocation",
     "GraphicsPipelineDesc.vertexLayout.attributes[{}].location is {}; allowed [0, {}]"},
    {E::VertexAttributeLocationTwice, C::InvalidArgument, "VertexAttributeLocationTwice",
     "GraphicsPipelineDesc.vertexLayout.attributes[{}].location is {}, which attributes[{}] also has; allowed a location no other attribute uses"},
    {E::VertexAttributeOffset, C::InvalidArgument, "VertexAttributeOffset",
     "GraphicsPipelineDesc.vertexLayout.attributes[{}].offset is {}; allowed [0, {}], so that its {} bytes end within the stride of {}"},
    {E::PipelineCull, C::InvalidArgument, "PipelineCull", "GraphicsPipelineDesc.cull is {}; allowed None, Back or Front"},
    {E::PipelineDepthCompare, C::InvalidArgument, "PipelineDepthCompare",
     "GraphicsPipelineDesc.depth.compare is {}; allowed Never, Less, LessEqual, Greater, GreaterEqual, Equal, NotEqual or Always"},
    {E::PipelineBlendFactor, C::InvalidArgument, "PipelineBlendFactor",
     "GraphicsPipelineDesc.blend.{} is {}; allowed Zero, One, SrcAlpha, OneMinusSrcAlpha, DstAlpha or OneMinusDstAlpha"},
    {E::PipelineBlendInteger, C::InvalidArgument, "PipelineBlendInteger",
     "GraphicsPipelineDesc.blend.enable is true with the integer format {} in colorFormats[{}]; allowed false, as integer targets do not blend"},
    {E::PipelineBlendFormat, C::UnsupportedFormat, "PipelineBlendFormat",
     "GraphicsPipelineDesc.blend.enable is true with colorFormats[{}] = {}, which this device cannot blend; allowed blend.enable "
     "false, or a blendable format: {}"},
    {E::SpecializationConstantIdTwice, C::InvalidArgument, "SpecializationConstantIdTwice",
     "{}.constants[{}].id is {}, which constants[{}] also has; allowed an id no other constant uses"},

    {E::MipOutOfRange, C::InvalidArgument, "MipOutOfRange", "{} is {}; allowed [0, {}], the mips of the texture"},
    {E::TextureBytes, C::InvalidArgument, "TextureBytes", "{} is {}; allowed {}, the size of mip {} of a {}x{} {} texture"},
    {E::BufferRange, C::InvalidArgument, "BufferRange", "{} covers offset {} + {} bytes; allowed a non-empty range inside the buffer's {} bytes"},
    {E::NullPointer, C::InvalidArgument, "NullPointer", "{} is null; allowed a pointer to {}"},

    {E::TimerNotBegun, C::InvalidArgument, "TimerNotBegun", "endTimer: the timer was not begun; allowed after beginTimer"},
    {E::TimerNoMeasurement, C::InvalidArgument, "TimerNoMeasurement",
     "readTimer: the timer has no finished measurement; allowed after beginTimer, endTimer and flush"},

    {E::PassNoAttachments, C::InvalidArgument, "PassNoAttachments",
     "RenderPassDesc has no attachments; allowed at least one colour or depth attachment"},
    {E::PassColorCount, C::InvalidArgument, "PassColorCount", "RenderPassDesc.colors has {} attachments; allowed [0, {}]"},
    {E::PassColorTarget, C::InvalidArgument, "PassColorTarget",
     "RenderPassDesc.colors[{}].texture is a {} texture with usage {}; allowed a colour texture with usage render-target"},
    {E::PassDepthTarget, C::InvalidArgument, "PassDepthTarget",
     "RenderPassDesc.depth.texture is a {} texture with usage {}; allowed a depth texture with usage render-target"},
    {E::PassLoadOp, C::InvalidArgument, "PassLoadOp", "{} is {}; allowed Clear, Load or DontCare"},
    {E::PassSize, C::InvalidArgument, "PassSize", "{} is {}x{} at mip {}; allowed {}x{}, the size of the pass's first attachment"},

    {E::DrawPipelineCompute, C::InvalidArgument, "DrawPipelineCompute", "{} is a compute pipeline (program '{}'); allowed a graphics pipeline"},
    {E::DispatchPipelineGraphics, C::InvalidArgument, "DispatchPipelineGraphics",
     "DispatchDesc.pipeline is a graphics pipeline (program '{}'); allowed a compute pipeline"},
    {E::DrawPipelineFormats, C::InvalidArgument, "DrawPipelineFormats",
     "{} was made for colour formats [{}] and depth format {}; allowed a pipeline made for the pass's colour formats [{}] and depth format {}"},
    {E::DrawInstanceCount, C::InvalidArgument, "DrawInstanceCount", "{}.instanceCount is 0; allowed [1, 4294967295]"},
    {E::DrawVertexBufferMissing, C::InvalidArgument, "DrawVertexBufferMissing",
     "{}.vertexBuffer is null; allowed a buffer with usage vertex, as the pipeline has vertex attributes"},
    {E::DrawVertexBufferUnused, C::InvalidArgument, "DrawVertexBufferUnused",
     "{}.vertexBuffer is set; allowed null, as the pipeline has no vertex attributes"},
    {E::DrawIndexCount, C::InvalidArgument, "DrawIndexCount", "{}.count is {}; allowed [0, {}], the 32-bit indices in its index buffer of {} bytes"},
    {E::DrawVertexCount, C::InvalidArgument, "DrawVertexCount",
     "{}.count is {}; allowed [0, {}], the vertices of stride {} in its vertex buffer of {} bytes"},
    {E::DispatchUnsupported, C::UnsupportedFeature, "DispatchUnsupported", "dispatch: this device has no compute shaders{}"},
    {E::DispatchGroups, C::InvalidArgument, "DispatchGroups", "DispatchDesc.groups{} is {}; allowed [1, {}] (the device's maxComputeWorkGroupCount)"},

    {E::BindingTwice, C::InvalidArgument, "BindingTwice", "{}: binding {} is given again ({} has it); allowed each binding once"},
    {E::BindingUnknown, C::InvalidArgument, "BindingUnknown", "{}: binding {} does not exist in program '{}'; its bindings are {}"},
    {E::BindingKind, C::InvalidArgument, "BindingKind", "{}: binding {} of program '{}' is {} '{}'; allowed it in BindingSet.{}"},
    {E::BindingMissing, C::InvalidArgument, "BindingMissing", "{}.{} has nothing at binding {}; program '{}' needs {} '{}' there"},
    {E::BindingMips, C::InvalidArgument, "BindingMips", "{}: baseMip+mipCount is {}+{}; allowed a non-empty range inside the texture's {} mips"},
    {E::BindingNotFilterable, C::UnsupportedFormat, "BindingNotFilterable",
     "{}: a sampler with a Linear filter on the texture's format {}, which this device cannot filter; allowed a Nearest sampler, "
     "or a filterable format: {}"},
    {E::ResourceUsage, C::InvalidArgument, "ResourceUsage", "{} has usage {}; allowed a {} with usage {}"},
    {E::BufferBindingAlignment, C::InvalidArgument, "BufferBindingAlignment", "{}.offset is {}; allowed a multiple of {}, this device's {}"},
    {E::BufferBindingMaxRange, C::InvalidArgument, "BufferBindingMaxRange", "{} binds {} bytes; allowed at most {}, this device's {}"},
    {E::BufferBindingBlockSize, C::InvalidArgument, "BufferBindingBlockSize", "{} binds {} bytes; allowed at least the {} bytes of block '{}'"},
    {E::FeedbackLoop, C::InvalidArgument, "FeedbackLoop",
     "{}: mips {}+{} include mip {}, which the pass renders to ({}); allowed a range without it"},
    {E::MipUsedTwoWays, C::InvalidArgument, "MipUsedTwoWays",
     "{} uses mip {} of a texture that {} also uses as {}; allowed one use per mip in one command"},

    {E::MotionBlurOutputSize, C::InvalidArgument, "MotionBlurOutputSize", "MotionBlurInputs.output is {}x{}; allowed {}x{}, the MotionBlur size"},
    {E::MotionBlurOutputFormat, C::InvalidArgument, "MotionBlurOutputFormat",
     "MotionBlurInputs.output format is {}; allowed {}, the MotionBlurDesc.colorFormat"},
    {E::MotionBlurOutputUsage, C::InvalidArgument, "MotionBlurOutputUsage",
     "MotionBlurInputs.output has usage {}; allowed a texture with usage render-target"},

    {E::ShaderInvalidSpirv, C::ShaderError, "ShaderInvalidSpirv", "program '{}' has invalid SPIR-V in its {} stage:\n{}"},
    {E::ShaderCompile, C::ShaderError, "ShaderCompile", "program '{}' failed to compile its {} stage ({}): {}"},
    {E::ShaderLink, C::ShaderError, "ShaderLink", "program '{}' failed to link ({}): {}"},
    {E::HostCommandBufferRead, C::UnsupportedFeature, "HostCommandBufferRead",
     "{} needs a submit, but the device records into a host command buffer; allowed after the host submits it and calls flush()"},
    {E::ProgramTextureUnit, C::InvalidArgument, "ProgramTextureUnit",
     "program '{}' samples '{}' at binding {}; allowed bindings [0, {}], the texture units of this device"},
    {E::TimerPoolFull, C::InvalidArgument, "TimerPoolFull", "createTimer: all {} timers of the device are in use; allowed after destroying one"},
    {E::TimerHostPending, C::InvalidArgument, "TimerHostPending",
     "readTimer: the host command buffer holding the timer has not finished; allowed once the host's submit has completed"},

    {E::ExternalObjectNull, C::InvalidArgument, "ExternalObjectNull", "{} is null; allowed {}"},
    {E::ExternalQueueFamily, C::InvalidArgument, "ExternalQueueFamily",
     "ExternalVulkan.queueFamily is {}; allowed [0, {}], the queue families of ExternalVulkan.physicalDevice"},
    {E::ExternalQueueFamilyFlags, C::InvalidArgument, "ExternalQueueFamilyFlags",
     "ExternalVulkan.queueFamily is {}, a family with flags {}; allowed a family with graphics and compute"},
    {E::ExternalApiVersion, C::InvalidArgument, "ExternalApiVersion",
     "ExternalVulkan.physicalDevice supports Vulkan {}.{}; allowed 1.1 or later (1.3, or 1.1 with VK_KHR_dynamic_rendering)"},
    {E::ExternalSynchronization2, C::InvalidArgument, "ExternalSynchronization2",
     "ExternalVulkan.synchronization2Enabled is set, but ExternalVulkan.device has no vkCmdPipelineBarrier2; allowed when the device was created "
     "with the synchronization2 feature (Vulkan 1.3 or VK_KHR_synchronization2)"},
    {E::DeviceWrongApi, C::InvalidArgument, "DeviceWrongApi", "{}: device is a {} device; allowed a {} device"},
    {E::HostCommandBufferOwnDevice, C::InvalidArgument, "HostCommandBufferOwnDevice",
     "setCommandBuffer: device is the SDK's own Vulkan device (vulkan::createDevice), whose VkDevice no host command buffer belongs to; allowed a "
     "device from vulkan::wrapDevice"},
    {E::GlNoCurrentContext, C::InvalidArgument, "GlNoCurrentContext",
     "wrapCurrentContext: no GL context is current on this thread (glGetString(GL_VERSION) is null); allowed a call with the host's context current"},
};
static_assert(std::size(kTable) == size_t(Error::Count), "one row per validation::Error");

constexpr bool rowsInOrder() {
    for (size_t i = 0; i < std::size(kTable); ++i)
        if (size_t(kTable[i].error) != i) return false;
    return true;
}
static_assert(rowsInOrder(), "rows in the order of validation::Error");

std::string usageNames(uint32_t usage, std::initializer_list<std::pair<uint32_t, const char*>> bits) {
    if (usage == 0) return "none";
    std::string out;
    for (const auto& [bit, name] : bits)
        if (usage & bit) {
            out += out.empty() ? "" : " | ";
            out += name;
            usage &= ~bit;
        }
    if (usage) {
        char hex[32];
        std::snprintf(hex, sizeof hex, "0x%x (unknown)", usage);
        out += out.empty() ? "" : " | ";
        out += hex;
    }
    return out;
}

}  // namespace

const ErrorEntry& entry(Error error) { return kTable[size_t(error) < std::size(kTable) ? size_t(error) : 0]; }

Status fail(Error error, std::initializer_list<std::string_view> args) {
    const ErrorEntry& e = entry(error);
    std::string message;
    const std::string_view text = e.message;
    auto arg = args.begin();
    for (size_t i = 0; i < text.size(); ++i) {
        if (text[i] == '{' && i + 1 < text.size() && text[i + 1] == '}') {
            if (arg != args.end()) message += *arg++;
            ++i;
        } else {
            message += text[i];
        }
    }
    return {e.code, message};
}

std::string textureUsageNames(uint32_t usage) {
    return usageNames(usage, {{kTextureSampled, "sampled"}, {kTextureRenderTarget, "render-target"}, {kTextureStorage, "storage"}});
}

std::string bufferUsageNames(uint32_t usage) {
    return usageNames(usage, {{kBufferUniform, "uniform"}, {kBufferStorage, "storage"}, {kBufferVertex, "vertex"}, {kBufferIndex, "index"}});
}

std::string orList(const std::vector<std::string>& names) {
    std::string out;
    size_t i = 0;
    for (const std::string& n : names) {
        if (i > 0) out += i + 1 == names.size() ? " or " : ", ";
        out += n;
        ++i;
    }
    return out.empty() ? "none" : out;
}

}  // namespace sfx::validation
