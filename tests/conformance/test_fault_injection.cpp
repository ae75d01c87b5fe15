// Injected faults (support/fault_injection.hpp): for every k over an effect's create, dispatch
// and readback, failing the k-th resource creation, the k-th submit, or losing the device at
// the k-th call gives a named error (never a crash or an Ok with garbage), leaks nothing (the
// wrapped device's live object counts come back once the effect is gone), and the next attempt
// without the fault works and gives the same output as before any fault.
#include <catch2/catch.hpp>

#include <cstdio>
#include <functional>
#include <glm/gtc/matrix_transform.hpp>

#include "analytic_scenes.hpp"
#include "effect_runs.hpp"
#include "fault_injection.hpp"
#include "sfx/ao.hpp"
#include "sfx/depth.hpp"
#include "sfx/half.hpp"
#include "sfx/motion_blur.hpp"
#include "sfx/oit.hpp"
#include "test_device.hpp"

using namespace sfx;

namespace {

constexpr uint32_t kW = 32, kH = 18;

// What one attempt leaves behind: every live count a leak would raise.
struct LiveCounts {
    uint64_t textures, buffers, samplers, programs, pipelines, timers, memory, views, framebuffers, bytes;
    bool operator==(const LiveCounts&) const = default;
};
LiveCounts liveCounts(Device& inner) {
    // Vulkan frees destroyed objects once the submit that may use them is done: flush first.
    (void)inner.flush();
    const DeviceStats s = inner.stats();
    return {s.textures.live, s.buffers.live,           s.samplers.live,   s.programs.live,     s.pipelines.live,
            s.timers.live,   s.memoryAllocations.live, s.imageViews.live, s.framebuffers.live, s.deviceMemoryBytes};
}

Status readAll(Device& d, TextureHandle t, std::vector<uint8_t>& out) {
    Result<TextureDesc> desc = d.textureDesc(t);
    if (!desc) return desc.status();
    out.assign(size_t(mipLevelBytes(desc.value(), 0)), 0);
    return d.readTexture(t, 0, out.data(), out.size());
}

// One attempt: create the effect on `d`, run it, flush, read its output into `out`, destroy it.
using Attempt = std::function<Status(Device& d, std::vector<uint8_t>& out)>;

enum class Kind { Creation, Submit, Loss };
const char* name(Kind k) { return k == Kind::Creation ? "creation" : k == Kind::Submit ? "submit" : "device loss"; }

void checkEveryFault(const std::string& what, const Attempt& attempt) {
    Device& inner = test::device();
    test::FaultInjectingDevice fd(inner);
    std::vector<uint8_t> expected, got;
    {
        INFO(test::label() << " " << what << ": fault-free run");
        SFX_REQUIRE_OK(attempt(fd, expected));
    }
    // The second fault-free run is the one counted: warm-up work of the first (backend caches,
    // staging blocks) is not repeated.
    fd.resetCounts();
    SFX_REQUIRE_OK(attempt(fd, got));
    REQUIRE(got == expected);
    const uint64_t creations = fd.creations(), submits = fd.submits(), calls = fd.calls();
    REQUIRE(creations > 0);
    REQUIRE(submits > 0);
    std::printf("fault injection %s %s: %llu creations, %llu submits, %llu calls\n", test::label().c_str(), what.c_str(),
                (unsigned long long)creations, (unsigned long long)submits, (unsigned long long)calls);
    for (Kind kind : {Kind::Creation, Kind::Submit, Kind::Loss}) {
        const uint64_t n = kind == Kind::Creation ? creations : kind == Kind::Submit ? submits : calls;
        for (uint64_t k = 1; k <= n; ++k) {
            INFO(test::label() << " " << what << ": " << name(kind) << " fault at " << k << " of " << n);
            const LiveCounts before = liveCounts(inner);
            if (kind == Kind::Creation) fd.failCreation(k);
            if (kind == Kind::Submit) fd.failSubmit(k);
            if (kind == Kind::Loss) fd.loseDevice(k);
            const Status s = attempt(fd, got);
            const bool fired = fd.faultFired();
            fd.clearFaults();
            INFO("attempt -> " << s.toString());
            REQUIRE(fired);
            CHECK(s.code() == StatusCode::DeviceError);
            CHECK(s.message().find("injected fault") != std::string::npos);
            const LiveCounts after = liveCounts(inner);
            INFO("live textures " << before.textures << " -> " << after.textures << ", buffers " << before.buffers << " -> " << after.buffers
                                  << ", samplers " << before.samplers << " -> " << after.samplers << ", programs " << before.programs << " -> "
                                  << after.programs << ", pipelines " << before.pipelines << " -> " << after.pipelines << ", timers " << before.timers
                                  << " -> " << after.timers << ", memory " << before.memory << " -> " << after.memory << ", views " << before.views
                                  << " -> " << after.views << ", framebuffers " << before.framebuffers << " -> " << after.framebuffers << ", bytes "
                                  << before.bytes << " -> " << after.bytes);
            CHECK(after == before);
            // The fault is gone: the same attempt works and gives the same output.
            SFX_REQUIRE_OK(attempt(fd, got));
            CHECK(got == expected);
        }
    }
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

// The host's inputs, made on the wrapped device so that no fault touches them.
struct HostTexture {
    Device& device;
    TextureHandle handle;
    HostTexture(Device& d, const TextureDesc& desc, const void* data, size_t bytes) : device(d) {
        handle = d.createTexture(desc).value();
        if (data) SFX_REQUIRE_OK(d.writeTexture(handle, 0, data, bytes));
    }
    HostTexture(const HostTexture&) = delete;
    HostTexture& operator=(const HostTexture&) = delete;
    ~HostTexture() { (void)device.destroyTexture(handle); }
};

}  // namespace

TEST_CASE("fault injection: AO of each technique fails cleanly at every creation, submit and call", "[fault][ao]") {
    Device& inner = test::device();
    const tools::AnalyticScene scene = tools::cornerScene(kW, kH, 1.0);
    const std::vector<float> depth(scene.linearDepth.values.begin(), scene.linearDepth.values.end());
    HostTexture depthTex(inner, {kW, kH, 1, Format::R32F, kTextureSampled, "fault-depth"}, depth.data(), depth.size() * 4);
    const Format of = test::pickFormat(inner, {Format::R32F, Format::R16F, Format::RGBA8}, true);
    HostTexture outTex(inner, {kW, kH, 1, of, kTextureSampled | kTextureRenderTarget, "fault-ao"}, nullptr, 0);
    struct Variant {
        AoTechnique technique;
        bool profiling;  // per-pass timers: the timer creations are faulted too
    };
    for (Variant v : {Variant{AoTechnique::Alchemy, false}, Variant{AoTechnique::Scalable, false}, Variant{AoTechnique::Crease, false},
                      Variant{AoTechnique::Horizon, false}, Variant{AoTechnique::Scalable, true}}) {
        const AoSettings settings = test::aoTestSettings(v.technique);
        // Hardware depth in the desc: the linearisation pass (and on the high tier the MIP) runs too.
        checkEveryFault(std::string("ao ") + toString(v.technique) + (v.profiling ? " profiled" : ""),
                        [&](Device& d, std::vector<uint8_t>& out) -> Status {
                            auto ao = AmbientObscurance::create(d, {kW, kH, test::tierProfile(), settings, DepthKind::Hardware});
                            if (!ao) return ao.status();
                            if (v.profiling)
                                if (Status s = ao.value()->setProfiling(true); !s) return s;
                            AoInputs in;
                            in.depth = DepthSource{depthTex.handle, DepthKind::Linear, scene.camera};
                            in.output = outTex.handle;
                            if (Status s = ao.value()->dispatch(in); !s) return s;
                            if (Status s = d.flush(); !s) return s;
                            if (v.profiling) {
                                auto t = ao.value()->passTimings();
                                if (!t) return t.status();
                            }
                            return readAll(d, outTex.handle, out);
                        });
    }
}

TEST_CASE("fault injection: the depth pyramid fails cleanly at every creation, submit and call", "[fault][depth]") {
    Device& inner = test::device();
    const tools::AnalyticScene scene = tools::cornerScene(kW, kH, 1.0);
    const std::vector<float> depth(scene.linearDepth.values.begin(), scene.linearDepth.values.end());
    HostTexture depthTex(inner, {kW, kH, 1, Format::R32F, kTextureSampled, "fault-depth"}, depth.data(), depth.size() * 4);
    const uint32_t levels = test::tier() == Tier::High ? 3 : 1;
    checkEveryFault("depth pyramid " + std::to_string(levels) + " levels", [&](Device& d, std::vector<uint8_t>& out) -> Status {
        auto ld = LinearDepth::create(d, {kW, kH, test::tier(), levels, DepthKind::Hardware});
        if (!ld) return ld.status();
        if (Status s = ld.value()->dispatch({depthTex.handle, DepthKind::Linear, scene.camera}); !s) return s;
        if (Status s = d.flush(); !s) return s;
        std::vector<uint8_t> level;
        out.clear();
        Result<TextureDesc> desc = d.textureDesc(ld.value()->texture());
        if (!desc) return desc.status();
        for (uint32_t m = 0; m < levels; ++m) {
            level.assign(size_t(mipLevelBytes(desc.value(), m)), 0);
            if (Status s = d.readTexture(ld.value()->texture(), m, level.data(), level.size()); !s) return s;
            out.insert(out.end(), level.begin(), level.end());
        }
        return {};
    });
}

TEST_CASE("fault injection: motion blur fails cleanly at every creation, submit and call", "[fault][motion_blur]") {
    Device& inner = test::device();
    const tools::AnalyticScene scene = tools::tiltedPlaneScene(kW, kH);
    const std::vector<float> depth(scene.linearDepth.values.begin(), scene.linearDepth.values.end());
    std::vector<uint16_t> color(size_t(kW) * kH * 4, floatToHalf(1.0f));
    std::vector<float> velocity(size_t(kW) * kH * 2);
    for (size_t i = 0; i < size_t(kW) * kH; ++i) {
        color[i * 4 + 0] = floatToHalf(float(i % kW) / kW);
        color[i * 4 + 1] = floatToHalf(float(i / kW) / kH);
        velocity[i * 2 + 0] = 5.0f;
        velocity[i * 2 + 1] = -2.0f;
    }
    HostTexture depthTex(inner, {kW, kH, 1, Format::R32F, kTextureSampled, "fault-depth"}, depth.data(), depth.size() * 4);
    HostTexture colorTex(inner, {kW, kH, 1, Format::RGBA16F, kTextureSampled, "fault-colour"}, color.data(), color.size() * 2);
    HostTexture velTex(inner, {kW, kH, 1, Format::RG32F, kTextureSampled, "fault-velocity"}, velocity.data(), velocity.size() * 4);
    checkEveryFault("motion blur", [&](Device& d, std::vector<uint8_t>& out) -> Status {
        auto mb = MotionBlur::create(d, {kW, kH, test::tierProfile(), Format::RGBA16F, DepthKind::Hardware});
        if (!mb) return mb.status();
        MotionBlurInputs in;
        in.color = colorTex.handle;
        in.depth = DepthSource{depthTex.handle, DepthKind::Linear, scene.camera};
        in.velocity = velTex.handle;
        if (Status s = mb.value()->dispatch(in); !s) return s;
        if (Status s = d.flush(); !s) return s;
        return readAll(d, mb.value()->output(), out);
    });
}

TEST_CASE("fault injection: transparency fails cleanly at every creation, submit and call", "[fault][oit]") {
    Device& inner = test::device();
    std::vector<uint16_t> color(size_t(kW) * kH * 4, floatToHalf(0.5f));
    std::vector<float> depth(size_t(kW) * kH, 1.0f);
    HostTexture opaque(inner, {kW, kH, 1, Format::RGBA16F, kTextureSampled | kTextureRenderTarget, "fault-opaque"}, color.data(), color.size() * 2);
    HostTexture opaqueDepth(inner, {kW, kH, 1, Format::D32F, kTextureSampled | kTextureRenderTarget, "fault-opaque-depth"}, depth.data(),
                            depth.size() * 4);
    const float c[6][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, -1}, {1, 1}, {-1, 1}};
    std::vector<TransparentVertex> quad;
    for (const auto& p : c) quad.push_back({{p[0] * 0.8f, p[1] * 0.8f, 0.0f}, {0.0f, 0.0f, 1.0f}});
    BufferHandle vb = inner.createBuffer({quad.size() * sizeof(TransparentVertex), kBufferVertex, "fault-quad"}).value();
    SFX_REQUIRE_OK(inner.writeBuffer(vb, 0, quad.data(), quad.size() * sizeof(TransparentVertex)));
    std::vector<TransparentDraw> draws;
    for (uint32_t i = 0; i < 3; ++i) {
        TransparentDraw d;
        d.vertices = vb;
        d.vertexCount = 6;
        d.model = glm::translate(glm::mat4(1.0f), glm::vec3(0.1f * float(i), 0.0f, -2.0f - float(i)));
        d.color = glm::vec3(0.2f + 0.3f * float(i), 0.5f, 0.9f - 0.2f * float(i));
        d.opacity = 0.5f;
        d.id = i;
        draws.push_back(d);
    }
    // Orthographic along -z into the device's clip depth range, near 0.5, far 20.
    const bool zeroToOne = inner.caps().clipDepth == ClipDepthRange::ZeroToOne;
    glm::mat4 proj(1.0f);
    proj[2][2] = zeroToOne ? -1.0f / 19.5f : -2.0f / 19.5f;
    proj[3][2] = zeroToOne ? -0.5f / 19.5f : -1.0f / 19.5f - 1.0f;
    checkEveryFault("transparency", [&](Device& d, std::vector<uint8_t>& out) -> Status {
        TransparencyDesc desc;
        desc.width = kW;
        desc.height = kH;
        desc.profile = test::tierProfile();
        auto oit = Transparency::create(d, desc);
        if (!oit) return oit.status();
        TransparencyInputs in;
        in.opaqueColor = opaque.handle;
        in.opaqueDepth = opaqueDepth.handle;
        in.projection = proj;
        in.draws = draws;
        // Two frames: the second reads the first's fragment count and sizes the pool from it.
        for (int f = 0; f < 2; ++f) {
            if (Status s = oit.value()->render(in); !s) return s;
            if (Status s = d.flush(); !s) return s;
        }
        return readAll(d, oit.value()->output(), out);
    });
    (void)inner.destroyBuffer(vb);
}
