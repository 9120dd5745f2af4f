// Bags for the tests, written through rosbag::Bag like `rosbag record` does.
#include "test_bag_writer.h"

#include <nav_msgs/Odometry.h>
#include <rosbag/bag.h>
#include <sensor_msgs/PointCloud.h>
#include <sensor_msgs/PointCloud2.h>
#include <std_msgs/Header.h>
#include <tf2_msgs/TFMessage.h>

#include <cmath>
#include <cstring>
#include <map>

namespace cogmap::hw::bag::testing {
namespace {

// p2os_msgs/SonarArray as p2os generates it, and two broken look-alikes.
template <SonarArrayVariant V>
struct FakeSonarArray {
  std_msgs::Header header;
  std::int32_t ranges_count = 0;
  std::vector<double> ranges;
};

// A sensor_msgs/PointCloud that serializes only its header.
struct ShortPointCloud {
  std_msgs::Header header;
};

constexpr const char* kHeaderDef =
    "================================================================================\n"
    "MSG: std_msgs/Header\n"
    "uint32 seq\ntime stamp\nstring frame_id\n";

ros::Time stamp(double s) { return ros::Time(s); }

geometry_msgs::Quaternion yaw_quaternion(double yaw) {
  geometry_msgs::Quaternion q;
  q.z = std::sin(yaw / 2.0);
  q.w = std::cos(yaw / 2.0);
  return q;
}

}  // namespace
}  // namespace cogmap::hw::bag::testing

namespace ros::message_traits {
using cogmap::hw::bag::testing::FakeSonarArray;
using cogmap::hw::bag::testing::ShortPointCloud;
using cogmap::hw::bag::testing::SonarArrayVariant;

template <SonarArrayVariant V>
struct MD5Sum<FakeSonarArray<V>> {
  static const char* value() {
    return V == SonarArrayVariant::kWrongDefinition ? "0123456789abcdef0123456789abcdef"
                                                    : "2984921c09aef26ad253c7629937a5bb";
  }
  static const char* value(const FakeSonarArray<V>&) { return value(); }
};
template <SonarArrayVariant V>
struct DataType<FakeSonarArray<V>> {
  static const char* value() { return "p2os_msgs/SonarArray"; }
  static const char* value(const FakeSonarArray<V>&) { return value(); }
};
template <SonarArrayVariant V>
struct Definition<FakeSonarArray<V>> {
  static const char* value() {
    static const std::string def =
        std::string(
            V == SonarArrayVariant::kWrongDefinition
                ? "std_msgs/Header header\nfloat32[] ranges\n\n"
                : "std_msgs/Header    header\nint32     ranges_count\nfloat64[] ranges\n\n") +
        cogmap::hw::bag::testing::kHeaderDef;
    return def.c_str();
  }
  static const char* value(const FakeSonarArray<V>&) { return value(); }
};
template <>
struct MD5Sum<ShortPointCloud> : MD5Sum<sensor_msgs::PointCloud> {
  static const char* value(const ShortPointCloud&) {
    return MD5Sum<sensor_msgs::PointCloud>::value();
  }
};
template <>
struct DataType<ShortPointCloud> : DataType<sensor_msgs::PointCloud> {
  static const char* value(const ShortPointCloud&) {
    return DataType<sensor_msgs::PointCloud>::value();
  }
};
template <>
struct Definition<ShortPointCloud> : Definition<sensor_msgs::PointCloud> {
  static const char* value(const ShortPointCloud&) {
    return Definition<sensor_msgs::PointCloud>::value();
  }
};
}  // namespace ros::message_traits

namespace ros::serialization {
using cogmap::hw::bag::testing::FakeSonarArray;
using cogmap::hw::bag::testing::ShortPointCloud;
using cogmap::hw::bag::testing::SonarArrayVariant;

template <SonarArrayVariant V>
struct Serializer<FakeSonarArray<V>> {
  template <typename Stream, typename T>
  inline static void allInOne(Stream& stream, T m) {
    stream.next(m.header);
    if (V != SonarArrayVariant::kWrongDefinition) stream.next(m.ranges_count);
    if (V == SonarArrayVariant::kTruncated) {
      stream.next(static_cast<std::uint32_t>(m.ranges.size()));
    } else if (V == SonarArrayVariant::kWrongDefinition) {
      std::vector<float> f(m.ranges.begin(), m.ranges.end());
      stream.next(f);
    } else {
      stream.next(m.ranges);
    }
  }
  ROS_DECLARE_ALLINONE_SERIALIZER
};
template <>
struct Serializer<ShortPointCloud> {
  template <typename Stream, typename T>
  inline static void allInOne(Stream& stream, T m) {
    stream.next(m.header);
  }
  ROS_DECLARE_ALLINONE_SERIALIZER
};
}  // namespace ros::serialization

namespace cogmap::hw::bag::testing {

struct TestBagWriter::Impl {
  rosbag::Bag bag;
  std::map<std::string, Publisher> publishers;

