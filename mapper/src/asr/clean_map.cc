// Clean map, thesis §3.1.5, Fig. 3.7 (the Fig. 3.8 pseudo code is missing from the text).
//
// The definition is applied literally, per occupied cell: the cell survives iff a Bresenham ray
// from it to some robot-path cell within max_dist crosses no other occupied cell of the input.
// It is exact, not an approximation by outward rays, because Bresenham is not symmetric and
// rays cast from the path would visit different cells than rays cast towards it.
//
// Cost control: a hidden cell's rays usually stop one or two cells out (at the wall that hides
// it), and a visible cell usually sees the same path cell as the previous visible cell, so the
// search for a free ray starts at the path cell that served last.

#include <cstddef>
#include <vector>

#include "cogmap/mapper/asr/stages.h"
#include "cogmap/mapper/grid/bresenham.h"

namespace cogmap::mapper {

HistogramGrid clean_map(const HistogramGrid& grid, double occupied_threshold,
                        double max_range_cells) {
  HistogramGrid out = grid;
  const GridGeometry& geometry = grid.geometry();
  const int width = grid.width(), height = grid.height();
  if (width <= 0 || height <= 0) return out;
  const float* cells = grid.data();
  const auto occupied = [&](CellIndex c) {
    return static_cast<double>(cells[geometry.linear(c)]) > occupied_threshold;
  };

  std::vector<CellIndex> path;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      if (cells[geometry.linear({x, y})] == kRobotPathValue) path.push_back({x, y});
    }
  }
  const double range2 = max_range_cells * max_range_cells;
  std::size_t hint = 0;  // the path cell that gave the last free ray

  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const CellIndex c{x, y};
      if (!occupied(c)) continue;
      bool seen = false;
      for (std::size_t k = 0; k < path.size() && !seen; ++k) {
        const std::size_t index = (hint + k) % path.size();
        const CellIndex p = path[index];
        const double dx = p.x - c.x, dy = p.y - c.y;
        if (dx * dx + dy * dy > range2) continue;
        // Both ends are inside the grid, so every cell of the ray is too.
        seen = for_each_line_cell(c, p, [&](CellIndex q) { return q == c || !occupied(q); });
        if (seen) hint = index;
      }
      if (!seen) out.at(c) = 0.0f;
    }
  }
  return out;
}

}  // namespace cogmap::mapper
