#include "nav/obstacle_memory.h"

#include <algorithm>
#include <cmath>

namespace cogmap::mapper::nav {

void ObstacleMemory::push(const Point2& world_m, double expires_s, bool contact) {
  if (options_.max_hits == 0) return;
  while (hits_.size() >= options_.max_hits) hits_.pop_front();
  hits_.push_back({world_m, expires_s, contact});
}

bool ObstacleMemory::has_echoes() const {
  return std::any_of(hits_.begin(), hits_.end(), [](const Hit& h) { return !h.contact; });
}

void ObstacleMemory::add_frame(const SensorFrame& frame, const Pose2& pose,
                               const RobotGeometry& robot) {
  const double now = frame.time_s;
  // Contacts outlive echoes, so the deque is not sorted by expiry: filter it whole. A clock
  // that jumped backwards (a new log) also invalidates everything remembered.
  std::erase_if(hits_, [&](const Hit& h) {
    return h.expires_s <= now || h.expires_s > now + options_.contact_keep_s + options_.keep_s;
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
