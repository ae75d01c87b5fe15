#include "ao_scoring.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "bench_device.hpp"
#include "sfx/tiers.hpp"
#include "truth_cache.hpp"

namespace sfx::tools {

Result<std::vector<AoCase>> loadCases(const std::vector<TradeView>& views, size_t first, size_t last, const std::vector<double>& radii,
                                      const TruthSettings& settings, const std::function<void(const std::string&)>& progress) {
    std::vector<AoCase> cases;
    for (size_t v = first; v < last; ++v) {
        Result<TruthScene> scene = viewTruthScene(views[v], settings.width, settings.height);
        if (!scene) return Status{scene.status().code(), views[v].name() + ": " + scene.status().message()};
        for (double radius : radii.empty() ? std::vector<double>{views[v].radius} : radii) {
            truth::Settings ts;
            ts.radius = radius;
            ts.samples = settings.samples;
            double seconds = 0;
            Result<truth::Image> t = cachedTruth(settings.cacheDir, scene.value(), ts, &seconds);
            if (!t) return Status{t.status().code(), "truth of " + views[v].name() + ": " + t.status().message()};
            char line[160];
            std::snprintf(line, sizeof line, "truth %s r=%g: %s", views[v].name().c_str(), radius, seconds > 0 ? "traced" : "cached");
            progress(seconds > 0 ? std::string(line) + " in " + std::to_string(seconds).substr(0, 4) + " s" : line);
            cases.push_back({v, radius, std::move(t.value())});
        }
    }
    return cases;
}

AoScore noAoScore(const std::vector<AoCase>& cases) {
    std::vector<truth::Comparison> errors;
    for (const AoCase& c : cases) errors.push_back(truth::compare(c.truth, std::vector<double>(c.truth.visibility.size(), 1.0)).value());
    return summarise(errors);
}

AoScore summarise(const std::vector<truth::Comparison>& errors) {
    AoScore s;
    size_t nf = 0, no = 0;
    for (const truth::Comparison& e : errors) {
        if (std::isfinite(e.psnr)) s.psnr += e.psnr, s.worstPsnr = std::min(s.worstPsnr, e.psnr), ++nf;
        if (std::isfinite(e.psnrOccluded)) {
            s.psnrOccluded += e.psnrOccluded, s.worstPsnrOccluded = std::min(s.worstPsnrOccluded, e.psnrOccluded);
            s.signedOccluded += e.meanSignedErrorOccluded, ++no;
        }
    }
    s.psnr /= double(std::max<size_t>(nf, 1)), s.psnrOccluded /= double(std::max<size_t>(no, 1)), s.signedOccluded /= double(std::max<size_t>(no, 1));
    s.cases = errors.size();
    return s;
}

Status AoEvaluator::prepare(const std::vector<TradeView>& views) {
    Result<tiers::TierChoice> choice = tiers::choose(dev_.caps(), tier_);
    if (!choice) return choice.status();
    profile_ = choice->profile;
    format_ = aoOutputFormat(dev_);
    Result<TextureHandle> out = dev_.createTexture({width_, height_, 1, format_, kTextureSampled | kTextureRenderTarget, "fit-ao-out"});
    if (!out) return out.status();
    out_ = out.value();
    for (const TradeView& v : views) {
        Result<std::unique_ptr<ViewInputs>> in = ViewInputs::create(dev_, tier_, v, width_, height_);
        if (!in) return in.status();
        inputs_.push_back(std::move(in.value()));
    }
    return Status::ok();
}

AoEvaluator::~AoEvaluator() {
    inputs_.clear();
    if (!out_.isNull()) (void)dev_.destroyTexture(out_);
}

std::vector<AoTechnique> allAoTechniques() {
    std::vector<AoTechnique> all;
    for (uint32_t i = 0; std::string(toString(AoTechnique(i))) != "unknown"; ++i) all.push_back(AoTechnique(i));
    return all;
}

Result<std::vector<truth::Comparison>> AoEvaluator::run(AoSettings s, const std::vector<AoCase>& cases, std::vector<reference::Grid>* visibilities) {
    std::vector<truth::Comparison> errors;
    for (const AoCase& c : cases) {
        const ViewInputs& in = *inputs_[c.view];
        s.radius = float(c.radius);
        Result<std::unique_ptr<AmbientObscurance>> ao = AmbientObscurance::create(dev_, {width_, height_, profile_, s, in.depthKind()});
        if (!ao) return ao.status();
        SFX_TRY(ao.value()->dispatch({DepthSource{in.depth(), in.depthKind(), in.camera()}, in.normals(), out_}));
        SFX_TRY(dev_.flush());
        Result<reference::Grid> vis = readVisibility(dev_, out_, format_, width_, height_);
        if (!vis) return vis.status();
        Result<truth::Comparison> e = truth::compare(c.truth, vis->values);
        if (!e) return e.status();
        errors.push_back(e.value());
        if (visibilities) visibilities->push_back(std::move(vis.value()));
    }
    ++evaluations_;
    return errors;
}

Result<AoScore> AoEvaluator::score(const AoSettings& s, const std::vector<AoCase>& cases) {
    Result<std::vector<truth::Comparison>> e = run(s, cases);
    if (!e) return e.status();
    return summarise(e.value());
}

}  // namespace sfx::tools
