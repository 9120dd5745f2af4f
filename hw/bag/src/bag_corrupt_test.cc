// Bad bags are refused with a LogError that names the file and, where there is one, the topic
// and message index; nothing is returned in part.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iostream>

#include "bag_test_helpers.h"
#include "cogmap/hw/bag_import.h"
#include "corridor_scenario.h"

namespace cogmap::hw {
namespace {

namespace fs = std::filesystem;
using bag::testing::expect_contains;
using bag::testing::import_error;
using bag::testing::OdomForm;
using bag::testing::SonarArrayVariant;
using bag::testing::SonarForm;
using bag::testing::TestBagWriter;

fs::path corrupt_bag_path(const std::string& name) {
  return bag::testing::temp_bag("cogmap_bag_corrupt_test", name);
}

TEST(BagCorrupt, TruncatedFile) {
  const fs::path path = corrupt_bag_path("truncated");
  bag::testing::write_corridor_bag(path.string(), SonarForm::kPointCloud, OdomForm::kOdometry);
  fs::resize_file(path, fs::file_size(path) / 2);
  const std::string e = import_error(path, bag::testing::with_robot("p3dx"));
  expect_contains(e, path.string() + ": ");
  expect_contains(e, "not a readable ROS 1 bag");
  // The offsets a user can act on: the file's length and where its header put the index.
  expect_contains(e, "the file is " + std::to_string(fs::file_size(path)) +
                         " bytes long, but its header puts the index at byte ");
  expect_contains(e, "it was cut short");
}

TEST(BagCorrupt, CutInsideItsHeaderRecord) {
  const fs::path path = corrupt_bag_path("cut_header");
  bag::testing::write_corridor_bag(path.string(), SonarForm::kPointCloud, OdomForm::kOdometry);
  fs::resize_file(path, 30);  // within the header record's fields (index_pos among them)
  const std::string e = import_error(path, bag::testing::with_robot("p3dx"));
  expect_contains(e, "the file is 30 bytes long, but it ends inside its bag header record");
}

TEST(BagCorrupt, GarbageInsideAChunk) {
  const fs::path path = corrupt_bag_path("garbage");
  bag::testing::write_corridor_bag(path.string(), SonarForm::kPointCloud, OdomForm::kOdometry);
  // Overwrite 64 bytes in the first third: message data and record headers, not the index.
  {
    std::fstream f(path, std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(static_cast<std::streamoff>(fs::file_size(path) / 3));
    const std::string junk(64, '\xff');
    f.write(junk.data(), static_cast<std::streamsize>(junk.size()));
  }
  const std::string e = import_error(path, bag::testing::with_robot("p3dx"));
  expect_contains(e, path.string() + ": topic /RosAria/");
  expect_contains(e, ", message ");
  // The index is intact: no claim that the file was cut short.
  EXPECT_EQ(e.find("cut short"), std::string::npos) << e;
}

TEST(BagCorrupt, NotABagAtAll) {
  const fs::path path = corrupt_bag_path("text");
  std::ofstream(path) << "#ROSBAG V2.0\nthis is not a bag\n";
  expect_contains(import_error(path, bag::testing::with_robot("p3dx")), "not a readable ROS 1 bag");
}

TEST(BagCorrupt, NamedTopicOfTheWrongType) {
  const fs::path path = corrupt_bag_path("wrongtype");
  bag::testing::write_corridor_bag(path.string(), SonarForm::kPointCloud, OdomForm::kOdometry);
  const std::string e =
      import_error(path, {.sonar_topic = "/RosAria/pose", .odom_topic = "", .robot = "p3dx"});
  expect_contains(e, "topic /RosAria/pose is nav_msgs/Odometry, not a sonar type");
  const std::string e2 =
      import_error(path, {.sonar_topic = "", .odom_topic = "/RosAria/sonar", .robot = "p3dx"});
  expect_contains(e2, "topic /RosAria/sonar is sensor_msgs/PointCloud, not nav_msgs/Odometry");
  const std::string e3 =
      import_error(path, {.sonar_topic = "/nothing", .odom_topic = "", .robot = "p3dx"});
  expect_contains(e3, "no topic /nothing (topics: /RosAria/pose (nav_msgs/Odometry, 501 messages)");
}

TEST(BagCorrupt, NoSonarTopic) {
  const fs::path path = corrupt_bag_path("nosonar");
  {
    TestBagWriter w(path.string());
    w.odometry("/RosAria/pose", 10.0, 0, 0, 0);
  }
  expect_contains(import_error(path, bag::testing::with_robot("p3dx")), "no sonar topic");
}

TEST(BagCorrupt, NoOdometry) {
  const fs::path path = corrupt_bag_path("noodom");
  {
    TestBagWriter w(path.string());
    w.point_cloud("/RosAria/sonar", 10.0, {{1, 1}});
    w.tf("/tf", 10.0, 0, 0, 0, "map", "odom");
  }
  expect_contains(import_error(path, bag::testing::with_robot("p3dx")),
                  "topic /tf has no odom -> base_link transform");
}

TEST(BagCorrupt, AmbiguousSonarTopics) {
  const fs::path path = corrupt_bag_path("ambiguous");
  {
    TestBagWriter w(path.string());
    w.odometry("/a/pose", 10.0, 0, 0, 0);
    w.point_cloud("/a/sonar", 10.0, {{1, 1}});
    w.point_cloud("/b/sonar", 10.0, {{1, 1}});
  }
  expect_contains(import_error(path, bag::testing::with_robot("p3dx")),
                  "more than one sonar topic: /a/sonar (sensor_msgs/PointCloud, 1 messages), "
                  "/b/sonar (sensor_msgs/PointCloud, 1 messages); choose one with --sonar-topic");
}

TEST(BagCorrupt, TimeGoingBackwards) {
  const fs::path path = corrupt_bag_path("backwards");
  {
    TestBagWriter w(path.string());
    w.odometry("/RosAria/pose", 10.0, 0, 0, 0);
    w.odometry("/RosAria/pose", 11.0, 0, 0, 0);
    w.point_cloud("/RosAria/sonar", 10.2, {{1, 1}});
    w.point_cloud("/RosAria/sonar", 10.1, {{1, 2}}, 10.25);  // recorded after, stamped before
  }
  expect_contains(import_error(path, bag::testing::with_robot("p3dx")),
                  ": topic /RosAria/sonar, message 1: header stamp 10.100000 s is earlier than "
                  "message 0's 10.200000 s: time goes backwards");
}

TEST(BagCorrupt, UnsetStamp) {
  const fs::path path = corrupt_bag_path("unset");
  {
    TestBagWriter w(path.string());
    w.odometry("/RosAria/pose", 10.0, 0, 0, 0);
    w.odometry("/RosAria/pose", 0.0, 0, 0, 0, 10.05);  // stamp never set
    w.point_cloud("/RosAria/sonar", 10.0, {{1, 1}});
  }
  expect_contains(import_error(path, bag::testing::with_robot("p3dx")),
                  "topic /RosAria/pose, message 1: header stamp is unset");
}

TEST(BagCorrupt, TruncatedPointCloudMessage) {
  const fs::path path = corrupt_bag_path("shortcloud");
  {
    TestBagWriter w(path.string());
    w.odometry("/RosAria/pose", 10.0, 0, 0, 0);
    w.point_cloud("/RosAria/sonar", 10.0, {{1, 1}});
    w.truncated_point_cloud("/RosAria/sonar", 10.1);
  }
  expect_contains(import_error(path, bag::testing::with_robot("p3dx")),
                  ": topic /RosAria/sonar, message 1: ");
}

TEST(BagCorrupt, SonarArrayWithAnotherDefinition) {
  const fs::path path = corrupt_bag_path("wrongdef");
  {
    TestBagWriter w(path.string());
    w.odometry("/pose", 10.0, 0, 0, 0);
    w.sonar_array("/sonar", 10.0, {1.0, 2.0}, SonarArrayVariant::kWrongDefinition);
  }
  const std::string e = import_error(path, bag::testing::with_robot("p2at"));
  expect_contains(e,
                  "topic /sonar, message 0: p2os_msgs/SonarArray with MD5 "
                  "0123456789abcdef0123456789abcdef, expected 2984921c09aef26ad253c7629937a5bb");
}

TEST(BagCorrupt, SonarArrayTruncated) {
  const fs::path path = corrupt_bag_path("shortarray");
  {
    TestBagWriter w(path.string());
    w.odometry("/pose", 10.0, 0, 0, 0);
    w.sonar_array("/sonar", 10.0, {1.0, 2.0}, SonarArrayVariant::kTruncated);
  }
  expect_contains(import_error(path, bag::testing::with_robot("p2at")),
                  "topic /sonar, message 0: SonarArray truncated: 2 ranges need 16 bytes, 0 left");
}

TEST(BagCorrupt, MoreTransducersThanTheModel) {
  const fs::path path = corrupt_bag_path("toomany");
  {
    TestBagWriter w(path.string());
    w.odometry("/RosAria/pose", 10.0, 0, 0, 0);
    w.point_cloud("/RosAria/sonar", 10.0, std::vector<bag::testing::Xy>(17, {1.0, 1.0}));
  }
  expect_contains(import_error(path, bag::testing::with_robot("p3dx")),
                  "topic /RosAria/sonar, message 0: 17 transducers, but the robot model has 16 "
                  "sonars: pass the right --robot");
}

// A bag's odometry gets the limits a cogmap, CARMEN or Player log gets (log_checks.h): a pose
// beyond +/-1000 m (1e30 m asked the grid for more cells than exist) or a jump the robot cannot
// drive is refused, naming the pose message.
void write_pose_bag(const fs::path& path, double x1_m) {
  TestBagWriter w(path.string());
  w.odometry("/RosAria/pose", 10.0, 0, 0, 0);
  w.odometry("/RosAria/pose", 10.1, x1_m, 0, 0);
  w.odometry("/RosAria/pose", 10.2, 0, 0, 0);
  w.point_cloud("/RosAria/sonar", 10.05, {{1, 1}});
  w.point_cloud("/RosAria/sonar", 10.15, {{1, 2}});
}

TEST(BagCorrupt, PoseBeyondTheLogCoordinateLimit) {
  for (const double x : {5000.0, 1e30, -1e30}) {
    const fs::path path = corrupt_bag_path("far_pose");
    write_pose_bag(path, x);
    const std::string e = import_error(path, bag::testing::with_robot("p3dx"));
    expect_contains(e, path.string() +
                           ": topic /RosAria/pose, message 1: odometry x_m must be in "
                           "[-1000, 1000], got ");
  }
}

TEST(BagCorrupt, OdometryJumpBeyondTheRobotsSpeed) {
  const fs::path path = corrupt_bag_path("jump");
  write_pose_bag(path, 50.0);
  const std::string e = import_error(path, bag::testing::with_robot("p3dx"));
  expect_contains(e, path.string() + ": topic /RosAria/pose, message 1: odometry jumps 50 m in ");
}

TEST(BagCorrupt, TfPoseBeyondTheLogCoordinateLimit) {
  const fs::path path = corrupt_bag_path("far_tf");
  {
    TestBagWriter w(path.string());
    w.tf("/tf", 10.0, 0, 0, 0);
    w.tf("/tf", 10.1, 0, -2000, 0);
    w.point_cloud("/RosAria/sonar", 10.05, {{1, 1}});
  }
  expect_contains(import_error(path, bag::testing::with_robot("p3dx")),
                  path.string() +
                      ": topic /tf, message 1: odometry y_m must be in [-1000, 1000], "
                      "got -2000");
}

TEST(BagCorrupt, RobotModelMissingOrUnknown) {
  const fs::path path = corrupt_bag_path("norobot");
  bag::testing::write_corridor_bag(path.string(), SonarForm::kPointCloud, OdomForm::kOdometry);
  expect_contains(import_error(path, BagImportOptions{}),
                  "pass --robot (one of p2at, p2at8, p3at, p3dx, p2dx, p2de, peoplebot)");
  expect_contains(import_error(path, bag::testing::with_robot("r2d2")),
                  "unknown robot model 'r2d2'");
}

}  // namespace
}  // namespace cogmap::hw

namespace cogmap::hw {
namespace {

// Corruption anywhere in a bag ends in a LogError or, where it only changed numbers, in a
// result; never in a crash or another exception type. 40 seeded positions over the file.
TEST(BagCorrupt, SeededCorruptionIsRefusedOrRead) {
  const fs::path clean = corrupt_bag_path("seeded_clean");
  bag::testing::write_corridor_bag(clean.string(), SonarForm::kPointCloud, OdomForm::kOdometry);
  const auto size = fs::file_size(clean);
  std::uint64_t state = 12345;
  int refused = 0;
  for (int i = 0; i < 40; ++i) {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    const auto offset = static_cast<std::streamoff>((state >> 33) % size);
    const fs::path path = corrupt_bag_path("seeded");
    fs::copy_file(clean, path, fs::copy_options::overwrite_existing);
    {
      std::fstream f(path, std::ios::in | std::ios::out | std::ios::binary);
      f.seekp(offset);
      const std::string junk(16, static_cast<char>(0xA5 ^ i));
      f.write(junk.data(), static_cast<std::streamsize>(junk.size()));
    }
    try {
      import_ros_bag(path, bag::testing::with_robot("p3dx"));
    } catch (const LogError& e) {
      ++refused;
      EXPECT_EQ(std::string(e.what()).rfind(path.string() + ": ", 0), 0u) << e.what();
    }
  }
  std::cout << "seeded corruption: " << refused << " of 40 refused\n";
}

}  // namespace
}  // namespace cogmap::hw
