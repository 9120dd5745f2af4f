// import_ros_bag: pick topics, read them through rosbag, turn them into frames. Errors from
// every step come back as LogError with the file name in front.
#include <exception>

#include "bag_file_probe.h"
#include "bag_frames.h"
#include "bag_isolation.h"
#include "cogmap/hw/bag_import.h"
#include "cogmap/mapper/seam/robot_models.h"
#include "ros_bag_reader.h"

namespace cogmap::hw {

bool ros_bag_support() { return true; }

ImportedBag import_ros_bag(const std::filesystem::path& path, const BagImportOptions& options) {
  const std::string file = path.string();
  try {
    // The model decides which mount each transducer index means: never guess it.
    if (options.robot.empty()) {
      throw std::runtime_error("the bag does not name its robot: pass --robot (one of " +
                               mapper::robot_model_names() + ")");
    }
    const mapper::RobotModel* model = mapper::find_robot_model(options.robot);
    if (!model) {
      throw std::runtime_error("unknown robot model '" + options.robot + "' (one of " +
                               mapper::robot_model_names() + ")");
    }
    const bag::BagContents contents =
        bag::read_bag_isolated(file, options, model->geometry.sonars.size());
    const bag::TopicChoice& choice = contents.choice;
    const bag::Streams& streams = contents.streams;
    ImportedBag result;
    result.log.geometry = model->geometry;
    result.stats.sonar_topic = choice.request.sonar_topic;
    result.stats.sonar_type = choice.sonar_type;
    result.stats.odom_topic = choice.request.odometry_topic;
    result.stats.odom_type = choice.odom_type;
    result.stats.robot_model = model->name;
    bag::build_frames(streams, choice.request, model->geometry, result.log, result.stats);
    return result;
  } catch (const LogError&) {
    throw;
  } catch (const std::exception& e) {
    std::string message = file + ": " + e.what();
    // rosbag names no offset for a file cut short; its own header says where the index was.
    if (message.find("not a readable ROS 1 bag") != std::string::npos) {
      if (const auto cut = bag::describe_truncation(path)) message += " (" + *cut + ")";
    }
    throw LogError(message);
  }
}

}  // namespace cogmap::hw
