// The p2os SonarArray decoder on hand-made bytes and definitions.
#include <gtest/gtest.h>

#include <cstring>

#include "ros_bag_reader.h"
#include "sonar_array_decoder.h"

namespace cogmap::hw::bag {
namespace {

void put_u32(std::vector<std::uint8_t>& b, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) b.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
}

void put_f64(std::vector<std::uint8_t>& b, double d) {
  std::uint64_t v;
  std::memcpy(&v, &d, sizeof v);
  for (int i = 0; i < 8; ++i) b.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
}

std::vector<std::uint8_t> message(std::int32_t count, const std::vector<double>& ranges) {
  std::vector<std::uint8_t> b;
  put_u32(b, 7);          // seq
  put_u32(b, 12);         // stamp.sec
  put_u32(b, 500000000);  // stamp.nsec
  put_u32(b, 5);          // frame_id length
  for (char c : std::string("sonar")) b.push_back(static_cast<std::uint8_t>(c));
  put_u32(b, static_cast<std::uint32_t>(count));
  put_u32(b, static_cast<std::uint32_t>(ranges.size()));
  for (double r : ranges) put_f64(b, r);
  return b;
}

TEST(SonarArrayDecoder, DecodesP2osLayout) {
  const auto b = message(3, {0.5, 1.25, 5.0});
  const SonarArrayData d = decode_sonar_array(b.data(), b.size());
  EXPECT_DOUBLE_EQ(d.stamp_s, 12.5);
  EXPECT_EQ(d.ranges_m, (std::vector<double>{0.5, 1.25, 5.0}));
}

TEST(SonarArrayDecoder, RefusesShortLongAndInconsistentMessages) {
  auto b = message(3, {0.5, 1.25, 5.0});
  EXPECT_THROW(decode_sonar_array(b.data(), b.size() - 1), BagReadError);
  EXPECT_THROW(decode_sonar_array(b.data(), 10), BagReadError);
  b.push_back(0);
  EXPECT_THROW(decode_sonar_array(b.data(), b.size()), BagReadError);
  const auto c = message(4, {0.5, 1.25, 5.0});
  EXPECT_THROW(decode_sonar_array(c.data(), c.size()), BagReadError);
  // A length that would overflow 32-bit arithmetic is still caught.
  auto d = message(0, {});
  d[d.size() - 4] = d[d.size() - 3] = d[d.size() - 2] = d[d.size() - 1] = 0xff;
  EXPECT_THROW(decode_sonar_array(d.data(), d.size()), BagReadError);
}

TEST(SonarArrayDecoder, ChecksTheDefinitionText) {
  const std::string good =
      "std_msgs/Header    header\nint32     ranges_count\nfloat64[] ranges\n\n"
      "================================================================================\n"
      "MSG: std_msgs/Header\nuint32 seq\ntime stamp\nstring frame_id\n";
  EXPECT_NO_THROW(check_sonar_array_definition(kSonarArrayMd5, good));
  EXPECT_NO_THROW(check_sonar_array_definition(kSonarArrayMd5,
                                               "# comment\nHeader header\n"
                                               "int32 ranges_count\n"
                                               "float64[] ranges # metres\n"));
  EXPECT_NO_THROW(check_sonar_array_definition(kSonarArrayMd5, ""));
  EXPECT_THROW(check_sonar_array_definition("ffffffffffffffffffffffffffffffff", good),
               BagReadError);
  EXPECT_THROW(check_sonar_array_definition(
                   kSonarArrayMd5, "Header header\nint32 ranges_count\nfloat32[] ranges\n"),
               BagReadError);
}

}  // namespace
}  // namespace cogmap::hw::bag
