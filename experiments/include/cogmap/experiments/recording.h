#pragma once
/// Opens any recording a user may hold as a mapper::Robot that plays it back: a cogmap robot
/// log (streamed), or a CARMEN log, a Player 2.x-3.x log or a ROS 1 bag (imported into memory).
/// One place decides the format, so every reader of recordings accepts the same files.

#include <filesystem>
#include <memory>
#include <string>

#include "cogmap/hw/bag_import.h"
#include "cogmap/mapper/seam/robot.h"

namespace cogmap::experiments {

/// How to read a recording.
struct RecordingOptions {
  /// auto | cogmap | carmen | player | rosbag ("auto": a bag by its magic, else by content).
  std::string format = "auto";
  hw::BagImportOptions bag;  ///< topics and robot model, for bags
};

/// The opened recording.
struct Recording {
  std::unique_ptr<mapper::Robot> robot;
  std::string format;           ///< the format it was read as
  std::string description;      ///< one line for the user: frames imported, bag statistics
  double last_time_s = 0.0;     ///< time of the last frame, seconds (0 for none)
  bool has_true_poses = false;  ///< a cogmap log of a simulated run carries ground truth
};

/// Opens `path`. Throws hw::LogError ("FILE:LINE: ..." or "FILE: topic T, message K: ...") for a
/// file that cannot be read in the chosen format or bag options given for a file that is not a
/// bag, std::invalid_argument for an unknown format.
Recording open_recording(const std::filesystem::path& path, const RecordingOptions& options = {});

}  // namespace cogmap::experiments
