#pragma once
/// Room grids in the ROS map_server convention (grid_NNN.pgm + grid_NNN.yaml), so any ROS tool
/// can open them: 254 free, 0 occupied, 205 unknown; binary PGM, top row = largest y.

#include <filesystem>
#include <string>

#include "cogmap/mapper/grid/grid.h"
#include "cogmap/mapper/io/asr_json.h"
#include "cogmap/mapper/nav/controller.h"

namespace cogmap::experiments {

/// map_server pixel values.
inline constexpr unsigned char kPgmFree = 254;
inline constexpr unsigned char kPgmOccupied = 0;
inline constexpr unsigned char kPgmUnknown = 205;
/// The explore map's frontier and given-up frontier: map_server reads both as unknown.
inline constexpr unsigned char kPgmFrontier = 160;
inline constexpr unsigned char kPgmBannedFrontier = 100;

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

/// The explorer's own map as a PGM (P5), top row = largest y: 254 free, 0 obstacle, 205 unseen,
/// 160 frontier, 100 a frontier given up.
std::string explore_map_pgm(const mapper::nav::ExploreMapImage& image);

/// Writes `<dir>/explore_map.pgm` and `<dir>/explore_map.yaml` (map_server YAML, origin in the
/// estimate frame) atomically, fsynced per `durability`.
void write_explore_map(const mapper::nav::ExploreMapImage& image, const std::filesystem::path& dir,
                       mapper::io::Durability durability = mapper::io::Durability::kSynced);

}  // namespace cogmap::experiments
