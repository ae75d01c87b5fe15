// What an effect will run and hold: its passes and GPU memory, so a host can see that only
// what the scene needs is modelled (no depth MIP unless a high-tier effect reads it, nothing
// for an effect that is off).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "sfx/hal.hpp"

namespace sfx {

struct PlannedPass {
    std::string effect;  // "depth", "ao", "motion_blur"
    std::string name;    // "linearize", "depth_mip 1", ...
    uint32_t width = 0, height = 0;
};

// What one planned pass cost on the device, from an effect's optional profiling
// (AmbientObscurance::setProfiling): the host's answer to "what did I pay for what".
struct PassTiming {
    std::string effect;  // as in the PlannedPass
    std::string name;
    TimerReading reading;  // its source says GPU timestamps or wall clock after glFinish
};

struct PlannedResource {
    std::string effect;
    std::string name;
    Format format = Format::Undefined;
    uint32_t width = 0, height = 0, mipLevels = 1;
    uint64_t bytes = 0;
};

struct EffectPlan {
    std::vector<PlannedPass> passes;
    std::vector<PlannedResource> resources;

    uint64_t totalBytes() const;
    uint64_t bytesOf(const std::string& effect) const;
    void append(const EffectPlan& other);
    std::string describe() const;  // a table: passes, then resources with bytes, per effect
};

// A planned resource for a texture description (bytes summed over its mips).
PlannedResource plannedTexture(const std::string& effect, const std::string& name, const TextureDesc& desc);

}  // namespace sfx