  // Like rosbag record: with the publisher's connection header when one is set for the topic.
  template <typename T>
  void write(const std::string& topic, const ros::Time& time, const T& msg) {
    const auto p = publishers.find(topic);
    if (p == publishers.end()) {
      bag.write(topic, time, msg);
      return;
    }
    auto header = boost::make_shared<ros::M_string>();
    (*header)["callerid"] = p->second.callerid;
    (*header)["latching"] = p->second.latching ? "1" : "0";
    (*header)["topic"] = topic;
    (*header)["type"] = ros::message_traits::datatype(msg);
    (*header)["md5sum"] = ros::message_traits::md5sum(msg);
    (*header)["message_definition"] = ros::message_traits::definition(msg);
    bag.write(topic, time, msg, header);
  }
};

TestBagWriter::TestBagWriter(const std::string& path, Compression compression,
                             unsigned chunk_threshold)
    : impl_(std::make_unique<Impl>()) {
  impl_->bag.open(path, rosbag::bagmode::Write);
  if (chunk_threshold > 0) impl_->bag.setChunkThreshold(chunk_threshold);
  if (compression == Compression::kBz2) impl_->bag.setCompression(rosbag::compression::BZ2);
  if (compression == Compression::kLz4) impl_->bag.setCompression(rosbag::compression::LZ4);
}

TestBagWriter::~TestBagWriter() { close(); }

void TestBagWriter::close() {
  if (impl_) impl_->bag.close();
}

void TestBagWriter::odometry(const std::string& topic, double stamp_s, double x_m, double y_m,
                             double yaw_rad, double record_s) {
  const geometry_msgs::Quaternion q = yaw_quaternion(yaw_rad);
  write_odometry(topic, stamp_s, x_m, y_m, q.x, q.y, q.z, q.w, record_s);
}

void TestBagWriter::odometry_quaternion(const std::string& topic, double stamp_s, double x_m,
                                        double y_m, double qx, double qy, double qz, double qw) {
  write_odometry(topic, stamp_s, x_m, y_m, qx, qy, qz, qw, -1.0);
}

void TestBagWriter::write_odometry(const std::string& topic, double stamp_s, double x_m, double y_m,
                                   double qx, double qy, double qz, double qw, double record_s) {
  nav_msgs::Odometry o;
  o.header.stamp = stamp(stamp_s);
  o.header.frame_id = "odom";
  o.child_frame_id = "base_link";
  o.pose.pose.position.x = x_m;
  o.pose.pose.position.y = y_m;
  o.pose.pose.orientation.x = qx;
  o.pose.pose.orientation.y = qy;
  o.pose.pose.orientation.z = qz;
  o.pose.pose.orientation.w = qw;
  impl_->write(topic, stamp(record_s < 0 ? stamp_s : record_s), o);
}

void TestBagWriter::set_publisher(const std::string& topic, const Publisher& publisher) {
  impl_->publishers[topic] = publisher;
}

void TestBagWriter::tf(const std::string& topic, double stamp_s, double x_m, double y_m,
                       double yaw_rad, const std::string& parent, const std::string& child) {
  tf2_msgs::TFMessage m;
  geometry_msgs::TransformStamped t;
  t.header.stamp = stamp(stamp_s);
  t.header.frame_id = parent;
  t.child_frame_id = child;
  t.transform.translation.x = x_m;
  t.transform.translation.y = y_m;
  t.transform.rotation = yaw_quaternion(yaw_rad);
  m.transforms.push_back(t);
  impl_->write(topic, stamp(stamp_s), m);
}

void TestBagWriter::point_cloud(const std::string& topic, double stamp_s,
                                const std::vector<Xy>& points, double record_s) {
  sensor_msgs::PointCloud c;
  c.header.stamp = stamp(stamp_s);
  c.header.frame_id = "sonar_frame";
  for (const Xy& p : points) {
    geometry_msgs::Point32 q;
    q.x = static_cast<float>(p.x_m);
    q.y = static_cast<float>(p.y_m);
    c.points.push_back(q);
  }
  impl_->write(topic, stamp(record_s < 0 ? stamp_s : record_s), c);
}

void TestBagWriter::point_cloud2(const std::string& topic, double stamp_s,
                                 const std::vector<Xy>& points) {
  sensor_msgs::PointCloud2 c;
  c.header.stamp = stamp(stamp_s);
  c.header.frame_id = "sonar_frame";
  c.height = 1;
  c.width = static_cast<std::uint32_t>(points.size());
  const char* names[] = {"x", "y", "z"};
  for (std::uint32_t i = 0; i < 3; ++i) {
    sensor_msgs::PointField f;
    f.name = names[i];
    f.offset = 4 * i;
    f.datatype = sensor_msgs::PointField::FLOAT32;
    f.count = 1;
    c.fields.push_back(f);
  }
  c.point_step = 12;
  c.row_step = c.point_step * c.width;
  c.is_dense = false;
  c.data.resize(c.row_step);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const float xyz[3] = {static_cast<float>(points[i].x_m), static_cast<float>(points[i].y_m),
                          0.0f};
    std::memcpy(c.data.data() + i * 12, xyz, sizeof xyz);
  }
  impl_->write(topic, stamp(stamp_s), c);
}

void TestBagWriter::sonar_array(const std::string& topic, double stamp_s,
                                const std::vector<double>& ranges_m, SonarArrayVariant variant) {
  auto fill = [&](auto& m) {
    m.header.stamp = stamp(stamp_s);
    m.header.frame_id = "sonar";
    m.ranges_count = static_cast<std::int32_t>(ranges_m.size());
    m.ranges = ranges_m;
    impl_->write(topic, stamp(stamp_s), m);
  };
  switch (variant) {
    case SonarArrayVariant::kGood: {
      FakeSonarArray<SonarArrayVariant::kGood> m;
      fill(m);
      break;
    }
    case SonarArrayVariant::kWrongDefinition: {
      FakeSonarArray<SonarArrayVariant::kWrongDefinition> m;
      fill(m);
      break;
    }
    case SonarArrayVariant::kTruncated: {
      FakeSonarArray<SonarArrayVariant::kTruncated> m;
      fill(m);
      break;
    }
  }
}

void TestBagWriter::truncated_point_cloud(const std::string& topic, double stamp_s) {
  ShortPointCloud m;
  m.header.stamp = stamp(stamp_s);
  impl_->write(topic, stamp(stamp_s), m);
}

}  // namespace cogmap::hw::bag::testing
