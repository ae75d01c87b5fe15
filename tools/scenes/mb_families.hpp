// Scene families for scoring motion blur on scenes it was not tuned on: 2D analytic pictures
// (textured objects of several sizes, thin posts and wires, rotating and approaching objects,
// objects crossing at different depths, and an independent checkered square over stripes),
// each generated from a seed at a chosen speed. Every instant of the shutter is exact, so the
// truth is the average of many instants; the effect gets the mid-shutter frame with its exact
// linear depth and the instantaneous velocity of each visible point.
#pragma once

#include <string>
#include <vector>

#include "sfx/reference/motion_blur_reference.hpp"

namespace sfx::tools {

// One object of a family picture. Its motion across the shutter interval (t in [-0.5, 0.5]):
// the centre moves by velocityPx * t, the object turns by spinRad * t about its centre and is
// scaled by exp(growth * t) about it (growth > 0: approaching the camera). angleRad and scale are
// the pose at t = 0 (0 and 1 as laid out; a later frame of a sequence starts turned and grown).
struct FamilyObject {
    enum class Shape { Plane, Rect, Disc };
    enum class Texture { Flat, Checker, Stripes };
    Shape shape = Shape::Rect;
    Texture texture = Texture::Flat;
    double cell = 8;  // checker cell or stripe width, pixels (object's own frame)
    std::array<double, 4> colorA{1, 1, 1, 1}, colorB{0, 0, 0, 1};
    double depth = 10;                     // linear depth, constant across the shutter
    std::array<double, 2> centre{0, 0};    // pixels at mid-shutter
    std::array<double, 2> halfSize{0, 0};  // Rect: half extents; Disc: radius in [0]
    std::array<double, 2> velocityPx{0, 0};
    double spinRad = 0, growth = 0;
    double angleRad = 0, scale = 1;
};

struct FamilyScene {
    uint32_t width = 0, height = 0;
    std::vector<FamilyObject> objects;  // any order: the nearest covering object is seen
    // The exact picture at shutter time t; velocity = the visible point's displacement across the
    // shutter at its t = 0 rate (what a velocity buffer holds); layer = object index or -1.
    reference::SceneFrame render(double t) const;
    // Average of `instants` instants spread evenly over the shutter interval.
    reference::ColorGrid truth(uint32_t instants) const;
};

// Where a pixel's error is counted: the moving region (any instant shows a moving surface or
// the visible object changes), and within it the two kinds of edge: leading = the surface
// visible at shutter open is covered by a nearer one at close; trailing = the nearer one at
// open uncovers a farther one by close (the revealed background).
struct FamilyMasks {
    std::vector<bool> moving, leading, trailing;
};
FamilyMasks familyMasks(const FamilyScene& scene, uint32_t instants);

struct FamilyCase {
    std::string family;
    bool heldOut = false;  // never used to choose a design or a preset
    double speedPx = 0;    // displacement across the shutter of the family's fastest edge
    FamilyScene scene;
    // Rows the moving object spans (the independent scene's own measure); empty: whole frame.
    std::vector<bool> rowsMask;
};

// The family names, training ones first.
std::vector<std::string> familyNames();
bool familyHeldOut(const std::string& family);
// One picture of `family` at `speedPx`, laid out from `seed` in a w x h frame.
FamilyCase makeFamilyCase(const std::string& family, double speedPx, uint32_t seed, uint32_t w, uint32_t h);

}  // namespace sfx::tools
