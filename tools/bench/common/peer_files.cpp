#include "peer_files.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>

#include "bench_device.hpp"
#include "sfx/half.hpp"
#include "sfx/image_io.hpp"

namespace sfx::tools {
namespace {

// One view's inputs read back from the device: linear depth from the G-buffer's hardware depth
// as the SDK's linearisation computes it, +inf where nothing was drawn, and the normals.
Status writeView(Device& dev, const TradeView& view, uint32_t w, uint32_t h, const std::string& prefix) {
    Result<std::unique_ptr<ViewInputs>> in = ViewInputs::create(dev, Tier::High, view, w, h);
    if (!in) return in.status();
    if (in.value()->depthKind() != DepthKind::Hardware) return invalidArgument("view", "'" + view.name() + "'", "a rasterised view");
    const size_t n = size_t(w) * h;
    reference::Grid stored(w, h);
    std::vector<float> depth(n);
    std::vector<uint16_t> normals(n * 4);
    SFX_TRY(dev.readTexture(in.value()->depth(), 0, depth.data(), n * sizeof(float)));
    SFX_TRY(dev.readTexture(in.value()->normals(), 0, normals.data(), normals.size() * sizeof(uint16_t)));
    for (size_t i = 0; i < n; ++i) stored.values[i] = depth[i];
    Result<DepthReconstruction> reconstruction = makeDepthReconstruction(in.value()->camera(), w, h);
    if (!reconstruction) return reconstruction.status();
    const reference::Grid linear = reference::linearizeDepth(stored, reconstruction.value());
    io::Image d(w, h, 1), nm(w, h, 3);
    for (size_t i = 0; i < n; ++i) {
        const bool drawn = halfToFloat(normals[i * 4 + 3]) != 0.0f;
        d.pixels[i] = drawn ? float(linear.values[i]) : std::numeric_limits<float>::infinity();
        for (int c = 0; c < 3; ++c) nm.pixels[i * 3 + c] = drawn ? halfToFloat(normals[i * 4 + c]) : (c == 2 ? 1.0f : 0.0f);
    }
    SFX_TRY(io::writePfm(prefix + ".depth.pfm", d));
    return io::writePfm(prefix + ".normals.pfm", nm);
}

}  // namespace

Status writePeerInputs(const PeerInputs& o, const std::vector<TradeView>& views) {
    BackendConfig config;
    if (!parseBackendConfig(o.backend, &config)) return invalidArgument("backend", "'" + o.backend + "'", "vulkan, gles, gl, gl-egl, gl-osmesa");
    Result<std::unique_ptr<Device>> dev = openForTier(config, Tier::High);
    if (!dev) return dev.status();
    std::filesystem::create_directories(o.dir);
    std::ofstream list(o.dir + "/views.txt");
    auto add = [&](const TradeView& view, const std::string& name, uint32_t w, uint32_t h) -> Status {
        Result<RasterScene> scene = viewScene(view);
        if (!scene) return scene.status();
        SFX_TRY(writeView(*dev.value(), view, w, h, o.dir + "/" + name));
        list << name << " " << w << " " << h << " " << scene->fovYDegrees << " " << view.radius << "\n";
        return Status::ok();
    };
    for (const TradeView& v : views) {
        SFX_TRY(add(v, v.name(), o.width, o.height));
        if (v.name() == o.costView) SFX_TRY(add(v, "cost", o.costWidth, o.costHeight));
    }
    if (!list) return Status{StatusCode::FileError, o.dir + "/views.txt: cannot be written"};
    return Status::ok();
}

Result<std::vector<double>> readPeerOutput(const std::string& dir, const std::string& view, const std::string& preset) {
    const std::string path = dir + "/" + view + ".xegtao-" + preset + ".pfm";
    if (!std::filesystem::exists(path)) return Status{StatusCode::FileError, path + ": missing"};
    Result<io::Image> image = io::readImage(path);
    if (!image) return image.status();
    std::vector<double> out(size_t(image->width) * image->height);
    for (size_t i = 0; i < out.size(); ++i) out[i] = image->pixels[i * image->channels];
    return out;
}

Result<PeerScore> scorePeerOutput(const std::string& dir, const std::string& view, const std::string& preset, const truth::Image& truth) {
    Result<std::vector<double>> out = readPeerOutput(dir, view, preset);
    if (!out) return out.status();
    for (size_t i = 0; i < out->size() && i < truth.surface.size(); ++i)
        if (!truth.isSurface(i)) (*out)[i] = 1.0;
    Result<truth::Comparison> e = truth::compare(truth, out.value());
    if (!e) return e.status();
    return PeerScore{std::move(out.value()), e.value()};
}

std::vector<PeerCost> readPeerCosts(const std::string& dir) {
    std::vector<PeerCost> costs;
    std::ifstream in(dir + "/xegtao_cost.txt");
    for (PeerCost c; in >> c.preset >> c.prefilterMs >> c.mainMs >> c.denoiseMs >> c.totalMs;) costs.push_back(c);
    return costs;
}

}  // namespace sfx::tools
