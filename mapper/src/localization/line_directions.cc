// Fig. A.7 / Eqs. 3.25-3.31: the direction of each polyline segment, folded modulo 90°.

#include <cmath>

#include "cogmap/mapper/localization/em.h"

namespace cogmap::mapper {

std::vector<LineDirection> line_directions(std::span<const Polyline> polylines) {
  std::vector<LineDirection> out;
  for (const Polyline& line : polylines) {
    for (std::size_t i = 1; i < line.size(); ++i) {
      // A ← A − B (Fig. A.7): the segment as a vector from the previous vertex.
      const Point2 a = line[i] - line[i - 1];
      const double length_m = a.norm();
      if (length_m <= 0.0) continue;
      // Eqs. 3.25-3.27: φ = acos(A_x / |A|), negated below the x axis. The printed test is on
      // A_x; the sign of the angle is the sign of A_y, which is what atan2 computes exactly.
      const double phi_rad = std::atan2(a.y(), a.x());
      // Eqs. 3.28-3.31 as printed reflect (180° − φ, 90° − φ); the equivalent direction of a
      // wall is φ modulo 90°, which is what keeps a rotated room's walls on one value.
      out.push_back({fold_direction_rad(phi_rad), length_m});
    }
  }
  return out;
}

}  // namespace cogmap::mapper
