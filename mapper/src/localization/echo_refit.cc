#include "cogmap/mapper/localization/echo_refit.h"

#include <cmath>

namespace cogmap::mapper {

std::vector<Polyline> refit_wall_directions(std::span<const Polyline> walls,
                                            std::span<const Point2> echoes,
                                            const EchoRefitOptions& options) {
  std::vector<Polyline> out;
  std::vector<Point2> near;
  for (const Polyline& line : walls) {
    for (std::size_t i = 1; i < line.size(); ++i) {
      const Point2 a = line[i - 1];
      const Point2 b = line[i];
      const double length_m = (b - a).norm();
      if (length_m <= 0.0) continue;
      const Point2 along = (b - a) / length_m;
      const Point2 normal(-along.y(), along.x());
      near.clear();
      Point2 mean = Point2::Zero();
      for (const Point2& p : echoes) {
        const Point2 d = p - a;
        const double t = d.dot(along);
        if (t < 0.0 || t > length_m || std::abs(d.dot(normal)) > options.band_m) continue;
        near.push_back(p);
        mean += p;
      }
      if (near.empty() || static_cast<int>(near.size()) < options.min_echoes) {
        out.push_back({a, b});
        continue;
      }
      mean /= static_cast<double>(near.size());
      double sxx = 0.0, sxy = 0.0, syy = 0.0;
      for (const Point2& p : near) {
        const Point2 d = p - mean;
        sxx += d.x() * d.x();
        sxy += d.x() * d.y();
        syy += d.y() * d.y();
      }
      // The major axis of the scatter: the direction that minimises the squared perpendicular
      // distances (the sonar's error is across the wall, not along it).
      const double axis_rad = 0.5 * std::atan2(2.0 * sxy, sxx - syy);
      Point2 axis(std::cos(axis_rad), std::sin(axis_rad));
      if (axis.dot(along) < 0.0) axis = -axis;
      const double turn_rad = std::atan2(cross(along, axis), along.dot(axis));
      if (std::abs(turn_rad) > options.max_turn_rad) {
        out.push_back({a, b});
        continue;
      }
      out.push_back({mean - 0.5 * length_m * axis, mean + 0.5 * length_m * axis});
    }
  }
  return out;
}

}  // namespace cogmap::mapper
