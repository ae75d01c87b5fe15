// The worst-pixel bounds between two backends or drivers, each derived from what the Vulkan and
// GL ES specifications let a conformant implementation do with that effect's operations
// (docs/conformance.md, "Cross-backend agreement", gives the rule and the measured worst).
#pragma once

#include "effect_runs.hpp"

namespace sfx::test {

// One step of fp16 just below 1 (2^-11): where a float result is stored to an RGBA16F or RG16F
// target, or packed with packHalf2x16, the APIs let it round to nearest or toward zero, so two
// drivers may store neighbouring fp16 values of the same float.
inline constexpr double kHalfStepBelowOne = 1.0 / 2048.0;
inline constexpr double kUnorm8Step = 1.0 / 255.0;

// AO: every backend evaluates the same float taps on the same float inputs, so only the order
// of float operations may differ: a few ulps of a visibility in [0, 1]. A tap that rounds to
// another pixel, a wrong MIP level or a missed blur weight moves a pixel by 1e-3 or more and
// fails. Multilayer AO reads the same R32F layers and writes R32F: the same bound.
inline constexpr double kAoPairWorst = 1e-5;
// Horizon's arc takes acos: each backend is within kAoHorizonTrigBound of the exact arc
// (docs/ao.md), so two are within twice that. On the current tier the AO passes through 8-bit
// targets, where two floats that differ at all may round to neighbouring codes: one unorm8 step
// more.
inline constexpr double kAoHorizonPairWorst = 2 * kAoHorizonTrigBound;
// Motion blur: the output is fp16, so operation order can move a channel by one fp16 step
// below 1; two allowed. A different tap or weight decision moves it far more.
inline constexpr double kMotionBlurPairWorst = 2 * kHalfStepBelowOne;
// Motion blur's pass-1 velocities (the packed texture's xy, in pixels): put on fp16's grid by
// integer operations on the float's bits (mbQuantizeVelocity), the same in every language, and
// stored exactly: bit for bit.
inline constexpr double kVelocityPairWorst = 0.0;

// The A-buffer (high tier): every backend sorts each pixel's fragments by the same exact key
// (depth, draw id, primitive id), so the layers are composited in the same order; each node's
// premultiplied colour is packed to fp16 (packHalf2x16) and the composite stored to RGBA16F,
// each rounding either way. The layers' weights (transmittance products) sum to at most 1, so
// the nodes' roundings move a channel below 1 by at most one fp16 step together, the output's
// by one more.
inline constexpr double kAbufferPairWorst = 2 * kHalfStepBelowOne;
// Weighted blended OIT (current tier): each of a pixel's n layers blends into three fp16
// accumulators (weighted colour sum, weight sum, revealage product), and every blend result is
// stored as fp16, rounding either way: one fp16 ulp, 2^-10 relative, per layer and accumulator.
// The resolve divides the sums (2n ulps relative of an average colour at most 1, so 4n steps
// below 1), scales the opaque colour by the revealage (n ulps relative: 2n steps), and stores
// fp16 (one step): (6n + 1) steps. The test's pixels have up to n = 3 layers. A wrong weight or
// blend factor moves the average by whole percent.
inline constexpr uint32_t kWeightedBlendedLayers = 3;
inline constexpr double kWeightedBlendedPairWorst = (6 * kWeightedBlendedLayers + 1) * kHalfStepBelowOne;
// AO through the transparent layers (high tier): the fragments' view positions are interpolated
// by each rasteriser (the specifications do not make interpolation exact), so they agree to a
// few float ulps, not bit for bit; Scalable's occlusion is continuous in them, and the RG16F
// output rounds either way: one step, and one for the filter's continuous weights and the
// interpolation together. Alchemy cuts its taps at the radius (a step): a tap within interpolation
// error of it counts on one rasteriser and not the other, which is a tie, not a defect; at most
// kAlchemyTieFraction of the values (Filament's image tests allow 0.1 % of pixels, beyond 5/255)
// may exceed the bound.
inline constexpr double kLayerAoPairWorst = 2 * kHalfStepBelowOne;
inline constexpr double kAlchemyTieFraction = 0.001;
// Scene renderer, wherever two rasterisers cover the same pixels (edges far from pixel centres,
// or the same sub-pixel grid: requireRasterPairsWithin): the same float shading of interpolated
// normals and depth and the AO of the same taps, stored as fp16 on the way (one step each way
// per store) - two steps; the current tier adds one unorm8 step (its AO passes through 8-bit
// targets; the colour scales it by an ambient share of at most 1).
inline constexpr double kRenderPairWorst = 2 * kHalfStepBelowOne;

}  // namespace sfx::test
