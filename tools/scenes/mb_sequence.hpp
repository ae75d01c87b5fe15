// Frame sequences over a scene family (mb_families.hpp), for measuring how stable motion blur is
// from frame to frame: frame f of a sequence is the family's picture at a later (or earlier)
// centre time, with a slow camera pan added to everything, the background included. Motion is
// analytic, so every frame's truth is exact like the family's own.
#pragma once

#include <array>
#include <vector>

#include "mb_families.hpp"

namespace sfx::tools {

// The scene of the frame whose shutter is centred at `centreTime` (in shutter intervals from the
// family's layout at t = 0), with every object, the background plane included, also moving by
// `panPx` per shutter interval (a camera pan; moving objects keep their own motion on top).
// A moving object that would leave the frame bounces off its edges instead (each axis of its
// path folds back and the velocity flips), and a growing one folds back between half and twice
// its laid-out size (it recedes again), so every frame of a long sequence still shows the
// family's motion. The result's t in [-0.5, 0.5] is that frame's shutter; centreTime 0 and no
// pan gives the scene unchanged.
FamilyScene sequenceScene(const FamilyScene& scene, double centreTime, std::array<double, 2> panPx);

// One frame of a sequence: what the effect gets (the mid-shutter picture with its depth and
// velocity), the truth (the average of `instants` instants over the shutter), the truth from the
// even-numbered instants only (half as many, to measure the truth's own noise), and where the
// objects are: every pixel where some instant shows an object other than the background plane.
struct SequenceFrame {
    reference::SceneFrame input;
    reference::ColorGrid truth, truthHalf;
    std::vector<bool> objects;
};
SequenceFrame sequenceFrame(const FamilyScene& frameScene, uint32_t instants);

}  // namespace sfx::tools
