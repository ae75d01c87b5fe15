// Internal helpers shared by the effect contexts in sdk/src/effects/ (not installed).
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <initializer_list>
#include <span>
#include <string>
#include <vector>

#include "sfx/hal.hpp"
#include "sfx/tier.hpp"
#include "sfx_shaders.hpp"

namespace sfx::detail {

// The generated program `name` for `tier`, created on `device`; shaders::find's status when
// this build has no such program. One definition for every effect context.
// The colour formats an effect reads and writes as RGBA colour (motion blur, transparency).
inline bool isColorFormat(Format f) { return f == Format::RGBA8 || f == Format::RGBA16F || f == Format::RGBA32F; }

inline Result<ProgramHandle> loadProgram(Device& device, const char* name, Tier tier) {
    Result<const CompiledProgram*> program = shaders::find(name, tier);
    if (!program) return program.status();
    return device.createProgram(*program.value());
}

// A target size inside the device's limits; `what` prefixes the field names in the message
// ("AoDesc" gives "AoDesc.width is 0; allowed [1, 16384]").
inline Status checkTargetSize(const Device& device, uint32_t width, uint32_t height, const std::string& what) {
    const DeviceLimits& limits = device.caps().limits;
    const auto range = [](uint32_t max) { return "[1, " + std::to_string(max) + "] (the device's render-target limit)"; };
    if (width == 0 || width > limits.maxRenderTargetWidth)
        return invalidArgument(what + "width", std::to_string(width), range(limits.maxRenderTargetWidth));
    if (height == 0 || height > limits.maxRenderTargetHeight)
        return invalidArgument(what + "height", std::to_string(height), range(limits.maxRenderTargetHeight));
    return Status::ok();
}

// The graphics pipelines of an effect's full-screen passes, one per (program, colour format,
// specialisation constants): a dispatch asks for the one it needs and only a combination not
// seen yet compiles one. Loop counts and branches are specialisation constants (never
// uniforms: lavapipe recompiles shaders whose control flow reads uniform values), so steady
// frames reuse their pipelines and a settings change compiles just the passes it affects.
class PipelineCache {
public:
    explicit PipelineCache(Device& device) : device_(device) {}
    ~PipelineCache() { clear(); }
    PipelineCache(const PipelineCache&) = delete;
    PipelineCache& operator=(const PipelineCache&) = delete;

    // The constants as a span (a stack array at the call site): a steady-frame lookup allocates nothing.
    // `second`: a second colour attachment's format (Undefined: one attachment).
    Result<PipelineHandle> get(ProgramHandle program, Format format, std::initializer_list<SpecializationConstant> constants, const char* debugName,
                               Format second = Format::Undefined) {
        return get(program, format, std::span<const SpecializationConstant>(constants.begin(), constants.size()), debugName, second);
    }
    Result<PipelineHandle> get(ProgramHandle program, Format format, std::span<const SpecializationConstant> constants, const char* debugName,
                               Format second = Format::Undefined) {
        for (const Entry& e : entries_)
            if (e.program == program && e.format == format && e.second == second && sameConstants(e.constants, constants)) return e.pipeline;
        // Combinations left behind by earlier settings go first, oldest first, once there are many.
        if (entries_.size() >= kMaxEntries) {
            (void)device_.destroyPipeline(entries_.front().pipeline);
            entries_.erase(entries_.begin());
        }
        GraphicsPipelineDesc pd;
        pd.program = program;
        pd.colorFormats = {format};
        if (second != Format::Undefined) pd.colorFormats.push_back(second);
        pd.debugName = debugName;
        pd.constants.assign(constants.begin(), constants.end());
        Result<PipelineHandle> pipeline = device_.createGraphicsPipeline(pd);
        if (!pipeline) return pipeline.status();
        entries_.push_back({program, format, second, pd.constants, pipeline.value()});
        return pipeline.value();
    }
    void clear() {
        for (const Entry& e : entries_) (void)device_.destroyPipeline(e.pipeline);
        entries_.clear();
    }

private:
    static constexpr size_t kMaxEntries = 32;
    struct Entry {
        ProgramHandle program;
        Format format, second;
        std::vector<SpecializationConstant> constants;
        PipelineHandle pipeline;
    };
    static bool sameConstants(const std::vector<SpecializationConstant>& a, std::span<const SpecializationConstant> b) {
        if (a.size() != b.size()) return false;
        for (size_t i = 0; i < a.size(); ++i)
            if (a[i].id != b[i].id || a[i].value != b[i].value) return false;
        return true;
    }
    Device& device_;
    std::vector<Entry> entries_;
};

// The uniform buffers of an effect, each written only when its bytes differ from the last ones
// written to it. A steady frame's parameters repeat, and every write records a staged copy and
// its barrier (Vulkan) or a buffer upload (GL) in the middle of the effect's passes. Only the
// effect writes its own uniform buffers, so the last bytes written are what the buffer holds.
// Handles carry a generation, so a recreated buffer never matches an old entry.
class UniformWrites {
public:
    Status write(Device& device, BufferHandle buffer, const void* data, size_t bytes) {
        Entry* entry = nullptr;
        for (Entry& e : entries_)
            if (e.buffer == buffer) entry = &e;
        if (entry && entry->bytes.size() == bytes && std::memcmp(entry->bytes.data(), data, bytes) == 0) return Status::ok();
        if (entry) entry->bytes.clear();  // a failed write leaves no stale match behind
        SFX_TRY(device.writeBuffer(buffer, 0, data, bytes));
        if (!entry) {
            entries_.push_back({buffer, {}});
            entry = &entries_.back();
        }
        const auto* first = static_cast<const uint8_t*>(data);
        entry->bytes.assign(first, first + bytes);  // same size: no allocation
        return Status::ok();
    }
    template <class Block>
    Status write(Device& device, BufferHandle buffer, const Block& block) {
        return write(device, buffer, &block, sizeof block);
    }

private:
    struct Entry {
        BufferHandle buffer;
        std::vector<uint8_t> bytes;
    };
    std::vector<Entry> entries_;
};

}  // namespace sfx::detail
