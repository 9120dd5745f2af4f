#pragma once
// Test support for the peer tests: ARIA's `.map` format, only what the map metric needs: the
// walls (`LINES` section, `x1 y1 x2 y2` in mm between `LINES` and `DATA`) and the `RobotHome`
// cairn (`Cairn: RobotHome x_mm y_mm theta_deg ...`), where AMRISim starts the robot.

#include <filesystem>
#include <optional>
#include <vector>

#include "cogmap/mapper/seam/geometry.h"
#include "cogmap/mapper/seam/pose2.h"

namespace cogmap::peers {

struct AriaMap {
  std::vector<mapper::Segment> lines;  ///< walls, metres, map frame
  std::optional<mapper::Pose2> robot_home;
};

/// Reads `path`. Throws std::runtime_error "file:line: ..." for a file that is not a 2D-Map, a
/// malformed LINES row, or a NumLines header that disagrees with the rows.
AriaMap read_aria_map(const std::filesystem::path& path);

}  // namespace cogmap::peers
