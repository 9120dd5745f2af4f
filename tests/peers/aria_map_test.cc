// The .map reader on a small map written here (no peers needed).
#include <gtest/gtest.h>

#include <fstream>
#include <numbers>

#include "aria_map.h"
#include "cogmap/test_support/scratch_dir.h"

namespace cogmap::peers {
namespace {

std::filesystem::path write(const std::string& name, const std::string& text) {
  const auto p = test_support::process_scratch() / name;
  std::ofstream(p) << text;
  return p;
}

TEST(AriaMap, ReadsLinesAndRobotHome) {
  const auto p = write("cogmap_small.map",
                       "2D-Map\nLineMinPos: 0 0\nNumLines: 2\n"
                       "Cairn: RobotHome 1000 1498 90 \"\" ICON \"Home\"\nLINES\n"
                       "0 0 5000 0\n5000 0 5000 2500\nDATA\n100 100\n");
  const AriaMap m = read_aria_map(p);
  ASSERT_EQ(m.lines.size(), 2u);
  EXPECT_DOUBLE_EQ(m.lines[1].a.x(), 5.0);
  EXPECT_DOUBLE_EQ(m.lines[1].b.y(), 2.5);
  ASSERT_TRUE(m.robot_home.has_value());
  EXPECT_DOUBLE_EQ(m.robot_home->x_m, 1.0);
  EXPECT_DOUBLE_EQ(m.robot_home->y_m, 1.498);
  EXPECT_NEAR(m.robot_home->theta_rad, std::numbers::pi / 2, 1e-12);
}

TEST(AriaMap, RefusesBadFiles) {
  EXPECT_THROW(read_aria_map(write("cogmap_bad1.map", "not a map\n")), std::runtime_error);
  try {
    read_aria_map(write("cogmap_bad2.map", "2D-Map\nLINES\n0 0 1\nDATA\n"));
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("cogmap_bad2.map:3: expected x1 y1 x2 y2"),
              std::string::npos);
  }
  EXPECT_THROW(read_aria_map(write("cogmap_bad3.map", "2D-Map\nNumLines: 3\nLINES\n0 0 1 1\n")),
               std::runtime_error);
}

}  // namespace
}  // namespace cogmap::peers
