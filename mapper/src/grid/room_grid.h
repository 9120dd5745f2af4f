#pragma once
/// Room-grid bookkeeping shared by the updaters: the initial geometry around reset()'s centre,
/// growth that keeps every touched cell inside, and where a beam leaves the window w.

#include <cmath>

#include "cogmap/mapper/grid/grid.h"
#include "cogmap/mapper/grid/grid_updater.h"
#include "grid/sonar_projection.h"

namespace cogmap::mapper {

/// A square grid of side `options.initial_extent_m` (rounded up to whole cells, at least one)
/// centred on `center`, cells of ℘ = `options.cell_scale_mm`.
GridGeometry room_geometry(const Point2& center, const GridOptions& options);

/// True when cell `c` and its 8 neighbours lie inside `g`.
inline bool contains_with_border(const GridGeometry& g, CellIndex c) {
  return c.x >= 1 && c.y >= 1 && c.x < g.width() - 1 && c.y < g.height() - 1;
}

/// Grows `primary` and every grid in `others` (kept in lockstep: same geometry in, same
/// geometry out) so the cell of `p` and its 8 neighbours are inside. Cheap when they already are.
template <typename P, typename... Others>
void grow_to_hold(const Point2& p, Grid<P>& primary, Grid<Others>&... others) {
  if (contains_with_border(primary.geometry(), primary.geometry().cell_of(p))) return;
  // 1.5 cells: cell_of(p ± margin) then reaches at least one whole cell past cell_of(p).
  const double margin_m = 1.5 * primary.geometry().cell_size_m();
  primary.ensure_contains(p, margin_m);
  (others.ensure_contains(p, margin_m), ...);
}

/// The cells of `a` and `b` in `primary`, after growing `primary` and `others` in lockstep if
/// either cell or one of its 8 neighbours lies outside. One cell_of per point when no growth is
/// needed (the hot path of HIMM/MHIMM).
struct CellPair {
  CellIndex a;
  CellIndex b;
};
template <typename P, typename... Others>
CellPair hold_pair(const Point2& a, const Point2& b, Grid<P>& primary, Grid<Others>&... others) {
  CellPair cells{primary.geometry().cell_of(a), primary.geometry().cell_of(b)};
  if (contains_with_border(primary.geometry(), cells.a) &&
      contains_with_border(primary.geometry(), cells.b)) {
    return cells;
  }
  grow_to_hold(a, primary, others...);
  grow_to_hold(b, primary, others...);
  return {primary.geometry().cell_of(a), primary.geometry().cell_of(b)};
}

/// Distance from the transducer, along the beam, at which the beam leaves the circle of radius
/// `window_m` around the robot centre (thesis Fig. A.3 tests dist(x_i, y_i, x_0, y_0) < w, a
/// circle). Negative when the transducer itself lies outside the window.
inline double window_exit_m(const SonarBeam& beam, const Point2& robot_center, double window_m) {
  const double qx = beam.origin.x() - robot_center.x(), qy = beam.origin.y() - robot_center.y();
  const double q2 = qx * qx + qy * qy, w2 = window_m * window_m;
  if (q2 >= w2) return -1.0;
  const double qd = qx * beam.cos_h + qy * beam.sin_h;
  return -qd + std::sqrt(qd * qd - q2 + w2);
}

}  // namespace cogmap::mapper
