#include "nav/obstacle_field.h"

#include <algorithm>
#include <cmath>
#include <span>

namespace cogmap::mapper::nav {

int ObstacleField::slot(CellIndex c) const {
  const int x = c.x - lo_.x, y = c.y - lo_.y;
  if (x < 0 || y < 0 || x >= nx_ || y >= ny_) return -1;
  return x * ny_ + y;
}

bool ObstacleField::occupied(CellIndex cell) const {
  const int k = slot(cell);
  return k >= 0 && cells_[static_cast<std::size_t>(k)] >= 0.0f;
}

void ObstacleField::build(const Point2& center, const GridUpdater* grid,
                          const ObstacleMemory& memory) {
  points_.clear();
  geometry_ = grid ? grid->geometry() : GridGeometry(0.0, 0.0, 100.0, 0, 0);
  const double window = vfh_.window_m;
  const double window_sq = window * window;
  // Every cell whose centre lies in the window is inside this box. Dense arrays over it, not
  // maps: this runs every cycle over ~2500 cells, and the x-major index keeps the (x, y) order
  // the points have always had (VFH sums them in that order).
  lo_ = geometry_.cell_of(center - Point2(window, window));
  const CellIndex hi = geometry_.cell_of(center + Point2(window, window));
  nx_ = std::max(0, hi.x - lo_.x + 1);
  ny_ = std::max(0, hi.y - lo_.y + 1);
  const std::size_t n = static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_);
  // The three arrays hold -1 (none) everywhere but in the slots the last build listed: reset
  // those alone while the box keeps its size (it almost always does), else refill.
  if (cells_.size() != n) {
    cells_.assign(n, -1.0f);
    near_grid_.assign(n, -1.0f);
    echoes_.assign(n, -1.0f);
  } else {
    for (const int k : cell_slots_) cells_[static_cast<std::size_t>(k)] = -1.0f;
    for (const int k : near_slots_) near_grid_[static_cast<std::size_t>(k)] = -1.0f;
    for (const int k : echo_slots_) echoes_[static_cast<std::size_t>(k)] = -1.0f;
  }
  cell_slots_.clear();
  near_slots_.clear();
  echo_slots_.clear();
  // A cell's offset from the centre, center_of(c) - center, has an x that depends on the
  // column alone and a y on the row alone: one table each, so a cell's squared distance is a
  // single addition, the same sum (bit for bit) as (center_of(c) - center).squaredNorm().
  dx_.resize(static_cast<std::size_t>(nx_));
  dx2_.resize(static_cast<std::size_t>(nx_));
  dy_.resize(static_cast<std::size_t>(ny_));
  dy2_.resize(static_cast<std::size_t>(ny_));
  for (int i = 0; i < nx_; ++i) {
    const double d = geometry_.center_of({lo_.x + i, lo_.y}).x() - center.x();
    dx_[static_cast<std::size_t>(i)] = d;
    dx2_[static_cast<std::size_t>(i)] = d * d;
  }
  for (int j = 0; j < ny_; ++j) {
    const double d = geometry_.center_of({lo_.x, lo_.y + j}).y() - center.y();
    dy_[static_cast<std::size_t>(j)] = d;
    dy2_[static_cast<std::size_t>(j)] = d * d;
  }
  // The rows of each column that may hold a point, so listing them skips the empty ones.
  column_first_.assign(static_cast<std::size_t>(nx_), ny_);
  column_last_.assign(static_cast<std::size_t>(nx_), -1);
  const auto mark = [&](int i, int j) {
    int& first = column_first_[static_cast<std::size_t>(i)];
    int& last = column_last_[static_cast<std::size_t>(i)];
    first = std::min(first, j);
    last = std::max(last, j);
  };
  // Near the robot only the recent echoes count (a grid cell there only confirms one, its
  // certainty then merged by maximum): every echo is painted on its beam's axis, so the grid
  // accumulates a 30° smear that closes 1 m openings; the memory holds only the last few
  // seconds, from nearby, where the smear is small.
  // Without any remembered echo (sonar off, a replay without sonar) the grid is all there is.
  const double near_sq =
      memory.has_echoes() ? vfh_.grid_min_range_m * std::abs(vfh_.grid_min_range_m) : 0.0;
  const int x_first = std::max(lo_.x, 0), x_last = std::min(hi.x, geometry_.width() - 1);
  const int y_first = std::max(lo_.y, 0), y_last = std::min(hi.y, geometry_.height() - 1);
  if (grid && x_first <= x_last) {
    // Each row's cells inside the window form one run (its chord): dx2_ falls, then rises
    // with x (every step of its arithmetic is monotonic), so dx2_ + dy2 <= window² holds on
    // an interval around the column of least dx2_, `mid`. The run's ends move by a cell or
    // two from row to row, so each is found by stepping from the previous row's.
    int mid = x_first;
    for (int x = x_first + 1; x <= x_last; ++x) {
      if (dx2_[static_cast<std::size_t>(x - lo_.x)] < dx2_[static_cast<std::size_t>(mid - lo_.x)]) {
        mid = x;
      }
    }
    const float above = vfh_.occupied_above;
    int a = mid, b = mid;
    for (int y = y_first; y <= y_last; ++y) {
      const int j = y - lo_.y;
      const double dy2 = dy2_[static_cast<std::size_t>(j)];
      const auto in = [&](int x) {
        return dx2_[static_cast<std::size_t>(x - lo_.x)] + dy2 <= window_sq;
      };
      if (!in(mid)) continue;  // the row's nearest cell is outside: the whole row is
      if (in(a)) {
        while (a > x_first && in(a - 1)) --a;
      } else {
        while (!in(a)) ++a;  // stops at mid at the latest
      }
      if (in(b)) {
        while (b < x_last && in(b + 1)) ++b;
      } else {
        while (!in(b)) --b;
      }
      // The row in place when the grid offers it (one virtual call per row), else cell by cell.
      const float* values = nullptr;
      const std::span<const float> row = grid->histogram_row(y);
      if (!row.empty()) {
        values = row.data() + a;
      } else {
        row_values_.resize(static_cast<std::size_t>(b - a + 1));
        for (int x = a; x <= b; ++x) {
          row_values_[static_cast<std::size_t>(x - a)] = grid->histogram_at({x, y});
        }
        values = row_values_.data();
      }
      const int run = b - a + 1;
      for (int r = 0; r < run; ++r) {
        const float value = values[r];
        if (value <= above) continue;
        const int i = a + r - lo_.x;
        const double d_sq = dx2_[static_cast<std::size_t>(i)] + dy2;
        const int k = i * ny_ + j;
        if (d_sq < near_sq) {
          near_grid_[static_cast<std::size_t>(k)] = value;
          near_slots_.push_back(k);
        } else {
          cells_[static_cast<std::size_t>(k)] = value;
          cell_slots_.push_back(k);
          mark(i, j);
        }
      }
    }
  }
  // Echoes falling in one cell add up like HIMM increments; a cell the grid also holds keeps
  // the larger of the two certainties.
  for (const ObstacleMemory::Hit& h : memory.hits()) {
    const CellIndex c = geometry_.cell_of(h.world_m);
    const int k = slot(c);
    if (k < 0) continue;
    const auto i = static_cast<std::size_t>(c.x - lo_.x), j = static_cast<std::size_t>(c.y - lo_.y);
    if (!(dx2_[i] + dy2_[j] <= window_sq)) continue;  // outside the window
    float& v = echoes_[static_cast<std::size_t>(k)];
    if (v < 0.0f) echo_slots_.push_back(k);  // (a slot listed twice merges the same way twice)
    v = std::min(kHistogramMax, std::max(v, 0.0f) + memory_.hit_value);
  }
  for (const int slot_index : echo_slots_) {
    const auto k = static_cast<std::size_t>(slot_index);
    if (echoes_[k] < 0.0f) continue;
    if (near_grid_[k] >= 0.0f) cells_[k] = near_grid_[k];
    cells_[k] = std::max(std::max(cells_[k], 0.0f), echoes_[k]);
    cell_slots_.push_back(slot_index);
    mark(slot_index / ny_, slot_index % ny_);
  }
  for (int i = 0; i < nx_; ++i) {
    const int last = column_last_[static_cast<std::size_t>(i)];
    for (int j = column_first_[static_cast<std::size_t>(i)]; j <= last; ++j) {
      const float value = cells_[static_cast<std::size_t>(i * ny_ + j)];
      if (value < 0.0f) continue;
      points_.push_back(
          {Point2(dx_[static_cast<std::size_t>(i)], dy_[static_cast<std::size_t>(j)]), value});
    }
  }
}

}  // namespace cogmap::mapper::nav
