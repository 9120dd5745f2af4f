#include "import_common.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <sstream>
#include <string_view>

#include "log_checks.h"

namespace cogmap::hw::detail {
namespace {

// The decimal `t` (digits, an optional point, an optional exponent) in nanoseconds, rounded
// half away from zero; empty when it is no such decimal or beyond 4e9 s.
std::optional<std::int64_t> decimal_ns(std::string_view t) {
  std::size_t i = 0;
  const bool negative = !t.empty() && t[0] == '-';
  if (!t.empty() && (t[0] == '-' || t[0] == '+')) ++i;
  std::string digits;
  long point = -1;
  for (; i < t.size(); ++i) {
    if (t[i] >= '0' && t[i] <= '9') {
      digits.push_back(t[i]);
    } else if (t[i] == '.' && point < 0) {
      point = static_cast<long>(digits.size());
    } else {
      break;
    }
  }
  if (digits.empty()) return std::nullopt;
  if (point < 0) point = static_cast<long>(digits.size());
  long exponent = 0;
  if (i < t.size() && (t[i] == 'e' || t[i] == 'E')) {
    const char* b = t.data() + i + 1;
    if (b < t.data() + t.size() && *b == '+') ++b;
    const auto r = std::from_chars(b, t.data() + t.size(), exponent);
    if (r.ec != std::errc() || r.ptr != t.data() + t.size()) return std::nullopt;
    i = t.size();
  }
  if (i != t.size() || exponent < -40 || exponent > 40) return std::nullopt;
  // The first `whole` digits are whole nanoseconds; the next one rounds.
  const long whole = point + exponent + 9;
  const auto size = static_cast<long>(digits.size());
  std::string ns_digits = whole <= 0 ? "0" : digits.substr(0, std::min(whole, size));
  if (whole > size) ns_digits.append(static_cast<std::size_t>(whole - size), '0');
  const auto first = ns_digits.find_first_not_of('0');
  ns_digits = first == std::string::npos ? "0" : ns_digits.substr(first);
  if (ns_digits.size() > 19) return std::nullopt;
  std::uint64_t ns = 0;
  std::from_chars(ns_digits.data(), ns_digits.data() + ns_digits.size(), ns);
  if (whole >= 0 && whole < size && digits[static_cast<std::size_t>(whole)] >= '5') ++ns;
  if (ns > 4'000'000'000'000'000'000ULL) return std::nullopt;
  const auto v = static_cast<std::int64_t>(ns);
  return negative ? -v : v;
}

}  // namespace

std::vector<std::string> tokens_of(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> out;
  std::string t;
  while (in >> t) out.push_back(t);
  return out;
}

std::ifstream open_log(const std::filesystem::path& path) {
  require_regular_file(path);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw LogError(path.string() + ": cannot open log: " + std::strerror(errno));
  return in;
}

double seconds_between(const Stamp& later, const Stamp& earlier) {
  if (later.ns && earlier.ns) return static_cast<double>(*later.ns - *earlier.ns) / 1e9;
  return later.seconds - earlier.seconds;
}

void Fields::fail(const std::string& expected, std::size_t i) const {
  fail_line("expected " + expected + " at field " + std::to_string(i + 1) + ", got '" +
            (i < tokens_.size() ? printable(tokens_[i]) : "end of line") + "'");
}

void Fields::fail_line(const std::string& message) const {
  throw LogError(file_.string() + ":" + std::to_string(line_) + ": " + message);
}

double Fields::number(std::size_t i, const std::string& what) const {
  if (i >= tokens_.size()) fail(what, i);
  const std::string& t = tokens_[i];
  const char* b = t.data() + (!t.empty() && t[0] == '+' ? 1 : 0);
  double v = 0.0;
  const auto r = std::from_chars(b, t.data() + t.size(), v);
  if (r.ec != std::errc() || r.ptr != t.data() + t.size() || !std::isfinite(v)) fail(what, i);
  return v;
}

long Fields::integer(std::size_t i, const std::string& what, long lo, long hi) const {
  const double v = number(i, what);
  if (v != std::floor(v) || v < static_cast<double>(lo) || v > static_cast<double>(hi)) {
    fail(what + " (" + std::to_string(lo) + ".." + std::to_string(hi) + ")", i);
  }
  return static_cast<long>(v);
}

Stamp Fields::stamp(std::size_t i, const std::string& what) const {
  Stamp s;
  s.seconds = number(i, what);
  s.ns = decimal_ns(tokens_[i]);
  return s;
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

void push_frame(ImportedLog& log, mapper::SensorFrame frame, const std::filesystem::path& path,
                std::size_t line_no) {
  const std::string where = path.string() + ":" + std::to_string(line_no);
  check_geometry(log.geometry, where);  // SONAR and geometry lines may change it
  check_frame(frame, log.frames.empty() ? nullptr : &log.frames.back(), log.geometry, LogLimits{},
              where);
  log.frames.push_back(std::move(frame));
}

void require_frames(const ImportedLog& log, const std::filesystem::path& path, const char* format,
                    const char* lines) {
  if (log.frames.empty()) {
    throw LogError(path.string() + ": no " + lines + " lines: not a " + format +
                   " log, or an empty one (" + std::to_string(log.ignored_lines) + " other lines)");
  }
}

bool is_carmen_message(const std::string& name) {
  // The message names CARMEN's logger and its tools write (writelog.c, the logger's header),
  // each between spaces.
  static constexpr std::string_view kCarmenMessages =
      " PARAM SYNC ODOM TRUEPOS GLOBALPOS FLASER RLASER LASER3 LASER4 REMISSIONFLASER"
      " REMISSIONRLASER REMISSIONLASER3 REMISSIONLASER4 RAWLASER1 RAWLASER2 RAWLASER3 RAWLASER4"
      " ROBOTLASER1 ROBOTLASER2 POSITIONLASER NMEAGGA NMEARMC GPSNMEA SONAR BUMPER SCANMARK IMU"
      " VECTORMOVE ROBOTVELOCITY FOLLOWTRAJECTORY BASEVELOCITY ARM COMMENT ";
  return kCarmenMessages.find(" " + name + " ") != std::string_view::npos;
}

LineTally::Entry& LineTally::entry(const std::string& kind) {
  const auto [it, added] = index_.try_emplace(kind, entries_.size());
  if (added) entries_.push_back(Entry{kind, 0, 0, {}});
  return entries_[it->second];
}

void LineTally::skipped(const std::string& kind, const std::string& why) {
  Entry& e = entry(kind);
  e.skipped++;
  if (!why.empty() && std::find(e.whys.begin(), e.whys.end(), why) == e.whys.end()) {
    e.whys.push_back(why);
  }
}

std::string LineTally::describe() const {
  constexpr std::size_t kListed = 12;  // a file of garbage has a kind per line
  std::string out;
  for (std::size_t i = 0; i < entries_.size() && i < kListed; ++i) {
    const Entry& e = entries_[i];
    if (i > 0) out += ", ";
    out += printable(e.kind, 40) + " (";
    if (e.read > 0) out += std::to_string(e.read) + " read";
    if (e.read > 0 && e.skipped > 0) out += ", ";
    if (e.skipped > 0) out += std::to_string(e.skipped) + " skipped";
    for (std::size_t w = 0; w < e.whys.size(); ++w) out += (w == 0 ? ": " : "; ") + e.whys[w];
    out += ")";
  }
  if (entries_.size() > kListed) {
    out += " and " + std::to_string(entries_.size() - kListed) + " more kinds";
  }
  return out.empty() ? "none" : out;
}

void require_sonar_readings(const ImportedLog& log, const std::filesystem::path& path,
                            const char* wanted, const LineTally& tally) {
  for (const mapper::SensorFrame& f : log.frames) {
    if (!f.sonar.empty()) return;
  }
  throw LogError(path.string() + ": no sonar readings (" + wanted +
                 "); lines: " + tally.describe());
}

}  // namespace cogmap::hw::detail
