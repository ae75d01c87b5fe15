// What the steady-frame tests check once an effect has warmed up: no object made (every count
// of Device::stats() the same, creation totals included) and flat resident memory.
#pragma once

#include <catch2/catch.hpp>

#include <unistd.h>

#include <fstream>

#include "sfx/hal.hpp"

namespace sfx::test {

// Resident growth allowed over a few hundred steady frames: allocator and driver noise, far
// below the megabytes per frame that a per-frame allocation or shader compile costs.
constexpr double kMaxSteadyGrowthMiB = 2.0;

// Resident memory must stay flat on every backend. (Before the effects' loop counts and branches
// became specialisation constants, lavapipe recompiled their fragment shaders at every bind of
// the uniforms that decided them and kept the code: 0.8-2 MiB per frame.)
inline void checkResidentFlat(BackendKind backend, double growthMiB) {
    (void)backend;  // the same bound on every backend
    INFO("resident growth " << growthMiB << " MiB");
#if defined(__SANITIZE_ADDRESS__)
    // AddressSanitizer keeps freed memory in its quarantine, so resident memory grows with every
    // free: the sanitizer run checks memory errors and object counts, the normal build this bound.
    WARN("resident growth not bounded under AddressSanitizer: " << growthMiB << " MiB");
    return;
#endif
    CHECK(growthMiB < kMaxSteadyGrowthMiB);
}

inline double residentMiB() {
    std::ifstream statm("/proc/self/statm");
    long pages = 0, resident = 0;
    statm >> pages >> resident;
    return double(resident) * double(sysconf(_SC_PAGESIZE)) / (1024.0 * 1024.0);
}

inline void checkNothingMade(const DeviceStats& before, const DeviceStats& after) {
    auto same = [](const char* kind, const ObjectCount& a, const ObjectCount& b) {
        INFO(kind << ": live " << a.live << " -> " << b.live << ", created " << a.created << " -> " << b.created);
        CHECK(a == b);
    };
    same("textures", before.textures, after.textures);
    same("buffers", before.buffers, after.buffers);
    same("samplers", before.samplers, after.samplers);
    same("programs", before.programs, after.programs);
    same("pipelines", before.pipelines, after.pipelines);
    same("timers", before.timers, after.timers);
    same("recordings", before.recordings, after.recordings);
    same("memory allocations", before.memoryAllocations, after.memoryAllocations);
    same("staging buffers", before.stagingBuffers, after.stagingBuffers);
    same("descriptor sets", before.descriptorSets, after.descriptorSets);
    same("descriptor pools", before.descriptorPools, after.descriptorPools);
    same("image views", before.imageViews, after.imageViews);
    same("framebuffers", before.framebuffers, after.framebuffers);
    CHECK(before.deviceMemoryBytes == after.deviceMemoryBytes);
}

}  // namespace sfx::test
