#pragma once
// The only code that touches the ROS 1 libraries (rosbag_storage and the message packages). It
// is compiled as C++17 because the Debian message headers use std::allocator<void>::rebind,
// which C++20 removed; so this header speaks plain standard types only, and the C++20 side
// (bag_import.cc) turns what it returns into frames.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace cogmap::hw::bag {

/// A bag that cannot be read, or a message that cannot be decoded. The message names the topic
/// and the message's index in that topic (0-based) where there is one; no file name (the
/// caller adds it).
class BagReadError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// One topic of the bag, from its connection records.
struct TopicInfo {
  std::string topic;
  std::string datatype;  ///< e.g. "sensor_msgs/PointCloud"
  std::string md5sum;
  std::size_t messages = 0;
};

/// The topics of the bag, sorted by name. Throws BagReadError when the file is not a readable
/// ROS 1 bag (wrong magic, truncated, unindexed, encrypted with an unknown plugin).
std::vector<TopicInfo> list_topics(const std::string& path);

/// How a sonar topic is encoded.
enum class SonarEncoding {
  kPointCloud,   ///< sensor_msgs/PointCloud: one point per transducer (RosAria /RosAria/sonar)
  kPointCloud2,  ///< sensor_msgs/PointCloud2 with float x and y fields (RosAria sonar_pointcloud2)
  kSonarArray,   ///< p2os_msgs/SonarArray: ranges in metres (p2os /sonar)
};

/// How odometry is recorded.
enum class OdometryEncoding {
  kOdometry,  ///< nav_msgs/Odometry (RosAria /RosAria/pose, p2os /pose)
  kTf,        ///< tf2_msgs/TFMessage (or tf/tfMessage): the odom -> base_link transform
};

/// What to read.
struct StreamRequest {
  std::string sonar_topic;
  SonarEncoding sonar = SonarEncoding::kPointCloud;
  std::string odometry_topic;
  OdometryEncoding odometry = OdometryEncoding::kOdometry;
  /// The robot model's sonar count: a sonar message with more values is refused as it is read
  /// (0: no bound).
  std::size_t max_transducers = 0;
};

/// One sonar message: its header stamp and, per transducer in order, either a point (clouds,
/// robot frame, metres) or a range (SonarArray, metres).
struct SonarMessage {
  std::size_t index = 0;         ///< index in its topic
  double stamp_s = 0.0;          ///< header.stamp, seconds
  std::vector<double> x_m, y_m;  ///< clouds: one point per transducer
  std::vector<double> ranges_m;  ///< SonarArray: one range per transducer
};

/// One odometry sample: header stamp and the planar pose (yaw from the quaternion).
struct PoseMessage {
  std::size_t index = 0;  ///< index in its topic
  double stamp_s = 0.0;
  double x_m = 0.0, y_m = 0.0, yaw_rad = 0.0;
};

/// The two streams in bag order.
struct Streams {
  std::vector<SonarMessage> sonar;
  std::vector<PoseMessage> poses;
  std::size_t tf_messages = 0;      ///< tf messages read (kTf), with or without the pair
  std::string tf_parent, tf_child;  ///< the frames the tf poses came from (kTf)
};

/// Reads both topics. For kTf, a transform counts when its parent frame is `odom` and its child
/// `base_link` or `base_footprint`, ignoring a leading '/' and any tf prefix (`robot1/odom`).
/// Throws BagReadError naming the topic and message index for a message that does not decode
/// (wrong type or MD5, truncated data, a SonarArray whose definition is not p2os's) or holds
/// more than request.max_transducers values.
/// `on_message` (optional) is called with each message's topic and index before it is decoded,
/// so a caller can tell where a crash inside the ROS library happened.
Streams read_streams(const std::string& path, const StreamRequest& request,
                     const std::function<void(const std::string&, std::size_t)>& on_message = {});

}  // namespace cogmap::hw::bag
