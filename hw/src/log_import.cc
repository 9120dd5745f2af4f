// CARMEN and Player 2.x log importers.
#include "cogmap/hw/log_import.h"

#include "log_checks.h"

#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <optional>
#include <sstream>

namespace cogmap::hw {
namespace {

std::vector<std::string> tokens_of(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> out;
  std::string t;
  while (in >> t) out.push_back(t);
  return out;
}

// Reads numbered tokens of one line; errors name file:line and the field.
class Fields {
 public:
  Fields(const std::filesystem::path& file, std::size_t line, std::vector<std::string> tokens)
      : file_(file), line_(line), tokens_(std::move(tokens)) {}
  [[noreturn]] void fail(const std::string& expected, std::size_t i) const {
    throw LogError(file_.string() + ":" + std::to_string(line_) + ": expected " + expected +
                   " at field " + std::to_string(i + 1) + ", got '" +
                   (i < tokens_.size() ? detail::printable(tokens_[i]) : "end of line") + "'");
  }
  std::size_t size() const { return tokens_.size(); }
  const std::string& at(std::size_t i) const { return tokens_[i]; }
  double number(std::size_t i, const std::string& what) const {
    if (i >= tokens_.size()) fail(what, i);
    const std::string& t = tokens_[i];
    const char* b = t.data() + (!t.empty() && t[0] == '+' ? 1 : 0);
    double v = 0.0;
    const auto r = std::from_chars(b, t.data() + t.size(), v);
    if (r.ec != std::errc() || r.ptr != t.data() + t.size() || !std::isfinite(v)) fail(what, i);
    return v;
  }
  long integer(std::size_t i, const std::string& what, long lo, long hi) const {
    const double v = number(i, what);
    if (v != std::floor(v) || v < lo || v > hi) {
      fail(what + " (" + std::to_string(lo) + ".." + std::to_string(hi) + ")", i);
    }
    return static_cast<long>(v);
  }

