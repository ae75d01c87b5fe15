#version 450
#extension GL_EXT_control_flow_attributes : require
// Motion blur pass 3: the largest tile velocity among the tiles around each tile whose velocity
// can reach it (mbNeighborReaches), out to the radius (mbNeighborReachTiles: the 3 x 3 of the
// course when the tile is the radius): a bound on what can blur over any pixel of the tile.
// Row-major scan, first wins ties.
#include "sfx_shared.h"
#include "sfx_shared_mb.h"

layout(set = 0, binding = 0) uniform sampler2D uTileMax;

layout(location = 0) out vec2 outNeighborMax;
// N and k in pixels, [1, SFX_MB_MAX_RADIUS_LIMIT_PX]; MotionBlur gives both.
layout(constant_id = SFX_MB_SC_TILE_SIZE) const int kTileSize = 1;
layout(constant_id = SFX_MB_SC_RADIUS) const int kRadius = 1;

void main() {
    ivec2 size = textureSize(uTileMax, 0);
    ivec2 t = ivec2(gl_FragCoord.xy);
    int reach = mbNeighborReachTiles(kRadius, kTileSize);
    vec2 best = vec2(0.0);
    float bestLen2 = -1.0;
    [[unroll]] for (int dy = -reach; dy <= reach; ++dy) {
        [[unroll]] for (int dx = -reach; dx <= reach; ++dx) {
            ivec2 q = t + ivec2(dx, dy);
            if (q.x < 0 || q.y < 0 || q.x >= size.x || q.y >= size.y) continue;
            vec2 v = sfxTexel(uTileMax, q, 0).xy;
            if (!mbNeighborReaches(dx, dy, v, kTileSize)) continue;
            float len2 = mbRankKey(v);
            if (len2 > bestLen2) {
                bestLen2 = len2;
                best = v;
            }
        }
    }
    outNeighborMax = best;
}
