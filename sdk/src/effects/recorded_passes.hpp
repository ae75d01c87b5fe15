// Internal helper of the effect contexts in sdk/src/effects/ (not installed): an effect's passes
// recorded once and replayed in later frames (Device::beginRecording / beginReplay).
//
// Why: on Vulkan most of a steady dispatch's CPU time is recording the same commands again —
// binding resolution, descriptor-set lookups, barrier tracking, the HAL's argument checks and
// the driver copying every command. A replay runs the recorded secondary command buffer with
// one vkCmdExecuteCommands and the barriers its inputs need after the host's own work.
//
// Correctness does not rest on the key: the device compares every renderPass and dispatch
// argument of the replayed calls with the recorded ones, and refuses (StaleHandle) a recording
// whose objects or resource states changed; the effect then records again in the same frame.
// The key (the effect's input handles) only picks which recording to try, so that a host
// alternating between images (double-buffered outputs) keeps one recording per image set.
#pragma once

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <vector>

#include "sfx/hal.hpp"

namespace sfx::detail {

class RecordedPasses {
public:
    explicit RecordedPasses(Device& device) : device_(device) {}
    ~RecordedPasses() { clear(); }
    RecordedPasses(const RecordedPasses&) = delete;
    RecordedPasses& operator=(const RecordedPasses&) = delete;

    // The key of a set of input handles (bits of TextureHandle and the like).
    static uint64_t key(std::initializer_list<uint64_t> handleBits) {
        uint64_t h = 1469598103934665603ull;  // FNV-1a over the 64-bit words
        for (uint64_t v : handleBits) h = (h ^ v) * 1099511628211ull;
        return h;
    }

    // Runs record() — the effect's passes, uniform writes included — as a replay of the
    // recording kept for `key` where the device keeps recordings, else as a new recording kept
    // for the next frame. Devices without recordings (GL, the null backend) just run it.
    template <class Record>
    Status run(uint64_t key, Record&& record) {
        if (!device_.caps().reusableRecordings) return record();
        Entry* e = find(key);
        if (e && e->misses >= kMaxMisses) return record();  // never steady: recording would only add work
        // An entry without a recording: the last attempt to record for it failed; record again.
        if (e && !e->recording.isNull()) {
            SFX_TRY(device_.beginReplay(e->recording));
            const Status recorded = record();
            const Status replayed = device_.endReplay();
            SFX_TRY(recorded);
            if (replayed) {
                e->misses = 0;
                e->lastUse = ++clock_;
                return Status::ok();
            }
            if (replayed.code() != StatusCode::StaleHandle) return replayed;
            // Stale: the same calls once more, recorded (this frame's work is still to do).
            (void)device_.destroyRecording(e->recording);
            e->recording = {};
            if (++e->misses >= kMaxMisses) return record();
        }
        if (const Status begun = device_.beginRecording(); !begun) {
            // A decorator of a device that forwards caps() but not these calls keeps none.
            if (begun.code() == StatusCode::UnsupportedFeature) return record();
            return begun;
        }
        const Status recorded = record();
        Result<RecordingHandle> recording = device_.endRecording();
        if (!recorded) {
            if (recording) (void)device_.destroyRecording(recording.value());
            return recorded;
        }
        if (!recording) return recording.status();
        if (!e) e = &slotFor(key);
        e->recording = recording.value();
        e->lastUse = ++clock_;
        return Status::ok();
    }

    // Forgets every recording (the device also refuses them once an object they use is gone).
    void clear() {
        for (const Entry& e : entries_)
            if (!e.recording.isNull()) (void)device_.destroyRecording(e.recording);
        entries_.clear();
    }

private:
    // Recordings kept per effect: a host's rotation of output images, and a little more.
    static constexpr size_t kMaxEntries = 4;
    // Replays refused in a row (each one costs a comparison and a new recording) before the key
    // is recorded directly every frame: a resource whose state differs every frame never replays.
    static constexpr uint32_t kMaxMisses = 3;
    struct Entry {
        uint64_t key = 0;
        RecordingHandle recording;
        uint64_t lastUse = 0;
        uint32_t misses = 0;
    };

    Entry* find(uint64_t key) {
        for (Entry& e : entries_)
            if (e.key == key) return &e;
        return nullptr;
    }
    // A new entry for `key`, in place of the least recently used one once there are enough.
    Entry& slotFor(uint64_t key) {
        if (entries_.size() < kMaxEntries) {
            entries_.push_back({key, {}, 0, 0});
            return entries_.back();
        }
        Entry* oldest = &entries_.front();
        for (Entry& e : entries_)
            if (e.lastUse < oldest->lastUse) oldest = &e;
        if (!oldest->recording.isNull()) (void)device_.destroyRecording(oldest->recording);
        *oldest = {key, {}, 0, 0};
        return *oldest;
    }

    Device& device_;
    std::vector<Entry> entries_;
    uint64_t clock_ = 0;
};

}  // namespace sfx::detail
