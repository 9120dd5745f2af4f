// Reading a ROS 1 bag through Debian's rosbag_storage and the generated message classes.
// C++17 (see ros_bag_reader.h). Every failure becomes a BagReadError naming topic and index.
#include "ros_bag_reader.h"

#include <console_bridge/console.h>
#include <nav_msgs/Odometry.h>
#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <sensor_msgs/PointCloud.h>
#include <sensor_msgs/PointCloud2.h>
#include <sensor_msgs/PointField.h>
#include <tf2_msgs/TFMessage.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <memory>
#include <new>

#include "bag_index_check.h"
#include "message_layout.h"
#include "sonar_array_decoder.h"

namespace cogmap::hw::bag {
namespace {

void open_bag(rosbag::Bag& bag, const std::string& path) {
  // rosbag also prints what it throws; the exception alone reaches the user, with context.
  console_bridge::setLogLevel(console_bridge::CONSOLE_BRIDGE_LOG_NONE);
  try {
    bag.open(path, rosbag::bagmode::Read);
  } catch (const rosbag::BagUnindexedException&) {
    // What `rosbag record` leaves when it is killed (FILE.bag.active): the chunks are there,
    // the index it writes on closing is not.
    throw BagReadError(
        "not a readable ROS 1 bag: it has no index (its recording was not closed: rosbag record "
        "killed, or a .bag.active file); rebuild the index with ROS's `rosbag reindex` and "
        "replay the result");
  } catch (const std::bad_alloc&) {
    throw;  // the child process names it (bag_isolation.cc)
  } catch (const std::exception& e) {
    throw BagReadError(std::string("not a readable ROS 1 bag: ") + e.what());
  }
}

std::string at(const std::string& topic, std::size_t index) {
  return "topic " + topic + ", message " + std::to_string(index) + ": ";
}

double yaw_of(const geometry_msgs::Quaternion& q) {
  const double n2 = q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w;
  // A zero or far-from-unit quaternion is an unset field, not a heading.
  if (!(n2 > 0.81 && n2 < 1.21)) {
    throw BagReadError("orientation quaternion has norm " + std::to_string(std::sqrt(n2)) +
                       " (expected 1)");
  }
  // w² + x² - y² - z² rather than 1 - 2(y² + z²): equal for a unit quaternion, and unlike it
  // the same yaw for any length (a quaternion 5 % long turned 90° into 95°).
  return std::atan2(2.0 * (q.w * q.z + q.x * q.y), q.w * q.w + q.x * q.x - q.y * q.y - q.z * q.z);
}

void check_finite(double v, const char* what) {
  if (!std::isfinite(v)) throw BagReadError(std::string(what) + " is not a finite number");
}

// "/robot1/odom" -> "odom": tf frame names carry an optional leading slash and tf prefix.
std::string last_segment(const std::string& frame) {
  const auto slash = frame.find_last_of('/');
  return slash == std::string::npos ? frame : frame.substr(slash + 1);
}

double read_float(const std::uint8_t* p, std::uint8_t datatype) {
  if (datatype == sensor_msgs::PointField::FLOAT32) {
    float f;
    std::memcpy(&f, p, sizeof f);
    return f;
  }
  double d;
  std::memcpy(&d, p, sizeof d);
  return d;
}

// A message of more values than the robot has sonars is refused as soon as it is read, not
// after the whole topic: a camera's or a lidar's cloud chosen as the sonar topic is hundreds of
// thousands of points a message, and a few minutes of it filled gigabytes before the count was
// checked.
void check_transducers(std::uint64_t n, std::size_t max_transducers) {
  if (max_transducers > 0 && n > max_transducers) {
    throw BagReadError(std::to_string(n) + " transducers, but the robot model has " +
                       std::to_string(max_transducers) + " sonars: pass the right --robot" +
                       (n > 64 ? " (or --sonar-topic: a cloud this large is no sonar ring)" : ""));
  }
}

SonarMessage from_cloud2(const sensor_msgs::PointCloud2& c, std::size_t max_transducers) {
  const sensor_msgs::PointField* fx = nullptr;
  const sensor_msgs::PointField* fy = nullptr;
  for (const auto& f : c.fields) {
    if (f.name == "x") fx = &f;
    if (f.name == "y") fy = &f;
  }
  if (!fx || !fy) throw BagReadError("PointCloud2 without x and y fields");
  for (const auto* f : {fx, fy}) {
    if (f->datatype != sensor_msgs::PointField::FLOAT32 &&
        f->datatype != sensor_msgs::PointField::FLOAT64) {
      throw BagReadError("PointCloud2 field " + f->name + " has datatype " +
                         std::to_string(f->datatype) + ", expected FLOAT32 (7) or FLOAT64 (8)");
    }
    const std::size_t width = f->datatype == sensor_msgs::PointField::FLOAT32 ? 4 : 8;
    if (f->offset + width > c.point_step) {
      throw BagReadError("PointCloud2 field " + f->name + " lies outside point_step " +
                         std::to_string(c.point_step));
    }
  }
  if (c.is_bigendian) throw BagReadError("big-endian PointCloud2 is not supported");
  const std::uint64_t n = static_cast<std::uint64_t>(c.width) * c.height;
  if (c.height > 1 && c.row_step != static_cast<std::uint64_t>(c.width) * c.point_step) {
    throw BagReadError("PointCloud2 rows with padding are not supported");
  }
  // Divided, not multiplied: width x height x point_step can pass 2^64 (point_step >= 4 here).
  if (n > c.data.size() / c.point_step) {
    throw BagReadError("PointCloud2 of " + std::to_string(n) + " points of " +
                       std::to_string(c.point_step) + " bytes has " +
                       std::to_string(c.data.size()) + " bytes of data");
  }
  check_transducers(n, max_transducers);
  SonarMessage out;
  out.stamp_s = c.header.stamp.toSec();
  for (std::uint64_t i = 0; i < n; ++i) {
    const std::uint8_t* p = c.data.data() + i * c.point_step;
    out.x_m.push_back(read_float(p + fx->offset, fx->datatype));
    out.y_m.push_back(read_float(p + fy->offset, fy->datatype));
  }
  return out;
}

// What rosbag's MessageInstance::instantiate does (the same MD5 test, the same bytes, the same
// deserialization), with the message's lengths checked before roscpp_serialization resizes
// its vectors to them (message_layout.h).
template <typename T>
boost::shared_ptr<T> instantiate(const rosbag::MessageInstance& m, MessageLayout layout) {
  if (!m.isType<T>()) {
    throw BagReadError("is " + m.getDataType() + " (MD5 " + m.getMD5Sum() + "), expected " +
                       ros::message_traits::DataType<T>::value() + " (MD5 " +
                       ros::message_traits::MD5Sum<T>::value() + ")");
  }
  // The record's data: the index check found it within its chunk (at most 256 MiB).
  std::vector<std::uint8_t> bytes(m.size());
  const auto size = static_cast<std::uint32_t>(bytes.size());
  ros::serialization::OStream out(bytes.data(), size);
  m.write(out);
  check_message_layout(layout, bytes.data(), bytes.size());
  auto msg = boost::make_shared<T>();
  ros::serialization::IStream in(bytes.data(), size);
  ros::serialization::deserialize(in, *msg);
  return msg;
}

SonarMessage read_sonar(const rosbag::MessageInstance& m, const StreamRequest& request) {
  switch (request.sonar) {
    case SonarEncoding::kPointCloud: {
      const auto cloud = instantiate<sensor_msgs::PointCloud>(m, MessageLayout::kPointCloud);
      check_transducers(cloud->points.size(), request.max_transducers);
      SonarMessage out;
      out.stamp_s = cloud->header.stamp.toSec();
      for (const auto& p : cloud->points) {
        out.x_m.push_back(p.x);
        out.y_m.push_back(p.y);
      }
      return out;
    }
    case SonarEncoding::kPointCloud2:
      return from_cloud2(*instantiate<sensor_msgs::PointCloud2>(m, MessageLayout::kPointCloud2),
                         request.max_transducers);
    case SonarEncoding::kSonarArray: {
      if (m.getDataType() != kSonarArrayType) {
        throw BagReadError("is " + m.getDataType() + ", expected " + kSonarArrayType);
      }
      check_sonar_array_definition(m.getMD5Sum(), m.getMessageDefinition());
      std::vector<std::uint8_t> bytes(m.size());
      ros::serialization::OStream stream(bytes.data(), static_cast<std::uint32_t>(bytes.size()));
      m.write(stream);
      SonarArrayData data = decode_sonar_array(bytes.data(), bytes.size());
      check_transducers(data.ranges_m.size(), request.max_transducers);
      SonarMessage out;
      out.stamp_s = data.stamp_s;
      out.ranges_m = std::move(data.ranges_m);
      return out;
    }
  }
  throw BagReadError("unknown sonar encoding");
}

PoseMessage pose_of(double stamp_s, double x, double y, const geometry_msgs::Quaternion& q) {
  check_finite(x, "position x");
  check_finite(y, "position y");
  PoseMessage p;
  p.stamp_s = stamp_s;
  p.x_m = x;
  p.y_m = y;
  p.yaw_rad = yaw_of(q);
  return p;
}

// True when the message held the odom -> base_link pair.
bool read_tf(const rosbag::MessageInstance& m, std::size_t index, Streams& out) {
  const auto tf = instantiate<tf2_msgs::TFMessage>(m, MessageLayout::kTfMessage);
  ++out.tf_messages;
  bool found = false;
  for (const auto& t : tf->transforms) {
    const std::string parent = last_segment(t.header.frame_id);
    const std::string child = last_segment(t.child_frame_id);
    if (parent != "odom" || (child != "base_link" && child != "base_footprint")) continue;
    // One robot's pair only: the first one seen fixes which frames count.
    if (out.tf_parent.empty()) {
      out.tf_parent = t.header.frame_id;
      out.tf_child = t.child_frame_id;
    } else if (t.header.frame_id != out.tf_parent || t.child_frame_id != out.tf_child) {
      continue;
    }
    const auto& tr = t.transform.translation;
    PoseMessage p = pose_of(t.header.stamp.toSec(), tr.x, tr.y, t.transform.rotation);
    p.index = index;
    out.poses.push_back(p);
    found = true;
  }
  return found;
}

// The odometry must be one robot's: two publishers taking turns on it (a driver and an EKF
// that both broadcast odom -> base_link, a classic misconfiguration) gave a pose stream that
// alternates between two estimates, interpolated into frames without a word. One publisher
// after another (a driver restarted mid-recording) is one stream.
class OnePublisher {
 public:
  void check(const std::string& callerid) {
    if (callerid.empty() || callerid == current_) return;  // empty: a bag without headers
    for (const std::string& p : earlier_) {
      if (p == callerid) {
        throw BagReadError("the odometry comes from two publishers taking turns (" + current_ +
                           " and " + callerid +
                           "): two estimates of the robot's pose in one stream; record (or "
                           "choose with --odom-topic) a topic that only one of them publishes");
      }
    }
    if (!current_.empty()) earlier_.push_back(current_);
    current_ = callerid;
  }

