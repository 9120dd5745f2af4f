#pragma once
/// The cogmap robot log (docs/robot-driver.md "Log format"): line-based text, one header line
/// with the format version and the RobotGeometry, then one line per frame (`F`) and per command
/// (`C`, `S`). Numbers are written in the shortest form that reads back bit-identical, so a
/// replay feeds the mapper exactly the frames of the live run.

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <stdexcept>
#include <string>
#include <variant>

#include "cogmap/mapper/seam/robot_geometry.h"
#include "cogmap/mapper/seam/sensor_frame.h"
#include "cogmap/mapper/seam/velocity_command.h"

namespace cogmap::hw {

/// The first word of every log, and the version this code writes and reads.
inline constexpr const char* kLogMagic = "cogmap-log";
inline constexpr int kLogVersion = 1;

/// A malformed log: the message is "file:line: expected ..., got '...'".
class LogError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// What every log reader accepts (docs/reliability.md "Limits"); beyond it a line is an error
/// naming the file and line, because a mapper fed such a log would build a grid of gigabytes.
struct LogLimits {
  /// Longest line, bytes: a frame of 4096 readings (the format's maximum) is about 160 kB.
  std::size_t max_line_bytes = std::size_t{1} << 20;
  /// Largest |x| or |y| of an odometry or true pose, metres; the same bound as a world's
  /// coordinates (a 1e5 m jump made a 3.7 GB run with a 180 MB grid image).
  double max_coordinate_m = 1000.0;
  /// Odometry may move at most jump_slack_m + speed_factor x max_speed_mps x dt between two
  /// frames: twice the header's top speed, plus 1 m for encoder resets and rounding.
  double jump_slack_m = 1.0;
  double speed_factor = 2.0;
  /// A frame's readings are the pulses fired since the previous frame: each reading's time_s
  /// may lie at most this far outside (previous frame, this frame] (for a log's first frame,
  /// from this frame's time). A ring of 16 fires in well under a second; a reading stamped
  /// 1000 s before its frame was mapped at whatever pose that time gave.
  double reading_time_slack_s = 1.0;
};

/// The header line for `geometry`.
std::string format_log_header(const mapper::RobotGeometry& geometry);
/// One `F` line (without newline).
std::string format_frame_line(const mapper::SensorFrame& frame);
/// One `C` line: a motion command given at `time_s` (the time of the last frame seen).
std::string format_command_line(double time_s, const mapper::VelocityCommand& cmd);
/// One `S` line: stop() at `time_s`.
std::string format_stop_line(double time_s);

/// A command line read back.
struct LoggedCommand {
  double time_s = 0.0;
  mapper::VelocityCommand cmd;
  bool stop = false;  ///< an `S` line
};

/// Reads a log line by line. Comment (`#`) and blank lines are skipped.
class LogReader {
 public:
  /// Opens `path` and parses the header. Throws LogError (file and line) when the file is not
  /// a regular file, or the header is malformed, of another version, or describes geometry no
  /// robot has (ranges, beam width, body, limits: see detail::check_geometry).
  explicit LogReader(const std::filesystem::path& path, const LogLimits& limits = {});

  const mapper::RobotGeometry& geometry() const { return geometry_; }

  /// The next frame or command; empty at end of file. Throws LogError for a malformed line, a
  /// number that is not finite, time going backwards or an odometry jump beyond `limits`; for
  /// a last line without its newline (a recording cut off mid-line) the message says so.
  std::optional<std::variant<mapper::SensorFrame, LoggedCommand>> next();

  /// The line number of the last line read (1-based).
  std::size_t line() const { return line_no_; }

 private:
  std::filesystem::path path_;
  std::ifstream in_;
  std::size_t line_no_ = 0;
  LogLimits limits_;
  mapper::RobotGeometry geometry_;
  std::optional<mapper::SensorFrame> previous_;  // the last frame, for the sequence checks

  std::variant<mapper::SensorFrame, LoggedCommand> parse_line(const std::string& text);
};

/// Appends lines to a log file, flushing after each so a crash loses at most one line.
class LogWriter {
 public:
  /// Creates (truncates) `path` and writes the header. Throws std::runtime_error naming the
  /// file when it cannot be written.
  LogWriter(const std::filesystem::path& path, const mapper::RobotGeometry& geometry);
  ~LogWriter();
  LogWriter(const LogWriter&) = delete;
  LogWriter& operator=(const LogWriter&) = delete;

  /// Writes one line and flushes. Throws std::runtime_error when the write fails.
  void write_line(const std::string& line);

 private:
  std::filesystem::path path_;
  std::FILE* file_ = nullptr;
};

}  // namespace cogmap::hw
