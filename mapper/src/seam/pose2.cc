#include "cogmap/mapper/seam/pose2.h"

#include <numbers>

namespace cogmap::mapper {

double wrap_angle_rad(double angle_rad) {
  if (angle_rad > -std::numbers::pi && angle_rad <= std::numbers::pi) return angle_rad;
  double wrapped = std::remainder(angle_rad, 2.0 * std::numbers::pi);
  if (wrapped <= -std::numbers::pi) wrapped += 2.0 * std::numbers::pi;
  return wrapped;
}

Pose2 rotation_about(const Point2& pivot, double angle_rad) {
  // p' = R (p - pivot) + pivot  =>  translation = pivot - R pivot.
  const Pose2 rotation{0.0, 0.0, angle_rad};
  const Point2 t = pivot - rotation.transform(pivot);
  return {t.x(), t.y(), wrap_angle_rad(angle_rad)};
}

}  // namespace cogmap::mapper
