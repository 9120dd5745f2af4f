#include "log_checks.h"

#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>
#include <system_error>

namespace cogmap::hw::detail {
namespace {

std::string number_text(double v) {
  std::ostringstream out;
  out << v;
  return out.str();
}

void in_range(double v, double lo, double hi, const char* field, const std::string& where) {
  if (!(std::isfinite(v) && v >= lo && v <= hi)) {
    throw LogError(where + ": " + field + " must be in [" + number_text(lo) + ", " +
                   number_text(hi) + "], got " + number_text(v));
  }
}

// What a file that is no text log may start with, and what to tell its owner.
struct Magic {
  std::string_view bytes;
  const char* what;
};
constexpr Magic kNotText[] = {
    {"\x1f\x8b", "gzip-compressed: decompress it first (gunzip -k FILE)"},
    {std::string_view("\xfd"
                      "7zXZ\0",
                      6),
     "xz-compressed: decompress it first (unxz -k FILE)"},
    {"\x28\xb5\x2f\xfd", "zstd-compressed: decompress it first (unzstd FILE)"},
    {"PK\x03\x04", "a zip archive: extract the log from it first (unzip FILE)"},
    {"\xff\xfe", "UTF-16 text (as some Windows editors save it): save it as UTF-8"},
    {"\xfe\xff", "UTF-16 text (as some Windows editors save it): save it as UTF-8"},
};

}  // namespace

std::string printable(std::string_view text, std::size_t max_bytes) {
  static constexpr char kHex[] = "0123456789abcdef";
  std::string out;
  for (std::size_t i = 0; i < text.size() && i < max_bytes; ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c >= 0x20 && c < 0x7f) {
      out.push_back(static_cast<char>(c));
    } else {
      out += "\\x";
      out.push_back(kHex[c >> 4]);
      out.push_back(kHex[c & 15]);
    }
  }
  if (text.size() > max_bytes) out += "... (" + std::to_string(text.size()) + " bytes)";
  return out;
}

void require_regular_file(const std::filesystem::path& path) {
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (ec || !std::filesystem::exists(status)) {
    throw LogError(path.string() + ": cannot open log: no such file");
  }
  if (!std::filesystem::is_regular_file(status)) {
    throw LogError(path.string() + ": not a regular file (a device, pipe or directory)");
  }
  std::ifstream in(path, std::ios::binary);
  char head[8] = {};
  in.read(head, sizeof head);
  const std::string_view start(head, static_cast<std::size_t>(in.gcount()));
  if (start.size() >= 4 && start.substr(0, 3) == "BZh" && start[3] >= '1' && start[3] <= '9') {
    throw LogError(path.string() +
                   ": not a text log: bzip2-compressed: decompress it first (bunzip2 -k FILE)");
  }
  for (const Magic& m : kNotText) {
    if (start.substr(0, m.bytes.size()) == m.bytes) {
      throw LogError(path.string() + ": not a text log: " + m.what);
    }
  }
}

namespace {

// A UTF-8 byte order mark before line 1 (Windows editors add one) made "cogmap-log 1 ..." an
// unknown first word, reported as "expected a cogmap log line, got 'cogmap-log 1 ...'". A line
// of NUL bytes (a file whose last blocks were allocated but never written) is said as such.
// False for an empty line at end of file.
bool finish_line(std::string& line, const std::filesystem::path& path, std::size_t line_no) {
  if (line_no == 1 && line.rfind("\xef\xbb\xbf", 0) == 0) line.erase(0, 3);
  if (!line.empty() && line.find_first_not_of('\0') == std::string::npos) {
    throw LogError(path.string() + ":" + std::to_string(line_no) + ": " +
                   std::to_string(line.size()) +
                   " NUL bytes instead of a line: the end of the file was never written (power "
                   "lost or disk full while recording?); the lines before it are whole, cut the "
                   "file there to use them");
  }
  return !line.empty();
}

}  // namespace

bool read_bounded_line(std::istream& in, std::string& line, const std::filesystem::path& path,
                       std::size_t line_no, const LogLimits& limits) {
  line.clear();
  std::istream::sentry sentry(in, true);
  if (!sentry) return false;
  std::streambuf* buf = in.rdbuf();
  for (;;) {
    const int c = buf->sbumpc();
    if (c == std::char_traits<char>::eof()) {
      in.setstate(std::ios::eofbit);
      if (line.empty()) in.setstate(std::ios::failbit);
      return finish_line(line, path, line_no);
    }
    if (c == '\n') {
      finish_line(line, path, line_no);
      return true;
    }
    if (line.size() >= limits.max_line_bytes) {
      throw LogError(path.string() + ":" + std::to_string(line_no) + ": line longer than " +
                     std::to_string(limits.max_line_bytes) + " bytes: not a text log");
    }
    line.push_back(static_cast<char>(c));
  }
}

