#version 450
// Motion blur pass 3: the largest tile velocity in the 3x3 tiles around each tile, among the
// tiles whose velocity can reach it (mbNeighborReaches): a bound on what can blur over any pixel
// of the tile. Row-major scan, first wins ties.
#include "sfx_shared.h"
#include "sfx_shared_mb.h"

layout(set = 0, binding = 0) uniform sampler2D uTileMax;

layout(location = 0) out vec2 outNeighborMax;

void main() {
    ivec2 size = textureSize(uTileMax, 0);
    ivec2 t = ivec2(gl_FragCoord.xy);
    vec2 best = vec2(0.5);
    float bestLen2 = -1.0;
    for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
            ivec2 q = t + ivec2(dx, dy);
            if (q.x < 0 || q.y < 0 || q.x >= size.x || q.y >= size.y) continue;
            vec2 e = sfxTexel(uTileMax, q, 0).xy;
            vec2 d = e - 0.5;
            if (!mbNeighborReaches(dx, dy, d)) continue;
            float len2 = dot(d, d);
            if (len2 > bestLen2) {
                bestLen2 = len2;
                best = e;
            }
        }
    }
    outNeighborMax = best;
}
