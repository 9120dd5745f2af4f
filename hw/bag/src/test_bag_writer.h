#pragma once
// Test support: writes small bags with the rosbag API, in the shapes RosAria and p2os record
// them. C++17 behind plain types, like the reader (ros_bag_reader.h says why).

#include <memory>
#include <string>
#include <vector>

namespace cogmap::hw::bag::testing {

/// A point in the robot frame, metres.
struct Xy {
  double x_m = 0.0, y_m = 0.0;
};

/// How a p2os_msgs/SonarArray is written: as p2os does, or broken on purpose.
enum class SonarArrayVariant {
  kGood,
  kWrongDefinition,  ///< same type name, another layout (and so another MD5)
  kTruncated,        ///< ranges_count and the array length, but no range values
};

/// Chunk compression, as `rosbag record --bz2 / --lz4` writes it.
enum class Compression { kNone, kBz2, kLz4 };

/// The publisher a topic's next messages come from, as `rosbag record` stores it in the
/// connection header. rosbag keeps one connection per topic and header, so another callerid (a
/// driver restarted mid-recording, a second publisher) is a second connection on the topic.
struct Publisher {
  std::string callerid = "/RosAria";
  bool latching = false;
};

/// Writes one bag; closed by close() or the destructor.
class TestBagWriter {
 public:
  /// `chunk_threshold`: bytes after which rosbag closes a chunk (0: rosbag's 768 KiB).
  explicit TestBagWriter(const std::string& path, Compression compression = Compression::kNone,
                         unsigned chunk_threshold = 0);
  ~TestBagWriter();

  /// nav_msgs/Odometry (frame odom, child base_link). Every message is recorded at its stamp
  /// unless `record_s` (the bag's receive time) is given.
  void odometry(const std::string& topic, double stamp_s, double x_m, double y_m, double yaw_rad,
                double record_s = -1.0);
  /// nav_msgs/Odometry with the orientation quaternion as given (not necessarily unit length).
  void odometry_quaternion(const std::string& topic, double stamp_s, double x_m, double y_m,
                           double qx, double qy, double qz, double qw);
  /// From now on, messages on `topic` are written with `publisher`'s connection header.
  void set_publisher(const std::string& topic, const Publisher& publisher);
  /// tf2_msgs/TFMessage with one transform parent -> child.
  void tf(const std::string& topic, double stamp_s, double x_m, double y_m, double yaw_rad,
          const std::string& parent = "odom", const std::string& child = "base_link");
  /// sensor_msgs/PointCloud, one float32 point per transducer (RosAria /RosAria/sonar).
  void point_cloud(const std::string& topic, double stamp_s, const std::vector<Xy>& points,
                   double record_s = -1.0);
  /// sensor_msgs/PointCloud2 with float32 x, y, z as RosAria's conversion writes it.
  void point_cloud2(const std::string& topic, double stamp_s, const std::vector<Xy>& points);
  /// p2os_msgs/SonarArray (ranges in metres, transducer order).
  void sonar_array(const std::string& topic, double stamp_s, const std::vector<double>& ranges_m,
                   SonarArrayVariant variant = SonarArrayVariant::kGood);
  /// A sensor_msgs/PointCloud whose bytes end after the header: a message that cannot decode.
  void truncated_point_cloud(const std::string& topic, double stamp_s);
  /// Finishes the file (also done by the destructor).
  void close();

 private:
  void write_odometry(const std::string& topic, double stamp_s, double x_m, double y_m, double qx,
                      double qy, double qz, double qw, double record_s);
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace cogmap::hw::bag::testing
