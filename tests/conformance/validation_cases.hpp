// The invalid calls of the validation parity test (test_validation_parity.cpp): for each rule of
// the validation table (sfx/validation_errors.hpp) at least one call that breaks it, the devices
// it can be made on, and the message every backend must give, spelled out.
#pragma once

#include <functional>
#include <set>
#include <string>
#include <vector>

#include "sfx/hal.hpp"
#include "sfx/validation_errors.hpp"

namespace sfx::test {

// What one case made on one device, destroyed in reverse order however the case ends.
class Objects {
public:
    explicit Objects(Device& device) : dev(device) {}
    ~Objects();
    Objects(const Objects&) = delete;
    Objects& operator=(const Objects&) = delete;

    TextureHandle texture(uint32_t w, uint32_t h, Format f, uint32_t usage, uint32_t mips = 1);
    BufferHandle buffer(uint64_t size, uint32_t usage);
    SamplerHandle sampler(const SamplerDesc& desc);
    ProgramHandle program(const CompiledProgram& p);
    ProgramHandle program(const char* name, Tier tier);
    PipelineHandle graphics(const char* name, std::vector<Format> colors, Format depth = Format::Undefined, VertexLayout layout = {},
                            Tier tier = Tier::Current);
    PipelineHandle compute(const char* name);  // a high-tier compute program
    PipelineHandle computeFrom(const CompiledProgram& p);

    Device& dev;

private:
    std::vector<std::function<void()>> undo_;
};

// The programs the cases use, from the generated table.
const CompiledProgram& shaderProgram(const char* name, Tier tier);
// hal_test_mesh's layout: position (float3) and colour (float4) in a 28-byte vertex.
VertexLayout meshLayout();
// createProgram's status; a program it made is destroyed again.
Status tryProgram(Objects& o, const CompiledProgram& p);

struct ValidationCase {
    const char* what;
    validation::Error rule;
    // Whether the call can be made on a device with these caps; empty: on every device.
    std::function<bool(const DeviceCaps&)> applies;
    // The message every backend gives; "" where part of it is the API's own words (a compiler's
    // log): then the message is only matched against the rule's template.
    std::function<std::string(const DeviceCaps&)> expected;
    std::function<Status(Objects&)> call;
    // The backend whose API alone makes this check (see the comment at its use); the call
    // succeeds on the others. Null for the shared rules.
    bool (*onlyOn)(const DeviceCaps&) = nullptr;
};

const std::vector<ValidationCase>& validationCases();

// Runs every case that applies on `device`, checking code, template and message; with `withTwin`
// a null device with the same caps must give the same status. Returns the rules it exercised.
std::set<validation::Error> runValidationCases(Device& device, bool withTwin);
// Null devices posing as what no device here is, so every rule is reached somewhere.
std::vector<DeviceCaps> craftedNullCaps();
// Every row of the table has a case, and every shared rule is in `exercised`.
void checkEveryRuleExercised(const std::set<validation::Error>& exercised);

// The first format lacking in `has` for which `eligible` holds (Undefined: none).
Format firstLackingWhere(const std::array<bool, size_t(Format::Count)>& has, const std::function<bool(Format)>& eligible);
// A colour format the device renders to but cannot blend (Undefined: none).
Format firstNonBlendableTarget(const DeviceCaps& c);

// Words the expected messages share.
inline std::string str(uint64_t v) { return std::to_string(v); }
inline std::string ceiling(const DeviceCaps& c) {
    return c.ceiling == CapabilityCeiling::None ? "" : std::string(" under its capability ceiling (") + toString(c.ceiling) + ")";
}
// The formats for which `keep` holds, as the messages list them: "R8, RGBA8 or R32F".
template <class Keep>
std::string formatList(Keep keep) {
    std::vector<std::string> names;
    for (uint32_t f = 1; f < uint32_t(Format::Count); ++f)
        if (keep(Format(f))) names.push_back(toString(Format(f)));
    return validation::orList(names);
}
inline constexpr uint32_t kRenderable = kTextureSampled | kTextureRenderTarget;

}  // namespace sfx::test
