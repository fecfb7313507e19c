// Viridis (van der Walt and Smith, matplotlib, CC0): a perceptually uniform colour map,
// dark blue for little work to yellow for much, readable by colour-blind people and in
// greyscale. Stored as 11 samples of the original 256-entry table and interpolated.
#pragma once

#include "core/rgb_image.h"

namespace rt {

// t in [0, 1] (clamped; NaN maps to 0) to an sRGB colour.
Rgb8 viridis(float t);

}  // namespace rt
