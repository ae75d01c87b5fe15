#include "sfx/plan.hpp"

#include <cstdio>
#include <set>

namespace sfx {

uint64_t EffectPlan::totalBytes() const {
    uint64_t total = 0;
    for (const auto& r : resources) total += r.bytes;
    return total;
}

uint64_t EffectPlan::bytesOf(const std::string& effect) const {
    uint64_t total = 0;
    for (const auto& r : resources)
        if (r.effect == effect) total += r.bytes;
    return total;
}

void EffectPlan::append(const EffectPlan& other) {
    passes.insert(passes.end(), other.passes.begin(), other.passes.end());
    resources.insert(resources.end(), other.resources.begin(), other.resources.end());
}

std::string EffectPlan::describe() const {
    std::string s;
    char line[256];
    std::snprintf(line, sizeof line, "%zu passes, %zu resources, %.2f MiB\n", passes.size(), resources.size(),
                  double(totalBytes()) / (1024.0 * 1024.0));
    s += line;
    for (const auto& p : passes) {
        std::snprintf(line, sizeof line, "  pass     %-12s %-24s %5ux%-5u\n", p.effect.c_str(), p.name.c_str(), p.width, p.height);
        s += line;
    }
    for (const auto& r : resources) {
        std::snprintf(line, sizeof line, "  resource %-12s %-24s %5ux%-5u %-8s %u mip(s) %10llu bytes\n", r.effect.c_str(), r.name.c_str(), r.width,
                      r.height, toString(r.format), r.mipLevels, (unsigned long long)r.bytes);
        s += line;
    }
    std::set<std::string> effects;
    for (const auto& r : resources) effects.insert(r.effect);
    for (const auto& e : effects) {
        std::snprintf(line, sizeof line, "  total    %-12s %.2f MiB\n", e.c_str(), double(bytesOf(e)) / (1024.0 * 1024.0));
        s += line;
    }
    return s;
}

PlannedResource plannedTexture(const std::string& effect, const std::string& name, const TextureDesc& desc) {
    PlannedResource r{effect, name, desc.format, desc.width, desc.height, desc.mipLevels, 0};
    r.bytes = textureBytes(desc);
    return r;
}

}  // namespace sfx
