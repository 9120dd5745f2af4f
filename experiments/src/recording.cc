#include "cogmap/experiments/recording.h"

#include <stdexcept>

#include "cogmap/hw/log_import.h"
#include "cogmap/hw/log_robot.h"
#include "cogmap/mapper/seam/fake_robot.h"

namespace cogmap::experiments {

Recording open_recording(const std::filesystem::path& path, const RecordingOptions& options) {
  const std::string& f = options.format;
  if (f != "auto" && f != "cogmap" && f != "carmen" && f != "player" && f != "rosbag") {
    throw std::invalid_argument("unknown recording format '" + f +
                                "' (auto, cogmap, carmen, player, rosbag)");
  }
  Recording out;
  if (f == "rosbag" || (f == "auto" && hw::looks_like_ros_bag(path))) {
    hw::ImportedBag bag = hw::import_ros_bag(path, options.bag);
    out.format = "rosbag";
    out.description = hw::format_bag_stats(bag.stats);
    out.robot = std::make_unique<mapper::FakeRobot>(bag.log.geometry, std::move(bag.log.frames));
    return out;
  }
  hw::LogFormat format = hw::LogFormat::kCogmap;
  if (f == "auto") {
    format = hw::detect_log_format(path);
  } else if (f == "carmen") {
    format = hw::LogFormat::kCarmen;
  } else if (f == "player") {
    format = hw::LogFormat::kPlayer;
  }
  if (format == hw::LogFormat::kCogmap) {
    out.format = "cogmap";
    out.robot = std::make_unique<hw::LogRobot>(path);
    return out;
  }
  hw::ImportedLog imported =
      format == hw::LogFormat::kCarmen ? hw::import_carmen_log(path) : hw::import_player_log(path);
  out.format = format == hw::LogFormat::kCarmen ? "carmen" : "player";
  out.description = "imported " + std::to_string(imported.frames.size()) + " frames (" +
                    std::to_string(imported.ignored_lines) + " other lines skipped)";
  out.robot = std::make_unique<mapper::FakeRobot>(imported.geometry, std::move(imported.frames));
  return out;
}

}  // namespace cogmap::experiments
