// import_ros_bag on bags written here with the rosbag API, in RosAria's and p2os's shapes
// (corridor_scenario.h derives the expected counts by hand).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>

#include "bag_test_helpers.h"
#include "cogmap/hw/bag_import.h"
#include "cogmap/mapper/seam/robot_models.h"
#include "corridor_scenario.h"

namespace cogmap::hw {
namespace {

namespace fs = std::filesystem;
using bag::testing::CorridorCounts;
using bag::testing::OdomForm;
using bag::testing::SonarForm;

fs::path import_bag_path(const std::string& name) {
  return bag::testing::temp_bag("cogmap_bag_test", name);
}

ImportedBag import_corridor(SonarForm sonar, OdomForm odom, const std::string& name) {
  const fs::path path = import_bag_path(name);
  bag::testing::write_corridor_bag(path.string(), sonar, odom);
  return import_ros_bag(path, bag::testing::with_robot("p3dx"));
}

void expect_corridor_counts(const BagImportStats& s) {
  EXPECT_EQ(s.sonar_messages, CorridorCounts::kSonarMessages);
  EXPECT_EQ(s.odometry_messages, CorridorCounts::kOdometryMessages);
  EXPECT_EQ(s.frames, CorridorCounts::kSonarMessages);
  EXPECT_EQ(s.readings_accepted, CorridorCounts::kAccepted);
  EXPECT_EQ(s.readings_no_echo, CorridorCounts::kNoEcho);
  EXPECT_EQ(s.rejected_unchanged, CorridorCounts::kUnchanged);
  EXPECT_EQ(s.rejected_unreported, CorridorCounts::kUnreported);
  EXPECT_EQ(s.rejected_no_odometry, 0u);
  EXPECT_EQ(s.robot_model, "p3dx");
}

// Every frame's odometry is the pose interpolated at its stamp, and every reading's range is
// the corridor's: a side transducer hears its wall at 1 m minus its mount's y.
void expect_corridor_frames(const ImportedBag& b) {
  const mapper::RobotGeometry& g = mapper::find_robot_model("p3dx")->geometry;
  ASSERT_EQ(b.log.frames.size(), CorridorCounts::kSonarMessages);
  for (int k = 0; k < static_cast<int>(CorridorCounts::kSonarMessages); ++k) {
    const mapper::SensorFrame& f = b.log.frames[static_cast<std::size_t>(k)];
    const double stamp = bag::testing::sonar_stamp(k);
    EXPECT_NEAR(f.time_s, stamp - bag::testing::kT0, 1e-6) << "frame " << k;
    EXPECT_NEAR(f.odometry.x_m, bag::testing::corridor_x(stamp), 1e-6) << "frame " << k;
    EXPECT_NEAR(f.odometry.y_m, 0.0, 1e-12);
    EXPECT_NEAR(f.odometry.theta_rad, 0.0, 1e-12);
    for (const mapper::SonarReading& r : f.sonar) {
      ASSERT_TRUE(bag::testing::fires(r.index, k)) << "frame " << k << " sonar " << r.index;
      const auto expected = bag::testing::corridor_range(g.sonars[r.index], k);
      EXPECT_EQ(r.echo, expected.has_value()) << "frame " << k << " sonar " << r.index;
      EXPECT_NEAR(r.range_m, expected.value_or(5.0), 1e-5) << "frame " << k << " sonar " << r.index;
      EXPECT_EQ(r.time_s, f.time_s);
    }
  }
  // Message 0 fires transducers 0 (90°: 1 - 0.136 = 0.864 m) and 1 (50°: 0.881 / sin 50°).
  ASSERT_EQ(b.log.frames[0].sonar.size(), 2u);
  EXPECT_NEAR(b.log.frames[0].sonar[0].range_m, 0.864, 1e-5);
  EXPECT_NEAR(b.log.frames[0].sonar[1].range_m, 0.881 / std::sin(50.0 * std::numbers::pi / 180),
              1e-5);
}

TEST(BagImport, RosAriaPointCloudCorridor) {
  const ImportedBag b = import_corridor(SonarForm::kPointCloud, OdomForm::kOdometry, "pc");
  expect_corridor_counts(b.stats);
  expect_corridor_frames(b);
  EXPECT_EQ(b.stats.sonar_topic, "/RosAria/sonar");
  EXPECT_EQ(b.stats.odom_topic, "/RosAria/pose");
  EXPECT_EQ(b.log.geometry.sonars.size(), 16u);
  EXPECT_EQ(b.log.geometry.sonars[3].x_m, 0.166);
}

TEST(BagImport, RosAriaPointCloud2Corridor) {
  const ImportedBag b = import_corridor(SonarForm::kPointCloud2, OdomForm::kOdometry, "pc2");
  expect_corridor_counts(b.stats);
  expect_corridor_frames(b);
  EXPECT_EQ(b.stats.sonar_type, "sensor_msgs/PointCloud2");
}

TEST(BagImport, BothCloudsPickThePointCloudTopic) {
  const ImportedBag b = import_corridor(SonarForm::kBothClouds, OdomForm::kOdometry, "both");
  EXPECT_EQ(b.stats.sonar_topic, "/RosAria/sonar");
  EXPECT_EQ(b.stats.sonar_type, "sensor_msgs/PointCloud");
  expect_corridor_counts(b.stats);
}

TEST(BagImport, P2osSonarArrayCorridor) {
  const ImportedBag b = import_corridor(SonarForm::kSonarArray, OdomForm::kOdometry, "p2os");
  expect_corridor_counts(b.stats);
  expect_corridor_frames(b);
  EXPECT_EQ(b.stats.sonar_topic, "/sonar");
  EXPECT_EQ(b.stats.odom_topic, "/pose");
}

TEST(BagImport, TfOnlyOdometry) {
  const ImportedBag b = import_corridor(SonarForm::kPointCloud, OdomForm::kTf, "tf");
  expect_corridor_counts(b.stats);
  expect_corridor_frames(b);
  EXPECT_EQ(b.stats.odom_topic, "/tf");
  EXPECT_EQ(b.stats.odom_type, "tf2_msgs/TFMessage");
}

TEST(BagImport, CompressedBagsReadAlike) {
  for (const auto c : {bag::testing::Compression::kBz2, bag::testing::Compression::kLz4}) {
    const fs::path path = import_bag_path(c == bag::testing::Compression::kBz2 ? "bz2" : "lz4");
    bag::testing::write_corridor_bag(path.string(), SonarForm::kPointCloud, OdomForm::kOdometry, c);
    const ImportedBag b = import_ros_bag(path, bag::testing::with_robot("p3dx"));
    expect_corridor_counts(b.stats);
    expect_corridor_frames(b);
  }
}

TEST(BagImport, ExplicitTopicsOverrideDetection) {
  const fs::path path = import_bag_path("explicit");
  bag::testing::write_corridor_bag(path.string(), SonarForm::kBothClouds, OdomForm::kOdometry);
  const ImportedBag b = import_ros_bag(
      path, {.sonar_topic = "/RosAria/sonar_pointcloud2", .odom_topic = "", .robot = "p3dx"});
  EXPECT_EQ(b.stats.sonar_topic, "/RosAria/sonar_pointcloud2");
  expect_corridor_counts(b.stats);
}

TEST(BagImport, HeadingInterpolatesTheShortWayAcrossPi) {
  const fs::path path = import_bag_path("wrap");
  {
    bag::testing::TestBagWriter w(path.string());
    w.odometry("/RosAria/pose", 10.0, 0.0, 0.0, 3.0);
    w.odometry("/RosAria/pose", 10.2, 0.2, 0.0, -3.0);  // turned 0.283 rad through ±π
    w.point_cloud("/RosAria/sonar", 10.1, {{0.069, 1.0}});
  }
  const ImportedBag b = import_ros_bag(path, bag::testing::with_robot("p3dx"));
  ASSERT_EQ(b.log.frames.size(), 1u);
  const double mid = 3.0 + (2 * std::numbers::pi - 6.0) / 2;  // π
  EXPECT_NEAR(std::abs(b.log.frames[0].odometry.theta_rad), mid, 1e-9);
  EXPECT_NEAR(b.log.frames[0].odometry.x_m, 0.1, 1e-9);
  ASSERT_EQ(b.log.frames[0].sonar.size(), 1u);
  EXPECT_NEAR(b.log.frames[0].sonar[0].range_m, 1.0 - 0.136, 1e-6);
}

TEST(BagImport, ReadingsOutsideTheOdometryAreRejected) {
  const fs::path path = import_bag_path("outside");
  {
    bag::testing::TestBagWriter w(path.string());
    w.point_cloud("/RosAria/sonar", 9.95, {{0.069, 1.0}});  // before the first pose
    w.odometry("/RosAria/pose", 10.0, 0.0, 0.0, 0.0);
    w.point_cloud("/RosAria/sonar", 10.05, {{0.069, 1.1}});
    w.odometry("/RosAria/pose", 10.1, 0.05, 0.0, 0.0);
    w.odometry("/RosAria/pose", 11.1, 0.55, 0.0, 0.0);  // a 1 s gap: nothing interpolates there
    w.point_cloud("/RosAria/sonar", 10.6, {{0.069, 1.2}});
  }
  const ImportedBag b = import_ros_bag(path, bag::testing::with_robot("p3dx"));
  EXPECT_EQ(b.stats.frames, 1u);
  EXPECT_EQ(b.stats.readings_accepted, 1u);
  EXPECT_EQ(b.stats.rejected_no_odometry, 2u);
  ASSERT_EQ(b.log.frames.size(), 1u);
  EXPECT_NEAR(b.log.frames[0].time_s, 0.1, 1e-9);  // from the first stamp, 9.95 s
  EXPECT_NEAR(b.log.frames[0].sonar[0].range_m, 1.1 - 0.136, 1e-6);
}

TEST(BagImport, AGenuineRepeatIsNotANewReading) {
  // The rule the issue sets: a value equal to the last message's is the old reading.
  const fs::path path = import_bag_path("repeat");
  {
    bag::testing::TestBagWriter w(path.string());
    w.odometry("/sonar_pose", 10.0, 0.0, 0.0, 0.0);
    w.odometry("/sonar_pose", 10.3, 0.0, 0.0, 0.0);
    w.sonar_array("/sonar", 10.1, {1.5, 0.0});
    w.sonar_array("/sonar", 10.2, {1.5, 2.5});
  }
  const ImportedBag b = import_ros_bag(path, bag::testing::with_robot("p2at"));
  EXPECT_EQ(b.stats.readings_accepted, 2u);  // 1.5 m once, 2.5 m once
  EXPECT_EQ(b.stats.rejected_unchanged, 1u);
  EXPECT_EQ(b.stats.rejected_unreported, 1u);
  ASSERT_EQ(b.log.frames.size(), 2u);
  ASSERT_EQ(b.log.frames[1].sonar.size(), 1u);
  EXPECT_EQ(b.log.frames[1].sonar[0].index, 1);
}

TEST(BagImport, RangesFromFourPointNineMetresAreNoEcho) {
  const fs::path path = import_bag_path("noecho");
  {
    bag::testing::TestBagWriter w(path.string());
    w.odometry("/pose", 10.0, 0.0, 0.0, 0.0);
    w.odometry("/pose", 10.2, 0.0, 0.0, 0.0);
    w.sonar_array("/sonar", 10.1, {4.85, 4.95, 5.0, 5.3});
  }
  const ImportedBag b = import_ros_bag(path, bag::testing::with_robot("p2at"));
  ASSERT_EQ(b.log.frames.size(), 1u);
  const auto& r = b.log.frames[0].sonar;
  ASSERT_EQ(r.size(), 4u);
  EXPECT_TRUE(r[0].echo);
  EXPECT_DOUBLE_EQ(r[0].range_m, 4.85);
  for (std::size_t i = 1; i < 4; ++i) {
    EXPECT_FALSE(r[i].echo) << i;
    EXPECT_DOUBLE_EQ(r[i].range_m, 5.0) << i;  // the model's maximum
  }
  EXPECT_EQ(b.stats.readings_no_echo, 3u);
}

TEST(BagImport, RecognisesBagsByTheirMagic) {
  const fs::path path = import_bag_path("magic");
  bag::testing::write_corridor_bag(path.string(), SonarForm::kPointCloud, OdomForm::kOdometry);
  EXPECT_TRUE(looks_like_ros_bag(path));
  EXPECT_FALSE(looks_like_ros_bag(fs::path(COGMAP_HW_TESTDATA) / "sample.carmen.log"));
  EXPECT_FALSE(looks_like_ros_bag(import_bag_path("does_not_exist_x")));
  EXPECT_TRUE(ros_bag_support());
}

}  // namespace
}  // namespace cogmap::hw
