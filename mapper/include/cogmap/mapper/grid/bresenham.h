#pragma once
/// Bresenham's line algorithm (thesis §3.1.5, ref. [6]): visits the cells from `from` to `to`,
/// both included, in order. The visitor returns false to stop early.

#include <cstdlib>

#include "cogmap/mapper/grid/grid_geometry.h"

namespace cogmap::mapper {

/// Calls `visit(CellIndex)` for each cell of the line; returns false if the visitor stopped it.
template <typename Visitor>
bool for_each_line_cell(CellIndex from, CellIndex to, Visitor&& visit) {
  const int dx = std::abs(to.x - from.x), dy = -std::abs(to.y - from.y);
  const int sx = from.x < to.x ? 1 : -1, sy = from.y < to.y ? 1 : -1;
  int err = dx + dy;
  CellIndex c = from;
  while (true) {
    if (!visit(c)) return false;
    if (c.x == to.x && c.y == to.y) return true;
    const int e2 = 2 * err;
    if (e2 >= dy) {
      err += dy;
      c.x += sx;
    }
    if (e2 <= dx) {
      err += dx;
      c.y += sy;
    }
  }
}

}  // namespace cogmap::mapper
