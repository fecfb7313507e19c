// rt-render --light: a light given on the command line, as pbrt's LightSource or a line of
// Blender Python adds one (docs/rt-render.md, Lights from the command line).
#pragma once

#include <string>

#include "scene/light.h"

namespace rt::tool::render {

// One --light value, TYPE:NUMBERS with TYPE from kLightOptionNames:
//   point:X,Y,Z[,R,G,B[,W]]                 at (X, Y, Z)
//   spot:X,Y,Z,TX,TY,TZ[,CONE[,R,G,B[,W]]]  at (X, Y, Z), shining towards the point (TX, TY, TZ),
//                                           CONE degrees from its axis to its edge (0-90, default 45)
//   sun:DX,DY,DZ[,R,G,B[,W]]                infinitely far, shining along (DX, DY, DZ)
// The colour is R,G,B (default white) times W (default 1); the light does not fall off with
// distance, as the thesis's lights and the headlight do not. Throws rt::InputError naming the
// value for anything else: a wrong count, a number not finite, a negative colour or W, a zero
// direction, a cone outside (0, 90].
Light parseLightOption(const std::string& text);

}  // namespace rt::tool::render
