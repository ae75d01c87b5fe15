#include "ao_horizon_reference.hpp"

#include <algorithm>

#include "sfx_shared_ao_horizon.h"

namespace sfx::reference::detail {

namespace sh = sfx::shared;

double horizonVisibility(const HorizonPass& pass, int x, int y, double z, const glm::dvec3& C, const glm::dvec3& n, glm::dvec3* bent) {
    const AoConfig& c = pass.config;
    const Grid& base = pass.pyramid[0];
    const sh::ivec2 size{int(base.width), int(base.height)};
    const int slices = int(c.horizon.slices), steps = int(c.horizon.steps);
    const int levels = int(pass.pyramid.size());
    // The float values the shader computes its tap pixels from (sfx_shared_ao.h, "Where a tap lands").
    const float screenRadius = sh::aoScreenRadius(float(c.radius), pass.pixelsPerUnit, float(z));
    const uint32_t hash = sh::aoRotationHash(x, y);
    const int rotation = int(hash & 0xFFu);
    const double invFalloffWidth = 1.0 / (c.horizon.falloff * c.radius);
    const glm::dvec3 V = sh::aoHorizonViewVector(C);
    double visibleSum = 0.0, openSum = 0.0;
    glm::dvec3 bentSum(0.0), openBentSum(0.0);
    for (int i = 0; i < slices; ++i) {
        const sh::vec2 d = sh::aoTapDirection(sh::aoHorizonSliceTurnsQ16(i, slices), rotation);
        const glm::dvec3 u = sh::aoHorizonSliceDirection(d.x, d.y, pass.projInfo[0], pass.projInfo[1], V);
        const glm::dvec3 t = sh::aoHorizonSliceTangent(u);
        const double weight = sh::aoHorizonSliceWeight(u);
        const glm::dvec3 projected = sh::aoHorizonProjectedNormal(n, V, t);
        const int jitter = sh::aoHorizonJitterIndex(hash, i);
        const double invProjectedLength = 1.0 / projected.x;
        double horizon[2] = {0.0, 0.0};  // both sides start at the tangent plane
        for (int j = 0; j < steps; ++j) {
            const float rho = sh::aoHorizonStepRadius(j, steps, jitter, screenRadius);
            int level = 0;
            if (levels > 1) level = std::clamp(sh::aoFloorLog2(rho) - int(sh::SFX_AO_MIP_LEVEL_OFFSET), 0, levels - 1);
            const Grid& g = pass.pyramid[size_t(level)];
            for (int side = 0; side < 2; ++side) {
                const sh::vec2 ds = side == 0 ? d : sh::vec2{-d.x, -d.y};
                const sh::ivec2 q = sh::aoTap(sh::ivec2{x, y}, rho, ds, size);
                const uint32_t mx = std::min(uint32_t(q.x) >> level, g.width - 1), my = std::min(uint32_t(q.y) >> level, g.height - 1);
                const glm::dvec3 v = pass.position(q.x, q.y, g.at(mx, my)) - C;
                const double s = sh::aoHorizonSampleSin(v, n, invProjectedLength, c.radius, invFalloffWidth, c.epsilon);
                horizon[side] = sh::aoHorizonUpdate(horizon[side], s, c.horizon.thickness);
            }
        }
        const double nAngle = sh::aoHorizonNormalAngle(projected);
        visibleSum += weight * sh::aoHorizonSliceVisibility(horizon[0], horizon[1], projected, nAngle);
        openSum += weight * sh::aoHorizonSliceVisibility(0.0, 0.0, projected, nAngle);
        if (bent) {
            bentSum += weight * sh::aoHorizonSliceBent(horizon[0], horizon[1], projected, nAngle, V, t);
            openBentSum += weight * sh::aoHorizonSliceBent(0.0, 0.0, projected, nAngle, V, t);
        }
    }
    if (bent) *bent = sh::aoHorizonBentVector(bentSum, openBentSum, visibleSum, openSum, n);
    return sh::aoHorizonRatio(visibleSum, openSum);
}

}  // namespace sfx::reference::detail
