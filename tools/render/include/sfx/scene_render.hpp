// The scene renderer behind `sfx render` and the demo: a scene file (sfx/scene_file.hpp) drawn
// through the HAL into the SDK's own textures (the samples' G-buffer raster pass), ambient
// obscurance on it, and a composite: lambert objects get colour * (ambient * AO + light * n.l),
// unlit objects their colour exactly; then the translucent objects through sfx::Transparency
// (the A-buffer on the high tier, weighted blended OIT on the current one) over that picture.
// It models only what the scene and the options ask for (no AO resources with AO off, no
// transparency effect, pool or pass when nothing is transparent), and its plan says what each
// pass and resource is for.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "sfx/ao.hpp"
#include "sfx/image_io.hpp"
#include "sfx/oit.hpp"
#include "sfx/plan.hpp"
#include "sfx/scene_file.hpp"
#include "sfx/tiers.hpp"

namespace sfx::render {

// The fixed light of lambert shading, in view space (from the upper left, toward the scene),
// and the weights of its terms: colour * (kAmbient * AO + kDirect * max(0, n . light)).
inline constexpr double kLightDirectionView[3] = {-0.4, 0.7, 0.59};
inline constexpr double kAmbient = 0.5;
inline constexpr double kDirect = 0.6;

struct RenderOptions {
    uint32_t width = 0, height = 0;                         // 0: the scene's; else [1, scene::kMaxSceneSize]
    std::optional<AoTechnique> ao = AoTechnique::Scalable;  // nullopt: AO off
    float aoRadius = 0.5f;                                  // AoSettings.radius
    uint32_t aoLayers = 1;                                  // opaque depth layers AO tests; 1 = single-layer AO
    bool oit = true;                                        // false: transparent objects are not drawn (--oit off)
    uint32_t maxLayers = 16;                                // K: fragments kept exact per pixel by the A-buffer resolve: 16 or 32
    uint32_t nodes = 4;                                     // M: nodes of a compressed list
    // The order the translucent objects are drawn in: a permutation of 0..N-1 over the scene's
    // N translucent objects in file order; empty = file order. Each keeps its draw id (its index
    // in the file), so on the high tier the picture does not depend on it (the tests check).
    std::vector<uint32_t> transparentDrawOrder;
    // Also return what the transparency step composited over (RenderResult::opaque), for tests.
    bool keepOpaqueInputs = false;
};
// InvalidArgument naming the field (by its `sfx render` flag, e.g. "--ao-radius") and its allowed values.
Status validateOptions(const RenderOptions& options);

// One line of the plan: a pass, a resource, a host step, or something left out, and why.
struct PlanLine {
    enum class Kind { Pass, Resource, Host, Omitted } kind = Kind::Pass;
    std::string effect, name;
    uint32_t width = 0, height = 0;
    uint64_t bytes = 0;  // resources
    std::string why;
};
struct FramePlan {
    std::vector<PlanLine> lines;
    uint64_t totalBytes() const;
    std::string describe() const;
};

// What the frame drew; the transparency numbers are zero where it did not run.
struct RenderStats {
    uint32_t opaqueObjects = 0, transparentObjects = 0, triangles = 0, transparentTriangles = 0;
    bool transparencyRan = false;
    bool abuffer = false;             // the high tier's A-buffer; false: weighted blended (no pool, no counts)
    uint32_t transparencyFrames = 0;  // frames drawn until one dropped no fragment (1, or 2 when the first pool was short)
    uint64_t firstFrameDropped = 0;   // fragments the first frame dropped (its pool is a guess)
    TransparencyStats oit;            // the last frame's counts (A-buffer only)
    double meanDepthComplexity = 0;   // oit.fragments per pixel of the picture (A-buffer only)
    std::string describe() const;
};

struct RenderResult {
    io::Image color;              // linear RGB, row 0 = top
    std::optional<io::Image> ao;  // visibility in [0, 1], 1 channel, when AO ran
    FramePlan plan;
    RenderStats stats;
    std::vector<std::string> warnings;  // printable: what was asked but not drawn
    // With RenderOptions::keepOpaqueInputs and a transparency step: its inputs, row 0 = top.
    struct OpaqueInputs {
        io::Image color;                 // linear RGB exactly as the effect read it (RGBA16F halves)
        std::vector<float> storedDepth;  // the D32F depth attachment the draws were tested against
        glm::dmat4 view{1.0}, projection{1.0};
        ClipDepthRange clipDepth = ClipDepthRange::ZeroToOne;
    };
    std::optional<OpaqueInputs> opaque;
};

class SceneRender {
public:
    // Uploads the scene and creates exactly the passes the options need; errors name the option.
    static Result<std::unique_ptr<SceneRender>> create(Device& device, const tiers::TierChoice& tier, const scene::Scene& scene,
                                                       const RenderOptions& options);
    ~SceneRender();
    SceneRender(const SceneRender&) = delete;
    SceneRender& operator=(const SceneRender&) = delete;

    uint32_t width() const { return width_; }
    uint32_t height() const { return height_; }
    // Known before render(): the passes, resources and bytes, and why each is there.
    FramePlan plan() const;
    Result<RenderResult> render();

private:
    struct Impl;
    explicit SceneRender(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
    uint32_t width_ = 0, height_ = 0;
};

// Linear [0, 1] -> the sRGB transfer function (PNG output).
double linearToSrgb(double linear);
// The image as a PNG stores it: each channel sRGB-encoded.
io::Image srgbEncoded(const io::Image& linear);
// By extension: .pfm and .exr hold linear RGB, .png sRGB-encoded. Other extensions:
// InvalidArgument naming `flag`.
Status writeRendered(const std::string& path, const io::Image& linear, const char* flag);

}  // namespace sfx::render
