#pragma once
/// A dense 2-D grid of values that owns its world <-> cell conversion and grows on demand.

#include <algorithm>
#include <cassert>
#include <vector>

#include "cogmap/mapper/grid/grid_geometry.h"

namespace cogmap::mapper {

template <typename T>
class Grid {
 public:
  Grid() = default;
  Grid(GridGeometry geometry, T fill)
      : geometry_(geometry), fill_(fill), cells_(geometry.cell_count(), fill) {}

  const GridGeometry& geometry() const { return geometry_; }
  int width() const { return geometry_.width(); }
  int height() const { return geometry_.height(); }
  T fill() const { return fill_; }
  bool contains(CellIndex c) const { return geometry_.contains(c); }

  /// Value of a cell; cells outside the grid read as the fill value.
  T get(CellIndex c) const { return contains(c) ? cells_[geometry_.linear(c)] : fill_; }
  /// Mutable access; the cell must be inside the grid.
  T& at(CellIndex c) {
    assert(contains(c));
    return cells_[geometry_.linear(c)];
  }
  const T& at(CellIndex c) const {
    assert(contains(c));
    return cells_[geometry_.linear(c)];
  }
  void set(CellIndex c, T value) {
    if (contains(c)) cells_[geometry_.linear(c)] = value;
  }
  T* data() { return cells_.data(); }
  const T* data() const { return cells_.data(); }
  /// Row y (0 <= y < height()): width() values, x ascending, without a bounds check per cell.
  const T* row(int y) const {
    assert(y >= 0 && y < height());
    return cells_.data() + static_cast<std::size_t>(y) * static_cast<std::size_t>(width());
  }
  std::size_t bytes() const { return cells_.size() * sizeof(T); }

  /// Grows the grid (never shrinks) so every point within `margin_m` of `p` lies inside.
  /// Growth is by whole cells and at least doubles a side, so cell centres keep their world
  /// position and the amortised cost stays constant. Returns true when the grid changed.
  bool ensure_contains(const Point2& p, double margin_m);

 private:
  GridGeometry geometry_;
  T fill_{};
  std::vector<T> cells_;
};

template <typename T>
bool Grid<T>::ensure_contains(const Point2& p, double margin_m) {
  const double cell = geometry_.cell_size_m();
  const CellIndex lo = geometry_.cell_of(p - Point2(margin_m, margin_m));
  const CellIndex hi = geometry_.cell_of(p + Point2(margin_m, margin_m));
  if (geometry_.width() > 0 && contains(lo) && contains(hi)) return false;
  int grow_left = std::max(0, -lo.x), grow_down = std::max(0, -lo.y);
  int grow_right = std::max(0, hi.x - geometry_.width() + 1);
  int grow_up = std::max(0, hi.y - geometry_.height() + 1);
  const int w = geometry_.width(), h = geometry_.height();
  // Grow by at least the current size on each side that needs it (amortised doubling).
  if (grow_left > 0) grow_left = std::max(grow_left, w / 2);
  if (grow_right > 0) grow_right = std::max(grow_right, w / 2);
  if (grow_down > 0) grow_down = std::max(grow_down, h / 2);
  if (grow_up > 0) grow_up = std::max(grow_up, h / 2);
  const int new_w = w + grow_left + grow_right, new_h = h + grow_down + grow_up;
  GridGeometry grown(geometry_.origin_x_m() - grow_left * cell,
                     geometry_.origin_y_m() - grow_down * cell, geometry_.cell_scale_mm(), new_w,
                     new_h);
  std::vector<T> cells(grown.cell_count(), fill_);
  for (int y = 0; y < h; ++y) {
    std::copy_n(cells_.begin() + static_cast<std::ptrdiff_t>(y) * w, w,
                cells.begin() + static_cast<std::ptrdiff_t>(y + grow_down) * new_w + grow_left);
  }
  geometry_ = grown;
  cells_ = std::move(cells);
  return true;
}

/// The HIMM-scale grid every updater can present and the ASR pipeline consumes:
/// values in [-3, 15] (> ε occupied, < 0 seen empty, 0 unexplored) and kRobotPathValue
/// for cells the robot's centre passed through (thesis §3.1.4-3.1.5).
using HistogramGrid = Grid<float>;
inline constexpr float kRobotPathValue = -100.0f;  ///< robot_path, thesis §3.1.5
inline constexpr float kHistogramMax = 15.0f;      ///< cap, thesis §2.2.3
inline constexpr float kHistogramFloor = -3.0f;    ///< empty floor, thesis §3.1.4

}  // namespace cogmap::mapper
