// A damaged array or string length inside a message's own bytes (found by fuzzing 400
// corrupted bags, 7 of which ended in a bare std::bad_alloc): roscpp_serialization resized its
// vectors to the length before it saw that the message was too short. Each is refused, naming
// the field, quickly and without allocating what the length claims; the same bags before the
// damage read as before. The layouts themselves: message_layout_test.cc.
#include <gtest/gtest.h>
#include <sys/resource.h>

#include <chrono>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <functional>

#include "bag_isolation.h"
#include "bag_test_helpers.h"
#include "cogmap/hw/bag_import.h"
#include "corridor_scenario.h"
#include "test_raw_bag.h"

namespace cogmap::hw {
namespace {

namespace fs = std::filesystem;
using bag::testing::expect_contains;
using bag::testing::import_error;
using bag::testing::RawBag;
using bag::testing::RawRecord;
using bag::testing::SonarArrayVariant;
using bag::testing::TestBagWriter;

fs::path length_bag_path(const std::string& name) {
  return bag::testing::temp_bag("cogmap_bag_message_length_test", name);
}

std::uint32_t get_u32(const std::string& data, std::size_t at) {
  std::uint32_t v;
  std::memcpy(&v, data.data() + at, 4);
  return v;
}

void put_u32_at(std::string& data, std::size_t at, std::uint32_t v) {
  ASSERT_LE(at + 4, data.size());
  std::memcpy(data.data() + at, &v, 4);
}

// Where the field after a std_msgs/Header that begins at `at` begins.
std::size_t after_header(const std::string& data, std::size_t at = 0) {
  return at + 12 + 4 + get_u32(data, at + 12);
}

// Edits the bytes of the nth message on `topic` in place (an uncompressed bag: the chunk keeps
// its size, the index stays right).
void damage_message(const fs::path& path, const std::string& topic, std::size_t nth,
                    const std::function<void(std::string&)>& edit) {
  RawBag b(path.string());
  const std::uint32_t conn = b.connection(topic).u32("conn");
  for (const std::size_t c : b.find(bag::testing::kOpChunk)) {
    RawRecord& chunk = b.records[c];
    ASSERT_EQ(chunk.field("compression"), "none");
    std::vector<RawRecord> inner = bag::testing::parse_records(chunk.data);
    for (RawRecord& r : inner) {
      if (r.op() == bag::testing::kOpMessageData && r.u32("conn") == conn && nth-- == 0) {
        const std::size_t size = r.data.size();
        edit(r.data);
        ASSERT_EQ(r.data.size(), size);
        chunk.data = bag::testing::serialize_records(inner);
        b.save(path.string());
        return;
      }
    }
  }
  FAIL() << "no such message on " << topic;
}

// The import's error, which must come quickly and from a reader that never held more than a
// few hundred MB (ru_maxrss of the children this test process waited for: the ROS libraries
// are ~60 MB of it; a vector of 1.5e9 bytes made it 1.5 GB).
std::string quick_error(const fs::path& path, const std::string& robot) {
  const auto start = std::chrono::steady_clock::now();
  const std::string e = import_error(path, bag::testing::with_robot(robot));
  const std::chrono::duration<double> took = std::chrono::steady_clock::now() - start;
  EXPECT_LT(took.count(), 10.0) << e;
  rusage children{};
  ::getrusage(RUSAGE_CHILDREN, &children);
  EXPECT_LT(children.ru_maxrss, 400L * 1024) << "peak RSS of the reader, kB; " << e;
  return e;
}

// Odometry and RosAria-style sonar; `sonar` writes the two sonar messages.
fs::path pose_and_sonar_bag(const std::string& name,
                            const std::function<void(TestBagWriter&, double)>& sonar) {
  const fs::path path = length_bag_path(name);
  {
    TestBagWriter w(path.string());
    for (int k = 0; k < 3; ++k) w.odometry("/RosAria/pose", 10.0 + 0.1 * k, 0.01 * k, 0, 0);
    sonar(w, 10.05);
    sonar(w, 10.15);
  }
  // Intact, it reads.
  EXPECT_EQ(import_ros_bag(path, bag::testing::with_robot("p3dx")).log.frames.size(), 2u);
  return path;
}

fs::path cloud_bag(const std::string& name) {
  return pose_and_sonar_bag(name, [](TestBagWriter& w, double t) {
    w.point_cloud("/RosAria/sonar", t, {{1.0, t}});
  });
}

TEST(BagMessageLength, PointCloudPointsClaimingTwoBillionElements) {
  // Was "topic /RosAria/sonar, message 1: std::bad_alloc" (24 GiB asked for).
  const fs::path path = cloud_bag("points_2g");
  damage_message(path, "/RosAria/sonar", 1,
                 [](std::string& d) { put_u32_at(d, after_header(d), 0x7fffffff); });
  // One point (12 bytes) and the channels' length (4) follow the points' length.
  expect_contains(quick_error(path, "p3dx"),
                  path.string() +
                      ": topic /RosAria/sonar, message 1: its points array claims 2147483647 "
                      "elements (25769803764 bytes) but the message holds only 16 more bytes: "
                      "the message is damaged");
}

TEST(BagMessageLength, PointCloudPointsClaimingAGigabyte) {
  // 1.2 GB: roscpp_serialization allocated it and zeroed it before it found the message short.
  const fs::path path = cloud_bag("points_1g");
  damage_message(path, "/RosAria/sonar", 0,
                 [](std::string& d) { put_u32_at(d, after_header(d), 100'000'000); });
  expect_contains(quick_error(path, "p3dx"),
                  ": topic /RosAria/sonar, message 0: its points array claims 100000000 elements "
                  "(1200000000 bytes) but the message holds only 16 more bytes");
}

TEST(BagMessageLength, PointCloud2DataClaimingOnePointFiveGigabytes) {
  // Was 1.5 GB allocated and zeroed in the reader, then "Buffer Overrun".
  const fs::path path = pose_and_sonar_bag("data_1g5", [](TestBagWriter& w, double t) {
    w.point_cloud2("/RosAria/sonar_pointcloud2", t, {{1.0, t}});
  });
  damage_message(path, "/RosAria/sonar_pointcloud2", 1, [](std::string& d) {
    // height, width, fields (3 of name length, "x", offset, datatype, count), is_bigendian,
    // point_step, row_step, then data's length.
    put_u32_at(d, after_header(d) + 8 + 4 + 3 * 14 + 1 + 4 + 4, 1'500'000'000);
  });
  // The data (one point of 12 bytes) and is_dense follow.
  expect_contains(quick_error(path, "p3dx"),
                  path.string() +
                      ": topic /RosAria/sonar_pointcloud2, message 1: its data array claims "
                      "1500000000 elements (1500000000 bytes) but the message holds only 13 more "
                      "bytes: the message is damaged");
}

TEST(BagMessageLength, PointCloud2FieldsClaimingTwoBillionElements) {
  const fs::path path = pose_and_sonar_bag("fields_2g", [](TestBagWriter& w, double t) {
    w.point_cloud2("/RosAria/sonar_pointcloud2", t, {{1.0, t}});
  });
  damage_message(path, "/RosAria/sonar_pointcloud2", 0,
                 [](std::string& d) { put_u32_at(d, after_header(d) + 8, 0x7fffffff); });
  expect_contains(quick_error(path, "p3dx"),
                  ": topic /RosAria/sonar_pointcloud2, message 0: its fields array claims "
                  "2147483647 elements (at least 27917287411 bytes) but the message holds only ");
}

TEST(BagMessageLength, OdometryChildFrameIdClaimingTwoGigabytes) {
  const fs::path path = cloud_bag("odometry_2g");
  damage_message(path, "/RosAria/pose", 1,
                 [](std::string& d) { put_u32_at(d, after_header(d), 0x7fffffff); });
  // "base_link", the pose (344 bytes) and the twist (336) follow.
  expect_contains(quick_error(path, "p3dx"),
                  path.string() +
                      ": topic /RosAria/pose, message 1: its child_frame_id string claims "
                      "2147483647 bytes but the message holds only 689 more bytes: the message "
                      "is damaged");
}

TEST(BagMessageLength, OdometryHeaderFrameIdClaimingMoreThanItHolds) {
  const fs::path path = cloud_bag("odometry_frame_id");
  damage_message(path, "/RosAria/pose", 2, [](std::string& d) { put_u32_at(d, 12, 1000); });
  expect_contains(quick_error(path, "p3dx"),
                  ": topic /RosAria/pose, message 2: its header.frame_id string claims 1000 bytes "
                  "but the message holds only 697 more bytes: the message is damaged");
}

fs::path tf_bag(const std::string& name) {
  const fs::path path = length_bag_path(name);
  {
    TestBagWriter w(path.string());
    for (int k = 0; k < 3; ++k) w.tf("/tf", 10.0 + 0.1 * k, 0.01 * k, 0, 0);
    w.point_cloud("/RosAria/sonar", 10.05, {{1.0, 1.0}});
    w.point_cloud("/RosAria/sonar", 10.15, {{1.0, 2.0}});
  }
  EXPECT_EQ(import_ros_bag(path, bag::testing::with_robot("p3dx")).log.frames.size(), 2u);
  return path;
}

TEST(BagMessageLength, TfTransformsClaimingTwoBillionElements) {
  // Was std::bad_alloc (2^31 TransformStamped asked for); a length of 10^7 allocated and
  // constructed 1.4 GB of them.
  const fs::path path = tf_bag("transforms_2g");
  damage_message(path, "/tf", 1, [](std::string& d) { put_u32_at(d, 0, 0x7fffffff); });
  // One transform: seq and stamp (12), "odom" (8), "base_link" (13) and the transform (56).
  expect_contains(quick_error(path, "p3dx"),
                  path.string() +
                      ": topic /tf, message 1: its transforms array claims 2147483647 elements "
                      "(at least 163208757172 bytes) but the message holds only 89 more bytes: "
                      "the message is damaged");
}

TEST(BagMessageLength, TfNestedChildFrameIdClaimingMoreThanItHolds) {
  const fs::path path = tf_bag("transform_child");
  damage_message(path, "/tf", 0, [](std::string& d) {
    put_u32_at(d, after_header(d, 4), 0xfffffff0u);  // transforms[0].child_frame_id
  });
  expect_contains(quick_error(path, "p3dx"),
                  ": topic /tf, message 0: its transforms[0].child_frame_id string claims "
                  "4294967280 bytes but the message holds only 65 more bytes: the message is "
                  "damaged");
}

TEST(BagMessageLength, SonarArrayRangesClaimingTwoBillionElements) {
  // p2os's SonarArray has cogmap's own decoder (sonar_array_decoder.cc): it checked this already.
  const fs::path path = length_bag_path("sonar_array_2g");
  {
    TestBagWriter w(path.string());
    w.odometry("/pose", 10.0, 0, 0, 0);
    w.odometry("/pose", 10.1, 0, 0, 0);
    w.sonar_array("/sonar", 10.05, {1.0, 2.0}, SonarArrayVariant::kGood);
  }
  ASSERT_EQ(import_ros_bag(path, bag::testing::with_robot("p2at")).log.frames.size(), 1u);
  damage_message(path, "/sonar", 0,
                 [](std::string& d) { put_u32_at(d, after_header(d) + 4, 0x7fffffff); });
  expect_contains(quick_error(path, "p2at"),
                  path.string() +
                      ": topic /sonar, message 0: SonarArray truncated: 2147483647 ranges need "
                      "17179869176 bytes, 16 left");
}

// The second line of defence: a length that gets past the checks and asks for gigabytes makes
// the reader's child process run out of its address space (bag_isolation.cc), which is
// reported naming the file, the topic and the message, not as a bare "std::bad_alloc". The
// reading is a stand-in plugin's (oom_test_plugin.cc) that asks for 8 GiB at message 2.
TEST(BagMessageLength, RunningOutOfTheReadersMemoryNamesTheMessage) {
  if (!bag::reader_memory_is_limited()) GTEST_SKIP() << "no limit in a sanitizer build";
  const fs::path path = length_bag_path("oom");
  {
    TestBagWriter w(path.string());
    w.odometry("/RosAria/pose", 10.0, 0, 0, 0);
  }
  const char* was = std::getenv("COGMAP_PLUGIN_DIR");
  const std::string previous = was != nullptr ? was : "";
  ::setenv("COGMAP_PLUGIN_DIR", COGMAP_OOM_TEST_PLUGIN_DIR, 1);
  const std::string e = quick_error(path, "p3dx");
  if (was != nullptr) {
    ::setenv("COGMAP_PLUGIN_DIR", previous.c_str(), 1);
  } else {
    ::unsetenv("COGMAP_PLUGIN_DIR");
  }
  expect_contains(e, path.string() +
                         ": topic /RosAria/sonar, message 2: ran out of memory reading this "
                         "message (the bag reader may map 4.");
  expect_contains(e, " GiB for this bag of " + std::to_string(fs::file_size(path)) +
                         " bytes, more than an intact bag needs): a length in the bag is damaged");
}

}  // namespace
}  // namespace cogmap::hw
