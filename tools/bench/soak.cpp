// soak: many frames of AO and motion blur per backend with resize churn (sizes cycling, 1x1
// included), settings changes and tier changes, to find what a short test cannot: slow leaks
// of host memory or device objects, and validation errors on rare transitions.
//   soak [--backends vulkan,gles,gl-egl,gl-osmesa] [--frames 10000] [--progress 1000] [--no-validation]
//        [--memory-report-only]
// Every frame: AO (technique cycling, horizon with and without bent normals) and motion blur
// (settings cycling) dispatched and flushed. Every kFramesPerChange frames the size changes; the
// tier changes every kSizes.size() changes (both effects are made again) and the AO technique
// every kSizes.size() x tiers changes, so one cycle meets every size x technique x tier. Checks
// per backend:
//   - resident memory after the warm-up (one full cycle of every size x technique x tier, or a
//     tenth of the frames if more) peaks at most 1% above its peak in the warm-up's last cycle;
//   - Device::stats() live counts are what they were before the first frame once everything is
//     destroyed, and the backend's caches (descriptor sets, staging) do not grow after warm-up;
//   - no validation message (validation on unless --no-validation).
// --memory-report-only prints the growth without checking it: for a run whose resident memory
// includes the API's validation layers, which grow on their own under object churn (Vulkan's:
// docs/robustness.md, "Soak"); tools/run_soak.sh checks memory in a run without them.
// Exit 0 when every backend passed, 1 when one failed, 2 on bad arguments.
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "sfx/ao.hpp"
#include "sfx/backends.hpp"
#include "sfx/depth.hpp"
#include "sfx/half.hpp"
#include "sfx/motion_blur.hpp"
#include "sfx/tiers.hpp"
#include "sfx_shaders.hpp"
#include "sfx_shared_mb.h"

using namespace sfx;

