#pragma once
/// A planar pose (SE(2)): position in metres and heading in radians, counter-clockwise.

#include <cmath>
#include <numbers>

#include "cogmap/mapper/seam/geometry.h"

namespace cogmap::mapper {

/// Wraps an angle to (-π, π].
double wrap_angle_rad(double angle_rad);

/// Degrees (options, docs) to radians (everything computed).
constexpr double deg_to_rad(double deg) { return deg * std::numbers::pi / 180.0; }

/// Pose of a frame B in a frame A: a point p_B maps to p_A = R(theta) p_B + (x, y).
struct Pose2 {
  double x_m = 0.0;
  double y_m = 0.0;
  double theta_rad = 0.0;  ///< counter-clockwise from +x (the thesis measures clockwise)

  Point2 translation() const { return {x_m, y_m}; }

  /// Maps a point expressed in this pose's frame into the parent frame.
  Point2 transform(const Point2& p) const {
    const double c = std::cos(theta_rad), s = std::sin(theta_rad);
    return {x_m + c * p.x() - s * p.y(), y_m + s * p.x() + c * p.y()};
  }

  /// this ∘ other: `other` is expressed in this pose's frame.
  Pose2 compose(const Pose2& other) const {
    const Point2 t = transform(other.translation());
    return {t.x(), t.y(), wrap_angle_rad(theta_rad + other.theta_rad)};
  }

  /// The inverse transform (parent frame expressed in this frame).
  Pose2 inverse() const {
    const double c = std::cos(theta_rad), s = std::sin(theta_rad);
    return {-(c * x_m + s * y_m), -(-s * x_m + c * y_m), wrap_angle_rad(-theta_rad)};
  }
};

/// The rigid transform that rotates by `angle_rad` about `pivot` (both in the parent frame).
Pose2 rotation_about(const Point2& pivot, double angle_rad);

}  // namespace cogmap::mapper
