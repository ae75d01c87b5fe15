// The calibration run behind settings by budget: every candidate of the device's tier rendered on
// synthetic inputs of the asked size and timed with the HAL's timers; the table is cached per
// backend, device, effect and size, and read back only while its fingerprint holds.
#include <algorithm>
#include <cmath>
#include <filesystem>

#include "sfx/budget.hpp"
#include "sfx/motion_blur.hpp"

namespace sfx::budget {
namespace {

// A floor seen from above its horizon with rows of bumps, as linear depth (no sky: every pixel
// costs what a surface pixel costs). The cost of the effects does not depend on the picture
// beyond that.
std::vector<float> syntheticLinearDepth(uint32_t w, uint32_t h) {
    std::vector<float> depth(size_t(w) * h);
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) {
            const double u = (x + 0.5) / w, v = (y + 0.5) / h;
            depth[size_t(y) * w + x] = float(2.0 + 10.0 * (1.0 - v) * (1.0 - v) + 0.3 * std::sin(40.0 * u) * std::sin(25.0 * v));
        }
    return depth;
}

class Resources {
public:
    explicit Resources(Device& device) : device_(device) {}
    ~Resources() {
        for (TextureHandle t : textures_) (void)device_.destroyTexture(t);
    }
    Resources(const Resources&) = delete;
    Resources& operator=(const Resources&) = delete;
    Result<TextureHandle> texture(const TextureDesc& desc) {
        Result<TextureHandle> t = device_.createTexture(desc);
        if (t) textures_.push_back(t.value());
        return t;
    }

    // The synthetic scene's linear depth as an R32F texture.
    Result<TextureHandle> syntheticDepth(uint32_t w, uint32_t h) {
        Result<TextureHandle> depth = texture({w, h, 1, Format::R32F, kTextureSampled, "budget-depth"});
        if (!depth) return depth.status();
        const std::vector<float> values = syntheticLinearDepth(w, h);
        SFX_TRY(device_.writeTexture(depth.value(), 0, values.data(), values.size() * sizeof(float)));
        return depth;
    }

private:
    Device& device_;
    std::vector<TextureHandle> textures_;
};

Result<CameraProjection> syntheticCamera(uint32_t w, uint32_t h) {
    PerspectiveDesc pd;
    pd.aspect = double(w) / double(h);
    return makePerspective(pd);
}

Result<double> timeAo(Device& dev, const TierProfile& profile, AoTechnique technique, uint32_t w, uint32_t h, uint32_t runs) {
    Resources res(dev);
    Result<TextureHandle> depth = res.syntheticDepth(w, h);
    if (!depth) return depth.status();
    const Format outFormat = dev.caps().renderableFormat[size_t(Format::R32F)] ? Format::R32F : Format::RGBA8;
    Result<TextureHandle> out = res.texture({w, h, 1, outFormat, kTextureSampled | kTextureRenderTarget, "budget-ao-out"});
    if (!out) return out.status();
    Result<CameraProjection> camera = syntheticCamera(w, h);
    if (!camera) return camera.status();
    AoSettings settings;
    settings.technique = technique;
    Result<std::unique_ptr<AmbientObscurance>> ao = AmbientObscurance::create(dev, {w, h, profile, settings, DepthKind::Linear});
    if (!ao) return ao.status();
    const AoInputs in{DepthSource{depth.value(), DepthKind::Linear, camera.value()}, {}, out.value()};
    Result<TimerReading> r = timeMedian(dev, runs, [&] { return ao.value()->dispatch(in); });
    if (!r) return r.status();
    return r->milliseconds;
}

Result<double> timeMotionBlur(Device& dev, const TierProfile& profile, uint32_t w, uint32_t h, uint32_t runs) {
    Resources res(dev);
    Result<TextureHandle> depth = res.syntheticDepth(w, h);
    if (!depth) return depth.status();
    Result<TextureHandle> color = res.texture({w, h, 1, Format::RGBA8, kTextureSampled, "budget-color"});
    if (!color) return color.status();
    std::vector<uint8_t> pixels(size_t(w) * h * 4);
    for (size_t i = 0; i < pixels.size(); ++i) pixels[i] = uint8_t((i * 37) % 251);
    SFX_TRY(dev.writeTexture(color.value(), 0, pixels.data(), pixels.size()));
    Result<CameraProjection> camera = syntheticCamera(w, h);
    if (!camera) return camera.status();
    MotionBlurDesc desc{w, h, profile, Format::RGBA8, DepthKind::Linear};
    Result<std::unique_ptr<MotionBlur>> mb = MotionBlur::create(dev, desc);
    if (!mb) return mb.status();
    MotionBlurInputs in;
    in.color = color.value();
    in.depth = DepthSource{depth.value(), DepthKind::Linear, camera.value()};
    // The camera moved sideways between frames: every pixel moves, the near ones most.
    glm::dmat4 moved(1.0);
    moved[3] = glm::dvec4(0.2, 0.0, 0.0, 1.0);
    in.camera.currentViewProjection = camera->projection;
    in.camera.previousViewProjection = camera->projection * moved;
    Result<TimerReading> r = timeMedian(dev, runs, [&] { return mb.value()->dispatch(in); });
    if (!r) return r.status();
    return r->milliseconds;
}

}  // namespace

