#include "nav/turn_backs.h"

#include <cmath>
#include <numbers>

#include "cogmap/mapper/seam/pose2.h"

namespace cogmap::mapper::nav {
bool turns_back(double from_rad, double to_rad) {
  return std::abs(wrap_angle_rad(to_rad - from_rad)) > 0.5 * std::numbers::pi;
}

bool TurnBacks::same_target(double target_rad) const {
  return has_target_ && std::abs(wrap_angle_rad(target_rad - target_rad_)) <=
                            options_.turn_back_target_deg * std::numbers::pi / 180.0;
}

void TurnBacks::record(double time_s, double target_rad, double previous_rad,
                       double direction_rad) {
  if (options_.turn_back_limit <= 0) return;
  if (!same_target(target_rad)) {
    target_rad_ = target_rad;
    has_target_ = true;
    turn_back_times_s_.clear();
    hold_until_s_ = -1.0;
  }
  if (!turns_back(previous_rad, direction_rad)) return;
  turn_back_times_s_.push_back(time_s);
  while (time_s - turn_back_times_s_.front() > options_.turn_back_window_s) {
    turn_back_times_s_.pop_front();
  }
  if (static_cast<int>(turn_back_times_s_.size()) >= options_.turn_back_limit) {
    hold_until_s_ = time_s + options_.turn_back_hold_s;
    turn_back_times_s_.clear();
  }
}

bool TurnBacks::holding(double time_s, double target_rad) const {
  return time_s < hold_until_s_ && same_target(target_rad);
}

}  // namespace cogmap::mapper::nav
