// The host's camera as the effects need it: its projection matrix and the API's clip depth
// convention. Everything that reconstructs positions from depth derives from this one struct.
#pragma once

#include <glm/glm.hpp>

#include "sfx/hal.hpp"
#include "sfx/status.hpp"

namespace sfx {

struct CameraProjection {
    // The column-major perspective projection the host rendered depth with (camera looking down
    // -z). Reversed-Z, infinite far and off-centre (jittered) projections are all fine.
    glm::dmat4 projection{1.0};
    // How the API mapped clip z to stored depth: [0,1] (Vulkan, D3D, glClipControl) or [-1,1] (GL default).
    ClipDepthRange clipDepth = ClipDepthRange::ZeroToOne;
};

// Constants derived once, in double precision, from a CameraProjection for a W x H target.
struct DepthReconstruction {
    // Linear (eye) depth from stored depth d: z = numerator / (d * ndcScale + denomOffset).
    double ndcScale = 1, denomOffset = 0, numerator = 0;
    double nearDepth = 0;  // linear depth at the near plane
    double maxDepth = 0;   // far plane, or SFX_SKY_DEPTH for an infinite projection
    bool reversedZ = false;
    // View position from pixel centre and linear depth (sfx_shared.h: reconstructViewPosition).
    double projInfo[4] = {0, 0, 0, 0};
    // A world-space length L at linear depth z covers L * pixelsPerUnitAtUnitDepth / z pixels.
    double pixelsPerUnitAtUnitDepth = 0;
};

// InvalidArgument naming CameraProjection.projection when it is not a finite perspective
// projection looking down -z (P[2][3] = -1, P[3][3] = 0), or width/height is 0.
Result<DepthReconstruction> makeDepthReconstruction(const CameraProjection& camera, uint32_t width, uint32_t height);

// A perspective projection for tools, samples and tests. far = +infinity gives an infinite
// far plane. rowZeroIsTop flips y so that memory row 0 is the top of the picture (as the SDK's
// image files are); clipDepth picks the stored-depth range of the API it will render on.
struct PerspectiveDesc {
    double fovYRadians = 1.0471975511965976;  // 60 degrees
    double aspect = 1.0;                      // width / height
    double nearPlane = 0.1;
    double farPlane = 100.0;  // may be +infinity
    bool reversedZ = false;
    ClipDepthRange clipDepth = ClipDepthRange::ZeroToOne;
    bool rowZeroIsTop = true;
};
Result<CameraProjection> makePerspective(const PerspectiveDesc& desc);

// Stored depth for a linear depth, the exact inverse used by tests and the CPU references.
double storedDepthFromLinear(const CameraProjection& camera, double linearDepth);

}  // namespace sfx
