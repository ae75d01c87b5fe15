#include "sfx/camera.hpp"

#include <cmath>
#include <limits>
#include <string>

#include "sfx_shared.h"

namespace sfx {

Result<DepthReconstruction> makeDepthReconstruction(const CameraProjection& camera, uint32_t width, uint32_t height) {
    if (width == 0 || height == 0) return invalidArgument("target size", std::to_string(width) + "x" + std::to_string(height), "both > 0");
    const glm::dmat4& P = camera.projection;
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(P[c][r])) return invalidArgument("CameraProjection.projection", "non-finite", "a finite perspective matrix");
    // A perspective projection looking down -z has clip.w = -z_view.
    if (P[2][3] != -1.0 || P[3][3] != 0.0 || P[0][3] != 0.0 || P[1][3] != 0.0)
        return invalidArgument("CameraProjection.projection", "not perspective",
                               "a perspective matrix with P[2][3] = -1 and P[3][3] = 0 (camera looking down -z)");
    if (P[0][0] == 0.0 || P[1][1] == 0.0)
        return invalidArgument("CameraProjection.projection", "degenerate (P[0][0] or P[1][1] is 0)",
                               "a perspective matrix with a finite field of view");
    if (P[3][2] == 0.0)
        return invalidArgument("CameraProjection.projection", "with P[3][2] = 0 (depth independent of distance)",
                               "a perspective matrix with a near plane");
    if (uint32_t(camera.clipDepth) > 1)
        return invalidArgument("CameraProjection.clipDepth", std::to_string(uint32_t(camera.clipDepth)), "ZeroToOne or MinusOneToOne");

    DepthReconstruction r;
    // ndc_z = -A - B / z_view with A = P[2][2], B = P[3][2]; eye depth z = -z_view = B / (ndc_z + A).
    const double A = P[2][2], B = P[3][2];
    const bool minusOneToOne = camera.clipDepth == ClipDepthRange::MinusOneToOne;
    r.ndcScale = minusOneToOne ? 2.0 : 1.0;
    r.denomOffset = (minusOneToOne ? -1.0 : 0.0) + A;
    r.numerator = B;
    auto depthAt = [&](double stored) {
        const double denom = stored * r.ndcScale + r.denomOffset;
        const double z = r.numerator / denom;
        return (denom == 0.0 || !(z > 0.0) || !std::isfinite(z)) ? std::numeric_limits<double>::infinity() : z;
    };
    const double z0 = depthAt(0.0), z1 = depthAt(1.0);
    r.reversedZ = z0 > z1;
    r.nearDepth = std::min(z0, z1);
    const double farDepth = std::max(z0, z1);
    r.maxDepth = std::isfinite(farDepth) && farDepth < shared::SFX_SKY_DEPTH ? farDepth : double(shared::SFX_SKY_DEPTH);
    if (!(r.nearDepth > 0.0) || !std::isfinite(r.nearDepth))
        return invalidArgument("CameraProjection.projection", "with no positive near plane",
                               "a projection whose stored depth 0 or 1 maps to a positive distance");
    r.projInfo[0] = 2.0 / (double(width) * P[0][0]);
    r.projInfo[1] = 2.0 / (double(height) * P[1][1]);
    r.projInfo[2] = (P[2][0] - 1.0) / P[0][0];
    r.projInfo[3] = (P[2][1] - 1.0) / P[1][1];
    r.pixelsPerUnitAtUnitDepth = std::abs(P[1][1]) * double(height) * 0.5;
    return r;
}

Result<CameraProjection> makePerspective(const PerspectiveDesc& d) {
    if (!(d.fovYRadians > 0.0 && d.fovYRadians < 3.14159265358979323846))
        return invalidArgument("PerspectiveDesc.fovYRadians", std::to_string(d.fovYRadians), "(0, pi)");
    if (!(d.aspect > 0.0) || !std::isfinite(d.aspect))
        return invalidArgument("PerspectiveDesc.aspect", std::to_string(d.aspect), "a finite value > 0");
    if (!(d.nearPlane > 0.0) || !std::isfinite(d.nearPlane))
        return invalidArgument("PerspectiveDesc.nearPlane", std::to_string(d.nearPlane), "a finite value > 0");
    if (!(d.farPlane > d.nearPlane)) return invalidArgument("PerspectiveDesc.farPlane", std::to_string(d.farPlane), "> nearPlane, or +infinity");
    const double f = 1.0 / std::tan(d.fovYRadians * 0.5);
    const double n = d.nearPlane, fa = d.farPlane;
    const bool infinite = std::isinf(fa);
    // Stored depth d_s as a function of eye depth z (the map A, B encode):
    //   [0,1]:  standard d_s = far (z - n) / (z (far - n)),   reversed d_s = n (far - z) / (z (far - n))
    //   [-1,1]: ndc = (far + n) / (far - n) - 2 far n / ((far - n) z), reversed: its negation
    double A, B;
    if (d.clipDepth == ClipDepthRange::ZeroToOne) {
        if (!d.reversedZ) {
            A = infinite ? -1.0 : -fa / (fa - n);
            B = infinite ? -n : -fa * n / (fa - n);
        } else {
            A = infinite ? 0.0 : n / (fa - n);
            B = infinite ? n : fa * n / (fa - n);
        }
    } else {
        if (!d.reversedZ) {
            A = infinite ? -1.0 : -(fa + n) / (fa - n);
            B = infinite ? -2.0 * n : -2.0 * fa * n / (fa - n);
        } else {
            A = infinite ? 1.0 : (fa + n) / (fa - n);
            B = infinite ? 2.0 * n : 2.0 * fa * n / (fa - n);
        }
    }
    CameraProjection c;
    c.clipDepth = d.clipDepth;
    glm::dmat4 P(0.0);
    P[0][0] = f / d.aspect;
    P[1][1] = d.rowZeroIsTop ? -f : f;  // row 0 = NDC y -1: put the picture's top there
    P[2][2] = A;
    P[2][3] = -1.0;
    P[3][2] = B;
    c.projection = P;
    return c;
}

double storedDepthFromLinear(const CameraProjection& camera, double z) {
    // ndc_z = -A + B / z (z = -z_view > 0), then to the stored range.
    const double A = camera.projection[2][2], B = camera.projection[3][2];
    const double ndc = -A + B / z;
    return camera.clipDepth == ClipDepthRange::MinusOneToOne ? ndc * 0.5 + 0.5 : ndc;
}

}  // namespace sfx
