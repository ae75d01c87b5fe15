// bench_cpu_overhead (docs/integration.md, "CPU overhead"): the CPU time an effect's dispatch()
// costs the host's render thread, and its heap traffic. Not a test: numbers depend on the machine.
//   bench_cpu_overhead [--frames 300] [--warmup 30] [--width 1280] [--height 720]
//                      [--backends vulkan,gles,gl-egl] [--out file.md] [--recordings both|replay|record]
// Per backend (validation off, the best tier's profile), per effect (AO alchemy / scalable /
// crease with their default settings, motion blur at its defaults) on the columns scene's
// G-buffer: after the warm-up, each frame times dispatch() alone and the whole frame (dispatch
// + Device::flush, which submits and waits on Vulkan and calls glFinish on GL) with
// steady_clock, and the render thread's CPU time of both (CLOCK_THREAD_CPUTIME_ID: waiting
// excluded, the driver's worker threads not counted). The CPU time is the overhead a host pays:
// llvmpipe makes a draw that samples what the previous pass rendered wait for its rasteriser
// threads, so on GL the wall time of dispatch() holds most of the GPU work of the effect. Heap traffic of dispatch() on the
// calling thread: operator new calls and bytes, and malloc/calloc/realloc calls and bytes (which
// include the driver's own and those behind operator new), counted by replacing both in this
// executable only. Context switches of the render thread inside dispatch() (getrusage
// RUSAGE_THREAD): voluntary ones are the driver blocking (llvmpipe waits for its rasteriser
// threads), involuntary ones are preemption by the machine's other load; after either the
// thread resumes with cold caches, which the CPU time then includes. Prints median and p90 per
// cell as a markdown table.
#include <sys/resource.h>
#include <time.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <memory>
#include <new>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#if __has_include(<CLI/CLI.hpp>)
#include <CLI/CLI.hpp>
#define SFX_HAVE_CLI11 1
#endif

// Under callgrind (valgrind --tool=callgrind --collect-atstart=no) only the timed dispatch()
// calls are counted: instructions per steady dispatch, by library, with no warm-up compile in
// them. Outside valgrind the macro does nothing.
#if __has_include(<valgrind/callgrind.h>)
#include <valgrind/callgrind.h>
#define SFX_COLLECT_TOGGLE() CALLGRIND_TOGGLE_COLLECT
#else
#define SFX_COLLECT_TOGGLE() ((void)0)
#endif

#include "bench_device.hpp"
#include "scene.hpp"
#include "sfx/ao.hpp"
#include "sfx/backends.hpp"
#include "sfx/motion_blur.hpp"
#include "sfx/tiers.hpp"

// ---- heap counting (this executable only) ---------------------------------------------------
// Counted only on a thread that has turned counting on (the render thread around dispatch()):
// thread_local plain integers live in the executable's static TLS, so reading them allocates
// nothing. Off under the sanitizers, which interpose malloc themselves.
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__) || defined(__SANITIZE_MEMORY__)
#define SFX_COUNT_HEAP 0
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || __has_feature(memory_sanitizer)
#define SFX_COUNT_HEAP 0
#endif
#endif
#ifndef SFX_COUNT_HEAP
#define SFX_COUNT_HEAP 1
#endif

namespace {
struct HeapCounts {
    uint64_t news = 0, newBytes = 0, mallocs = 0, mallocBytes = 0;
};
thread_local bool tCounting = false;
thread_local HeapCounts tHeap;
}  // namespace

#if SFX_COUNT_HEAP
extern "C" {
void* __libc_malloc(size_t);
void* __libc_calloc(size_t, size_t);
void* __libc_realloc(void*, size_t);
void __libc_free(void*);

void* malloc(size_t n) {
    if (tCounting) ++tHeap.mallocs, tHeap.mallocBytes += n;
    return __libc_malloc(n);
}
void* calloc(size_t count, size_t n) {
    if (tCounting) ++tHeap.mallocs, tHeap.mallocBytes += count * n;
    return __libc_calloc(count, n);
}
void* realloc(void* p, size_t n) {
    if (tCounting && n) ++tHeap.mallocs, tHeap.mallocBytes += n;
    return __libc_realloc(p, n);
}
void free(void* p) { __libc_free(p); }
}

namespace {
void* countedNew(size_t n) {
    if (tCounting) ++tHeap.news, tHeap.newBytes += n;
    if (void* p = std::malloc(n ? n : 1)) return p;
    throw std::bad_alloc();
}
void* countedNewAligned(size_t n, std::align_val_t a) {
    if (tCounting) ++tHeap.news, tHeap.newBytes += n;
    const size_t align = std::max(size_t(a), sizeof(void*));
    void* p = nullptr;
    if (posix_memalign(&p, align, n ? n : 1) == 0) return p;
    throw std::bad_alloc();
}
}  // namespace

