#pragma once
/// Importers of foreign robot logs into cogmap frames (docs/robot-driver.md "Importers"):
/// CARMEN text logs (ODOM and SONAR lines) and Player 2.x/3.x writelog files (position2d, sonar
/// and ranger lines). Each becomes a list of SensorFrames plus the geometry (from the log where it
/// says, else the P2-AT's).

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "cogmap/hw/robot_log.h"
#include "cogmap/mapper/seam/robot_geometry.h"
#include "cogmap/mapper/seam/sensor_frame.h"

namespace cogmap::hw {

/// A foreign log converted to the seam's vocabulary.
struct ImportedLog {
  mapper::RobotGeometry geometry;
  std::vector<mapper::SensorFrame> frames;  ///< in file order; time_s from the first time used
  std::size_t ignored_lines = 0;  ///< other messages, devices, robots; SONAR lines without a pose
};

/// Reads a CARMEN log. Lines read: `ODOM x y theta tv rv accel timestamp host logger_ts` (one
/// frame without readings each) and `SONAR cone_angle n range*n (x y theta)*n timestamp host
/// logger_ts` as CARMEN's logger writes it (one frame with n readings at the latest ODOM's pose;
/// skipped before the first ODOM or when that is more than 0.5 s old), or with `robot_x robot_y
/// robot_theta [tv rv]` before the timestamp (the line's own pose). The first SONAR line sets the
/// sonar mounts and beam width. Other message types are counted and skipped. Times are decimal
/// differences from the first frame's timestamp. Throws LogError ("file:line: expected ...")
/// for a malformed ODOM or SONAR line, and ("file: no sonar readings ...", listing the lines
/// found) for a log without a SONAR reading (a laser-only log).
ImportedLog import_carmen_log(const std::filesystem::path& path);

/// Reads a Player 2.x/3.x writelog file: `time host robot interface index type subtype data...`.
/// Lines read: position2d type 1 subtype 1 (`px py pa vx vy va stall`), sonar type 1 subtype 1
/// (`count range*count`), and sonar geometry, type 1 subtype 2 or type 4 subtype 1
/// (`count (x y yaw)*count`); Player 3's ranger (Stage 4's sonar) type 1 subtypes 1-2 and its
/// geometry and config replies, type 4 subtypes 1 and 5, read as sonar when the geometry has one
/// pose per element (else a laser, skipped and counted). The odometry is the position2d device
/// of lowest address; the sonar arrays are that robot's, joined in index order (sonar devices,
/// then rangers) when several have a geometry. A frame
/// is emitted for every sonar ranges line, with the latest position; position lines before
/// the first sonar line or between two sonar lines make frames without readings. Lines of
/// other devices are counted and skipped. Throws LogError for a malformed line of those types,
/// an array whose geometry changes, sonar arrays of more than 255 transducers in all (a cogmap
/// log's most), a sonar ranger that never logs its geometry, a log without
/// sonar readings (naming every device and why it was skipped), and Player 1.x files.
ImportedLog import_player_log(const std::filesystem::path& path);

/// Which format a file holds, from its first meaningful line.
enum class LogFormat { kCogmap, kCarmen, kPlayer };
/// Guesses the format. Throws LogError when the file cannot be read or matches none.
LogFormat detect_log_format(const std::filesystem::path& path);

/// Writes frames as a cogmap log (so an import can be replayed or inspected).
void write_cogmap_log(const std::filesystem::path& path, const ImportedLog& log);

}  // namespace cogmap::hw
