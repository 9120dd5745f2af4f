// The parts of the bag import that need no ROS library: recognising a bag and describing an
// import. Built with or without the ROS 1 libraries.
#include <fstream>
#include <string>

#include "cogmap/hw/bag_import.h"

namespace cogmap::hw {

bool looks_like_ros_bag(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::string magic(13, '\0');
  if (!in.read(magic.data(), static_cast<std::streamsize>(magic.size()))) return false;
  return magic == "#ROSBAG V2.0\n";
}

std::string format_bag_stats(const BagImportStats& s) {
  return s.sonar_topic + " (" + s.sonar_type + ", " + std::to_string(s.sonar_messages) +
         " messages) + " + s.odom_topic + " (" + s.odom_type + ", " +
         std::to_string(s.odometry_messages) + " poses), robot " + s.robot_model + ": " +
         std::to_string(s.frames) + " frames, " + std::to_string(s.readings_accepted) +
         " readings accepted (" + std::to_string(s.readings_no_echo) + " without echo), " +
         std::to_string(s.rejected_unchanged) + " unchanged, " +
         std::to_string(s.rejected_unreported) + " never reported, " +
         std::to_string(s.rejected_no_odometry) + " outside odometry";
}

}  // namespace cogmap::hw
