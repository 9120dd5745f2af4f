#include "nav/explore_reopen.h"

#include <algorithm>
#include <cmath>

namespace cogmap::mapper::nav {
namespace {

/// Whether the room grid's cells inside the explore cell `c` show a beam passing through and
/// no echo: at least one below 0, none at `echo_himm` or above. Cells the room grid does not
/// hold decide nothing (false).
bool swept_and_silent(const ExploreMap& map, ExploreMap::Cell c, const GridUpdater& grid,
                      double echo_himm) {
  const GridGeometry& g = grid.geometry();
  const double half = 0.5 * map.cell_m();
  const Point2 centre = map.center_of(c);
  // Room cells whose centres lie inside the explore cell (a 0.2 m cell holds 2 x 2 of 0.1 m).
  const CellIndex lo = g.cell_of(centre - Point2(half, half));
  const CellIndex hi = g.cell_of(centre + Point2(half, half));
  bool swept = false;
  for (int y = lo.y; y <= hi.y; ++y) {
    for (int x = lo.x; x <= hi.x; ++x) {
      const CellIndex rc{x, y};
      const Point2 p = g.center_of(rc);
      if (std::abs(p.x() - centre.x()) > half || std::abs(p.y() - centre.y()) > half) continue;
      if (!g.contains(rc)) return false;
      const float v = grid.histogram_at(rc);
      if (v >= echo_himm) return false;
      swept = swept || v < 0.0f;
    }
  }
  return swept;
}

}  // namespace

std::size_t reopen_swept_cells(ExploreMap& map, const GridUpdater& room_grid, double echo_himm) {
  const GridGeometry& g = room_grid.geometry();
  if (g.width() <= 0 || g.height() <= 0) return 0;
  // Only the explore cells over the room grid can be decided.
  const ExploreMap::Cell lo = map.cell_of(Point2(g.origin_x_m(), g.origin_y_m()));
  const ExploreMap::Cell hi = map.cell_of(Point2(g.origin_x_m() + g.width() * g.cell_size_m(),
                                                 g.origin_y_m() + g.height() * g.cell_size_m()));
  std::size_t cleared = 0;
  for (int y = std::max(lo.y, 0); y <= std::min(hi.y, map.height() - 1); ++y) {
    for (int x = std::max(lo.x, 0); x <= std::min(hi.x, map.width() - 1); ++x) {
      const ExploreMap::Cell c{x, y};
      if (!map.occupied(c) || !swept_and_silent(map, c, room_grid, echo_himm)) continue;
      map.clear_echoes(c);
      ++cleared;
    }
  }
  return cleared;
}

}  // namespace cogmap::mapper::nav
