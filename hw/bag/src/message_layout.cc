// Walking a serialized message's lengths before roscpp_serialization allocates what they say.
#include "message_layout.h"

#include <string>

#include "ros_bag_reader.h"

namespace cogmap::hw::bag {
namespace {

// Sizes of the fixed parts (ROS 1 serialization packs fields without padding).
constexpr std::size_t kSeqAndStamp = 4 + 8;  // std_msgs/Header: uint32 seq, time stamp
constexpr std::size_t kLength = 4;           // every array's and string's length
constexpr std::size_t kHeaderMin = kSeqAndStamp + kLength;  // an empty frame_id
constexpr std::size_t kPoint32 = 3 * 4;              // geometry_msgs/Point32: float32 x, y, z
constexpr std::size_t kPointFieldFixed = 4 + 1 + 4;  // uint32 offset, uint8 datatype, uint32 count
constexpr std::size_t kPoseWithCovariance = (3 + 4 + 36) * 8;  // Point, Quaternion, float64[36]
constexpr std::size_t kTwistWithCovariance = (3 + 3 + 36) * 8;
constexpr std::size_t kTransform = (3 + 4) * 8;  // Vector3, Quaternion

std::string name(const std::string& array, std::uint32_t i, const char* field) {
  return array + "[" + std::to_string(i) + "]." + field;
}

class Walk {
 public:
  Walk(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}

  // A field of `n` bytes that holds no length.
  void fixed(std::size_t n, const std::string& field) {
    if (n > left()) damaged("its " + field + " needs " + std::to_string(n) + " bytes");
    pos_ += n;
  }
  void header(const std::string& field) {
    fixed(kSeqAndStamp, field + ".seq and .stamp");
    string(field + ".frame_id");
  }
  void string(const std::string& field) {
    const std::uint32_t n = length(field + " string's length");
    if (n > left()) {
      damaged("its " + field + " string claims " + std::to_string(n) + " bytes");
    }
    pos_ += n;
  }
  // An array of elements of `element_bytes` each.
  void array(const std::string& field, std::size_t element_bytes) {
    pos_ += static_cast<std::size_t>(count(field, element_bytes, false)) * element_bytes;
  }
  // An array of elements of at least `min_bytes` each, which the caller walks: their number.
  std::uint32_t elements(const std::string& field, std::size_t min_bytes) {
    return count(field, min_bytes, true);
  }

 private:
  std::size_t left() const { return size_ - pos_; }

  [[noreturn]] void damaged(const std::string& what) const {
    throw BagReadError(what + " but the message holds only " + std::to_string(left()) +
                       " more bytes: the message is damaged");
  }

  std::uint32_t length(const std::string& field) {
    if (left() < kLength) damaged("its " + field + " needs " + std::to_string(kLength) + " bytes");
    std::uint32_t v = 0;
    for (std::size_t i = kLength; i-- > 0;) v = (v << 8) | data_[pos_ + i];
    pos_ += kLength;
    return v;
  }

  std::uint32_t count(const std::string& field, std::size_t element_bytes, bool at_least) {
    const std::uint32_t n = length(field + " array's length");
    const std::uint64_t bytes = std::uint64_t{n} * element_bytes;
    if (bytes > left()) {
      damaged("its " + field + " array claims " + std::to_string(n) + " elements (" +
              (at_least ? "at least " : "") + std::to_string(bytes) + " bytes)");
    }
    return n;
  }

  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
};

void point_cloud(Walk& w) {
  w.header("header");
  w.array("points", kPoint32);
  // sensor_msgs/ChannelFloat32: string name, float32[] values.
  const std::uint32_t channels = w.elements("channels", 2 * kLength);
  for (std::uint32_t i = 0; i < channels; ++i) {
    w.string(name("channels", i, "name"));
    w.array(name("channels", i, "values"), 4);
  }
}

void point_cloud2(Walk& w) {
  w.header("header");
  w.fixed(8, "height and width");
  // sensor_msgs/PointField: string name, uint32 offset, uint8 datatype, uint32 count.
  const std::uint32_t fields = w.elements("fields", kLength + kPointFieldFixed);
  for (std::uint32_t i = 0; i < fields; ++i) {
    w.string(name("fields", i, "name"));
    w.fixed(kPointFieldFixed, name("fields", i, "offset, datatype and count"));
  }
  w.fixed(1 + 4 + 4, "is_bigendian, point_step and row_step");
  w.array("data", 1);
  w.fixed(1, "is_dense");
}

void odometry(Walk& w) {
  w.header("header");
  w.string("child_frame_id");
  w.fixed(kPoseWithCovariance, "pose");
  w.fixed(kTwistWithCovariance, "twist");
}

void tf_message(Walk& w) {
  // geometry_msgs/TransformStamped: Header header, string child_frame_id, Transform transform.
  const std::uint32_t n = w.elements("transforms", kHeaderMin + kLength + kTransform);
  for (std::uint32_t i = 0; i < n; ++i) {
    w.header(name("transforms", i, "header"));
    w.string(name("transforms", i, "child_frame_id"));
    w.fixed(kTransform, name("transforms", i, "transform"));
  }
}

}  // namespace

void check_message_layout(MessageLayout layout, const std::uint8_t* data, std::size_t size) {
  Walk w(data, size);
  switch (layout) {
    case MessageLayout::kPointCloud:
      return point_cloud(w);
    case MessageLayout::kPointCloud2:
      return point_cloud2(w);
    case MessageLayout::kOdometry:
      return odometry(w);
    case MessageLayout::kTfMessage:
      return tf_message(w);
  }
}

}  // namespace cogmap::hw::bag
