// The shared fixture of the HAL conformance tests (tests/conformance/test_hal_*.cpp): makers
// that destroy what a test created however it ends, the embedded test programs, full-screen
// passes, readback, and the named-error check. Backend-agnostic: only the HAL.
#pragma once

#include <catch2/catch.hpp>

#include <functional>
#include <vector>

#include "sfx_shaders.hpp"
#include "sfx_test_shaders.hpp"
#include "skips.hpp"
#include "test_device.hpp"

namespace sfx::test {

inline Device& dev() { return device(); }

// Destroys what a test made, in reverse order, however the test ends.
struct Cleanup {
    std::vector<std::function<void()>> steps;
    Cleanup() = default;
    Cleanup(const Cleanup&) = delete;
    Cleanup& operator=(const Cleanup&) = delete;
    ~Cleanup() {
        for (auto it = steps.rbegin(); it != steps.rend(); ++it) (*it)();
    }
};

// The embedded program `name` for `tier`: a runtime program (copy, ...) or a test one
// (hal_test_*, hal_gltest_*, hal_atomic_count).
const CompiledProgram& program(const char* name, Tier tier = test::tier());

TextureHandle makeTexture(Cleanup& c, uint32_t w, uint32_t h, Format f, uint32_t usage, uint32_t mips = 1);
BufferHandle makeBuffer(Cleanup& c, uint64_t size, uint32_t usage, const void* data = nullptr);
ProgramHandle makeProgram(Cleanup& c, const CompiledProgram& p);
PipelineHandle makePipeline(Cleanup& c, GraphicsPipelineDesc desc, const char* programName);
PipelineHandle fullscreenPipeline(Cleanup& c, const char* programName, Format color);

inline bool renderable(Format f) { return dev().caps().renderableFormat[size_t(f)]; }

template <class T>
std::vector<T> readLevel(TextureHandle t, uint32_t mip = 0) {
    TextureDesc d = dev().textureDesc(t).value();
    std::vector<T> out(mipLevelBytes(d, mip) / sizeof(T));
    SFX_REQUIRE_OK(dev().readTexture(t, mip, out.data(), out.size() * sizeof(T)));
    return out;
}

// Full-screen pass of `pipeline` into `target` with the given bindings.
void fullscreenPass(TextureHandle target, PipelineHandle pipeline, BindingSet bindings = {}, uint32_t mip = 0);

// Mip `mip` of `source` (w x h there) drawn through the copy program into a new R32F target,
// read back: what a pass sampling `source` sees.
std::vector<float> sampledThroughCopy(Cleanup& c, TextureHandle source, uint32_t w, uint32_t h, uint32_t mip = 0);

struct MeshVertex {
    float x, y, z;
    float r, g, b, a;
};
GraphicsPipelineDesc meshPipelineDesc(Format color, Format depth);

// The status names the field and the allowed range, the same words on every backend.
void checkNamed(const Status& s, StatusCode code, const char* field);

inline constexpr uint32_t kW = 16, kH = 8;  // not square, so a transposed readback shows

}  // namespace sfx::test
