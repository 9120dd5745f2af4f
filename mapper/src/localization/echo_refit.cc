#include "cogmap/mapper/localization/echo_refit.h"

#include <cmath>

#include "cogmap/mapper/asr/stages.h"

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
      for (const Point2& p : echoes) {
        const Point2 d = p - a;
        const double t = d.dot(along);
        if (t < 0.0 || t > length_m || std::abs(d.dot(normal)) > options.band_m) continue;
        near.push_back(p);
      }
      // The principal axis of the echoes (fit_line: orthogonal least squares, since the sonar's
      // error is across the wall, not along it).
      const LineFit fit =
          static_cast<int>(near.size()) >= options.min_echoes ? fit_line(near) : LineFit{};
      Point2 axis = fit.direction;
      if (axis.dot(along) < 0.0) axis = -axis;
      if (!fit.valid ||
          std::abs(std::atan2(cross(along, axis), along.dot(axis))) > options.max_turn_rad) {
        out.push_back({a, b});
        continue;
      }
      out.push_back({fit.point - 0.5 * length_m * axis, fit.point + 0.5 * length_m * axis});
    }
  }
  return out;
}

}  // namespace cogmap::mapper