void* operator new(size_t n) { return countedNew(n); }
void* operator new[](size_t n) { return countedNew(n); }
void* operator new(size_t n, const std::nothrow_t&) noexcept {
    try {
        return countedNew(n);
    } catch (...) {
        return nullptr;
    }
}
void* operator new[](size_t n, const std::nothrow_t&) noexcept {
    try {
        return countedNew(n);
    } catch (...) {
        return nullptr;
    }
}
void* operator new(size_t n, std::align_val_t a) { return countedNewAligned(n, a); }
void* operator new[](size_t n, std::align_val_t a) { return countedNewAligned(n, a); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, size_t) noexcept { std::free(p); }
void operator delete[](void* p, size_t) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, size_t, std::align_val_t) noexcept { std::free(p); }
#endif

using namespace sfx;

namespace {

struct Options {
    int frames = 300;
    int warmup = 30;
    uint32_t width = 1280, height = 720;
    std::vector<std::string> backends{"vulkan", "gles", "gl-egl"};
    std::string out;
    // MiB written by the render thread before each timed dispatch (outside the timed span), so
    // that the dispatch starts with caches as cold as after a large frame of software
    // rasterisation on the same cores; 0: no eviction.
    uint32_t evictMiB = 0;
    // Vulkan: effects replaying their recorded passes in steady frames (DeviceOptions::
    // reuseRecordings, the default), recording every command every frame, or both in one run.
    std::string recordings = "both";
};

// Writes one byte per cache line of `buffer`, so that what the caches held before is gone (a
// new value each call, so the stores cannot be skipped).
void evictCaches(std::vector<uint8_t>& buffer) {
    static uint8_t value = 0;
    ++value;
    for (size_t i = 0; i < buffer.size(); i += 64) buffer[i] = value;
}

// The render thread's voluntary and involuntary context switches so far.
std::pair<long, long> threadSwitches() {
    rusage u{};
    getrusage(RUSAGE_THREAD, &u);
    return {u.ru_nvcsw, u.ru_nivcsw};
}

double threadCpuSeconds() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

struct Stat {
    double median = 0, p90 = 0;
};
Stat stat(std::vector<double> v) {
    if (v.empty()) return {};
    std::sort(v.begin(), v.end());
    auto at = [&](double q) { return v[std::min(v.size() - 1, size_t(q * double(v.size() - 1) + 0.5))]; };
    return {at(0.5), at(0.9)};
}

struct Row {
    std::string backend, tier, effect;
    Stat dispatchUs, dispatchCpuUs, frameUs, frameCpuUs;
    double news = 0, newKiB = 0, mallocs = 0, mallocKiB = 0;  // per dispatch, mean over the timed frames
    double waits = 0, preemptions = 0;                        // context switches per dispatch (voluntary, involuntary), mean
};

// Times `frames` frames of `dispatch` + flush after `warmup` untimed ones.
template <class Dispatch>
Result<Row> measure(Device& dev, const Options& o, Dispatch&& dispatch) {
    for (int i = 0; i < o.warmup; ++i) {
        SFX_TRY(dispatch());
        SFX_TRY(dev.flush());
    }
    std::vector<double> dispatchUs, dispatchCpuUs, frameUs, cpuUs;
    HeapCounts sum;
    long waits = 0, preemptions = 0;
    std::vector<uint8_t> evictBuffer(size_t(o.evictMiB) << 20);
    for (int i = 0; i < o.frames; ++i) {
        if (o.evictMiB) evictCaches(evictBuffer);
        const std::pair<long, long> switches0 = threadSwitches();  // outside the timed span
        const double cpu0 = threadCpuSeconds();
        const auto t0 = std::chrono::steady_clock::now();
        tHeap = {};
        tCounting = true;
        SFX_COLLECT_TOGGLE();
        const Status st = dispatch();
        SFX_COLLECT_TOGGLE();
        tCounting = false;
        const auto t1 = std::chrono::steady_clock::now();
        const double cpuDispatch = threadCpuSeconds();
        const std::pair<long, long> switches1 = threadSwitches();
        waits += switches1.first - switches0.first;
        preemptions += switches1.second - switches0.second;
        const HeapCounts h = tHeap;
        SFX_TRY(st);
        SFX_TRY(dev.flush());
        const auto t2 = std::chrono::steady_clock::now();
        const double cpu1 = threadCpuSeconds();
        dispatchUs.push_back(std::chrono::duration<double, std::micro>(t1 - t0).count());
        dispatchCpuUs.push_back(1e6 * (cpuDispatch - cpu0));
        frameUs.push_back(std::chrono::duration<double, std::micro>(t2 - t0).count());
        cpuUs.push_back(1e6 * (cpu1 - cpu0));
        sum.news += h.news, sum.newBytes += h.newBytes, sum.mallocs += h.mallocs, sum.mallocBytes += h.mallocBytes;
    }
    Row r;
    r.dispatchUs = stat(dispatchUs);
    r.dispatchCpuUs = stat(dispatchCpuUs);
    r.frameUs = stat(frameUs);
    r.frameCpuUs = stat(cpuUs);
    const double n = double(o.frames);
    r.news = double(sum.news) / n, r.newKiB = double(sum.newBytes) / n / 1024.0;
    r.mallocs = double(sum.mallocs) / n, r.mallocKiB = double(sum.mallocBytes) / n / 1024.0;
    r.waits = double(waits) / n, r.preemptions = double(preemptions) / n;
    return r;
}

Status runBackend(const std::string& backend, const Options& o, bool reuseRecordings, std::vector<Row>& rows) {
    BackendConfig config;
    if (!parseBackendConfig(backend, &config)) return invalidArgument("--backends", "'" + backend + "'", "vulkan, gles, gl-egl, gl-osmesa");
    DeviceOptions options;
    options.validation = false;  // a host's release build; validation would be timed too
    options.reuseRecordings = reuseRecordings;
    Result<std::unique_ptr<Device>> opened = openDevice(config, options);
    if (!opened) {
        std::cout << "bench_cpu_overhead: skipping " << backend << ": " << opened.status().toString() << std::endl;
        return Status::ok();
    }
    Device& dev = *opened.value();
    Result<tiers::TierChoice> choice = tiers::choose(dev.caps());
    if (!choice) {
        std::cout << "bench_cpu_overhead: skipping " << backend << ": " << choice.status().toString() << std::endl;
        return Status::ok();
    }
    // Only Vulkan keeps recordings: elsewhere the option changes nothing.
    const std::string label = dev.caps().reusableRecordings ? backend + " (replayed)"
        : config.backend == BackendKind::Vulkan             ? backend + " (recorded every frame)"
                                                            : backend;
    std::cout << "bench_cpu_overhead: " << label << ": " << dev.caps().summary() << ", tier " << toString(choice->tier) << std::endl;

    Result<tools::RasterScene> scene = tools::makeScene("columns");
    if (!scene) return scene.status();
    Result<std::unique_ptr<tools::SceneRenderer>> renderer = tools::SceneRenderer::create(dev, choice->tier);
    if (!renderer) return renderer.status();
    SFX_TRY(renderer.value()->load(scene.value()));
    Result<tools::GBuffer> g = renderer.value()->render(scene.value(), o.width, o.height);
    if (!g) return g.status();
    const Format aoFormat = tools::aoOutputFormat(dev);
    Result<TextureHandle> aoOut = dev.createTexture({o.width, o.height, 1, aoFormat, kTextureSampled | kTextureRenderTarget, "bench-ao"});
    if (!aoOut) return aoOut.status();
    SFX_TRY(dev.flush());

    auto addRow = [&](const std::string& effect, Result<Row> r) -> Status {
        if (!r) return Status{r.status().code(), effect + ": " + r.status().message()};
        r->backend = label, r->tier = toString(choice->tier), r->effect = effect;
        std::printf(
            "  %-12s dispatch CPU median %7.1f us (p90 %7.1f), wall %9.1f us; frame CPU %7.1f us, wall %9.1f us; "
            "%.1f new / %.1f KiB, %.1f malloc / %.1f KiB, %.1f waits + %.1f preemptions per dispatch\n",
            effect.c_str(), r->dispatchCpuUs.median, r->dispatchCpuUs.p90, r->dispatchUs.median, r->frameCpuUs.median, r->frameUs.median, r->news,
            r->newKiB, r->mallocs, r->mallocKiB, r->waits, r->preemptions);
        std::fflush(stdout);
        rows.push_back(r.value());
        return Status::ok();
    };

    const AoTechnique techniques[] = {AoTechnique::Alchemy, AoTechnique::Scalable, AoTechnique::Crease, AoTechnique::Horizon};
    for (AoTechnique t : techniques) {
        AoSettings settings;
        settings.technique = t;
        settings.normals = AoNormals::FromTexture;  // the G-buffer's normals, as a deferred renderer would
        Result<std::unique_ptr<AmbientObscurance>> ao = AmbientObscurance::create(dev, {o.width, o.height, choice->profile, settings});
        if (!ao) return ao.status();
        const AoInputs in{DepthSource{g->depth, DepthKind::Hardware, g->camera}, g->normals, aoOut.value()};
        SFX_TRY(addRow(std::string("AO ") + toString(t), measure(dev, o, [&] { return ao.value()->dispatch(in); })));
    }
    {
        Result<std::unique_ptr<MotionBlur>> mb = MotionBlur::create(dev, {o.width, o.height, choice->profile, Format::RGBA8});
        if (!mb) return mb.status();
        MotionBlurInputs in;
        in.color = g->albedo;
        in.depth = {g->depth, DepthKind::Hardware, g->camera};
        in.velocity = g->velocity;
        SFX_TRY(addRow("motion blur", measure(dev, o, [&] { return mb.value()->dispatch(in); })));
    }
    (void)dev.destroyTexture(aoOut.value());
    renderer.value()->destroy(g.value());
    return dev.flush();
}

std::string table(const std::vector<Row>& rows, const Options& o) {
    std::ostringstream s;
    char line[512];
    s << "| backend | tier | effect | dispatch() CPU median µs | p90 µs | dispatch() wall median µs | p90 µs | "
         "frame CPU median µs | frame wall median µs | new / dispatch | KiB | malloc / dispatch | KiB | "
         "waits / dispatch | preemptions / dispatch |\n"
         "|---|---|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|\n";
    for (const Row& r : rows) {
        std::snprintf(line, sizeof line, "| %s | %s | %s | %.1f | %.1f | %.1f | %.1f | %.0f | %.0f | %.1f | %.1f | %.1f | %.1f | %.1f | %.1f |\n",
                      r.backend.c_str(), r.tier.c_str(), r.effect.c_str(), r.dispatchCpuUs.median, r.dispatchCpuUs.p90, r.dispatchUs.median,
                      r.dispatchUs.p90, r.frameCpuUs.median, r.frameUs.median, r.news, r.newKiB, r.mallocs, r.mallocKiB, r.waits, r.preemptions);
        s << line;
    }
    s << "\n"
      << o.width << "x" << o.height << ", " << o.frames << " frames after " << o.warmup << " warm-up frames per cell; "
      << "CPU: the render thread's CPU time; frame: dispatch() + flush() (Vulkan: submit and wait; GL: glFinish); "
      << "new / malloc: calls and KiB on the render thread inside dispatch() (malloc includes the driver's and operator new's); "
      << "waits / preemptions: the render thread's voluntary / involuntary context switches inside dispatch()"
      << (SFX_COUNT_HEAP ? "" : "; heap counting off (sanitizer build)")
      << (o.evictMiB ? "; " + std::to_string(o.evictMiB) + " MiB written before each timed dispatch (cold caches)" : std::string()) << ".\n";
    return s.str();
}

}  // namespace