 private:
  std::string current_;
  std::vector<std::string> earlier_;
};

}  // namespace

std::vector<TopicInfo> list_topics(const std::string& path) {
  // rosbag trusts the index it is about to read: check it against the records first.
  check_bag_index(path);
  rosbag::Bag bag;
  open_bag(bag, path);
  try {
    rosbag::View view(bag);
    std::map<std::string, TopicInfo> topics;
    for (const rosbag::ConnectionInfo* c : view.getConnections()) {
      TopicInfo& t = topics[c->topic];
      t.topic = c->topic;
      t.datatype = c->datatype;
      t.md5sum = c->md5sum;
    }
    for (auto& [name, info] : topics) {
      info.messages = rosbag::View(bag, rosbag::TopicQuery(name)).size();
    }
    std::vector<TopicInfo> out;
    for (auto& [name, info] : topics) out.push_back(std::move(info));
    return out;
  } catch (const BagReadError&) {
    throw;
  } catch (const std::bad_alloc&) {
    throw;
  } catch (const std::exception& e) {
    throw BagReadError(std::string("cannot read the bag's index: ") + e.what());
  }
}

Streams read_streams(const std::string& path, const StreamRequest& request,
                     const std::function<void(const std::string&, std::size_t)>& on_message) {
  rosbag::Bag bag;
  open_bag(bag, path);
  Streams out;
  std::size_t sonar_index = 0, odometry_index = 0;
  std::string topic = request.sonar_topic;
  std::size_t index = 0;
  OnePublisher odometry_publisher;
  try {
    rosbag::View view(bag, rosbag::TopicQuery({request.sonar_topic, request.odometry_topic}));
    for (auto it = view.begin(); it != view.end(); ++it) {
      const rosbag::MessageInstance& m = *it;
      topic = m.getTopic();
      index = topic == request.sonar_topic ? sonar_index : odometry_index;
      if (on_message) on_message(topic, index);
      if (topic == request.sonar_topic) {
        ++sonar_index;
        SonarMessage s = read_sonar(m, request);
        s.index = index;
        out.sonar.push_back(std::move(s));
      } else {
        ++odometry_index;
        if (request.odometry == OdometryEncoding::kTf) {
          if (read_tf(m, index, out)) odometry_publisher.check(m.getCallerId());
        } else {
          odometry_publisher.check(m.getCallerId());
          const auto odom = instantiate<nav_msgs::Odometry>(m, MessageLayout::kOdometry);
          const auto& pose = odom->pose.pose;
          PoseMessage p = pose_of(odom->header.stamp.toSec(), pose.position.x, pose.position.y,
                                  pose.orientation);
          p.index = index;
          out.poses.push_back(p);
        }
      }
    }
  } catch (const std::bad_alloc&) {
    throw;  // the child process names it, with the message it was reading (bag_isolation.cc)
  } catch (const std::exception& e) {
    // Decoding errors and chunk read errors alike: the last message reached names the place.
    throw BagReadError(at(topic, index) + e.what());
  }
  return out;
}

}  // namespace cogmap::hw::bag
