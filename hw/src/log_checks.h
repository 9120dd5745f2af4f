#pragma once
// Checks every log reader applies (cogmap log, CARMEN, Player): bounded lines, regular files,
// a plausible header geometry, finite numbers, time that never goes back and odometry that
// never jumps further than the robot can drive. The ROS bag importer (hw/bag) runs check_frame
// on its odometry samples and frames too. Internal to hw/.

#include <cstddef>
#include <filesystem>
#include <istream>
#include <string>

#include "cogmap/hw/robot_log.h"
#include "cogmap/mapper/seam/robot_geometry.h"
#include "cogmap/mapper/seam/sensor_frame.h"

namespace cogmap::hw::detail {

/// Throws LogError unless `path` names a regular file (not /dev/zero, a pipe or a directory).
void require_regular_file(const std::filesystem::path& path);

/// std::getline with a bound: reads one line into `line`; false at end of file. Throws
/// LogError naming `path` and the line when a line exceeds limits.max_line_bytes (a log of
/// NUL bytes has no newline at all).
bool read_bounded_line(std::istream& in, std::string& line, const std::filesystem::path& path,
                       std::size_t line_no, const LogLimits& limits);

/// Throws LogError ("<where>: <field> ...") for geometry no robot has: ranges, beam width,
/// body and limits non-finite, non-positive or far outside a mobile robot's.
void check_geometry(const mapper::RobotGeometry& geometry, const std::string& where);

/// Throws LogError ("<where>: ...") for a frame whose numbers are not finite, whose time is
/// before `previous`'s, or whose odometry leaves limits.max_coordinate_m or jumps more than
/// limits.jump_slack_m + limits.speed_factor x max_speed_mps x dt from `previous` (null for
/// the first frame of a log).
void check_frame(const mapper::SensorFrame& frame, const mapper::SensorFrame* previous,
                 const mapper::RobotGeometry& geometry, const LogLimits& limits,
                 const std::string& where);

}  // namespace cogmap::hw::detail
