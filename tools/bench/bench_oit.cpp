// bench_oit: the measured trade of order-independent transparency's work on the layers
// (docs/oit.md, "Measured trade"). On the sample scenes bunny.json, panes.json, shell.json and a
// generated heavy scene (a stack of panes, up to --heavy-layers fragments per pixel), high tier,
// for each kept-layer count K and each of
//   lists        the A-buffer resolve alone (AO off)
//   compressed   the resolve also compressing every list to M = 4 nodes (back half only), AO off
//   brute AO     lists, and AO through the layers whose taps walk the lists
//   compr. AO    compressed lists, and AO whose taps read the 4 nodes
// it measures each pass (clear, fill, resolve, AO) with the effect's per-pass device timers, the
// median of --runs frames, in ms and as a ratio to one full-screen RGBA16F copy pass of the same
// size timed right after that configuration (the machine's load drifts); compression's cost is
// the compressing resolve minus the plain one. Also: memory per pixel (heads, pool as allocated
// and as used, compressed lists) and the error of compressed AO against brute-force AO over the
// same lists (max and mean of the blended and the opaque channel). A program, not a test.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <sstream>

#include "bench_args.hpp"
#include "bench_device.hpp"
#include "copy_pass.hpp"
#include "markdown_section.hpp"
#include "scene.hpp"
#include "sfx/budget.hpp"
#include "sfx/half.hpp"
#include "sfx/oit.hpp"
#include "sfx/scene_file.hpp"
#include "sfx/tiers.hpp"
#include "sfx_shared_raster.h"

using namespace sfx;
using tools::fixed;
using tools::median;
using tools::splitList;

