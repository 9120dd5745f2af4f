#include "cogmap/mapper/localization/odometry_recalibration.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace cogmap::mapper {

double applied_curvature_gain(const OdometryCalibration& calibration, const RobotGeometry& robot) {
  return robot.drive == DriveKind::kSkidSteer ? calibration.curvature_gain : 0.0;
}

double spin_fraction(double forward_m, double turn_rad, double track_m) {
  const double half_turn_m = 0.5 * turn_rad * track_m;
  const double travel_m = std::abs(forward_m - half_turn_m) + std::abs(forward_m + half_turn_m);
  if (!(travel_m > 0.0)) return 0.0;
  return std::abs(2.0 * half_turn_m) / travel_m;
}

Pose2 OdometryRecalibrator::update(const Pose2& raw) {
  if (curvature_gain_ == 0.0) return raw;
  if (!last_raw_) {
    last_raw_ = raw;
    pose_ = raw;
    return pose_;
  }
  // The increment in the previous pose's frame: the odometry moved along the chord at half its
  // turn (midpoint integration), so the chord's length and side give the forward travel.
  const Pose2 step = last_raw_->inverse().compose(raw);
  last_raw_ = raw;
  const double turn_rad = step.theta_rad;
  const double chord_m = std::hypot(step.x_m, step.y_m);
  const double chord_dir_rad = std::atan2(step.y_m, step.x_m);
  // A chord pointing backwards (beyond ±90° from half the turn) is reverse travel.
  const bool reverse =
      std::abs(wrap_angle_rad(chord_dir_rad - 0.5 * turn_rad)) > 0.5 * std::numbers::pi;
  const double forward_m = reverse ? -chord_m : chord_m;
  const double s = spin_fraction(forward_m, turn_rad, track_m_);
  const double scale = 1.0 + curvature_gain_ * (s - 1.0);
  const double true_turn_rad = turn_rad / std::max(scale, 0.1);  // no turn reversed by a wild g
  const double half = 0.5 * true_turn_rad;
  const Pose2 corrected{forward_m * std::cos(half), forward_m * std::sin(half), true_turn_rad};
  pose_ = pose_.compose(corrected);
  return pose_;
}

}  // namespace cogmap::mapper
