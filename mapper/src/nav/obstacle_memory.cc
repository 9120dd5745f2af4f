#include "nav/obstacle_memory.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>

namespace cogmap::mapper::nav {

void ObstacleMemory::push(const Point2& world_m, double expires_s, bool contact) {
  if (options_.max_hits == 0) return;
  // Full: the oldest go (all at once; the memory is full only with a very fast sonar).
  if (hits_.size() >= options_.max_hits) {
    hits_.erase(hits_.begin(),
                hits_.begin() + static_cast<std::ptrdiff_t>(hits_.size() - options_.max_hits + 1));
  }
  hits_.push_back({world_m, expires_s, contact});
}

bool ObstacleMemory::has_echoes() const {
  return std::any_of(hits_.begin(), hits_.end(), [](const Hit& h) { return !h.contact; });
}

void ObstacleMemory::add_frame(const SensorFrame& frame, const Pose2& pose,
                               const RobotGeometry& robot) {
  const double now = frame.time_s;
  collect_clearing_beams(frame, pose, robot);
  // One pass over the memory forgets the expired hits and the echoes this frame's beams saw
  // through (a hit goes if any beam clears it, so the order of the tests does not matter).
  // Contacts outlive echoes, so the list is not sorted by expiry: it is filtered whole. A clock
  // that jumped backwards (a new log) also invalidates everything remembered.
  const double tan_half = std::tan(options_.clear_half_angle_deg * std::numbers::pi / 180.0);
  std::erase_if(hits_, [&](const Hit& h) {
    if (h.expires_s <= now || h.expires_s > now + options_.contact_keep_s + options_.keep_s) {
      return true;
    }
    if (h.contact) return false;  // the bumper's word outweighs the sonar's silence
    for (const ClearingBeam& beam : beams_) {
      const Point2 d = h.world_m - beam.origin;
      const double along = d.dot(beam.axis);
      if (along <= 0.0 || along >= beam.free_m) continue;
      const double lateral = std::abs(cross(beam.axis, d));
      if (lateral <= std::max(options_.clear_min_half_width_m, along * tan_half)) return true;
    }
    return false;
  });
  const double max_range = std::min(options_.max_range_m, robot.sonar_max_range_m);
  for (const SonarReading& r : frame.sonar) {
    if (!r.echo || !std::isfinite(r.range_m)) continue;
    if (r.range_m < robot.sonar_min_range_m || r.range_m > max_range) continue;
    if (r.index < 0 || static_cast<std::size_t>(r.index) >= robot.sonars.size()) continue;
    const SonarMount& m = robot.sonars[static_cast<std::size_t>(r.index)];
    // The echo lies on the transducer's axis (the HIMM convention, thesis §2.2.3).
    const Point2 local(m.x_m + r.range_m * std::cos(m.heading_rad),
                       m.y_m + r.range_m * std::sin(m.heading_rad));
    push(pose.transform(local), now + options_.keep_s, false);
  }
}

void ObstacleMemory::collect_clearing_beams(const SensorFrame& frame, const Pose2& pose,
                                            const RobotGeometry& robot) {
  beams_.clear();
  if (options_.clear_half_angle_deg <= 0.0) return;
  for (const SonarReading& r : frame.sonar) {
    if (r.index < 0 || static_cast<std::size_t>(r.index) >= robot.sonars.size()) continue;
    if (!std::isfinite(r.range_m) || r.range_m < robot.sonar_min_range_m) continue;
    // A reading beyond the sonar's range is no echo the mapper would use: it proves only
    // that nothing answered nearer, like a pulse that never came back.
    const bool echo = r.echo && r.range_m <= robot.sonar_max_range_m;
    const double free_m = echo ? r.range_m - options_.clear_margin_m : options_.clear_max_m;
    if (free_m <= 0.0) continue;
    const SonarMount& m = robot.sonars[static_cast<std::size_t>(r.index)];
    const double axis_rad = pose.theta_rad + m.heading_rad;
    beams_.push_back({pose.transform(Point2(m.x_m, m.y_m)),
                      Point2(std::cos(axis_rad), std::sin(axis_rad)), free_m});
  }
}

void ObstacleMemory::add_contact(const Pose2& pose, const RobotGeometry& robot, double time_s,
                                 bool forward) {
  // 5 cm beyond the bumper, across most of its width: the bumper is the only sensor that
  // saw this obstacle.
  const double x = (forward ? 1.0 : -1.0) * (0.5 * robot.length_m + 0.05);
  const double y = 0.4 * robot.width_m;
  for (const double side : {-y, 0.0, y}) {
    push(pose.transform(Point2(x, side)), time_s + options_.contact_keep_s, true);
  }
}

}  // namespace cogmap::mapper::nav
