// Frames from bag streams. RosAria and p2os publish every transducer's last value each cycle;
// a value that did not change is the same old reading, so it is skipped (a genuine repeat of
// the identical range is lost too, which costs one reading now and then).
#include "bag_frames.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>

#include "cogmap/mapper/seam/pose2.h"
#include "log_checks.h"

namespace cogmap::hw::bag {
namespace {

std::string message_name(const std::string& topic, std::size_t index) {
  return "topic " + topic + ", message " + std::to_string(index);
}

std::string at(const std::string& topic, std::size_t index) {
  return message_name(topic, index) + ": ";
}

// The checks every log reader applies (log_checks.h): finite numbers, coordinates within the
// log limits, time that never goes back, no odometry jump the robot could not drive. Without
// them a pose of 1e30 m asked the grid for more cells than exist and 5000 m made a 21 MB grid
// of nothing. Their LogError becomes a plain error here so import_ros_bag puts the file name
// in front, as for every other bag error.
void check_like_a_log(const mapper::SensorFrame& frame, const mapper::SensorFrame* previous,
                      const mapper::RobotGeometry& geometry, const std::string& where) {
  try {
    detail::check_frame(frame, previous, geometry, LogLimits{}, where);
  } catch (const LogError& e) {
    throw std::runtime_error(e.what());
  }
}

// Every odometry sample as a frame of its own, so an error names the pose message that holds
// the bad value rather than a sonar message interpolated from it.
void check_odometry(const std::vector<PoseMessage>& poses, double t0, const std::string& topic,
                    const mapper::RobotGeometry& geometry) {
  std::optional<mapper::SensorFrame> previous;
  for (const PoseMessage& p : poses) {
    mapper::SensorFrame frame;
    frame.time_s = p.stamp_s - t0;
    frame.odometry = {p.x_m, p.y_m, p.yaw_rad};
    check_like_a_log(frame, previous ? &*previous : nullptr, geometry,
                     message_name(topic, p.index));
    previous = std::move(frame);
  }
}

// Stamps on one topic must be set and never go backwards.
template <typename Message>
void check_stamps(const std::vector<Message>& messages, const std::string& topic) {
  for (std::size_t i = 0; i < messages.size(); ++i) {
    const Message& m = messages[i];
    if (!(m.stamp_s > 0.0) || !std::isfinite(m.stamp_s)) {
      throw std::runtime_error(at(topic, m.index) + "header stamp is unset (0)");
    }
    if (i > 0 && m.stamp_s < messages[i - 1].stamp_s) {
      throw std::runtime_error(at(topic, m.index) + "header stamp " + std::to_string(m.stamp_s) +
                               " s is earlier than message " +
                               std::to_string(messages[i - 1].index) + "'s " +
                               std::to_string(messages[i - 1].stamp_s) + " s: time goes backwards");
    }
  }
}

std::string span(double first_s, double last_s) {
  return std::to_string(first_s) + " .. " + std::to_string(last_s) + " s";
}

// A bag whose sonar and odometry were stamped by different clocks (a driver that stamps one
// with the robot's uptime, a sonar recorded from another machine) has no reading with a pose:
// it used to become 0 frames, "0 rooms" and exit 0 (and, clocks decades apart, a time_s limit
// error on the first pose). Said as what it is, like a log without frames.
void check_overlap(const Streams& streams, const StreamRequest& request) {
  const double s0 = streams.sonar.front().stamp_s, s1 = streams.sonar.back().stamp_s;
  const double p0 = streams.poses.front().stamp_s, p1 = streams.poses.back().stamp_s;
  if (s1 < p0 || s0 > p1) {
    throw std::runtime_error("the header stamps of " + request.sonar_topic + " (" + span(s0, s1) +
                             ") and of " + request.odometry_topic + " (" + span(p0, p1) +
                             ") never overlap: the two topics were stamped by different clocks "
                             "(or the bag holds only part of one), so no sonar reading has a "
                             "pose: nothing to map");
  }
}

// Odometry at a time: linear in position, shortest way round in heading.
std::optional<mapper::Pose2> odometry_at(const std::vector<PoseMessage>& poses, double t) {
  if (poses.empty() || t < poses.front().stamp_s || t > poses.back().stamp_s) return std::nullopt;
  const auto it = std::lower_bound(poses.begin(), poses.end(), t,
                                   [](const PoseMessage& p, double s) { return p.stamp_s < s; });
  const PoseMessage& b = *it;
  if (b.stamp_s == t) return mapper::Pose2{b.x_m, b.y_m, b.yaw_rad};
  const PoseMessage& a = *(it - 1);
  if (b.stamp_s - a.stamp_s > kMaxOdometryGapS) return std::nullopt;
  const double f = (t - a.stamp_s) / (b.stamp_s - a.stamp_s);
  return mapper::Pose2{
      a.x_m + f * (b.x_m - a.x_m), a.y_m + f * (b.y_m - a.y_m),
      mapper::wrap_angle_rad(a.yaw_rad + f * mapper::wrap_angle_rad(b.yaw_rad - a.yaw_rad))};
}

// One transducer's value as the message gives it: a point for clouds, a range for arrays.
struct Value {
  double a = 0.0, b = 0.0;
  bool operator==(const Value&) const = default;
};

}  // namespace

void build_frames(const Streams& streams, const StreamRequest& request,
                  const mapper::RobotGeometry& geometry, ImportedLog& out, BagImportStats& stats) {
  check_stamps(streams.sonar, request.sonar_topic);
  check_stamps(streams.poses, request.odometry_topic);
  stats.sonar_messages = streams.sonar.size();
  stats.odometry_messages = streams.poses.size();
  if (streams.sonar.empty()) throw std::runtime_error("topic " + request.sonar_topic + " is empty");
  if (streams.poses.empty()) {
    throw std::runtime_error(request.odometry == OdometryEncoding::kTf
                                 ? "topic " + request.odometry_topic +
                                       " has no odom -> base_link transform"
                                 : "topic " + request.odometry_topic + " is empty");
  }
  check_overlap(streams, request);
  const double t0 = std::min(streams.sonar.front().stamp_s, streams.poses.front().stamp_s);
  check_odometry(streams.poses, t0, request.odometry_topic, geometry);
  const bool ranges = request.sonar == SonarEncoding::kSonarArray;
  const double max_m = geometry.sonar_max_range_m;
  std::vector<std::optional<Value>> last(geometry.sonars.size());

  for (const SonarMessage& m : streams.sonar) {
    const std::size_t n = ranges ? m.ranges_m.size() : m.x_m.size();
    if (n > geometry.sonars.size()) {
      throw std::runtime_error(at(request.sonar_topic, m.index) + std::to_string(n) +
                               " transducers, but the robot model has " +
                               std::to_string(geometry.sonars.size()) +
                               " sonars: pass the right --robot");
    }
    const std::optional<mapper::Pose2> pose = odometry_at(streams.poses, m.stamp_s);
    mapper::SensorFrame frame;
    frame.time_s = m.stamp_s - t0;
    for (std::size_t i = 0; i < n; ++i) {
      const Value v = ranges ? Value{m.ranges_m[i], 0.0} : Value{m.x_m[i], m.y_m[i]};
      if (!std::isfinite(v.a) || !std::isfinite(v.b)) {
        throw std::runtime_error(at(request.sonar_topic, m.index) + "transducer " +
                                 std::to_string(i) + " is not a finite number");
      }
      // Never reported: RosAria leaves the point at the robot's origin, p2os the range at 0.
      if (ranges ? v.a <= 0.0 : (v.a == 0.0 && v.b == 0.0)) {
        ++stats.rejected_unreported;
        continue;
      }
      if (last[i] && *last[i] == v) {
        ++stats.rejected_unchanged;
        continue;
      }
      last[i] = v;
      if (!pose) {
        ++stats.rejected_no_odometry;
        continue;
      }
      const mapper::SonarMount& mount = geometry.sonars[i];
      // RosAria's point is where the echo came from, robot frame: range from the transducer.
      const double range_m = ranges ? v.a : std::hypot(v.a - mount.x_m, v.b - mount.y_m);
      mapper::SonarReading r;
      r.index = static_cast<int>(i);
      r.time_s = frame.time_s;
      r.echo = range_m < max_m - kNoEchoMarginM;
      r.range_m = r.echo ? range_m : max_m;
      if (!r.echo) ++stats.readings_no_echo;
      ++stats.readings_accepted;
      frame.sonar.push_back(r);
    }
    if (!pose) continue;
    frame.odometry = *pose;
    // What replay reads is the frames: they get the checks a log's frames get.
    check_like_a_log(frame, out.frames.empty() ? nullptr : &out.frames.back(), geometry,
                     message_name(request.sonar_topic, m.index));
    out.frames.push_back(std::move(frame));
  }
  if (out.frames.empty()) {
    std::ostringstream gap_s;
    gap_s << kMaxOdometryGapS;
    throw std::runtime_error("no message of " + request.sonar_topic +
                             " has a pose: each lies outside the odometry of " +
                             request.odometry_topic + " (" +
                             span(streams.poses.front().stamp_s, streams.poses.back().stamp_s) +
                             ") or in a gap of more than " + gap_s.str() +
                             " s between two of its poses: nothing to map");
  }
  stats.frames = out.frames.size();
}

}  // namespace cogmap::hw::bag
