#pragma once
// Colour of one HIMM-scale cell (mapper/grid/grid.h): robot path green, unexplored mid-grey,
// seen-empty light, occupied darker as the count rises.

#include "cogmap/render/style.h"

namespace cogmap::render {

/// The display colour of histogram value `value` under `style`'s grid colours.
Rgb grid_cell_color(float value, const Style& style);

}  // namespace cogmap::render
