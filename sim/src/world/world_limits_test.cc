// The limits that keep a world inside what the physics engine can represent (issue 12): short
// segments, thin walls and far coordinates are refused with file:line:key, and the physics
// world survives slivers that validation cannot see.
#include <gtest/gtest.h>

#include <string>

#include "cogmap/sim/physics_world.h"
#include "cogmap/sim/world_spec.h"
#include "yaml/config_error_test_support.h"

namespace cogmap::sim {
namespace {

using yaml::testing::config_error_of;

std::string world_error_of(const std::string& text) {
  return config_error_of([&] { parse_world(yaml::Node::load_string(text, "w.yaml")); });
}

std::string world(const std::string& polyline, const std::string& extra = "") {
  return "name: w\nwalls:\n  polylines:\n    - " + polyline + "\n" + extra +
         "start: {x_m: 2, y_m: 2}\n";
}

TEST(WorldLimits, SegmentsShorterThanOneCentimetreAreRefused) {
  EXPECT_EQ(world_error_of(world("[[0, 0], [0.002, 0], [5, 0]]")),
            "w.yaml:4: walls.polylines[0][1]: wall segment of 0.002 m is shorter than the 0.01 m "
            "minimum (the physics engine cannot represent it)");
  // A 2 mm jog in the middle of a room outline.
  EXPECT_NE(
      world_error_of(world("[[0, 0], [3, 0], [3, 0.002], [6, 0.002], [6, 4], [0, 4], [0, 0]]"))
          .find("w.yaml:4: walls.polylines[0][2]: wall segment of 0.002 m"),
      std::string::npos);
  // Exactly the limit is accepted.
  EXPECT_EQ(world_error_of(world("[[0, 0], [0.01, 0], [5, 0]]")), "");
}

TEST(WorldLimits, CoordinatesBeyondOneKilometreAreRefused) {
  EXPECT_EQ(world_error_of(world("[[3e6, 0], [3e6, 5]]")),
            "w.yaml:4: walls.polylines[0][0][0]: coordinate 3e+06 m is beyond the +/-1000 m the "
            "simulator supports (single-precision physics)");
  EXPECT_EQ(world_error_of(world("[[1000, 0], [1000, 5]]")), "");
  EXPECT_NE(world_error_of("name: w\nwalls: {polylines: []}\nstart: {x_m: 2, y_m: -1e4}\n")
                .find("w.yaml:3: start.y_m: coordinate -10000 m"),
            std::string::npos);
}

TEST(WorldLimits, ThinWallsTinyBoxesAndEdgesAreRefused) {
  EXPECT_NE(world_error_of(world("{points: [[0, 0], [5, 0]], thickness_m: 0.001}"))
                .find("wall thickness 0.001 m is outside [0.01, 1000] m"),
            std::string::npos);
  EXPECT_NE(world_error_of(world("[[0, 0], [5, 0]]",
                                 "obstacles:\n  - box: {center: [3, 3], size: "
                                 "[0.005, 1]}\n"))
                .find("box sides must be at least 0.01 m"),
            std::string::npos);
  EXPECT_NE(world_error_of(world("[[0, 0], [5, 0]]",
                                 "obstacles:\n  - polygon: [[3, 3], [3.005, 3], "
                                 "[3, 4]]\n"))
                .find("polygon edge shorter than the 0.01 m minimum"),
            std::string::npos);
}

TEST(WorldLimits, PhysicsSkipsSliversInsteadOfAborting) {
  // Built by hand, past the loader: a 1 mm jog with thick walls gives mitred quads whose
  // corners Box2D would weld (b2PolygonShape::Set asserts). The world must still build.
  WorldSpec w;
  w.name = "sliver";
  WallPolyline wall;
  wall.points = {{0.0, 0.0}, {3.0, 0.0}, {3.0, 0.001}, {6.0, 0.001}, {6.0, 4.0}};
  wall.thickness_m = 0.12;
  w.walls.push_back(wall);
  w.start = {2.0, 2.0, 0.0};
  PhysicsWorld physics(w);
  EXPECT_GE(physics.static_fixture_count(), 3);  // the long segments are all there
}

}  // namespace
}  // namespace cogmap::sim
