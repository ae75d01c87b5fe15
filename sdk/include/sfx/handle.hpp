// Typed handles with generation bits. A handle names an object owned by one device:
// using it after destruction is StaleHandle, on another device ForeignHandle, never a crash.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "sfx/status.hpp"
#include "sfx/validation_errors.hpp"

namespace sfx {

// bits: [63..48] device serial, [47..32] generation, [31..0] slot index + 1. Zero is "no object".
template <class Tag>
struct Handle {
    uint64_t bits = 0;
    bool isNull() const { return bits == 0; }
    friend bool operator==(Handle a, Handle b) { return a.bits == b.bits; }
    friend bool operator!=(Handle a, Handle b) { return a.bits != b.bits; }
};

struct TextureTag;
struct BufferTag;
struct SamplerTag;
struct ProgramTag;
struct PipelineTag;
struct TimerTag;
struct RecordingTag;
using TextureHandle = Handle<TextureTag>;
using BufferHandle = Handle<BufferTag>;
using SamplerHandle = Handle<SamplerTag>;
using ProgramHandle = Handle<ProgramTag>;
using PipelineHandle = Handle<PipelineTag>;
using TimerHandle = Handle<TimerTag>;
using RecordingHandle = Handle<RecordingTag>;

// Returns a process-unique serial for a new device (1..65535, wrapping past 0).
uint16_t nextDeviceSerial();

// Slot storage behind a handle type; backends keep one per object kind.
template <class Tag, class T>
class HandlePool {
public:
    explicit HandlePool(uint16_t deviceSerial, const char* kindName) : serial_(deviceSerial), kind_(kindName) {}

    Handle<Tag> insert(T object) {
        uint32_t index;
        if (!freeList_.empty()) {
            index = freeList_.back();
            freeList_.pop_back();
        } else {
            index = static_cast<uint32_t>(slots_.size());
            slots_.push_back({});
        }
        Slot& slot = slots_[index];
        slot.object = std::move(object);
        slot.alive = true;
        ++created_;
        return Handle<Tag>{(uint64_t(serial_) << 48) | (uint64_t(slot.generation) << 32) | (uint64_t(index) + 1)};
    }

    // Ok when the handle names a live object of this pool; the error says which rule failed.
    Status check(Handle<Tag> h, std::string_view argument) const {
        using validation::Error;
        if (h.isNull()) return validation::fail(Error::HandleNull, {argument, kind_, kind_});
        if (uint16_t(h.bits >> 48) != serial_) return validation::fail(Error::HandleForeign, {argument, kind_, kind_});
        uint64_t index = (h.bits & 0xffffffffu) - 1;
        if (index >= slots_.size()) return validation::fail(Error::HandleUnknown, {argument, kind_, kind_});
        const Slot& slot = slots_[index];
        if (!slot.alive || slot.generation != uint16_t(h.bits >> 32)) return validation::fail(Error::HandleStale, {argument, kind_, kind_});
        return Status::ok();
    }

    // Precondition: check(h) is Ok.
    T& get(Handle<Tag> h) { return slots_[(h.bits & 0xffffffffu) - 1].object; }
    const T& get(Handle<Tag> h) const { return slots_[(h.bits & 0xffffffffu) - 1].object; }

    // Precondition: check(h) is Ok. Returns the object so the caller can release it.
    T remove(Handle<Tag> h) {
        uint32_t index = uint32_t((h.bits & 0xffffffffu) - 1);
        Slot& slot = slots_[index];
        T object = std::move(slot.object);
        slot.object = T{};
        slot.alive = false;
        // A slot whose generation would wrap is retired for good: reusing it would let a
        // handle from 65536 generations ago name the new object instead of being stale.
        if (slot.generation == 0xffffu) {
            ++retired_;
            return object;
        }
        slot.generation = uint16_t(slot.generation + 1);
        freeList_.push_back(index);
        return object;
    }

    template <class F>
    void forEachAlive(F&& f) {
        for (Slot& s : slots_)
            if (s.alive) f(s.object);
    }
    size_t aliveCount() const { return slots_.size() - freeList_.size() - retired_; }
    uint64_t createdCount() const { return created_; }  // inserts over the pool's life

private:
    struct Slot {
        T object{};
        uint16_t generation = 1;
        bool alive = false;
    };
    uint16_t serial_;
    const char* kind_;
    std::vector<Slot> slots_;
    std::vector<uint32_t> freeList_;
    size_t retired_ = 0;  // slots whose generations ran out
    uint64_t created_ = 0;
};

}  // namespace sfx
