#pragma once
/// ROS 1 bags as cogmap frames (docs/robot-driver.md "ROS bags"): sonar as RosAria publishes it
/// (sensor_msgs/PointCloud or PointCloud2, one point per transducer) or as p2os does
/// (p2os_msgs/SonarArray, decoded from the definition the bag carries), odometry from
/// nav_msgs/Odometry or the odom -> base_link transform on /tf. The result is the same
/// ImportedLog the CARMEN and Player importers produce, so replay and every other reader of
/// recordings take bags alike.
///
/// Needs the Debian ROS 1 libraries at build time (target cogmap_hw_bag); without them
/// ros_bag_support() is false and import_ros_bag() throws a LogError that says what to install.

#include <cstddef>
#include <filesystem>
#include <string>

#include "cogmap/hw/log_import.h"

namespace cogmap::hw {

/// What to read; empty strings mean "detect".
struct BagImportOptions {
  std::string sonar_topic;  ///< default: the one topic of a sonar type (names with "sonar" first)
  std::string odom_topic;   ///< default: the nav_msgs/Odometry topic, else /tf
  std::string robot;        ///< robot model (mapper::find_robot_model); required unless the
                            ///< bag names it
};

/// What the import did, for the user and the tests.
struct BagImportStats {
  std::string sonar_topic, sonar_type;
  std::string odom_topic, odom_type;
  std::string robot_model;
  std::size_t sonar_messages = 0;        ///< messages read from the sonar topic
  std::size_t odometry_messages = 0;     ///< messages (or odom->base_link transforms) read
  std::size_t frames = 0;                ///< frames produced (one per sonar message with odometry)
  std::size_t readings_accepted = 0;     ///< new readings placed on the odometry
  std::size_t readings_no_echo = 0;      ///< of the accepted, at the sonar's maximum range
  std::size_t rejected_unchanged = 0;    ///< a transducer's value repeated from the last message
  std::size_t rejected_unreported = 0;   ///< a transducer that never reported (origin point, 0 m)
  std::size_t rejected_no_odometry = 0;  ///< new readings outside the odometry's time span/gaps
};

/// A bag converted to frames.
struct ImportedBag {
  ImportedLog log;  ///< geometry of the robot model; frames with time_s from the first stamp
  BagImportStats stats;
};

/// Reads `path`. Throws LogError "FILE: ..." for a file that is not a readable bag, no (or an
/// ambiguous) sonar or odometry topic, a topic of the wrong type, an unknown or missing robot
/// model, and "FILE: topic T, message K: ..." for a message that does not decode, a header
/// stamp going backwards or unset, more transducers than the model has, or an odometry sample
/// or frame outside the limits every log has (LogLimits: coordinates, odometry jumps); and
/// "FILE: ...: nothing to map" when no sonar message has a pose (stamps of the two topics that
/// never overlap). Nothing is returned in part.
ImportedBag import_ros_bag(const std::filesystem::path& path, const BagImportOptions& options);

/// True when the file starts with the ROS 1 bag magic "#ROSBAG V2.0".
bool looks_like_ros_bag(const std::filesystem::path& path);

/// False when cogmap was built without the ROS 1 libraries.
bool ros_bag_support();

/// One line: topics, model, frames, readings accepted/rejected.
std::string format_bag_stats(const BagImportStats& stats);

}  // namespace cogmap::hw