 private:
  const std::filesystem::path& file_;
  std::size_t line_;
  std::vector<std::string> tokens_;
};

std::ifstream open_or_throw(const std::filesystem::path& path) {
  detail::require_regular_file(path);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw LogError(path.string() + ": cannot open log: " + std::strerror(errno));
  return in;
}

mapper::SonarReading reading(int index, double range_m, double time_s,
                             const mapper::RobotGeometry& g) {
  mapper::SonarReading r;
  r.index = index;
  r.time_s = time_s;
  // Logs mark a missing echo with max range (or 0 on some drivers).
  r.echo = range_m > 0.0 && range_m < g.sonar_max_range_m;
  r.range_m = r.echo ? range_m : g.sonar_max_range_m;
  return r;
}

// Appends a frame after the checks every log gets (finite, time order, no jump).
void push_frame(ImportedLog& log, mapper::SensorFrame frame, const std::filesystem::path& path,
                std::size_t line_no) {
  const std::string where = path.string() + ":" + std::to_string(line_no);
  detail::check_geometry(log.geometry, where);  // SONAR and geometry lines may change it
  detail::check_frame(frame, log.frames.empty() ? nullptr : &log.frames.back(), log.geometry,
                      LogLimits{}, where);
  log.frames.push_back(std::move(frame));
}

// A file with none of the lines an importer reads is not a log of that format.
void require_frames(const ImportedLog& log, const std::filesystem::path& path, const char* format,
                    const char* lines) {
  if (log.frames.empty()) {
    throw LogError(path.string() + ": no " + lines + " lines: not a " + format +
                   " log, or an empty one (" + std::to_string(log.ignored_lines) + " other lines)");
  }
}

}  // namespace

ImportedLog import_carmen_log(const std::filesystem::path& path) {
  std::ifstream in = open_or_throw(path);
  ImportedLog log;
  log.geometry = mapper::p2at_geometry();
  bool have_geometry = false;
  std::optional<double> t0;
  std::string text;
  std::size_t line_no = 0;
  while (detail::read_bounded_line(in, text, path, line_no + 1, LogLimits{})) {
    ++line_no;
    auto tokens = tokens_of(text);
    if (tokens.empty() || tokens[0][0] == '#') continue;
    const std::string kind = tokens[0];
    Fields f(path, line_no, std::move(tokens));
    if (kind == "ODOM") {
      // ODOM x y theta tv rv accel timestamp host logger_timestamp
      if (f.size() != 10) f.fail("ODOM x y theta tv rv accel timestamp host logger_ts", f.size());
      mapper::SensorFrame frame;
      const double ts = f.number(7, "timestamp");
      if (!t0) t0 = ts;
      frame.time_s = ts - *t0;
      frame.odometry = {f.number(1, "x"), f.number(2, "y"),
                        mapper::wrap_angle_rad(f.number(3, "theta"))};
      push_frame(log, std::move(frame), path, line_no);
    } else if (kind == "SONAR") {
      const double cone_rad = f.number(1, "cone_angle (rad)");
      const long n = f.integer(2, "num_sonars", 0, 255);
      const std::size_t poses_at = 3 + static_cast<std::size_t>(n);
      const std::size_t robot_at = poses_at + 3 * static_cast<std::size_t>(n);
      // Robot pose, then optionally tv rv, then timestamp host logger_timestamp.
      const std::size_t rest = f.size() > robot_at ? f.size() - robot_at : 0;
      if (rest != 6 && rest != 8) {
        f.fail("SONAR cone n range*n (x y theta)*n x y theta [tv rv] timestamp host logger_ts",
               std::min(f.size(), robot_at));
      }
      if (!have_geometry && n > 0) {
        log.geometry.sonars.clear();
        for (long i = 0; i < n; ++i) {
          const std::size_t k = poses_at + 3 * static_cast<std::size_t>(i);
          log.geometry.sonars.push_back(
              {f.number(k, "sonar x"), f.number(k + 1, "sonar y"), f.number(k + 2, "sonar theta")});
        }
        if (cone_rad > 0.0) log.geometry.sonar_beam_width_rad = cone_rad;
        have_geometry = true;
      }
      if (static_cast<std::size_t>(n) > log.geometry.sonars.size()) {
        f.fail("at most " + std::to_string(log.geometry.sonars.size()) + " sonars", 2);
      }
      const double ts = f.number(f.size() - 3, "timestamp");
      if (!t0) t0 = ts;
      mapper::SensorFrame frame;
      frame.time_s = ts - *t0;
      frame.odometry = {f.number(robot_at, "robot x"), f.number(robot_at + 1, "robot y"),
                        mapper::wrap_angle_rad(f.number(robot_at + 2, "robot theta"))};
      for (long i = 0; i < n; ++i) {
        frame.sonar.push_back(reading(static_cast<int>(i),
                                      f.number(3 + static_cast<std::size_t>(i), "range"),
                                      frame.time_s, log.geometry));
      }
      push_frame(log, std::move(frame), path, line_no);
    } else {
      ++log.ignored_lines;
    }
  }
  require_frames(log, path, "CARMEN", "ODOM or SONAR");
  return log;
}

ImportedLog import_player_log(const std::filesystem::path& path) {
  std::ifstream in = open_or_throw(path);
  ImportedLog log;
  log.geometry = mapper::p2at_geometry();
  std::optional<double> t0;
  mapper::Pose2 odometry;
  bool stall = false;
  bool pending_position = false;  // a position line not yet carried by a frame
  double pending_time_s = 0.0;
  std::string text;
  std::size_t line_no = 0;
  const auto flush_position = [&] {
    if (!pending_position) return;
    mapper::SensorFrame frame;
    frame.time_s = pending_time_s;
    frame.odometry = odometry;
    frame.stall_left = frame.stall_right = stall;
    push_frame(log, std::move(frame), path, line_no);
    pending_position = false;
  };
  while (detail::read_bounded_line(in, text, path, line_no + 1, LogLimits{})) {
    ++line_no;
    auto tokens = tokens_of(text);
    if (tokens.empty() || tokens[0][0] == '#') continue;
    Fields f(path, line_no, std::move(tokens));
    if (f.size() < 7) f.fail("time host robot interface index type subtype", f.size());
    const std::string& iface = f.at(3);
    if (iface != "position2d" && iface != "sonar") {
      ++log.ignored_lines;
      continue;
    }
    const double ts = f.number(0, "time");
    const long type = f.integer(5, "message type", 0, 255);
    const long subtype = f.integer(6, "message subtype", 0, 255);
    if (!t0) t0 = ts;
    const double time_s = ts - *t0;
    if (iface == "position2d" && type == 1 && subtype == 1) {
      // px py pa vx vy va stall
      if (f.size() != 14) f.fail("position2d data px py pa vx vy va stall", f.size());
      flush_position();  // two position lines in a row: the first becomes its own frame
      odometry = {f.number(7, "px"), f.number(8, "py"), mapper::wrap_angle_rad(f.number(9, "pa"))};
      stall = f.integer(13, "stall (0 or 1)", 0, 1) == 1;
      pending_position = true;
      pending_time_s = time_s;
    } else if (iface == "sonar" && ((type == 1 && subtype == 2) || (type == 4 && subtype == 1))) {
      const long n = f.integer(7, "pose count", 0, 255);
      if (f.size() != 8 + 3 * static_cast<std::size_t>(n)) {
        f.fail("sonar geometry count (x y yaw)*count", f.size());
      }
      log.geometry.sonars.clear();
      for (long i = 0; i < n; ++i) {
        const std::size_t k = 8 + 3 * static_cast<std::size_t>(i);
        log.geometry.sonars.push_back(
            {f.number(k, "sonar x"), f.number(k + 1, "sonar y"), f.number(k + 2, "sonar yaw")});
      }
    } else if (iface == "sonar" && type == 1 && subtype == 1) {
      const long n = f.integer(7, "range count", 0, 255);
      if (f.size() != 8 + static_cast<std::size_t>(n)) f.fail("sonar count range*count", f.size());
      if (static_cast<std::size_t>(n) > log.geometry.sonars.size()) {
        f.fail("at most " + std::to_string(log.geometry.sonars.size()) + " ranges", 7);
      }
      mapper::SensorFrame frame;
      frame.time_s = time_s;
      frame.odometry = odometry;
      frame.stall_left = frame.stall_right = stall;
      for (long i = 0; i < n; ++i) {
        frame.sonar.push_back(reading(static_cast<int>(i),
                                      f.number(8 + static_cast<std::size_t>(i), "range"), time_s,
                                      log.geometry));
      }
      pending_position = false;  // this frame carries the latest position
      push_frame(log, std::move(frame), path, line_no);
    } else {
      ++log.ignored_lines;
    }
  }
  flush_position();
  require_frames(log, path, "Player", "position2d or sonar");
  return log;
}

LogFormat detect_log_format(const std::filesystem::path& path) {
  std::ifstream in = open_or_throw(path);
  std::string text;
  std::size_t line_no = 0;
  while (line_no < 1000 && detail::read_bounded_line(in, text, path, line_no + 1, LogLimits{})) {
    ++line_no;
    if (text.rfind("## Player", 0) == 0) return LogFormat::kPlayer;
    const auto t = tokens_of(text);
    if (t.empty() || t[0][0] == '#') continue;
    if (t[0] == kLogMagic) return LogFormat::kCogmap;
    if (t[0] == "ODOM" || t[0] == "SONAR" || t[0] == "PARAM" || t[0] == "FLASER" ||
        t[0] == "ROBOTLASER1" || t[0] == "TRUEPOS" || t[0] == "SYNC") {
      return LogFormat::kCarmen;
    }
    if (t.size() >= 7 && (t[3] == "position2d" || t[3] == "sonar" || t[3] == "laser")) {
      return LogFormat::kPlayer;
    }
    throw LogError(path.string() + ":" + std::to_string(line_no) +
                   ": expected a cogmap, CARMEN or Player log line, got '" +
                   detail::printable(text, 60) + "'");
  }
  throw LogError(path.string() + ": empty log (no frame lines)");
}

void write_cogmap_log(const std::filesystem::path& path, const ImportedLog& log) {
  LogWriter writer(path, log.geometry);
  for (const mapper::SensorFrame& f : log.frames) writer.write_line(format_frame_line(f));
}

}  // namespace cogmap::hw
