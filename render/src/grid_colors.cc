#include "grid_colors.h"

#include <algorithm>

#include "cogmap/mapper/grid/grid.h"

namespace cogmap::render {
namespace {

Rgb mix_linear(Rgb a, Rgb b, float t) {
  return {a.r + (b.r - a.r) * t, a.g + (b.g - a.g) * t, a.b + (b.b - a.b) * t};
}

}  // namespace

Rgb grid_cell_color(float value, const Style& style) {
  // Anything at or below half the path marker is the path: updaters only write that value there.
  if (value <= mapper::kRobotPathValue * 0.5f) return style.grid_robot_path;
  if (value == 0.0f) return style.grid_unexplored;
  if (value < 0.0f) {
    // Even one "empty" reading reads clearly lighter than unexplored; the floor is lightest.
    const float t = std::min(value / mapper::kHistogramFloor, 1.0f);
    return mix_linear(style.grid_unexplored, style.grid_empty, 0.6f + 0.4f * t);
  }
  // Occupied: the grey darkens with the count so ε-crossing cells stand out (cap at 15).
  const float t = std::min(value / mapper::kHistogramMax, 1.0f);
  return mix_linear(style.grid_unexplored, style.grid_occupied, 0.25f + 0.75f * t);
}

}  // namespace cogmap::render