namespace {

struct Size {
    uint32_t w, h;
};
const std::vector<Size> kSizes = {{1, 1}, {160, 90}, {33, 17}, {1, 64}, {64, 1}, {320, 180}, {97, 61}};
constexpr int kFramesPerChange = 10;
const AoTechnique kTechniques[] = {AoTechnique::Alchemy, AoTechnique::Scalable, AoTechnique::Crease, AoTechnique::Horizon};

double residentMiB() {
    std::ifstream statm("/proc/self/statm");
    long pages = 0, resident = 0;
    statm >> pages >> resident;
    return double(resident) * double(sysconf(_SC_PAGESIZE)) / (1024.0 * 1024.0);
}

// The host's per-size inputs and AO output.
struct HostTargets {
    Device& dev;
    TextureHandle depth, color, velocity, aoOut, bentNormals;
    explicit HostTargets(Device& d) : dev(d) {}
    ~HostTargets() { release(); }
    void release() {
        for (TextureHandle* t : {&depth, &color, &velocity, &aoOut, &bentNormals})
            if (!t->isNull()) (void)dev.destroyTexture(*t), *t = {};
    }
    Status make(Size s) {
        release();
        const size_t n = size_t(s.w) * s.h;
        std::vector<float> z(n), v(n * 2);
        std::vector<uint16_t> c(n * 4);
        for (size_t i = 0; i < n; ++i) {
            const float x = float(i % s.w) / float(s.w), y = float(i / s.w) / float(s.h);
            z[i] = 2.0f + 6.0f * x + (y > 0.5f ? 1.0f : 0.0f);
            v[i * 2] = 12.0f * (x - 0.5f), v[i * 2 + 1] = -4.0f * y;
            c[i * 4] = floatToHalf(x), c[i * 4 + 1] = floatToHalf(y), c[i * 4 + 2] = floatToHalf(0.5f);
            c[i * 4 + 3] = floatToHalf(1.0f);
        }
        const Format aoFormat = dev.caps().renderableFormat[size_t(Format::R16F)] ? Format::R16F : Format::RGBA8;
        struct Make {
            TextureHandle* out;
            TextureDesc desc;
            const void* data;
            size_t bytes;
        };
        const Make makes[] = {{&depth, {s.w, s.h, 1, Format::R32F, kTextureSampled, "soak-depth"}, z.data(), z.size() * 4},
                              {&color, {s.w, s.h, 1, Format::RGBA16F, kTextureSampled, "soak-colour"}, c.data(), c.size() * 2},
                              {&velocity, {s.w, s.h, 1, Format::RG32F, kTextureSampled, "soak-velocity"}, v.data(), v.size() * 4},
                              {&aoOut, {s.w, s.h, 1, aoFormat, kTextureSampled | kTextureRenderTarget, "soak-ao"}, nullptr, 0},
                              {&bentNormals, {s.w, s.h, 1, Format::RGBA8, kTextureSampled | kTextureRenderTarget, "soak-bent-normals"}, nullptr, 0}};
        for (const Make& m : makes) {
            Result<TextureHandle> t = dev.createTexture(m.desc);
            if (!t) return t.status();
            *m.out = t.value();
            if (m.data)
                if (Status st = dev.writeTexture(*m.out, 0, m.data, m.bytes); !st) return st;
        }
        return {};
    }
};

CameraProjection camera(Size s) {
    PerspectiveDesc pd;
    pd.aspect = double(s.w) / double(s.h);
    return makePerspective(pd).value();
}

struct Live {
    DeviceStats s;
    // The HAL kinds and what the backend made behind them, without its caches.
    bool sameObjects(const DeviceStats& o) const {
        return s.textures.live == o.textures.live && s.buffers.live == o.buffers.live && s.samplers.live == o.samplers.live &&
            s.programs.live == o.programs.live && s.pipelines.live == o.pipelines.live && s.timers.live == o.timers.live &&
            s.imageViews.live == o.imageViews.live && s.framebuffers.live == o.framebuffers.live;
    }
};

std::string counts(const DeviceStats& s) {
    std::ostringstream o;
    o << "textures " << s.textures.live << ", buffers " << s.buffers.live << ", samplers " << s.samplers.live << ", programs " << s.programs.live
      << ", pipelines " << s.pipelines.live << ", timers " << s.timers.live << ", image views " << s.imageViews.live << ", framebuffers "
      << s.framebuffers.live << ", memory allocations " << s.memoryAllocations.live << ", staging " << s.stagingBuffers.live << ", descriptor sets "
      << s.descriptorSets.live << ", device bytes " << s.deviceMemoryBytes;
    return o.str();
}

struct Effects {
    std::unique_ptr<AmbientObscurance> ao;
    std::unique_ptr<MotionBlur> mb;
};

// One backend's soak; false when a check failed.
bool soak(const BackendConfig& config, int frames, int progressEvery, bool validation, bool checkMemory) {
    const std::string name = toString(config);
    DeviceOptions options;
    options.validation = validation;
    Result<std::unique_ptr<Device>> opened = openDevice(config, options);
    if (!opened) {
        std::printf("soak %s: skipped, %s\n", name.c_str(), opened.status().toString().c_str());
        return true;
    }
    Device& dev = *opened.value();
    Result<tiers::TierChoice> best = tiers::choose(dev.caps());
    if (!best) {
        std::printf("soak %s: skipped, %s\n", name.c_str(), best.status().toString().c_str());
        return true;
    }
    std::vector<Tier> tiersToRun{best->tier};
    if (best->tier != Tier::Current) tiersToRun.push_back(Tier::Current);
    const int techniques = int(std::size(kTechniques));
    const int cycle = int(kSizes.size()) * techniques * int(tiersToRun.size()) * kFramesPerChange;
    const int warmup = std::max(cycle, frames / 10);
    std::printf("soak %s: %s; %d frames, warm-up %d, tiers %zu, sizes %zu\n", name.c_str(), dev.caps().summary().c_str(), frames, warmup,
                tiersToRun.size(), kSizes.size());

    bool ok = true;
    std::vector<std::string> messages;
    auto fail = [&](int frame, const std::string& what) {
        std::printf("soak %s: FAIL at frame %d: %s\n", name.c_str(), frame, what.c_str());
        ok = false;
    };
    const Live start{dev.stats()};
    double rssWarm = 0, rssPeak = 0;
    DeviceStats warmStats;
    const auto t0 = std::chrono::steady_clock::now();
    {
        HostTargets host(dev);
        Effects fx;
        int lastTier = -1;
        Size size{0, 0};
        for (int f = 0; f < frames && ok; ++f) {
            const int phase = f / kFramesPerChange;
            if (f % kFramesPerChange == 0) {
                const Size s = kSizes[size_t(phase) % kSizes.size()];
                const int tierIndex = (phase / int(kSizes.size())) % int(tiersToRun.size());
                AoSettings aoSettings;
                aoSettings.technique = kTechniques[(phase / (int(kSizes.size()) * int(tiersToRun.size()))) % techniques];
                aoSettings.radius = 0.25f + 0.25f * float(phase % 4);
                aoSettings.bentNormals = aoSettings.technique == AoTechnique::Horizon && phase % 2 == 0;
                const TierProfile& profile = tiers::profile(tiersToRun[size_t(tierIndex)]);
                if (Status st = host.make(s); !st) fail(f, "host textures: " + st.toString());
                if (tierIndex != lastTier) {
                    fx = {};
                    auto ao = AmbientObscurance::create(dev, {s.w, s.h, profile, aoSettings, DepthKind::Hardware});
                    auto mb = MotionBlur::create(dev, {s.w, s.h, profile, Format::RGBA16F, DepthKind::Hardware});
                    if (!ao) fail(f, "AO create: " + ao.status().toString());
                    if (!mb) fail(f, "motion blur create: " + mb.status().toString());
                    if (!ok) break;
                    fx.ao = std::move(ao.value());
                    fx.mb = std::move(mb.value());
                    lastTier = tierIndex;
                } else {
                    if (s.w != size.w || s.h != size.h) {
                        if (Status st = fx.ao->resize(s.w, s.h); !st) fail(f, "AO resize: " + st.toString());
                        if (Status st = fx.mb->resize(s.w, s.h); !st) fail(f, "motion blur resize: " + st.toString());
                    }
                    if (Status st = fx.ao->setSettings(aoSettings); !st) fail(f, "AO settings: " + st.toString());
                }
                size = s;
            }
            if (!ok) break;
            AoInputs aoIn;
            aoIn.depth = DepthSource{host.depth, DepthKind::Linear, camera(size)};
            aoIn.output = host.aoOut;
            if (fx.ao->desc().settings.bentNormals) aoIn.bentNormals = host.bentNormals;
            MotionBlurInputs mbIn;
            mbIn.color = host.color;
            mbIn.depth = aoIn.depth;
            mbIn.velocity = (phase % 2) ? host.velocity : TextureHandle{};  // camera-only velocity every other change
            mbIn.camera.previousViewProjection[3][0] = 0.01 * double(phase % 5);
            MotionBlurSettings mbSettings;
            mbSettings.samples = 3 + 2 * uint32_t(phase % 5);
            mbSettings.maxRadiusPx = 4.0f + 4.0f * float(phase % 3);
            mbSettings.exposure = phase % 7 == 3 ? 0.0f : 1.0f;
            if (Status st = fx.ao->dispatch(aoIn); !st) fail(f, "AO dispatch: " + st.toString());
            if (Status st = fx.mb->dispatch(mbIn, mbSettings); !st) fail(f, "motion blur dispatch: " + st.toString());
            if (Status st = dev.flush(); !st) fail(f, "flush: " + st.toString());
            for (std::string& m : dev.takeValidationMessages()) {
                if (messages.size() < 5) std::printf("soak %s: validation at frame %d: %s\n", name.c_str(), f, m.c_str());
                messages.push_back(std::move(m));
            }
            // Like with like: the highest resident memory of the warm-up's last full cycle (every
            // size, technique and tier once) against the highest of every frame after it.
            if (f + 1 > warmup - cycle && f + 1 <= warmup) rssWarm = std::max(rssWarm, residentMiB());
            if (f + 1 == warmup) warmStats = dev.stats();
            if (f + 1 > warmup) rssPeak = std::max(rssPeak, residentMiB());
            if (progressEvery > 0 && (f + 1) % progressEvery == 0) {
                const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
                std::printf("soak %s: frame %d / %d, %.1f s, resident %.1f MiB\n", name.c_str(), f + 1, frames, secs, residentMiB());
                std::fflush(stdout);
            }
        }
        if (ok && frames > warmup) {
            const DeviceStats end = dev.stats();
            if (end.descriptorSets.live > warmStats.descriptorSets.live || end.stagingBuffers.live > warmStats.stagingBuffers.live ||
                end.memoryAllocations.live > warmStats.memoryAllocations.live)
                fail(frames, "backend caches grew after warm-up: " + counts(warmStats) + " -> " + counts(end));
        }
    }
    (void)dev.flush();
    const DeviceStats end = dev.stats();
    const double rssEnd = residentMiB();
    const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (!start.sameObjects(end)) fail(frames, "objects left after destroying everything: " + counts(start.s) + " -> " + counts(end));
    if (!messages.empty()) fail(frames, std::to_string(messages.size()) + " validation messages");
    double growth = 0;
    if (frames > warmup && rssWarm > 0) {
        growth = (rssPeak - rssWarm) / rssWarm * 100.0;
        if (growth > 1.0 && checkMemory) fail(frames, "resident memory grew " + std::to_string(growth) + "% after warm-up (allowed 1%)");
    }
    std::printf(
        "soak %s: %s, %d frames in %.1f s (%.2f ms/frame), validation %s, resident peak in the last warm-up cycle %.1f MiB, "
        "after it %.1f MiB (%+.2f%%%s), at end %.1f MiB; live objects at start [%s], at end [%s]; %zu validation messages\n",
        name.c_str(), ok ? "PASS" : "FAIL", frames, secs, 1000.0 * secs / frames, validation ? "on" : "off", rssWarm, rssPeak, growth,
        checkMemory ? "" : ", not checked: --memory-report-only", rssEnd, counts(start.s).c_str(), counts(end).c_str(), messages.size());
    return ok;
}

// --churn KIND N: one object kind made and destroyed N times on one backend, resident memory
// printed every tenth; to tell which layer keeps memory when the soak's effects are made again.
//   ao, mb: the effect created at 320x180, dispatched once, flushed, destroyed;
//   program: the motion blur reconstruct program created and destroyed;
//   pipeline: its graphics pipeline created and destroyed (the program kept);
//   program+pipeline: both, as an effect's re-creation does (KIND:PROGRAM another program);
//   depth:LEVELS: sfx::LinearDepth with LEVELS pyramid levels from hardware depth.
int churn(const BackendConfig& config, const std::string& kindAndProgram, int n, bool validation) {
    // KIND[:PROGRAM] for program, pipeline and program+pipeline (default mb_reconstruct).
    const size_t colon = kindAndProgram.find(':');
    const std::string kind = kindAndProgram.substr(0, colon);
    const std::string programName = colon == std::string::npos ? gen::mb_reconstruct::kName : kindAndProgram.substr(colon + 1);
    const bool isReconstruct = programName == gen::mb_reconstruct::kName;
    const Format passFormat = programName.rfind("mb_", 0) == 0 ? (programName == "mb_pack" ? Format::RGBA16F
                                                                      : isReconstruct      ? Format::RGBA16F
                                                                                           : Format::RG16F)
        : programName.rfind("ao_", 0) == 0                     ? Format::R16F
                                                               : Format::R32F;
    DeviceOptions options;
    options.validation = validation;
    Result<std::unique_ptr<Device>> opened = openDevice(config, options);
    if (!opened) {
        std::printf("churn %s: skipped, %s\n", toString(config).c_str(), opened.status().toString().c_str());
        return 0;
    }
    Device& dev = *opened.value();
    const Tier tier = tiers::choose(dev.caps()).value().tier;
    const TierProfile& profile = tiers::profile(tier);
    const Size s{320, 180};
    HostTargets host(dev);
    if (Status st = host.make(s); !st) return std::printf("churn: %s\n", st.toString().c_str()), 1;
    Result<const CompiledProgram*> found = shaders::find(kind == "depth" ? gen::mb_reconstruct::kName : programName.c_str(), tier);
    if (!found) return std::printf("churn: %s\n", found.status().toString().c_str()), 2;
    const CompiledProgram& compiled = *found.value();
    ProgramHandle kept;
    if (kind == "pipeline") kept = dev.createProgram(compiled).value();
    const DeviceStats start = dev.stats();
    const auto t0 = std::chrono::steady_clock::now();
    for (int i = 0; i < n; ++i) {
        Status st;
        if (kind == "ao") {
            auto ao = AmbientObscurance::create(dev, {s.w, s.h, profile, AoSettings{}, DepthKind::Hardware});
            if (!ao) return std::printf("churn: %s\n", ao.status().toString().c_str()), 1;
            AoInputs in;
            in.depth = DepthSource{host.depth, DepthKind::Linear, camera(s)};
            in.output = host.aoOut;
            st = ao.value()->dispatch(in);
        } else if (kind == "mb") {
            auto mb = MotionBlur::create(dev, {s.w, s.h, profile, Format::RGBA16F, DepthKind::Hardware});
            if (!mb) return std::printf("churn: %s\n", mb.status().toString().c_str()), 1;
            MotionBlurInputs in;
            in.color = host.color;
            in.depth = DepthSource{host.depth, DepthKind::Linear, camera(s)};
            in.velocity = host.velocity;
            MotionBlurSettings settings;
            settings.maxRadiusPx = 8;
            st = mb.value()->dispatch(in, settings);
        } else if (kind == "depth") {  // depth:LEVELS, the linear depth pyramid AO builds
            const uint32_t levels = colon == std::string::npos ? 4u : uint32_t(std::atoi(programName.c_str()));
            auto depth = LinearDepth::create(dev, {s.w, s.h, tier, levels, DepthKind::Hardware});
            if (!depth) return std::printf("churn: %s\n", depth.status().toString().c_str()), 1;
            st = depth.value()->dispatch(DepthSource{host.depth, DepthKind::Linear, camera(s)});
        } else if (kind == "program" || kind == "program+pipeline" || kind == "pipeline") {
            ProgramHandle program = kept;
            if (program.isNull()) program = dev.createProgram(compiled).value();
            if (kind != "program") {
                GraphicsPipelineDesc pd;
                pd.program = program;
                pd.colorFormats = {passFormat};
                if (isReconstruct) pd.constants = {{SFX_MB_SC_PAIRS, 4}};
                Result<PipelineHandle> pl = dev.createGraphicsPipeline(pd);
                if (!pl) return std::printf("churn: %s\n", pl.status().toString().c_str()), 1;
                (void)dev.destroyPipeline(pl.value());
            }
            if (kept.isNull()) (void)dev.destroyProgram(program);
            // Something to submit: lavapipe frees a destroyed pipeline at the next submit.
            const float z = 1.0f + float(i % 7);
            std::vector<float> depth(size_t(s.w) * s.h, z);
            st = dev.writeTexture(host.depth, 0, depth.data(), depth.size() * sizeof(float));
        } else {
            std::fprintf(stderr, "soak: --churn is '%s'; allowed ao, mb, depth[:LEVELS], program, pipeline, program+pipeline[:PROGRAM]\n",
                         kind.c_str());
            return 2;
        }
        if (!st) return std::printf("churn: %s\n", st.toString().c_str()), 1;
        if (Status f = dev.flush(); !f) return std::printf("churn: %s\n", f.toString().c_str()), 1;
        for (const std::string& m : dev.takeValidationMessages()) std::printf("churn: validation: %s\n", m.c_str());
        if ((i + 1) % std::max(1, n / 10) == 0)
            std::printf("churn %s %s: %d / %d, %.1f s, resident %.2f MiB\n", toString(config).c_str(), kind.c_str(), i + 1, n,
                        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), residentMiB());
        std::fflush(stdout);
    }
    const DeviceStats end = dev.stats();
    std::printf("churn: live objects at start [%s], at end [%s]\n", counts(start).c_str(), counts(end).c_str());
    if (!kept.isNull()) (void)dev.destroyProgram(kept);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    int frames = 10000, progress = 1000;
    bool validation = true, checkMemory = true;
    std::string churnKind;
    std::vector<BackendConfig> backends = compiledBackends();
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        const bool hasValue = i + 1 < argc;
        if (a == "--frames" && hasValue) {
            frames = std::atoi(argv[++i]);
            if (frames < 1) {
                std::fprintf(stderr, "soak: --frames is '%s'; allowed a positive integer\n", argv[i]);
                return 2;
            }
        } else if (a == "--churn" && hasValue) {
            churnKind = argv[++i];
        } else if (a == "--memory-report-only") {
            checkMemory = false;
        } else if (a == "--no-validation") {
            validation = false;  // to tell the API's validation layers from the driver in a finding
        } else if (a == "--progress" && hasValue) {
            progress = std::atoi(argv[++i]);
        } else if (a == "--backends" && hasValue) {
            backends.clear();
            std::stringstream ss(argv[++i]);
            for (std::string item; std::getline(ss, item, ',');) {
                BackendConfig c;
                if (!parseBackendConfig(item, &c)) {
                    std::fprintf(stderr, "soak: --backends has '%s'; allowed vulkan, gles, gl-egl, gl-osmesa\n", item.c_str());
                    return 2;
                }
                backends.push_back(c);
            }
        } else {
            std::fprintf(stderr,
                         "usage: soak [--backends vulkan,gles,gl-egl,gl-osmesa] [--frames 10000] [--progress 1000]\n"
                         "            [--no-validation] [--memory-report-only]\n"
                         "       soak --backends B --churn ao|mb|depth[:LEVELS]|program|pipeline|program+pipeline[:PROGRAM] --frames N\n");
            return a == "--help" ? 0 : 2;
        }
    }
    if (!churnKind.empty()) {
        int rc = 0;
        for (const BackendConfig& c : backends) rc = std::max(rc, churn(c, churnKind, frames, validation));
        return rc;
    }
    bool ok = true;
    for (const BackendConfig& c : backends) ok = soak(c, frames, progress, validation, checkMemory) && ok;
    return ok ? 0 : 1;
}
