#pragma once
/// Rasterises the sonar cone of thesis Fig. 2.1 onto a grid for the Bayes and Dempster-Shafer
/// updaters: region I (cells at the measured range, ± a tolerance) and region II (cells short of
/// it). A cell belongs to the cone when its centre lies within the half-angle of the axis.

#include <algorithm>
#include <cmath>
#include <numbers>

#include "cogmap/mapper/grid/grid_geometry.h"
#include "grid/sonar_projection.h"

namespace cogmap::mapper {

/// One reading's cone: the beam, the measured range and the region I band.
struct SonarCone {
  SonarBeam beam;
  double range_m = 0.0;         ///< r, the measured range
  double half_width_rad = 0.0;  ///< β/2 of RobotGeometry::sonar_beam_width_rad
  double tolerance_m = 0.0;     ///< region I is |d - r| <= tolerance_m
  bool has_region_one = true;   ///< false for a no-echo reading: region II only, up to r

  /// Farthest distance from the transducer a cell of the cone may have.
  double outer_m() const { return has_region_one ? range_m + tolerance_m : range_m; }
};

/// The cone's axis-aligned bounding box in the world: the apex, both edge ends and the arc's
/// extreme points where the arc crosses an axis direction.
inline void cone_bounds(const SonarCone& cone, Point2& lo, Point2& hi) {
  const double outer = cone.outer_m();
  const double heading = std::atan2(cone.beam.sin_h, cone.beam.cos_h);
  lo = hi = cone.beam.origin;
  auto take = [&](double angle_rad) {
    const Point2 p = cone.beam.origin + outer * Point2(std::cos(angle_rad), std::sin(angle_rad));
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  };
  take(heading - cone.half_width_rad);
  take(heading + cone.half_width_rad);
  for (int k = -4; k <= 4; ++k) {
    const double axis = k * std::numbers::pi / 2.0;
    if (std::abs(axis - heading) <= cone.half_width_rad) take(axis);
  }
}

/// Calls visit(CellIndex, distance_m, alpha_rad, bool region_one) for every cell of `g` whose
/// centre lies in the cone: distance d from the transducer with 0 < d <= outer, angle α off the
/// axis with α <= half-width. Region I: d >= r - tolerance (only with an echo); else region II.
/// Cells outside the grid are skipped, so the caller grows the grid to cone_bounds() first.
template <typename Visitor>
void for_each_cone_cell(const GridGeometry& g, const SonarCone& cone, Visitor&& visit) {
  Point2 lo, hi;
  cone_bounds(cone, lo, hi);
  const CellIndex c0 = g.cell_of(lo), c1 = g.cell_of(hi);
  const double outer = cone.outer_m(), outer2 = outer * outer;
  const double cos_half = std::cos(cone.half_width_rad);
  const double cos_half2 = cos_half * cos_half;
  const double region_one_from = cone.range_m - cone.tolerance_m;
  for (int y = std::max(c0.y, 0); y <= std::min(c1.y, g.height() - 1); ++y) {
    for (int x = std::max(c0.x, 0); x <= std::min(c1.x, g.width() - 1); ++x) {
      const Point2 v = g.center_of({x, y}) - cone.beam.origin;
      const double d2 = v.squaredNorm();
      if (d2 > outer2 || d2 <= 0.0) continue;
      const double along = v.x() * cone.beam.cos_h + v.y() * cone.beam.sin_h;
      // along >= d cos(β/2), squared to skip the sqrt for the half of the box outside the cone.
      if (along <= 0.0 || along * along < d2 * cos_half2) continue;
      const double d = std::sqrt(d2);
      const double across = v.y() * cone.beam.cos_h - v.x() * cone.beam.sin_h;
      const double alpha = std::atan2(std::abs(across), along);
      visit(CellIndex{x, y}, d, alpha, cone.has_region_one && d >= region_one_from);
    }
  }
}

}  // namespace cogmap::mapper
