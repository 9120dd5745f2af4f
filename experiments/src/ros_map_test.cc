#include "cogmap/experiments/ros_map.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "cogmap/test_support/scratch_dir.h"

namespace cogmap::experiments {
namespace {

TEST(RosMap, PgmBytesOfATinyGrid) {
  // 3 x 2 cells of 10 cm at origin (-0.5, 1.0). Row y=0: occupied, free, unexplored;
  // row y=1: robot path, weak evidence (≤ ε), above ε.
  mapper::HistogramGrid g(mapper::GridGeometry(-0.5, 1.0, 100.0, 3, 2), 0.0f);
  g.set({0, 0}, 12.0f);
  g.set({1, 0}, -3.0f);
  g.set({0, 1}, mapper::kRobotPathValue);
  g.set({1, 1}, 7.0f);
  g.set({2, 1}, 7.5f);
  const std::string pgm = histogram_to_pgm(g, 7.0);
  const std::string expected = std::string("P5\n3 2\n255\n") +
                               // top row first (y = 1): free, unknown, occupied
                               std::string{'\xfe', '\xcd', '\x00'} +
                               // then y = 0: occupied, free, unknown
                               std::string{'\x00', '\xfe', '\xcd'};
  EXPECT_EQ(pgm, expected);
}

TEST(RosMap, YamlIsMapServerConvention) {
  const mapper::GridGeometry geo(-0.5, 1.25, 55.0, 3, 2);
  EXPECT_EQ(ros_map_yaml(geo, "grid_004.pgm"),
            "# cogmap room grid; the origin is in the room's local (ASR) frame, metres\n"
            "image: grid_004.pgm\n"
            "resolution: 0.055\n"
            "origin: [-0.5, 1.25, 0.0]\n"
            "negate: 0\n"
            "occupied_thresh: 0.65\n"
            "free_thresh: 0.196\n");
}

TEST(RosMap, WritesBothFiles) {
  const auto dir = test_support::process_scratch() / "ros_map_test";
  mapper::HistogramGrid g(mapper::GridGeometry(0, 0, 100.0, 2, 2), 0.0f);
  write_ros_map(g, 7.0, dir, "grid_000");
  std::ifstream pgm(dir / "grid_000.pgm", std::ios::binary);
  std::stringstream s;
  s << pgm.rdbuf();
  EXPECT_EQ(s.str(), histogram_to_pgm(g, 7.0));
  EXPECT_TRUE(std::filesystem::exists(dir / "grid_000.yaml"));
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    EXPECT_EQ(e.path().string().find(".tmp."), std::string::npos) << "temp file left behind";
  }
}

TEST(RosMap, ExploreMapPgmAndYaml) {
  // 3 x 2 cells of 0.2 m at origin (-1, 2): row y = 0 unseen, free, obstacle; row y = 1
  // frontier, given-up frontier, unseen.
  using Image = mapper::nav::ExploreMapImage;
  Image image;
  image.width = 3;
  image.height = 2;
  image.cell_m = 0.2;
  image.origin_m = {-1.0, 2.0};
  image.cells = {Image::kUnseen,   Image::kFree,           Image::kObstacle,
                 Image::kFrontier, Image::kBannedFrontier, Image::kUnseen};
  const std::string expected = std::string("P5\n3 2\n255\n") +
                               std::string{'\xa0', '\x64', '\xcd'} +  // y = 1: 160, 100, 205
                               std::string{'\xcd', '\xfe', '\x00'};   // y = 0: 205, 254, 0
  EXPECT_EQ(explore_map_pgm(image), expected);
  const auto dir = test_support::process_scratch() / "explore_map_test";
  write_explore_map(image, dir);
  std::ifstream pgm(dir / "explore_map.pgm", std::ios::binary), yaml(dir / "explore_map.yaml");
  std::stringstream p, y;
  p << pgm.rdbuf();
  y << yaml.rdbuf();
  EXPECT_EQ(p.str(), expected);
  EXPECT_NE(y.str().find("image: explore_map.pgm\nresolution: 0.2\norigin: [-1, 2, 0.0]\n"),
            std::string::npos)
      << y.str();
}

}  // namespace
}  // namespace cogmap::experiments
