#pragma once
// Checks every log reader applies (cogmap log, CARMEN, Player): bounded lines, regular files,
// a plausible header geometry, finite numbers, time that never goes back and odometry that
// never jumps further than the robot can drive. The ROS bag importer (hw/bag) runs check_frame
// on its odometry samples and frames too. Internal to hw/.

#include <cstddef>
#include <filesystem>
#include <istream>
#include <string>
#include <string_view>

#include "cogmap/hw/robot_log.h"
#include "cogmap/mapper/seam/robot_geometry.h"
#include "cogmap/mapper/seam/sensor_frame.h"

namespace cogmap::hw::detail {

/// Throws LogError unless `path` names a regular file (not /dev/zero, a pipe or a directory)
/// that may be text: a gzip, bzip2, xz, zstd or zip archive (logs are shipped compressed) or
/// UTF-16 text is named as such, with what to do, instead of failing on its first line.
void require_regular_file(const std::filesystem::path& path);

/// std::getline with a bound: reads one line into `line`; false at end of file. A UTF-8 byte
/// order mark opening line 1 is dropped (an editor's, not the log's). Throws LogError naming
/// `path` and the line when a line exceeds limits.max_line_bytes (a log of NUL bytes has no
/// newline at all) or is nothing but NUL bytes (the tail of a file whose last blocks were never
/// written: power lost while recording).
bool read_bounded_line(std::istream& in, std::string& line, const std::filesystem::path& path,
                       std::size_t line_no, const LogLimits& limits);

/// `text` fit to quote in an error message: printable ASCII as it is, every other byte as
/// \xNN (a NUL ended the message there, binary garbled the terminal), and at most `max_bytes`
/// of it, then "... (N bytes)".
std::string printable(std::string_view text, std::size_t max_bytes = 80);

/// Throws LogError ("<where>: <field> ...") for geometry no robot has: ranges, beam width,
/// body and limits non-finite, non-positive or far outside a mobile robot's.
void check_geometry(const mapper::RobotGeometry& geometry, const std::string& where);

/// Odometry that moved `jump_m` in `dt_s` faster than a robot of `max_speed_mps` can drive
/// (more than limits.jump_slack_m + limits.speed_factor x max_speed_mps x dt_s): what is wrong,
/// "odometry jumps X m in T s (at most Y m at max_speed_mps Z)"; empty when it is within that.
/// check_frame holds a log's frames to it, P2osRobot its SIPs.
std::string odometry_jump_problem(double jump_m, double dt_s, double max_speed_mps,
                                  const LogLimits& limits);

/// Throws LogError ("<where>: ...") for a frame whose numbers are not finite, whose time is
/// before `previous`'s, or whose odometry leaves limits.max_coordinate_m or jumps more than
/// limits.jump_slack_m + limits.speed_factor x max_speed_mps x dt from `previous` (null for
/// the first frame of a log).
void check_frame(const mapper::SensorFrame& frame, const mapper::SensorFrame* previous,
                 const mapper::RobotGeometry& geometry, const LogLimits& limits,
                 const std::string& where);

}  // namespace cogmap::hw::detail
