// CARMEN log importer (docs/robot-driver.md "Importers"): ODOM and SONAR lines as CARMEN's
// logger writes them (carmen_logwrite_write_odometry, carmen_logwrite_write_base_sonar).
#include <algorithm>
#include <optional>

#include "cogmap/hw/log_import.h"
#include "import_common.h"
#include "log_checks.h"

namespace cogmap::hw {
namespace {

// A SONAR line in CARMEN's own layout has no robot pose: it takes the latest ODOM's, when that
// is at most this old (the pose of a robot moving at 0.75 m/s is then within 0.4 m; CARMEN's
// base publishes odometry at every 0.1 s cycle, before its sonar).
constexpr double kMaxSonarOdomAgeS = 0.5;

constexpr const char* kSonarLayout =
    "SONAR cone n range*n (x y theta)*n [robot_x robot_y robot_theta [tv rv]] timestamp host "
    "logger_ts";

struct Odometry {
  mapper::Pose2 pose;
  double time_s = 0.0;
};

}  // namespace

ImportedLog import_carmen_log(const std::filesystem::path& path) {
  std::ifstream in = detail::open_log(path);
  ImportedLog log;
  log.geometry = mapper::p2at_geometry();
  bool have_geometry = false;
  std::optional<detail::Stamp> t0;  // of the first line that made a frame
  std::optional<Odometry> odometry;
  std::size_t unposed_sonar = 0;  // SONAR lines before the first ODOM
  bool carmen_lines = false;      // any line CARMEN writes: a CARMEN log, whatever is in it
  detail::LineTally tally;        // what the log holds, should it hold no sonar readings
  std::string text;
  std::size_t line_no = 0;
  const auto time_of = [&](const detail::Stamp& ts) {
    if (!t0) t0 = ts;
    return detail::seconds_between(ts, *t0);
  };
  while (detail::read_bounded_line(in, text, path, line_no + 1, LogLimits{})) {
    ++line_no;
    auto tokens = detail::tokens_of(text);
    if (tokens.empty() || tokens[0][0] == '#') continue;
    const std::string kind = tokens[0];
    carmen_lines = carmen_lines || detail::is_carmen_message(kind);
    detail::Fields f(path, line_no, std::move(tokens));
    if (kind == "ODOM") {
      // ODOM x y theta tv rv accel timestamp host logger_timestamp
      if (f.size() < 10) f.fail("ODOM x y theta tv rv accel timestamp host logger_ts", f.size());
      if (f.size() > 10) {
        f.fail_line("ODOM has " + std::to_string(f.size() - 1) +
                    " fields where CARMEN writes 9 (x y theta tv rv accel timestamp host "
                    "logger_ts): field 11 '" +
                    detail::printable(f.at(10)) + "' is one too many");
      }
      mapper::SensorFrame frame;
      frame.odometry = {f.number(1, "x"), f.number(2, "y"),
                        mapper::wrap_angle_rad(f.number(3, "theta"))};
      // tv rv accel are not mapped, but a line of a type that is read is read whole.
      f.number(4, "tv");
      f.number(5, "rv");
      f.number(6, "accel");
      frame.time_s = time_of(f.stamp(7, "timestamp"));
      odometry = Odometry{frame.odometry, frame.time_s};
      detail::push_frame(log, std::move(frame), path, line_no);
      tally.read(kind);
    } else if (kind == "SONAR") {
      const double cone_rad = f.number(1, "cone_angle (rad)");
      const long n = f.integer(2, "num_sonars", 0, 255);
      const std::size_t poses_at = 3 + static_cast<std::size_t>(n);
      const std::size_t after = poses_at + 3 * static_cast<std::size_t>(n);
      // CARMEN's logger: timestamp host logger_timestamp. Other writers put the robot pose
      // (and tv rv) before them; the field count decides.
      const std::size_t rest = f.size() > after ? f.size() - after : 0;
      if (rest != 3 && rest != 6 && rest != 8) f.fail(kSonarLayout, std::min(f.size(), after));
      // Every line's mounts are read (the first line's are the geometry): a later line with
      // garbage there is not the layout it claims.
      std::vector<mapper::SonarMount> mounts;
      for (long i = 0; i < n; ++i) {
        const std::size_t k = poses_at + 3 * static_cast<std::size_t>(i);
        mounts.push_back(
            {f.number(k, "sonar x"), f.number(k + 1, "sonar y"), f.number(k + 2, "sonar theta")});
      }
      if (rest == 8) {  // robot x y theta tv rv: the velocities are read too
        f.number(after + 3, "tv");
        f.number(after + 4, "rv");
      }
      if (!have_geometry && n > 0) {
        log.geometry.sonars = std::move(mounts);
        if (cone_rad > 0.0) log.geometry.sonar_beam_width_rad = cone_rad;
        have_geometry = true;
      }
      if (static_cast<std::size_t>(n) > log.geometry.sonars.size()) {
        f.fail("at most " + std::to_string(log.geometry.sonars.size()) + " sonars", 2);
      }
      std::vector<double> ranges;
      for (long i = 0; i < n; ++i) {
        ranges.push_back(f.number(3 + static_cast<std::size_t>(i), "range"));
      }
      const detail::Stamp ts = f.stamp(f.size() - 3, "timestamp");
      if (n == 0) {
        // No reading to map: not "read", or a log of such lines says it read SONAR lines.
        ++log.ignored_lines;
        tally.skipped(kind, "no ranges");
        continue;
      }
      mapper::SensorFrame frame;
      if (rest == 3) {
        if (!odometry) {
          ++unposed_sonar;
          ++log.ignored_lines;
          tally.skipped(kind, "before the first ODOM");
          continue;
        }
        frame.time_s = time_of(ts);
        if (frame.time_s - odometry->time_s > kMaxSonarOdomAgeS) {
          ++log.ignored_lines;
          tally.skipped(kind, "more than 0.5 s after the latest ODOM");
          continue;
        }
        frame.odometry = odometry->pose;
      } else {
        frame.odometry = {f.number(after, "robot x"), f.number(after + 1, "robot y"),
                          mapper::wrap_angle_rad(f.number(after + 2, "robot theta"))};
        frame.time_s = time_of(ts);
        odometry = Odometry{frame.odometry, frame.time_s};
      }
      for (std::size_t i = 0; i < ranges.size(); ++i) {
        frame.sonar.push_back(
            detail::reading(static_cast<int>(i), ranges[i], frame.time_s, log.geometry));
      }
      detail::push_frame(log, std::move(frame), path, line_no);
      tally.read(kind);
    } else {
      ++log.ignored_lines;
      tally.skipped(kind);
    }
  }
  if (log.frames.empty() && unposed_sonar > 0) {
    throw LogError(path.string() + ": no ODOM line before its " + std::to_string(unposed_sonar) +
                   " SONAR lines: a CARMEN SONAR line has no robot pose (it takes the latest "
                   "ODOM's), so there is nothing to map");
  }
  // A file without one CARMEN message is another format (a cogmap log read as CARMEN); a
  // CARMEN log without sonar readings (lasers, odometry) says what it holds instead.
  if (!carmen_lines) detail::require_frames(log, path, "CARMEN", "ODOM or SONAR");
  detail::require_sonar_readings(log, path, "SONAR lines with ranges", tally);
  return log;
}

}  // namespace cogmap::hw
