// The cogmap robot log: formatting with round-trip numbers, strict line parsing.
#include "cogmap/hw/robot_log.h"

#include "log_checks.h"

#include <charconv>
#include <cmath>
#include <cstring>
#include <sstream>
#include <vector>

namespace cogmap::hw {
namespace {

// Shortest decimal that reads back to the same double (std::to_chars round-trip guarantee).
std::string shortest_number_text(double v) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

std::vector<std::string> split(const std::string& line, char sep) {
  std::vector<std::string> out;
  std::string cur;
  for (char c : line) {
    if (c == sep || (sep == ' ' && (c == '\t' || c == '\r'))) {
      if (!cur.empty() || sep != ' ') out.push_back(cur);
      cur.clear();
    } else {
      cur.push_back(c);
    }
  }
  if (!cur.empty() || (sep != ' ' && !line.empty())) out.push_back(cur);
  return out;
}

// Token-by-token reading of one line; every error names file:line and what was expected.
class LineParser {
 public:
  LineParser(const std::filesystem::path& file, std::size_t line, const std::string& text)
      : file_(file), line_(line), tokens_(split(text, ' ')) {}

  [[noreturn]] void fail(const std::string& expected, const std::string& got) const {
    throw LogError(file_.string() + ":" + std::to_string(line_) + ": expected " + expected +
                   ", got '" + detail::printable(got) + "'");
  }
  bool done() const { return pos_ >= tokens_.size(); }
  std::string word(const std::string& what) {
    if (done()) fail(what, "end of line");
    return tokens_[pos_++];
  }
  double number(const std::string& what) { return to_number(word(what), what); }
  double to_number(const std::string& token, const std::string& what) const {
    double v = 0.0;
    const auto r = std::from_chars(token.data(), token.data() + token.size(), v);
    if (r.ec != std::errc() || r.ptr != token.data() + token.size() || !std::isfinite(v)) {
      fail(what + " (a finite number)", token);
    }
    return v;
  }
  long integer(const std::string& what, long lo, long hi) {
    const std::string token = word(what);
    return to_integer(token, what, lo, hi);
  }
  long to_integer(const std::string& token, const std::string& what, long lo, long hi) const {
    long v = 0;
    const auto r = std::from_chars(token.data(), token.data() + token.size(), v);
    if (r.ec != std::errc() || r.ptr != token.data() + token.size() || v < lo || v > hi) {
      fail(what + " (integer " + std::to_string(lo) + ".." + std::to_string(hi) + ")", token);
    }
    return v;
  }
  bool flag(const std::string& what) { return integer(what + " (0 or 1)", 0, 1) == 1; }
  void end() const {
    if (!done()) fail("end of line", tokens_[pos_]);
  }
  // Splits a comma-joined token into exactly `n` fields.
  std::vector<std::string> fields(const std::string& token, std::size_t n,
                                  const std::string& what) const {
    auto f = split(token, ',');
    if (f.size() != n) fail(what, token);
    return f;
  }

