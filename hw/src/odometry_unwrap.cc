// Position counter unwrapping (P2AT.md "Position wraps") and reconnection anchoring.
#include "cogmap/hw/odometry_unwrap.h"

#include <cmath>

namespace cogmap::hw {
namespace {

// A raw 15-bit counter as a signed value (the robot starts at 0; small negatives wrap high).
std::int32_t signed15(std::uint16_t v) {
  const std::int32_t x = v & 0x7FFF;
  return x >= 0x4000 ? x - 0x8000 : x;
}

std::int32_t signed12(std::int16_t v) {
  const std::int32_t x = static_cast<std::uint16_t>(v) & 0xFFF;
  return x >= 0x800 ? x - 0x1000 : x;
}

}  // namespace

std::int32_t OdometryUnwrapper::position_delta(std::uint16_t now, std::uint16_t last) {
  std::int32_t d =
      static_cast<std::int32_t>(now & 0x7FFF) - static_cast<std::int32_t>(last & 0x7FFF);
  // One or the other (as ARIA does): applied in sequence they would cancel each other.
  if (d > 0x1000) {
    d -= 0x8000;
  } else if (d < -0x1000) {
    d += 0x8000;
  }
  return d;
}

std::int32_t OdometryUnwrapper::heading_delta(std::int16_t now, std::int16_t last) {
  std::int32_t d =
      (static_cast<std::uint16_t>(now) & 0xFFF) - (static_cast<std::uint16_t>(last) & 0xFFF);
  if (d >= 0x800) d -= 0x1000;
  if (d < -0x800) d += 0x1000;
  return d;
}

void OdometryUnwrapper::rebase_if_implausible(double max_distance_m) {
  plausible_m_ = max_distance_m;
}

void OdometryUnwrapper::rebase() {
  have_last_ = false;
  rebase_pending_ = true;
}

mapper::Pose2 OdometryUnwrapper::update(std::uint16_t x_raw, std::uint16_t y_raw,
                                        std::int16_t th_raw) {
  if (plausible_m_ >= 0.0 && have_last_) {
    const double dx_m = position_delta(x_raw, last_x_) * factors_.distance_mm_per_unit / 1000.0;
    const double dy_m = position_delta(y_raw, last_y_) * factors_.distance_mm_per_unit / 1000.0;
    if (std::hypot(dx_m, dy_m) > plausible_m_) rebase();
  }
  plausible_m_ = -1.0;
  if (!have_last_) {
    x_units_ = signed15(x_raw);
    y_units_ = signed15(y_raw);
    th_units_ = signed12(th_raw);
    have_last_ = true;
  } else {
    x_units_ += position_delta(x_raw, last_x_);
    y_units_ += position_delta(y_raw, last_y_);
    th_units_ += heading_delta(th_raw, last_th_);
  }
  last_x_ = x_raw;
  last_y_ = y_raw;
  last_th_ = th_raw;
  const mapper::Pose2 counters{x_units_ * factors_.distance_mm_per_unit / 1000.0,
                               y_units_ * factors_.distance_mm_per_unit / 1000.0,
                               mapper::wrap_angle_rad(th_units_ * factors_.angle_rad_per_unit)};
  if (rebase_pending_) {
    // The new counter origin is placed so this first pose equals the last pose reported.
    anchor_ = pose_.compose(counters.inverse());
    rebase_pending_ = false;
  }
  pose_ = anchor_.compose(counters);
  return pose_;
}

}  // namespace cogmap::hw
