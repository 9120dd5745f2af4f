#pragma once
// What the CARMEN and Player importers share (internal to hw/): numbered fields of one line with
// errors naming file:line and the field, timestamps kept as exact decimals, a reading from a
// range, the checks every imported frame gets, and the tally of lines that says what a log
// without sonar readings holds instead.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "cogmap/hw/log_import.h"

namespace cogmap::hw::detail {

/// The whitespace-separated tokens of a line (spaces, tabs, a CR of CRLF all separate).
std::vector<std::string> tokens_of(const std::string& line);

/// Opens a log after require_regular_file; LogError naming the file when it cannot.
std::ifstream open_log(const std::filesystem::path& path);

/// A timestamp as written: its value, and the same decimal in nanoseconds when it has one
/// (|t| < 4e9 s), so that differences of epoch times (1.1e9 s, 2.4e-7 s between doubles) are
/// the decimal differences: 1100000000.050000 - 1100000000.000000 is 0.05, not 0.04999995.
struct Stamp {
  double seconds = 0.0;
  std::optional<std::int64_t> ns;
};
/// later - earlier in seconds: exact decimal arithmetic when both have `ns`.
double seconds_between(const Stamp& later, const Stamp& earlier);

/// Reads numbered tokens of one line; errors name file:line and the field.
class Fields {
 public:
  Fields(const std::filesystem::path& file, std::size_t line, std::vector<std::string> tokens)
      : file_(file), line_(line), tokens_(std::move(tokens)) {}
  [[noreturn]] void fail(const std::string& expected, std::size_t i) const;
  /// LogError "file:line: <message>".
  [[noreturn]] void fail_line(const std::string& message) const;
  std::size_t size() const { return tokens_.size(); }
  std::size_t line() const { return line_; }
  const std::string& at(std::size_t i) const { return tokens_[i]; }
  /// A finite number (C's forms: 1.2e-05, -0.000, +0.5).
  double number(std::size_t i, const std::string& what) const;
  long integer(std::size_t i, const std::string& what, long lo, long hi) const;
  Stamp stamp(std::size_t i, const std::string& what) const;

 private:
  const std::filesystem::path& file_;
  std::size_t line_;
  std::vector<std::string> tokens_;
};

/// A reading of transducer `index`: a range of 0 or at/above the maximum is "no echo".
mapper::SonarReading reading(int index, double range_m, double time_s,
                             const mapper::RobotGeometry& g);

/// Appends a frame after the checks every log gets (geometry, finite, time order, no jump).
void push_frame(ImportedLog& log, mapper::SensorFrame frame, const std::filesystem::path& path,
                std::size_t line_no);

/// A file with none of the lines an importer reads is not a log of that format.
void require_frames(const ImportedLog& log, const std::filesystem::path& path, const char* format,
                    const char* lines);

/// A message name CARMEN's logger or its tools write (ODOM, SONAR, FLASER, PARAM, ...).
bool is_carmen_message(const std::string& name);

/// The lines of each kind (a CARMEN message, a Player device) an importer read or skipped, in
/// the order first seen: what a log without sonar readings holds instead.
class LineTally {
 public:
  void read(const std::string& kind) { entry(kind).read++; }
  /// `why` (may be empty) is listed once per kind however often it is given.
  void skipped(const std::string& kind, const std::string& why = "");
  bool empty() const { return entries_.empty(); }
  /// "ODOM (600 read), FLASER (1204 skipped), SONAR (3 read, 2 skipped: why)": the first 12
  /// kinds, then how many more.
  std::string describe() const;

 private:
  struct Entry {
    std::string kind;
    std::size_t read = 0;
    std::size_t skipped = 0;
    std::vector<std::string> whys;
  };
  Entry& entry(const std::string& kind);
  std::vector<Entry> entries_;
  std::map<std::string, std::size_t> index_;
};

/// Throws LogError "<file>: no sonar readings (<wanted>); lines: <tally>" unless some frame has
/// a reading: a log of odometry or lasers alone maps nothing (the ROS bag importer's "no sonar
/// topic" in the same words).
void require_sonar_readings(const ImportedLog& log, const std::filesystem::path& path,
                            const char* wanted, const LineTally& tally);

}  // namespace cogmap::hw::detail
