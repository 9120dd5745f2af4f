#pragma once
/// Room grids in the ROS map_server convention (grid_NNN.pgm + grid_NNN.yaml), so any ROS tool
/// can open them: 254 free, 0 occupied, 205 unknown; binary PGM, top row = largest y.

#include <filesystem>
#include <string>

#include "cogmap/mapper/grid/grid.h"
#include "cogmap/mapper/io/asr_json.h"

namespace cogmap::experiments {

/// map_server pixel values.
inline constexpr unsigned char kPgmFree = 254;
inline constexpr unsigned char kPgmOccupied = 0;
inline constexpr unsigned char kPgmUnknown = 205;

/// The PGM (P5) image of a HIMM-scale grid: value > ε occupied, < 0 free (including the robot
/// path), anything else (0 = unexplored, or weak evidence) unknown.
std::string histogram_to_pgm(const mapper::HistogramGrid& grid, double occupied_threshold);

/// The map_server YAML for an image named `image_name`: resolution, origin [x, y, 0] of the
/// lower-left pixel (the grid's local frame), occupied_thresh 0.65, free_thresh 0.196, negate 0.
std::string ros_map_yaml(const mapper::GridGeometry& geometry, const std::string& image_name);

/// Writes `<dir>/<stem>.pgm` and `<dir>/<stem>.yaml` atomically, fsynced per `durability`.
void write_ros_map(const mapper::HistogramGrid& grid, double occupied_threshold,
                   const std::filesystem::path& dir, const std::string& stem,
                   mapper::io::Durability durability = mapper::io::Durability::kSynced);

}  // namespace cogmap::experiments
