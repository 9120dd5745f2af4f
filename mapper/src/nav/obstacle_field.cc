#include "nav/obstacle_field.h"

#include <algorithm>
#include <cmath>

namespace cogmap::mapper::nav {

void ObstacleField::build(const Point2& center, const GridUpdater* grid,
                          const ObstacleMemory& memory) {
  cells_.clear();
  points_.clear();
  geometry_ = grid ? grid->geometry() : GridGeometry(0.0, 0.0, 100.0, 0, 0);
  const double window = vfh_.window_m;
  const double window_sq = window * window;
  const auto inside = [&](CellIndex c) {
    return (geometry_.center_of(c) - center).squaredNorm() <= window_sq;
  };
  // Near the robot only the recent echoes count (a grid cell there only confirms one, its
  // certainty then merged by maximum): every echo is painted on its beam's axis, so the grid
  // accumulates a 30° smear that closes 1 m openings; the memory holds only the last few
  // seconds, from nearby, where the smear is small.
  // Without any remembered echo (sonar off, a replay without sonar) the grid is all there is.
  const double near_sq =
      memory.has_echoes() ? vfh_.grid_min_range_m * std::abs(vfh_.grid_min_range_m) : 0.0;
  std::map<std::pair<int, int>, float> near_grid;  // only where a recent echo confirms it
  if (grid) {
    const CellIndex lo = geometry_.cell_of(center - Point2(window, window));
    const CellIndex hi = geometry_.cell_of(center + Point2(window, window));
    for (int y = std::max(lo.y, 0); y <= std::min(hi.y, geometry_.height() - 1); ++y) {
      for (int x = std::max(lo.x, 0); x <= std::min(hi.x, geometry_.width() - 1); ++x) {
        const CellIndex c{x, y};
        const float value = grid->histogram_at(c);
        if (value <= vfh_.occupied_above || !inside(c)) continue;
        if ((geometry_.center_of(c) - center).squaredNorm() < near_sq) {
          near_grid[{x, y}] = value;
        } else {
          cells_[{x, y}] = value;
        }
      }
    }
  }
  // Echoes falling in one cell add up like HIMM increments; a cell the grid also holds keeps
  // the larger of the two certainties.
  std::map<std::pair<int, int>, float> echoes;
  for (const ObstacleMemory::Hit& h : memory.hits()) {
    const CellIndex c = geometry_.cell_of(h.world_m);
    if (!inside(c)) continue;
    float& v = echoes[{c.x, c.y}];
    v = std::min(kHistogramMax, v + memory_.hit_value);
  }
  for (const auto& [key, value] : near_grid) {
    if (echoes.count(key) != 0) cells_[key] = value;
  }
  for (const auto& [key, value] : echoes) {
    float& v = cells_[key];
    v = std::max(v, value);
  }
  points_.reserve(cells_.size());
  for (const auto& [key, value] : cells_) {
    points_.push_back({geometry_.center_of({key.first, key.second}) - center, value});
  }
}

}  // namespace cogmap::mapper::nav
