// The start-enclosure warning (world_enclosure.h) on exact synthetic worlds and on every
// shipped world.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "cogmap/sim/world_enclosure.h"
#include "world/world_test_support.h"

namespace cogmap::sim {
namespace {

WorldSpec parse(const std::string& walls, const std::string& start,
                const std::string& obstacles = "") {
  return parse_world(yaml::Node::load_string(
      "name: t\nwalls: {polylines: [" + walls + "]}\n" + obstacles + "start: " + start + "\n",
      "w.yaml"));
}

const std::string kSquare = "[[0, 0], [10, 0], [10, 10], [0, 10], [0, 0]]";

TEST(WorldEnclosure, StartInsideASquareIsEnclosed) {
  const WorldSpec w = parse(kSquare, "{x_m: 5, y_m: 5}");
  EXPECT_EQ(open_directions(w, w.start.translation()), 0);
  EXPECT_EQ(start_enclosure_warning(w, w.start.translation()), std::nullopt);
  // Near a corner too: every ray still meets a wall.
  EXPECT_EQ(open_directions(w, {0.5, 9.5}), 0);
}

// From (15, 5) the square (faces at x, y = -0.06 and 10.06) spans 134.3 to 225.7 degrees:
// the 9 rays at 135, 146.25, ..., 225 degrees meet it, 23 meet nothing.
TEST(WorldEnclosure, StartOutsideASquareWarns) {
  const WorldSpec w = parse(kSquare, "{x_m: 15, y_m: 5}");  // loads: clear of every wall
  EXPECT_EQ(open_directions(w, w.start.translation()), 23);
  EXPECT_EQ(start_enclosure_warning(w, w.start.translation()),
            "start (15.00, 5.00) is not enclosed by walls: 23 of 32 directions from it meet no "
            "wall or obstacle at any distance (outside the building? the robot would hear "
            "nothing there)");
}

// A world of one wall is legitimate (sonar tests): it loads, with a warning.
TEST(WorldEnclosure, ASingleWallLoadsAndWarns) {
  WorldSpec w;
  ASSERT_NO_THROW(w = parse("[[0, 0], [10, 0]]", "{x_m: 5, y_m: 2}"));
  // The wall's top face (y = 0.06) spans 202.2 to 337.8 degrees: 13 rays meet it.
  EXPECT_EQ(open_directions(w, w.start.translation()), 19);
  EXPECT_TRUE(start_enclosure_warning(w, w.start.translation()).has_value());
}

// The threshold: a room with one side missing. From its centre the opening spans 90 degrees
// (7 open rays: the ones at +/-45 degrees meet the wall ends), which is a room with a wide door;
// 2 m from the opening it spans 136 degrees (13 open), more than a quarter of the turn.
TEST(WorldEnclosure, MoreThanAQuarterOfTheDirectionsOpenWarns) {
  const WorldSpec w = parse("[[10, 0], [0, 0], [0, 10], [10, 10]]", "{x_m: 5, y_m: 5}");
  EXPECT_EQ(open_directions(w, {5.0, 5.0}), 7);
  EXPECT_EQ(start_enclosure_warning(w, {5.0, 5.0}), std::nullopt);
  EXPECT_EQ(open_directions(w, {8.0, 5.0}), 13);
  EXPECT_TRUE(start_enclosure_warning(w, {8.0, 5.0}).has_value());
}

// Obstacles stop rays as walls do: the open side of that room closed by a box.
TEST(WorldEnclosure, ObstaclesCount) {
  const WorldSpec w = parse("[[10, 0], [0, 0], [0, 10], [10, 10]]", "{x_m: 5, y_m: 5}",
                            "obstacles:\n  - {box: {center: [10.5, 5], size: [1, 10.2]}}\n");
  EXPECT_EQ(open_directions(w, {8.0, 5.0}), 0);
}

using testing::source_dir;

TEST(WorldEnclosure, NoShippedWorldWarns) {
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(source_dir() / "worlds")) {
    if (entry.path().extension() != ".yaml") continue;
    ++count;
    const WorldSpec w = load_world(entry.path());
    EXPECT_EQ(start_enclosure_warning(w, w.start.translation()), std::nullopt) << entry.path();
  }
  EXPECT_GE(count, 4);
}

}  // namespace
}  // namespace cogmap::sim
