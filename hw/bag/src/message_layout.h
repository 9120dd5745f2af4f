#pragma once
// The serialized layouts of the messages the reader decodes with roscpp_serialization's
// generated classes (sensor_msgs/PointCloud, PointCloud2, nav_msgs/Odometry, tf2_msgs/
// TFMessage). ROS 1 serialization writes every array and string as a 4-byte little-endian
// length and then its elements, and roscpp_serialization resizes a vector to that length before
// it looks whether the message holds that many elements: a damaged length of 0x7fffffff points
// threw std::bad_alloc, one of 1.5e9 data bytes allocated (and zeroed) 1.5 GB before the message
// was found too short. check_message_layout walks a message's bytes first, every length checked
// against the bytes left, allocating nothing. (p2os_msgs/SonarArray has its own decoder,
// sonar_array_decoder.h, which checks its lengths the same way.) Plain C++17, no ROS headers.

#include <cstddef>
#include <cstdint>

namespace cogmap::hw::bag {

enum class MessageLayout {
  kPointCloud,   ///< Header, geometry_msgs/Point32[] points, ChannelFloat32[] channels
  kPointCloud2,  ///< Header, height, width, PointField[] fields, ..., uint8[] data, is_dense
  kOdometry,     ///< Header, string child_frame_id, PoseWithCovariance, TwistWithCovariance
  kTfMessage,    ///< geometry_msgs/TransformStamped[] transforms (also tf/tfMessage)
};

/// Walks the `size` bytes of one serialized message as `layout`. Throws BagReadError ending
/// "the message is damaged" for an array or string whose length claims more than the bytes that
/// follow it: "its points array claims 2147483647 elements (25769803764 bytes) but the message
/// holds only 8 more bytes" ("at least N bytes" for elements of varying size: channels,
/// fields, transforms, which are each walked in turn), "its child_frame_id string claims ...
/// bytes ...", and for a fixed field cut off, "its pose needs 344 bytes but the message holds
/// only ... more bytes". Nested fields are named by path (`channels[2].values`,
/// `transforms[0].header.frame_id`). Bytes after the last field are accepted, as
/// roscpp_serialization accepts them.
void check_message_layout(MessageLayout layout, const std::uint8_t* data, std::size_t size);

}  // namespace cogmap::hw::bag