void check_geometry(const mapper::RobotGeometry& g, const std::string& where) {
  // Bounds wide enough for any wheeled indoor robot and its sonars or rangefinders, narrow
  // enough that a mapper sized by them stays in memory.
  in_range(g.sonar_max_range_m, 0.05, 50.0, "sonar_max_range_m", where);
  in_range(g.sonar_min_range_m, 0.0, g.sonar_max_range_m, "sonar_min_range_m", where);
  if (!(g.sonar_min_range_m < g.sonar_max_range_m)) {
    throw LogError(where + ": sonar_min_range_m must be below sonar_max_range_m");
  }
  in_range(g.sonar_beam_width_rad, 1e-3, std::numbers::pi, "sonar_beam_width_rad", where);
  in_range(g.length_m, 0.01, 10.0, "length_m", where);
  in_range(g.width_m, 0.01, 10.0, "width_m", where);
  in_range(g.max_speed_mps, 1e-3, 10.0, "max_speed_mps", where);
  in_range(g.max_turn_rate_radps, 1e-3, 100.0, "max_turn_rate_radps", where);
  in_range(g.max_accel_mps2, 1e-3, 100.0, "max_accel_mps2", where);
  in_range(g.max_decel_mps2, 1e-3, 100.0, "max_decel_mps2", where);
  for (std::size_t i = 0; i < g.sonars.size(); ++i) {
    const std::string field = "sonar mount " + std::to_string(i);
    in_range(g.sonars[i].x_m, -10.0, 10.0, (field + " x_m").c_str(), where);
    in_range(g.sonars[i].y_m, -10.0, 10.0, (field + " y_m").c_str(), where);
    in_range(g.sonars[i].heading_rad, -100.0, 100.0, (field + " heading_rad").c_str(), where);
  }
}

std::string odometry_jump_problem(double jump_m, double dt_s, double max_speed_mps,
                                  const LogLimits& limits) {
  const double allowed_m = limits.jump_slack_m + limits.speed_factor * max_speed_mps * dt_s;
  if (jump_m <= allowed_m) return {};
  return "odometry jumps " + number_text(jump_m) + " m in " + number_text(dt_s) + " s (at most " +
         number_text(allowed_m) + " m at max_speed_mps " + number_text(max_speed_mps) + ")";
}

void check_frame(const mapper::SensorFrame& f, const mapper::SensorFrame* previous,
                 const mapper::RobotGeometry& geometry, const LogLimits& limits,
                 const std::string& where) {
  const double lim = limits.max_coordinate_m;
  in_range(f.time_s, -1e9, 1e9, "time_s", where);
  in_range(f.odometry.x_m, -lim, lim, "odometry x_m", where);
  in_range(f.odometry.y_m, -lim, lim, "odometry y_m", where);
  in_range(f.odometry.theta_rad, -1e6, 1e6, "odometry theta_rad", where);
  if (f.true_pose) {
    in_range(f.true_pose->x_m, -lim, lim, "true x_m", where);
    in_range(f.true_pose->y_m, -lim, lim, "true y_m", where);
    in_range(f.true_pose->theta_rad, -1e6, 1e6, "true theta_rad", where);
  }
  const double earliest_s = (previous ? previous->time_s : f.time_s) - limits.reading_time_slack_s;
  const double latest_s = f.time_s + limits.reading_time_slack_s;
  for (std::size_t i = 0; i < f.sonar.size(); ++i) {
    const mapper::SonarReading& r = f.sonar[i];
    in_range(r.range_m, 0.0, 1e3, "sonar range_m", where);
    in_range(r.time_s, -1e9, 1e9, "sonar time_s", where);
    if (r.time_s < earliest_s || r.time_s > latest_s) {
      throw LogError(
          where + ": reading " + std::to_string(i + 1) + " fired at " + number_text(r.time_s) +
          " s, more than " + number_text(limits.reading_time_slack_s) +
          " s outside its frame's interval (" +
          (previous ? number_text(previous->time_s) + " s" : std::string("start")) + ", " +
          number_text(f.time_s) + " s]: a frame holds the pulses fired since the previous frame");
    }
  }
  if (previous) {
    const double dt_s = f.time_s - previous->time_s;
    if (dt_s < 0.0) {
      throw LogError(where + ": time goes backwards (" + number_text(f.time_s) + " s after " +
                     number_text(previous->time_s) + " s)");
    }
    const double jump_m = std::hypot(f.odometry.x_m - previous->odometry.x_m,
                                     f.odometry.y_m - previous->odometry.y_m);
    const std::string jump = odometry_jump_problem(jump_m, dt_s, geometry.max_speed_mps, limits);
    if (!jump.empty()) throw LogError(where + ": " + jump);
  }
}

}  // namespace cogmap::hw::detail
