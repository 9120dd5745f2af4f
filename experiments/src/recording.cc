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
  // Before anything opens it: opening a FIFO for reading waits for a writer, so `replay` and
  // `sonar-stats` of a named pipe hung in the bag-magic check (a device or directory is refused
  // by each reader too, but only after that check opened it).
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (!ec && std::filesystem::exists(status) && !std::filesystem::is_regular_file(status)) {
    throw hw::LogError(path.string() + ": not a regular file (a device, pipe or directory)");
  }
  Recording out;
  const bool bag = f == "rosbag" || (f == "auto" && hw::looks_like_ros_bag(path));
  const hw::BagImportOptions& b = options.bag;
  if (!bag && !(b.robot.empty() && b.sonar_topic.empty() && b.odom_topic.empty())) {
    throw hw::LogError(path.string() +
                       ": --robot, --sonar-topic and --odom-topic apply to ROS bags only");
  }
  if (bag) {
    hw::ImportedBag imported = hw::import_ros_bag(path, b);
    out.format = "rosbag";
    out.description = hw::format_bag_stats(imported.stats);
    if (!imported.log.frames.empty()) out.last_time_s = imported.log.frames.back().time_s;
    out.robot =
        std::make_unique<mapper::FakeRobot>(imported.log.geometry, std::move(imported.log.frames));
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
    auto log = std::make_unique<hw::LogRobot>(path);
    out.format = "cogmap";
    out.last_time_s = log->last_time_s();
    out.has_true_poses = log->has_true_poses();
    out.robot = std::move(log);
    return out;
  }
  hw::ImportedLog imported =
      format == hw::LogFormat::kCarmen ? hw::import_carmen_log(path) : hw::import_player_log(path);
  out.format = format == hw::LogFormat::kCarmen ? "carmen" : "player";
  out.description = "imported " + std::to_string(imported.frames.size()) + " frames (" +
                    std::to_string(imported.ignored_lines) + " other lines skipped)";
  if (!imported.frames.empty()) out.last_time_s = imported.frames.back().time_s;
  out.robot = std::make_unique<mapper::FakeRobot>(imported.geometry, std::move(imported.frames));
  return out;
}

}  // namespace cogmap::experiments
