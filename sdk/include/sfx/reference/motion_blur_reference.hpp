// CPU reference of motion blur reconstruction, in double precision and written for clarity.
// It runs the same passes as the shaders with the same jitter, tap layout and weights (all
// from shader_src/include/sfx_shared_mb.h). Where the GPU stores fp16 (the packed velocity
// and the tile textures), both round the velocity to the same grid, which fp16 holds exactly
// (mbQuantizeVelocity), and rank velocities by the same float key (mbRankKey), so the two pick
// the same texels; everything else stays in double.
#pragma once

#include <array>
#include <functional>
#include <vector>

#include "sfx/motion_blur.hpp"
#include "sfx/reference/depth_reference.hpp"

namespace sfx::reference {

// W x H RGBA colours, row 0 first (memory rows).
struct ColorGrid {
    uint32_t width = 0, height = 0;
    std::vector<std::array<double, 4>> values;
    ColorGrid() = default;
    ColorGrid(uint32_t w, uint32_t h, std::array<double, 4> fill = {0, 0, 0, 0}) : width(w), height(h), values(size_t(w) * h, fill) {}
    std::array<double, 4>& at(uint32_t x, uint32_t y) { return values[size_t(y) * width + x]; }
    const std::array<double, 4>& at(uint32_t x, uint32_t y) const { return values[size_t(y) * width + x]; }
};

// W x H velocities in pixels (x toward increasing column, y toward increasing row).
struct VelocityGrid {
    uint32_t width = 0, height = 0;
    std::vector<std::array<double, 2>> values;
    VelocityGrid() = default;
    VelocityGrid(uint32_t w, uint32_t h, std::array<double, 2> fill = {0, 0}) : width(w), height(h), values(size_t(w) * h, fill) {}
    std::array<double, 2>& at(uint32_t x, uint32_t y) { return values[size_t(y) * width + x]; }
    const std::array<double, 2>& at(uint32_t x, uint32_t y) const { return values[size_t(y) * width + x]; }
};

// Round to the nearest fp16 value (ties to even), as a render target of RGBA16F / RG16F stores.
double roundToHalf(double value);

struct MotionBlurReferenceResult {
    ColorGrid color;           // the reconstruction
    VelocityGrid radiusPx;     // pass 1: the blur radius per pixel after exposure and clamp (decoded)
    VelocityGrid tileMax;      // pass 2, decoded pixels, one per tile
    VelocityGrid neighborMax;  // pass 3, decoded pixels
    // What the reconstruction did, for property tests.
    double maxSampleOffsetPx = 0;  // longest centre -> sample distance read
    uint64_t samplesOutside = 0;   // sample positions that needed clamping into the image
    uint64_t stillPixels = 0;      // pixels returned unchanged by the velocity branch
    uint64_t repeatedSamples = 0;  // samples left out on the texel the previous pair read (sfx_shared_mb.h)
};

// SFX_SKY_DEPTH of sfx_shared.h (the .cpp asserts they are equal): an infinite projection's maxDepth.
inline constexpr double kSkyDepth = 1.0e8;

// Candidate reconstructions the benches can score against today's (docs/motion_blur_studies.md,
// "Reconstruction candidates scored on the CPU reference"); the shaders have none of them, and
// the defaults are today's reconstruction exactly.
struct MotionBlurCandidate {
    // > 0: of each sample's background weight, the part behind the centre (the weight times
    // clamp(2 (z_S - z_C) / softDepthExtent, 0, 1): none when level, so a uniformly moving area
    // keeps its box filter) stands for the surface the centre hides, and that part's colour is the
    // average of those samples weighted by distance^-hiddenNearExponent (nearer samples likelier
    // to look like it); the weights, and so the background's share, are unchanged.
    double hiddenNearExponent = 0;
    // Per-pixel dither of the pair count: round(s + j) pairs instead of round(s), s the texel
    // steps of v_N (mbTexelSteps) and j the 4 x 4 table's offset (mbJitter size 4), so a
    // fractional count uses the pair counts either side of it in proportion.
    bool ditherPairs = false;
    // Jitter the sample positions at full share (s = 1) even where the pairs read every texel,
    // with the 4 x 4 table's offsets.
    bool jitterAlways = false;
};

// linearDepth: linear depth, read through sfxLinearDepthOrFar(z, maxDepth) as the pack pass does
// (maxDepth: the far plane of the depth's reconstruction, or SFX_SKY_DEPTH); velocityPx: the
// host's velocity, pixels across the shutter interval. Sizes must match (asserted by the caller).
// Hostile values follow the rules of sfx_shared.h / sfx_shared_mb.h, as on the GPU.
MotionBlurReferenceResult motionBlur(const ColorGrid& color, const Grid& linearDepth, const VelocityGrid& velocityPx, const MotionBlurParams& params,
                                     double maxDepth = kSkyDepth, const MotionBlurCandidate& candidate = {});

// Camera-only velocity (pixels across the shutter, current minus previous position) for
// linear depth under `projection`, as mb_pack.frag computes it.
VelocityGrid cameraVelocity(const Grid& linearDepth, const glm::dmat4& projection, const CameraMotion& camera);

// ---- Procedural 2.5D scenes with analytic motion (tests, benchmark, CLI tests) --------------
// Flat layers at fixed depths sliding at constant velocity across the shutter interval. Any
// instant can be rendered exactly, so the ground truth of motion blur is the average of many
// instants, and the SDK's input is the mid-shutter frame with its exact velocity and depth.
struct SceneLayer {
    enum class Shape { Plane, Rect, Disc };
    Shape shape = Shape::Plane;
    double depth = 10.0;                     // linear depth, scene units (> 0)
    std::array<double, 2> centre{0, 0};      // pixels, at mid-shutter (t = 0)
    std::array<double, 2> halfSize{0, 0};    // Rect: half extents; Disc: radius in [0]
    std::array<double, 2> velocityPx{0, 0};  // displacement across the whole shutter interval
    // Texture: a checker of `cell` pixels between two colours, moving with the layer; cell 0 = flat colourA.
    double cell = 0;
    std::array<double, 4> colorA{1, 1, 1, 1}, colorB{0, 0, 0, 1};
};

struct SceneFrame {
    ColorGrid color;
    Grid depth;              // linear depth
    VelocityGrid velocity;   // pixels across the shutter interval
    std::vector<int> layer;  // index of the visible layer per pixel, -1 = none (black, far)
};

struct MotionScene {
    uint32_t width = 0, height = 0;
    std::vector<SceneLayer> layers;
    // The picture at shutter time t in [-0.5, 0.5] (0 = mid-shutter), one sample per pixel centre.
    SceneFrame render(double t) const;
    // The average of `instants` frames evenly spread over the shutter interval.
    ColorGrid groundTruth(uint32_t instants) const;
};

// The average of `instants` pictures render(t) at times evenly spread over the shutter interval
// [-0.5, 0.5] (the truth of every motion scene, whatever draws it).
ColorGrid shutterAverage(uint32_t width, uint32_t height, uint32_t instants, const std::function<SceneFrame(double)>& render);

// Pixels within `radius` of a boundary between layers where at least one of them moves.
std::vector<bool> movingSilhouetteMask(const SceneFrame& frame, const MotionScene& scene, uint32_t radius);

}  // namespace sfx::reference