 private:
  const std::filesystem::path& file_;
  std::size_t line_;
  std::vector<std::string> tokens_;
  std::size_t pos_ = 0;
};

// The header keys, in the order written; all are required.
struct HeaderKey {
  const char* name;
  double mapper::RobotGeometry::*field;
};
constexpr HeaderKey kHeaderKeys[] = {
    {"sonar_min_range_m", &mapper::RobotGeometry::sonar_min_range_m},
    {"sonar_max_range_m", &mapper::RobotGeometry::sonar_max_range_m},
    {"sonar_beam_width_rad", &mapper::RobotGeometry::sonar_beam_width_rad},
    {"length_m", &mapper::RobotGeometry::length_m},
    {"width_m", &mapper::RobotGeometry::width_m},
    {"max_speed_mps", &mapper::RobotGeometry::max_speed_mps},
    {"max_turn_rate_radps", &mapper::RobotGeometry::max_turn_rate_radps},
    {"max_accel_mps2", &mapper::RobotGeometry::max_accel_mps2},
    {"max_decel_mps2", &mapper::RobotGeometry::max_decel_mps2},
};

}  // namespace

std::string format_log_header(const mapper::RobotGeometry& g) {
  std::string s = std::string(kLogMagic) + " " + std::to_string(kLogVersion);
  for (const HeaderKey& k : kHeaderKeys)
    s += " " + std::string(k.name) + "=" + shortest_number_text(g.*k.field);
  s += " sonars=" + std::to_string(g.sonars.size());
  for (const mapper::SonarMount& m : g.sonars) {
    s += " " + shortest_number_text(m.x_m) + "," + shortest_number_text(m.y_m) + "," +
         shortest_number_text(m.heading_rad);
  }
  return s;
}

std::string format_frame_line(const mapper::SensorFrame& f) {
  std::string s =
      "F " + shortest_number_text(f.time_s) + " " + shortest_number_text(f.odometry.x_m) + " " +
      shortest_number_text(f.odometry.y_m) + " " + shortest_number_text(f.odometry.theta_rad) +
      " " + (f.stall_left ? "1" : "0") + " " + (f.stall_right ? "1" : "0") + " ";
  if (f.true_pose) {
    s += shortest_number_text(f.true_pose->x_m) + "," + shortest_number_text(f.true_pose->y_m) +
         "," + shortest_number_text(f.true_pose->theta_rad);
  } else {
    s += "-";
  }
  s += " " + std::to_string(f.sonar.size());
  for (const mapper::SonarReading& r : f.sonar) {
    s += " " + std::to_string(r.index) + "," + shortest_number_text(r.range_m) + "," +
         (r.echo ? "1" : "0") + "," + shortest_number_text(r.time_s);
  }
  return s;
}

std::string format_command_line(double time_s, const mapper::VelocityCommand& cmd) {
  return "C " + shortest_number_text(time_s) + " " + shortest_number_text(cmd.v_mps) + " " +
         shortest_number_text(cmd.w_radps);
}

std::string format_stop_line(double time_s) { return "S " + shortest_number_text(time_s); }

LogReader::LogReader(const std::filesystem::path& path, const LogLimits& limits)
    : path_(path), limits_(limits) {
  detail::require_regular_file(path);
  in_.open(path, std::ios::binary);
  if (!in_) throw LogError(path.string() + ": cannot open log: " + std::strerror(errno));
  std::string text;
  while (detail::read_bounded_line(in_, text, path_, line_no_ + 1, limits_)) {
    ++line_no_;
    if (text.empty() || text[0] == '#') continue;
    LineParser p(path_, line_no_, text);
    if (p.word("'cogmap-log'") != kLogMagic) p.fail("a cogmap log header 'cogmap-log 1 ...'", text);
    const long version = p.integer("format version", 0, 1000000);
    if (version != kLogVersion) {
      p.fail("format version " + std::to_string(kLogVersion), std::to_string(version));
    }
    for (const HeaderKey& k : kHeaderKeys) {
      const std::string token = p.word(std::string(k.name) + "=VALUE");
      const std::string prefix = std::string(k.name) + "=";
      if (token.rfind(prefix, 0) != 0) p.fail(prefix + "VALUE", token);
      geometry_.*k.field = p.to_number(token.substr(prefix.size()), k.name);
    }
    const std::string count = p.word("sonars=N");
    if (count.rfind("sonars=", 0) != 0) p.fail("sonars=N", count);
    const long n = p.to_integer(count.substr(7), "sonars=N", 0, 255);
    geometry_.sonars.clear();
    for (long i = 0; i < n; ++i) {
      const std::string token = p.word("sonar mount x_m,y_m,heading_rad");
      const auto f = p.fields(token, 3, "sonar mount x_m,y_m,heading_rad");
      geometry_.sonars.push_back({p.to_number(f[0], "sonar x_m"), p.to_number(f[1], "sonar y_m"),
                                  p.to_number(f[2], "sonar heading_rad")});
    }
    p.end();
    detail::check_geometry(geometry_, path_.string() + ":" + std::to_string(line_no_) + ": header");
    return;
  }
  throw LogError(path.string() + ":" + std::to_string(line_no_ + 1) +
                 ": expected a cogmap log header 'cogmap-log 1 ...', got end of file");
}

std::variant<mapper::SensorFrame, LoggedCommand> LogReader::parse_line(const std::string& text) {
  LineParser p(path_, line_no_, text);
  const std::string kind = p.word("a line type F, C or S");
  if (kind == "F") {
    mapper::SensorFrame f;
    f.time_s = p.number("time_s");
    f.odometry.x_m = p.number("odometry x_m");
    f.odometry.y_m = p.number("odometry y_m");
    f.odometry.theta_rad = p.number("odometry theta_rad");
    f.stall_left = p.flag("stall_left");
    f.stall_right = p.flag("stall_right");
    const std::string truth = p.word("true pose x,y,theta or '-'");
    if (truth != "-") {
      const auto t = p.fields(truth, 3, "true pose x_m,y_m,theta_rad or '-'");
      f.true_pose = mapper::Pose2{p.to_number(t[0], "true x_m"), p.to_number(t[1], "true y_m"),
                                  p.to_number(t[2], "true theta_rad")};
    }
    const long n = p.integer("reading count", 0, 4096);
    for (long i = 0; i < n; ++i) {
      const std::string what = "reading index,range_m,echo,time_s (" + std::to_string(i + 1) +
                               " of " + std::to_string(n) + ")";
      const std::string token = p.word(what);
      const auto r = p.fields(token, 4, what);
      mapper::SonarReading reading;
      reading.index = static_cast<int>(
          p.to_integer(r[0], "sonar index", 0, static_cast<long>(geometry_.sonars.size()) - 1));
      reading.range_m = p.to_number(r[1], "range_m");
      reading.echo = p.to_integer(r[2], "echo (0 or 1)", 0, 1) == 1;
      reading.time_s = p.to_number(r[3], "reading time_s");
      f.sonar.push_back(reading);
    }
    p.end();
    detail::check_frame(f, previous_ ? &*previous_ : nullptr, geometry_, limits_,
                        path_.string() + ":" + std::to_string(line_no_));
    previous_ = f;
    previous_->sonar.clear();  // only time and pose are compared
    return f;
  }
  if (kind == "C" || kind == "S") {
    LoggedCommand c;
    c.time_s = p.number("time_s");
    c.stop = kind == "S";
    if (!c.stop) {
      c.cmd.v_mps = p.number("v_mps");
      c.cmd.w_radps = p.number("w_radps");
    }
    p.end();
    return c;
  }
  p.fail("a line type F, C or S", kind);
}

std::optional<std::variant<mapper::SensorFrame, LoggedCommand>> LogReader::next() {
  std::string text;
  while (detail::read_bounded_line(in_, text, path_, line_no_ + 1, limits_)) {
    ++line_no_;
    if (text.empty() || text[0] == '#' || text == "\r") continue;
    try {
      return parse_line(text);
    } catch (const LogError& e) {
      // The writer ends every line with a newline and flushes it, so a last line without one
      // was cut short by a crash, a kill or a full disk while it was written.
      if (!in_.eof()) throw;
      throw LogError(std::string(e.what()) +
                     " (the last line, cut short: no newline ends it, so the recording stopped "
                     "while writing it; the lines before it are whole: delete this one to "
                     "replay them)");
    }
  }
  if (in_.bad())
    throw LogError(path_.string() + ": read error after line " + std::to_string(line_no_));
  return std::nullopt;
}

LogWriter::LogWriter(const std::filesystem::path& path, const mapper::RobotGeometry& geometry)
    : path_(path) {
  file_ = std::fopen(path.c_str(), "w");
  if (!file_) {
    throw std::runtime_error(path.string() + ": cannot create log: " + std::strerror(errno));
  }
  write_line("# cogmap robot log (docs/robot-driver.md): F frame, C command, S stop");
  write_line(format_log_header(geometry));
}

LogWriter::~LogWriter() {
  if (file_) std::fclose(file_);
}

void LogWriter::write_line(const std::string& line) {
  if (std::fputs(line.c_str(), file_) < 0 || std::fputc('\n', file_) == EOF ||
      std::fflush(file_) != 0) {
    throw std::runtime_error(path_.string() + ": write failed: " + std::strerror(errno));
  }
}

}  // namespace cogmap::hw
