#include "cogmap/mapper/seam/geometry.h"

#include <algorithm>

namespace cogmap::mapper {

double polyline_length_m(const Polyline& line) {
  double total = 0.0;
  for (std::size_t i = 1; i < line.size(); ++i) total += (line[i] - line[i - 1]).norm();
  return total;
}

Point2 closest_point_on_segment(const Point2& p, const Segment& s) {
  const Point2 d = s.b - s.a;
  const double len2 = d.squaredNorm();
  if (len2 <= 0.0) return s.a;
  const double t = std::clamp((p - s.a).dot(d) / len2, 0.0, 1.0);
  return s.a + t * d;
}

double distance_to_segment_m(const Point2& p, const Segment& s) {
  return (p - closest_point_on_segment(p, s)).norm();
}

}  // namespace cogmap::mapper
