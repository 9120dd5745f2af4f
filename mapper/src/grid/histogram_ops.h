#pragma once
/// The cell operations of HIMM and MHIMM (thesis Figs. A.2-A.3) on a raw row-major float grid:
/// the 3x3 hit increment and the Bresenham line decrement. Kept inline: they are the hot path.

#include <algorithm>

#include "cogmap/mapper/grid/bresenham.h"
#include "cogmap/mapper/grid/grid.h"

namespace cogmap::mapper {

/// Bounds and path protection of one histogram variant.
struct HistogramLimits {
  float floor = 0.0f;         ///< HIMM 0 (§2.2.3), MHIMM -3 (§3.1.4)
  float cap = kHistogramMax;  ///< 15 for both
  bool protect_path = false;  ///< MHIMM: cells holding kRobotPathValue are never written
};

/// Fig. A.2/A.3 Update: C[t] += hit_increment, then every cell of the 3x3 block around t,
/// t included, += neighbour_increment, each capped. All nine cells must be inside the grid.
inline void increment_hit(Grid<float>& grid, CellIndex t, float hit_increment,
                          float neighbour_increment, const HistogramLimits& limits) {
  const int width = grid.width();
  float* const row0 = grid.data() + (static_cast<std::ptrdiff_t>(t.y) - 1) * width + t.x;
  float& centre = row0[width];
  if (!(limits.protect_path && centre == kRobotPathValue)) {
    centre = std::min(centre + hit_increment, limits.cap);
  }
  for (int l = 0; l < 3; ++l) {
    float* const row = row0 + static_cast<std::ptrdiff_t>(l) * width;
    for (int m = -1; m <= 1; ++m) {
      float& c = row[m];
      if (limits.protect_path && c == kRobotPathValue) continue;
      c = std::min(c + neighbour_increment, limits.cap);
    }
  }
}

/// LineDecrease: every cell of the Bresenham line from `from` (the robot centre) to `to`
/// -= decrement, floored; `to` itself only when `include_to`. Both ends must be inside.
inline void decrement_line(Grid<float>& grid, CellIndex from, CellIndex to, bool include_to,
                           float decrement, const HistogramLimits& limits) {
  float* const data = grid.data();
  const std::ptrdiff_t width = grid.width();
  for_each_line_cell(from, to, [&](CellIndex c) {
    if (!include_to && c == to) return false;
    float& v = data[static_cast<std::ptrdiff_t>(c.y) * width + c.x];
    if (!(limits.protect_path && v == kRobotPathValue)) v = std::max(v - decrement, limits.floor);
    return true;
  });
}

}  // namespace cogmap::mapper
