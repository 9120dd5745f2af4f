#pragma once
// p2os_msgs/SonarArray without its package (Debian has none): the bag carries the message
// definition in every connection header, so the layout is checked against that text and the
// MD5 ROS computes from it, then the serialized bytes are decoded by hand. C++17, no ROS types.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace cogmap::hw::bag {

inline constexpr const char* kSonarArrayType = "p2os_msgs/SonarArray";
/// ROS's MD5 of the definition `Header header / int32 ranges_count / float64[] ranges`:
/// md5("2176decaecbce78abc3b96ef049fabed header\nint32 ranges_count\nfloat64[] ranges"), where
/// the first word is std_msgs/Header's own MD5 (genmsg's rule for nested types).
inline constexpr const char* kSonarArrayMd5 = "2984921c09aef26ad253c7629937a5bb";

/// Throws BagReadError unless `md5` is kSonarArrayMd5 and `definition` (when not empty) declares
/// exactly the fields header (std_msgs/Header), int32 ranges_count, float64[] ranges.
void check_sonar_array_definition(const std::string& md5, const std::string& definition);

/// A decoded message.
struct SonarArrayData {
  double stamp_s = 0.0;          ///< header.stamp
  std::vector<double> ranges_m;  ///< in transducer order
};

/// Decodes the serialized bytes (little-endian ROS 1 serialization). Throws BagReadError for a
/// message shorter or longer than its layout, or whose ranges_count differs from the array's.
SonarArrayData decode_sonar_array(const std::uint8_t* data, std::size_t size);

}  // namespace cogmap::hw::bag
