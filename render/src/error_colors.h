#pragma once
// Colour of a map error on the style's scale (figures/map_error.png): green up to
// error_good_m, yellow at error_mid_m, red from error_bad_m, linear in between, so the eye
// reads the colour as a distance in metres the way the legend states it.

#include "cogmap/render/style.h"

namespace cogmap::render {

/// The display colour of a distance `error_m` to the nearest true surface under `style`.
Rgb error_color(double error_m, const Style& style);

}  // namespace cogmap::render
