#version 450
// Motion blur pass 2: per N x N tile (N = the tile edge, TierProfile::mbTilePx scaled), the velocity of largest
// magnitude, ranked by mbRankKey as the CPU reference ranks them.
// Ties keep the first in row-major scan order, as the CPU reference does.
#include "sfx_shared.h"
#include "sfx_shared_mb.h"

layout(set = 0, binding = 0) uniform sampler2D uPacked;

layout(location = 0) out vec2 outTileMax;
// N, [1, SFX_MB_MAX_RADIUS_LIMIT_PX]; MotionBlur gives it.
layout(constant_id = SFX_MB_SC_TILE_SIZE) const int kTileSize = 1;

void main() {
    ivec2 size = textureSize(uPacked, 0);
    ivec2 origin = ivec2(gl_FragCoord.xy) * kTileSize;
    vec2 best = vec2(0.0);
    float bestLen2 = -1.0;
    for (int j = 0; j < kTileSize; ++j) {
        int y = origin.y + j;
        if (y >= size.y) break;
        for (int i = 0; i < kTileSize; ++i) {
            int x = origin.x + i;
            if (x >= size.x) break;
            vec2 v = sfxTexel(uPacked, ivec2(x, y), 0).xy;
            float len2 = mbRankKey(v);
            if (len2 > bestLen2) {
                bestLen2 = len2;
                best = v;
            }
        }
    }
    outTileMax = best;
}