Result<TimerReading> timeMedian(Device& dev, uint32_t runs, const std::function<Status()>& record) {
    if (runs == 0) return invalidArgument("runs", "0", "at least 1");
    Result<TimerHandle> timer = dev.createTimer();
    if (!timer) return timer.status();
    std::vector<double> ms;
    TimerReading last;
    Status status = Status::ok();
    for (uint32_t i = 0; i < runs + 1 && status; ++i) {  // run 0 warms up (pipelines, caches)
        status = dev.beginTimer(timer.value());
        if (status) status = record();
        if (status) status = dev.endTimer(timer.value());
        if (status) status = dev.flush();
        if (!status) break;
        Result<TimerReading> r = dev.readTimer(timer.value());
        if (!r)
            status = r.status();
        else if (i > 0)
            ms.push_back(r->milliseconds), last = r.value();
    }
    (void)dev.destroyTimer(timer.value());
    if (!status) return status;
    std::sort(ms.begin(), ms.end());
    last.milliseconds = ms[ms.size() / 2];
    return last;
}

std::vector<Candidate> candidates(Effect effect, const std::vector<Preset>& presets) {
    std::vector<Candidate> out;
    for (const Preset& p : presets) {
        if (effect == Effect::MotionBlur) {
            out.push_back({effect, p.name, AoTechnique::Alchemy, p.accuracy.motionBlurPsnrDb});
            continue;
        }
        for (AoTechnique t : {AoTechnique::Alchemy, AoTechnique::Scalable, AoTechnique::Crease, AoTechnique::Horizon})
            out.push_back({effect, p.name, t, p.accuracy.aoPsnrDb[size_t(t)]});
    }
    return out;
}

Result<CostTable> costTable(Device& dev, const std::vector<Preset>& presets, Effect effect, uint32_t width, uint32_t height,
                            const CalibrationOptions& options) {
    if (width == 0 || height == 0 || width > dev.caps().limits.maxTextureSize || height > dev.caps().limits.maxTextureSize)
        return invalidArgument("width/height", std::to_string(width) + "x" + std::to_string(height),
                               "[1, " + std::to_string(dev.caps().limits.maxTextureSize) + "] each");
    if (options.runs == 0) return invalidArgument("CalibrationOptions.runs", "0", "at least 1");
    if (presets.empty()) return invalidArgument("presets", "empty", "one tier's presets (tiers::row(tier).presets)");
    const Tier tier = presets.front().params.tier;
    for (const Preset& p : presets)
        if (p.params.tier != tier)
            return invalidArgument("presets", "'" + p.name + "' of tier " + toString(p.params.tier) + " among presets of tier " + toString(tier),
                                   "presets of one tier");
    const std::vector<Candidate> list = candidates(effect, presets);
    const uint64_t measures = fingerprint(dev.caps(), effect, presets);
    const std::string path = options.cacheDir.empty() ? "" : costTablePath(options.cacheDir, dev.caps(), effect, width, height);
    if (!path.empty() && !options.recalibrate) {
        Result<CostTable> cached = readCostTable(path, list);
        // The fingerprint covers the device, effect, tier and presets; the size names the file.
        if (cached && cached->fingerprint == measures && cached->width == width && cached->height == height) return cached;
    }
    CostTable table{dev.caps().deviceName, tier, effect, width, height, {}, measures};
    for (const Candidate& c : list) {
        const auto preset = std::find_if(presets.begin(), presets.end(), [&](const Preset& p) { return p.name == c.preset; });
        Result<double> ms = effect == Effect::MotionBlur ? timeMotionBlur(dev, preset->params, width, height, options.runs)
                                                         : timeAo(dev, preset->params, c.technique, width, height, options.runs);
        if (!ms) return ms.status();
        table.entries.push_back({c, ms.value()});
    }
    if (!path.empty()) {
        std::error_code ec;
        std::filesystem::create_directories(options.cacheDir, ec);
        if (ec) return Status{StatusCode::FileError, options.cacheDir + ": cannot create the cost cache directory: " + ec.message()};
        SFX_TRY(writeCostTable(path, table));
    }
    return table;
}

}  // namespace sfx::budget
