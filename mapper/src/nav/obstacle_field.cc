#include "nav/obstacle_field.h"

#include <algorithm>
#include <cmath>

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
  const auto inside = [&](CellIndex c) {
    return (geometry_.center_of(c) - center).squaredNorm() <= window_sq;
  };
  // Every cell whose centre lies in the window is inside this box. Dense arrays over it, not
  // maps: this runs every cycle over ~2500 cells, and the x-major index keeps the (x, y) order
  // the points have always had (VFH sums them in that order).
  lo_ = geometry_.cell_of(center - Point2(window, window));
  const CellIndex hi = geometry_.cell_of(center + Point2(window, window));
  nx_ = hi.x - lo_.x + 1;
  ny_ = hi.y - lo_.y + 1;
  const std::size_t n = static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_);
  cells_.assign(n, -1.0f);
  near_grid_.assign(n, -1.0f);
  echoes_.assign(n, -1.0f);
  // Near the robot only the recent echoes count (a grid cell there only confirms one, its
  // certainty then merged by maximum): every echo is painted on its beam's axis, so the grid
  // accumulates a 30° smear that closes 1 m openings; the memory holds only the last few
  // seconds, from nearby, where the smear is small.
  // Without any remembered echo (sonar off, a replay without sonar) the grid is all there is.
  const double near_sq =
      memory.has_echoes() ? vfh_.grid_min_range_m * std::abs(vfh_.grid_min_range_m) : 0.0;
  if (grid) {
    for (int y = std::max(lo_.y, 0); y <= std::min(hi.y, geometry_.height() - 1); ++y) {
      for (int x = std::max(lo_.x, 0); x <= std::min(hi.x, geometry_.width() - 1); ++x) {
        const CellIndex c{x, y};
        const float value = grid->histogram_at(c);
        if (value <= vfh_.occupied_above || !inside(c)) continue;
        const auto k = static_cast<std::size_t>(slot(c));
        if ((geometry_.center_of(c) - center).squaredNorm() < near_sq) {
          near_grid_[k] = value;
        } else {
          cells_[k] = value;
        }
      }
    }
  }
  // Echoes falling in one cell add up like HIMM increments; a cell the grid also holds keeps
  // the larger of the two certainties.
  for (const ObstacleMemory::Hit& h : memory.hits()) {
    const CellIndex c = geometry_.cell_of(h.world_m);
    if (!inside(c)) continue;
    const int k = slot(c);
    if (k < 0) continue;
    float& v = echoes_[static_cast<std::size_t>(k)];
    v = std::min(kHistogramMax, std::max(v, 0.0f) + memory_.hit_value);
  }
  for (std::size_t k = 0; k < n; ++k) {
    if (echoes_[k] < 0.0f) continue;
    if (near_grid_[k] >= 0.0f) cells_[k] = near_grid_[k];
    cells_[k] = std::max(std::max(cells_[k], 0.0f), echoes_[k]);
  }
  for (int x = 0; x < nx_; ++x) {
    for (int y = 0; y < ny_; ++y) {
      const float value = cells_[static_cast<std::size_t>(x * ny_ + y)];
      if (value < 0.0f) continue;
      points_.push_back({geometry_.center_of({lo_.x + x, lo_.y + y}) - center, value});
    }
  }
}

}  // namespace cogmap::mapper::nav