namespace {

const char* kUsage =
    "usage: bench_oit [--width 320] [--height 180] [--runs 5] [--backends vulkan,gles]\n"
    "                 [--scenes bunny,panes,shell,heavy] [--ks 4,8,16,32] [--ao-ks 16] [--heavy-layers 32]\n"
    "                 [--out-dir docs] [--no-doc]\n";

struct Options {
    uint32_t width = 320, height = 180, runs = 5, heavyLayers = 32;
    std::vector<std::string> backends{"vulkan"};
    std::vector<std::string> scenes{"bunny", "panes", "shell", "heavy"};
    std::vector<uint32_t> ks{4, 8, 16, 32};
    // K of the AO rows: the AO pass does not read K (its receivers are every stored fragment, its
    // brute-force taps walk a fixed 32 nodes), so by default AO is timed at one K only.
    std::vector<uint32_t> aoKs{16};
    std::string outDir = "docs";
    bool writeDoc = true;
};

bool parseOptions(int argc, char** argv, Options* o) {
    for (int i = 1; i < argc; ++i) {
        const std::string k = argv[i];
        if (k == "--no-doc") {
            o->writeDoc = false;
            continue;
        }
        if (k == "--help" || i + 1 >= argc) return false;
        const std::string v = argv[++i];
        if (k == "--width")
            o->width = uint32_t(std::stoul(v));
        else if (k == "--height")
            o->height = uint32_t(std::stoul(v));
        else if (k == "--runs")
            o->runs = std::max(1u, uint32_t(std::stoul(v)));
        else if (k == "--heavy-layers")
            o->heavyLayers = std::clamp(uint32_t(std::stoul(v)), 1u, 64u);
        else if (k == "--backends")
            o->backends = splitList(v);
        else if (k == "--scenes")
            o->scenes = splitList(v);
        else if (k == "--out-dir")
            o->outDir = v;
        else if (k == "--ks" || k == "--ao-ks") {
            std::vector<uint32_t>& list = k == "--ks" ? o->ks : o->aoKs;
            list.clear();
            for (const std::string& s : splitList(v)) list.push_back(std::clamp(uint32_t(std::stoul(s)), 1u, 32u));
        } else {
            std::cerr << "bench_oit: unknown flag " << k << "\n";
            return false;
        }
    }
    return true;
}

// The heavy scene: `layers` panes one behind the other, filling most of the view, over a floor
// and before a wall; every pixel of the stack holds `layers` fragments.
std::string heavySceneJson(uint32_t layers) {
    std::ostringstream js;
    js << R"({"width": 320, "height": 180,
  "camera": {"position": [0, 0.8, 3], "target": [0, 0.8, -10], "up": [0, 1, 0], "fovY": 50, "near": 0.1, "far": 50},
  "background": [0.15, 0.15, 0.18],
  "objects": [
    {"mesh": "box", "position": [0, -0.6, -3], "scale": [12, 0.1, 14], "color": [0.7, 0.7, 0.7]},
    {"mesh": "box", "position": [0, 1, -8], "scale": [12, 5, 0.2], "color": [0.8, 0.8, 0.75]})";
    for (uint32_t i = 0; i < layers; ++i) {
        const double h = double(i) / double(layers);
        const double r = 0.5 + 0.5 * std::cos(6.2832 * h), g = 0.5 + 0.5 * std::cos(6.2832 * (h - 0.33)),
                     b = 0.5 + 0.5 * std::cos(6.2832 * (h - 0.67));
        js << ",\n    {\"mesh\": \"quad\", \"position\": [0, 0.8, " << 1.0 - 0.2 * i << "], \"scale\": 5, \"color\": [" << r << ", " << g << ", " << b
           << "], \"opacity\": 0.12, \"shading\": \"" << (i % 2 ? "unlit" : "lambert") << "\"}";
    }
    js << "\n  ]}\n";
    return js.str();
}

Result<scene::Scene> loadScene(const std::string& name, uint32_t heavyLayers) {
    if (name == "heavy") return scene::loadSceneFromString(heavySceneJson(heavyLayers), SFX_SCENE_FILES_DIR, "heavy");
    return scene::loadSceneFile(std::string(SFX_SCENE_FILES_DIR) + "/" + name + ".json");
}

// The translucent objects as TransparentDraws, one vertex buffer per object (owned by `buffers`).
Result<std::vector<TransparentDraw>> transparentDraws(Device& dev, const scene::Scene& file, std::vector<BufferHandle>& buffers) {
    std::vector<TransparentDraw> draws;
    for (size_t i = 0; i < file.objects.size(); ++i) {
        const scene::SceneObject& o = file.objects[i];
        if (!o.translucent()) continue;
        const scene::TriangleMesh& mesh = file.meshes[o.meshIndex];
        std::vector<TransparentVertex> v;
        for (uint32_t index : mesh.indices) {
            const scene::Vertex& s = mesh.vertices[index];
            v.push_back({{s.position.x, s.position.y, s.position.z}, {s.normal.x, s.normal.y, s.normal.z}});
        }
        Result<BufferHandle> b = dev.createBuffer({v.size() * sizeof(TransparentVertex), kBufferVertex, "bench-oit-vertices"});
        if (!b) return b.status();
        buffers.push_back(b.value());
        SFX_TRY(dev.writeBuffer(b.value(), 0, v.data(), v.size() * sizeof(TransparentVertex)));
        TransparentDraw d;
        d.vertices = b.value();
        d.vertexCount = uint32_t(v.size());
        d.model = glm::mat4(o.world);
        d.color = glm::vec3(o.color);
        d.opacity = float(o.opacity);
        d.id = uint32_t(i);
        draws.push_back(d);
    }
    return draws;
}

enum class Variant { Lists, Compressed, BruteAo, CompressedAo };
const char* variantName(Variant v) {
    switch (v) {
        case Variant::Lists: return "lists";
        case Variant::Compressed: return "compressed";
        case Variant::BruteAo: return "brute AO";
        case Variant::CompressedAo: return "compr. AO";
    }
    return "?";
}

struct Measured {
    double clear = 0, fill = 0, resolve = 0, ao = 0, copy = 0;
    double total() const { return clear + fill + resolve + ao; }
    TransparencyStats stats;
    std::vector<float> ao2;  // the AO output's r, g per pixel (AO variants)
};

struct Frame {
    TextureHandle opaqueColor, opaqueDepth;
    glm::mat4 view{1.0f}, projection{1.0f};
    std::vector<TransparentDraw> draws;
};

Result<Measured> measure(Device& dev, tools::CopyPass& copy, const Frame& f, const Options& o, uint32_t k, Variant v) {
    TransparencyDesc d;
    d.width = o.width;
    d.height = o.height;
    d.profile = tiers::profile(Tier::High);
    d.colorFormat = Format::RGBA16F;
    d.depthFormat = Format::D32F;
    d.maxLayers = k;
    if (v != Variant::Lists && v != Variant::BruteAo) d.compressedNodes = 4;
    d.compressBackHalfOnly = true;
    if (v == Variant::BruteAo || v == Variant::CompressedAo) {
        AoSettings s;
        s.technique = AoTechnique::Scalable;
        s.radius = 0.5f;
        Result<AoConfig> c = resolveAoConfig(s, d.profile, 1, d.height);
        if (!c) return c.status();
        d.ao.enabled = true;
        d.ao.config = c.value();
        d.ao.occluders = v == Variant::CompressedAo ? TransparencyAoOccluders::Compressed : TransparencyAoOccluders::BruteForce;
    }
    Result<std::unique_ptr<Transparency>> t = Transparency::create(dev, d);
    if (!t) return t.status();
    Transparency& oit = *t.value();
    TransparencyInputs in{f.opaqueColor, f.opaqueDepth, f.view, f.projection, f.draws};
    // Until the pool holds the scene (the first frame's pool is a guess), then one warm frame.
    for (int frame = 0; frame < 4; ++frame) {
        SFX_TRY(oit.render(in));
        SFX_TRY(dev.flush());
        Result<TransparencyStats> s = oit.stats();
        if (!s) return s.status();
        if (s->dropped == 0 && frame > 0) break;
    }
    SFX_TRY(oit.setProfiling(true));
    std::vector<std::vector<double>> passes(4);
    for (uint32_t r = 0; r < o.runs; ++r) {
        SFX_TRY(oit.render(in));
        SFX_TRY(dev.flush());
        Result<std::vector<PassTiming>> timings = oit.passTimings();
        if (!timings) return timings.status();
        for (size_t p = 0; p < timings->size() && p < 4; ++p) passes[p].push_back(timings.value()[p].reading.milliseconds);
    }
    Measured m;
    m.clear = median(passes[0]);
    m.fill = median(passes[1]);
    m.resolve = median(passes[2]);
    m.ao = median(passes[3]);
    Result<TransparencyStats> s = oit.stats();
    if (!s) return s.status();
    m.stats = s.value();
    if (!oit.aoOutput().isNull()) {
        std::vector<uint16_t> halves(size_t(o.width) * o.height * 2);
        SFX_TRY(dev.readTexture(oit.aoOutput(), 0, halves.data(), halves.size() * sizeof(uint16_t)));
        m.ao2.resize(halves.size());
        for (size_t i = 0; i < halves.size(); ++i) m.ao2[i] = halfToFloat(halves[i]);
    }
    Result<double> c = copy.medianMs(o.runs);
    if (!c) return c.status();
    m.copy = c.value();
    return m;
}

struct Row {
    std::string backend, scene;
    uint32_t k = 0;
    Variant variant = Variant::Lists;
    Measured m;
};

struct AoError {
    double maxBlended = 0, meanBlended = 0, maxOpaque = 0, meanOpaque = 0;
};

AoError aoError(const std::vector<float>& brute, const std::vector<float>& compressed) {
    AoError e;
    const size_t n = brute.size() / 2;
    for (size_t i = 0; i < n && 2 * i + 1 < compressed.size(); ++i) {
        const double b = std::abs(double(brute[2 * i]) - compressed[2 * i]), g = std::abs(double(brute[2 * i + 1]) - compressed[2 * i + 1]);
        e.maxBlended = std::max(e.maxBlended, b);
        e.maxOpaque = std::max(e.maxOpaque, g);
        e.meanBlended += b / double(n);
        e.meanOpaque += g / double(n);
    }
    return e;
}

std::string cell(double ms, double copyMs) { return fixed(ms, 2) + " (" + fixed(copyMs > 0 ? ms / copyMs : 0.0, 1) + ")"; }

Status benchBackend(Device& dev, const std::string& backend, const Options& o, std::vector<Row>& rows, std::map<std::string, AoError>& errors,
                    std::map<std::string, double>& complexity) {
    Result<std::unique_ptr<tools::CopyPass>> copy = tools::makeCopyPass(dev, Tier::High, o.width, o.height, Format::RGBA16F);
    if (!copy) return copy.status();
    Result<std::unique_ptr<tools::SceneRenderer>> raster = tools::SceneRenderer::create(dev, Tier::High, Format::RGBA16F);
    if (!raster) return raster.status();
    for (const std::string& name : o.scenes) {
        Result<scene::Scene> file = loadScene(name, o.heavyLayers);
        if (!file) return file.status();
        const tools::RasterScene opaque = tools::opaqueScene(file.value());
        SFX_TRY(raster.value()->load(opaque));
        Result<tools::GBuffer> g = raster.value()->render(opaque, o.width, o.height);
        if (!g) return g.status();
        std::vector<BufferHandle> buffers;
        Result<std::vector<TransparentDraw>> draws = transparentDraws(dev, file.value(), buffers);
        if (!draws) return draws.status();
        Frame f{g->albedo, g->depth, glm::mat4(opaque.view()), glm::mat4(g->camera.projection), draws.value()};
        Status status = Status::ok();
        for (uint32_t k : o.ks) {
            std::vector<float> brute;
            const bool withAo = std::find(o.aoKs.begin(), o.aoKs.end(), k) != o.aoKs.end();
            for (Variant v : {Variant::Lists, Variant::Compressed, Variant::BruteAo, Variant::CompressedAo}) {
                if (!withAo && (v == Variant::BruteAo || v == Variant::CompressedAo)) continue;
                Result<Measured> m = measure(dev, *copy.value(), f, o, k, v);
                if (!m) {
                    status = m.status();
                    break;
                }
                const Measured& r = m.value();
                std::printf("  %-6s %-6s K=%-2u %-10s clear %.3f fill %.3f resolve %.3f ao %.3f ms | copy %.3f ms | total x%.1f | %.2f frag/px\n",
                            backend.c_str(), name.c_str(), k, variantName(v), r.clear, r.fill, r.resolve, r.ao, r.copy,
                            r.copy > 0 ? r.total() / r.copy : 0.0, double(r.stats.fragments) / (double(o.width) * o.height));
                std::fflush(stdout);
                complexity[name] = double(r.stats.fragments) / (double(o.width) * o.height);
                if (v == Variant::BruteAo) brute = r.ao2;
                if (v == Variant::CompressedAo) errors[backend + "/" + name + "/" + std::to_string(k)] = aoError(brute, r.ao2);
                rows.push_back({backend, name, k, v, r});
            }
            if (!status) break;
        }
        for (BufferHandle b : buffers) (void)dev.destroyBuffer(b);
        raster.value()->destroy(g.value());
        SFX_TRY(status);
    }
    return Status::ok();
}

const Row* find(const std::vector<Row>& rows, const std::string& backend, const std::string& scene, uint32_t k, Variant v) {
    for (const Row& r : rows)
        if (r.backend == backend && r.scene == scene && r.k == k && r.variant == v) return &r;
    return nullptr;
}

std::string tables(const std::vector<Row>& rows, const std::map<std::string, AoError>& errors, const std::map<std::string, double>& complexity,
                   const Options& o, const std::string& load) {
    std::ostringstream md;
    md << "Generated by `tools/bench/bench_oit` (" << o.width << " x " << o.height << ", high tier, median of " << o.runs
       << " frames of per-pass device timers (AO timed at K = " <<
        [&] {
            std::string t;
            for (uint32_t k : o.aoKs) t += (t.empty() ? "" : ", ") + std::to_string(k);
            return t;
        }()
       << ": the AO pass does not read K); in brackets the ratio to one full-screen RGBA16F copy pass of the same size timed "
          "right after each configuration). Load during the run: "
       << load << ". Scalable AO, radius 0.5, the high tier's taps; M = 4 nodes, back half only.\n\n";
    std::vector<std::string> backends, scenes;
    for (const Row& r : rows) {
        if (std::find(backends.begin(), backends.end(), r.backend) == backends.end()) backends.push_back(r.backend);
        if (std::find(scenes.begin(), scenes.end(), r.scene) == scenes.end()) scenes.push_back(r.scene);
    }
    for (const std::string& b : backends) {
        md << "**" << b << "**, per stage, ms (copy passes):\n\n";
        md << "| scene (fragments/px) | K | clear | fill | resolve | compression (resolve delta) | AO brute force | AO compressed | "
              "AO brute / compressed | whole frame lists + brute AO | whole frame compressed + AO |\n";
        md << "|---|---|---|---|---|---|---|---|---|---|---|\n";
        for (const std::string& s : scenes)
            for (uint32_t k : o.ks) {
                const Row* l = find(rows, b, s, k, Variant::Lists);
                const Row* c = find(rows, b, s, k, Variant::Compressed);
                const Row* ba = find(rows, b, s, k, Variant::BruteAo);
                const Row* ca = find(rows, b, s, k, Variant::CompressedAo);
                if (!l || !c) continue;
                const double copy = l->m.copy;
                md << "| " << s << " (" << fixed(complexity.at(s), 2) << ") | " << k << " | " << cell(l->m.clear, copy) << " | "
                   << cell(l->m.fill, copy) << " | " << cell(l->m.resolve, copy) << " | " << cell(c->m.resolve - l->m.resolve, c->m.copy) << " | ";
                if (ba && ca)
                    md << cell(ba->m.ao, ba->m.copy) << " | " << cell(ca->m.ao, ca->m.copy) << " | "
                       << fixed(ca->m.ao > 0 ? ba->m.ao / ca->m.ao : 0.0, 1) << "x | " << cell(ba->m.total(), ba->m.copy) << " | "
                       << cell(ca->m.total(), ca->m.copy) << " |\n";
                else
                    md << "- | - | - | - | - |\n";
            }
        md << "\n";
    }
    md << "Memory per pixel (bytes): list heads 4 (R32UI); node pool 32 per stored fragment plus the 1.5x headroom; compressed "
          "lists 12 (M = 4); AO output 4 (RG16F).\n\n";
    md << "| scene | fragments/px | pool allocated B/px | pool used B/px | heads + pool + compressed B/px |\n|---|---|---|---|---|\n";
    for (const std::string& s : scenes) {
        const Row* c = find(rows, backends.front(), s, o.ks.front(), Variant::Compressed);
        if (!c) continue;
        const double px = double(o.width) * o.height;
        const double alloc = double(c->m.stats.poolBytes) / px, used = double(c->m.stats.stored) * kOitNodeBytes / px;
        md << "| " << s << " | " << fixed(complexity.at(s), 2) << " | " << fixed(alloc, 1) << " | " << fixed(used, 1) << " | "
           << fixed(4.0 + alloc + 12.0, 1) << " |\n";
    }
    md << "\nCompressed AO (taps read 4 nodes) against brute-force AO (taps walk the lists), the same lists and taps: absolute "
          "difference of visibility, r = blended through the layers, g = the opaque surface's.\n\n";
    md << "| backend / scene / K | max r | mean r | max g | mean g |\n|---|---|---|---|---|\n";
    for (const auto& [key, e] : errors)
        md << "| " << key << " | " << fixed(e.maxBlended, 4) << " | " << fixed(e.meanBlended, 5) << " | " << fixed(e.maxOpaque, 4) << " | "
           << fixed(e.meanOpaque, 5) << " |\n";
    return md.str();
}

std::string machineLoad() {
    double l[3] = {0, 0, 0};
    if (FILE* f = std::fopen("/proc/loadavg", "r")) {
        if (std::fscanf(f, "%lf %lf %lf", &l[0], &l[1], &l[2]) != 3) l[0] = l[1] = l[2] = 0;
        std::fclose(f);
    }
    return "load average " + fixed(l[0], 2) + ", " + fixed(l[1], 2) + ", " + fixed(l[2], 2);
}

}  // namespace

int main(int argc, char** argv) {
    Options o;
    if (!parseOptions(argc, argv, &o)) {
        std::cerr << kUsage;
        return 2;
    }
    std::vector<Row> rows;
    std::map<std::string, AoError> errors;
    std::map<std::string, double> complexity;
    const std::string loadBefore = machineLoad();
    std::cout << "bench_oit: " << o.width << "x" << o.height << ", " << o.runs << " runs, " << loadBefore << std::endl;
    Status s = tools::forEachDevice(o.backends, {Tier::High}, "bench_oit", [&](Device& dev, const std::string& backend, Tier) {
        return benchBackend(dev, backend, o, rows, errors, complexity);
    });
    if (!s) {
        std::cerr << "bench_oit: " << s.toString() << "\n";
        return 1;
    }
    const std::string load = loadBefore + " before, " + machineLoad() + " after";
    const std::string md = tables(rows, errors, complexity, o, load);
    std::cout << md;
    if (o.writeDoc && !rows.empty()) {
        Status w = tools::replaceMarkdownSection(o.outDir + "/oit.md", "bench_oit", md);
        if (!w) {
            std::cerr << "bench_oit: " << w.toString() << "\n";
            return 1;
        }
    }
    return 0;
}