int main(int argc, char** argv) {
    Options o;
#ifdef SFX_HAVE_CLI11
    CLI::App app{"CPU cost of the effects' dispatch() and heap traffic per dispatch"};
    app.add_option("--frames", o.frames, "timed frames per effect")->check(CLI::PositiveNumber);
    app.add_option("--warmup", o.warmup, "untimed frames first")->check(CLI::NonNegativeNumber);
    app.add_option("--width", o.width, "width")->check(CLI::Range(1u, 16384u));
    app.add_option("--height", o.height, "height")->check(CLI::Range(1u, 16384u));
    app.add_option("--backends", o.backends, "vulkan, gles, gl-egl, gl-osmesa")->delimiter(',');
    app.add_option("--out", o.out, "also write the table to this markdown file");
    app.add_option("--recordings", o.recordings, "Vulkan: replay (steady frames replay the recorded passes), record (every frame records), both")
        ->check(CLI::IsMember({"both", "replay", "record"}));
    app.add_option("--evict-mib", o.evictMiB, "MiB to write before each timed dispatch, to start it with cold caches")->check(CLI::Range(0u, 4096u));
    CLI11_PARSE(app, argc, argv);
#else
    (void)argc, (void)argv;
#endif
    std::vector<Row> rows;
    for (const std::string& b : o.backends) {
        std::vector<bool> modes;
        if (o.recordings != "record") modes.push_back(true);
        if (o.recordings != "replay" && b == "vulkan") modes.push_back(false);
        for (bool reuse : modes)
            if (Status st = runBackend(b, o, reuse, rows); !st) {
                std::cerr << "bench_cpu_overhead: " << b << ": " << st.toString() << std::endl;
                return 1;
            }
    }
    const std::string t = table(rows, o);
    std::cout << "\n" << t;
    if (!o.out.empty()) {
        std::ofstream f(o.out);
        f << t;
        if (!f) {
            std::cerr << "bench_cpu_overhead: cannot write --out " << o.out << std::endl;
            return 1;
        }
    }
    return 0;
}
