#include "motion_cases.hpp"

#include <algorithm>
#include <cmath>

#include "sfx/budget.hpp"

namespace sfx::tools {

using namespace sfx::reference;

// Scenes laid out in fractions of the picture, so every size shows the same thing; velocities
// scale with the height as the tier radii do. At 180 rows the displacements (8-10 px, a blur
// radius of 4-5 px) sit at the high tier's radius (4.5 px there) and beyond the current
// tier's (2.5 px): the current tier is expected to clamp, the high tier barely.
std::vector<NamedMotionScene> makeMotionScenes(uint32_t w, uint32_t h) {
    const double s = h / 180.0;  // pixels per "design pixel" (designed at 320x180)
    std::vector<NamedMotionScene> out;
    {
        // A ball flying across a still textured wall.
        MotionScene sc{w, h, {}};
        SceneLayer wall;
        wall.depth = 20, wall.cell = 10 * s, wall.colorA = {0.55, 0.5, 0.45, 1}, wall.colorB = {0.25, 0.3, 0.35, 1};
        SceneLayer ball;
        ball.shape = SceneLayer::Shape::Disc, ball.depth = 6, ball.centre = {w * 0.45, h * 0.5}, ball.halfSize = {28 * s, 0};
        ball.cell = 7 * s, ball.colorA = {1.0, 0.85, 0.2, 1}, ball.colorB = {0.9, 0.2, 0.1, 1}, ball.velocityPx = {10 * s, 2 * s};
        sc.layers = {wall, ball};
        out.push_back({"ball", sc});
    }
    {
        // A camera pan: the background slides, a post tracked by the camera stays still in front,
        // and a box moves against the pan behind the post.
        MotionScene sc{w, h, {}};
        SceneLayer bg;
        bg.depth = 40, bg.cell = 12 * s, bg.colorA = {0.2, 0.45, 0.7, 1}, bg.colorB = {0.8, 0.85, 0.9, 1}, bg.velocityPx = {-8 * s, 0};
        SceneLayer box;
        box.shape = SceneLayer::Shape::Rect, box.depth = 15, box.centre = {w * 0.55, h * 0.45}, box.halfSize = {30 * s, 22 * s};
        box.cell = 6 * s, box.colorA = {0.9, 0.3, 0.3, 1}, box.colorB = {0.3, 0.1, 0.1, 1}, box.velocityPx = {9 * s, -3 * s};
        SceneLayer post;
        post.shape = SceneLayer::Shape::Rect, post.depth = 4, post.centre = {w * 0.5, h * 0.5}, post.halfSize = {7 * s, h * 0.6};
        post.cell = 5 * s, post.colorA = {0.2, 0.8, 0.3, 1}, post.colorB = {0.1, 0.4, 0.15, 1};
        sc.layers = {bg, box, post};
        out.push_back({"pan", sc});
    }
    {
        // Two discs crossing at different depths, both moving, over a still floor.
        MotionScene sc{w, h, {}};
        SceneLayer floor;
        floor.depth = 25, floor.cell = 8 * s, floor.colorA = {0.4, 0.4, 0.4, 1}, floor.colorB = {0.6, 0.6, 0.6, 1};
        SceneLayer a;
        a.shape = SceneLayer::Shape::Disc, a.depth = 8, a.centre = {w * 0.42, h * 0.48}, a.halfSize = {24 * s, 0};
        a.colorA = {0.95, 0.6, 0.1, 1}, a.velocityPx = {8 * s, 0};
        SceneLayer b = a;
        b.depth = 12, b.centre = {w * 0.56, h * 0.55}, b.colorA = {0.2, 0.3, 0.95, 1}, b.cell = 6 * s, b.colorB = {0.9, 0.9, 1, 1};
        b.velocityPx = {-6 * s, -4 * s};
        sc.layers = {floor, b, a};
        out.push_back({"crossing", sc});
    }
    return out;
}

ColorErrors colorErrors(const ColorGrid& a, const ColorGrid& truth, const std::vector<bool>& mask) {
    double all = 0, sil = 0;
    size_t nSil = 0;
    for (size_t i = 0; i < a.values.size(); ++i) {
        double e = 0;
        for (int c = 0; c < 3; ++c) e += std::pow(a.values[i][c] - truth.values[i][c], 2);
        all += e;
        if (mask[i]) sil += e, ++nSil;
    }
    return {std::sqrt(all / (3.0 * a.values.size())), nSil ? std::sqrt(sil / (3.0 * nSil)) : 0.0};
}

Result<TextureHandle> uploadColor(Device& device, const ColorGrid& color, const char* name) {
    std::vector<float> c;
    c.reserve(color.values.size() * 4);
    for (const auto& px : color.values)
        for (double ch : px) c.push_back(float(ch));
    Result<TextureHandle> t = device.createTexture({color.width, color.height, 1, Format::RGBA32F, kTextureSampled, name});
    if (!t) return t.status();
    Status s = device.writeTexture(t.value(), 0, c.data(), c.size() * 4);
    if (!s) {
        (void)device.destroyTexture(t.value());
        return s;
    }
    return t;
}

// Shared by the 2.5D and the 3D cases so both are timed the same way.
Result<MotionBlurRun> timeMotionBlur(Device& device, const TierProfile& profile, const MotionBlurSettings& settings, uint32_t w, uint32_t h,
                                     const MotionBlurInputs& in, uint32_t runs) {
    Result<std::unique_ptr<MotionBlur>> mb = MotionBlur::create(device, {w, h, profile, Format::RGBA32F, in.depth.kind});
    if (!mb) return mb.status();
    Result<TimerReading> cost = budget::timeMedian(device, runs, [&] { return mb.value()->dispatch(in, settings); });
    if (!cost) return cost.status();
    MotionBlurRun run;
    run.source = cost->source;
    run.medianMs = cost->milliseconds;
    std::vector<float> out(size_t(w) * h * 4);
    SFX_TRY(device.readTexture(mb.value()->output(), 0, out.data(), out.size() * 4));
    run.output = ColorGrid(w, h);
    for (size_t i = 0; i < run.output.values.size(); ++i)
        for (int ch = 0; ch < 4; ++ch) run.output.values[i][ch] = out[i * 4 + size_t(ch)];
    return run;
}

Result<MotionBlurRun> runMotionBlur(Device& device, const TierProfile& profile, const MotionBlurSettings& settings, const SceneFrame& f,
                                    const CameraProjection& cam, uint32_t runs) {
    const uint32_t w = f.color.width, h = f.color.height;
    std::vector<float> z, v;
    for (double d : f.depth.values) z.push_back(float(d));
    for (const auto& e : f.velocity.values) v.push_back(float(e[0])), v.push_back(float(e[1]));
    Result<TextureHandle> ct = uploadColor(device, f.color, "bench-color");
    if (!ct) return ct.status();
    Result<TextureHandle> zt = device.createTexture({w, h, 1, Format::R32F, kTextureSampled, "bench-depth"});
    Result<TextureHandle> vt = device.createTexture({w, h, 1, Format::RG32F, kTextureSampled, "bench-velocity"});
    auto dispatch = [&]() -> Result<MotionBlurRun> {
        if (!zt) return zt.status();
        if (!vt) return vt.status();
        SFX_TRY(device.writeTexture(zt.value(), 0, z.data(), z.size() * 4));
        SFX_TRY(device.writeTexture(vt.value(), 0, v.data(), v.size() * 4));
        MotionBlurInputs in;
        in.color = ct.value();
        in.depth = {zt.value(), DepthKind::Linear, cam};
        in.velocity = vt.value();
        return timeMotionBlur(device, profile, settings, w, h, in, runs);
    };
    Result<MotionBlurRun> run = dispatch();
    (void)device.destroyTexture(ct.value());
    if (zt) (void)device.destroyTexture(zt.value());
    if (vt) (void)device.destroyTexture(vt.value());
    return run;
}

}  // namespace sfx::tools
