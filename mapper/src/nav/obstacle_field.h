#pragma once
/// The obstacles VFH sees this cycle: the room grid's occupied cells within the active window
/// merged, cell by cell, with the short-term memory (the larger certainty wins, so an obstacle
/// both in the grid and in the memory is not counted twice).

#include <vector>

#include "cogmap/mapper/grid/grid_updater.h"
#include "cogmap/mapper/nav/vfh.h"
#include "nav/obstacle_memory.h"

namespace cogmap::mapper::nav {

class ObstacleField {
 public:
  ObstacleField(const VfhOptions& vfh, const MemoryOptions& memory) : vfh_(vfh), memory_(memory) {}

  /// Collects the obstacles around `center` (estimate frame). `grid` may be null.
  void build(const Point2& center, const GridUpdater* grid, const ObstacleMemory& memory);

  /// Obstacles within the window, offsets from `center`, in cell order (deterministic).
  const std::vector<ObstaclePoint>& points() const { return points_; }

  /// True when `cell` (of geometry()) holds an obstacle inside the window.
  bool occupied(CellIndex cell) const;

  /// The cell lattice used: the room grid's (cells outside it included), or 10 cm cells at
  /// the origin when there is no grid.
  const GridGeometry& geometry() const { return geometry_; }

 private:
  VfhOptions vfh_;
  MemoryOptions memory_;
  GridGeometry geometry_;
  // The window's bounding box of cells, and per cell (x-major: index (x - lo.x)·ny + (y - lo.y),
  // the order points_ keep) the obstacle's certainty, or a negative value for none.
  CellIndex lo_{0, 0};
  int nx_ = 0, ny_ = 0;
  std::vector<float> cells_;
  std::vector<float> near_grid_;  // room-grid cells nearer than grid_min_range_m
  std::vector<float> echoes_;     // the memory's echoes, summed per cell
  // The slots this build wrote in each array (the next build resets them to -1; a slot may
  // be listed more than once).
  std::vector<int> cell_slots_, near_slots_, echo_slots_;
  // Per column x and row y of the box: the cell centre's offset from `center` (exactly
  // center_of(c) - center) and its square, so a cell's squared distance is dx2_[x] + dy2_[y].
  std::vector<double> dx_, dy_, dx2_, dy2_;
  // Per column of the box: the rows [first, last] that may hold a point (first > last: none).
  std::vector<int> column_first_, column_last_;
  std::vector<float> row_values_;  // one grid row, for grids without histogram_row
  std::vector<ObstaclePoint> points_;

  /// The index of `c` in the box, or -1 outside it.
  int slot(CellIndex c) const;
};

}  // namespace cogmap::mapper::nav
