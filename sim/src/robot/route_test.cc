// The shipped worlds are drivable: a simple waypoint follower on the true pose takes the robot
// through every door of nine_rooms in snake order and once round hallway_loop, never stalling.
// A door too narrow or furniture on the route fails here.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <vector>

#include "cogmap/sim/sim_robot.h"

namespace cogmap::sim {
namespace {

std::filesystem::path world_path(const char* name) {
  const char* env = std::getenv("COGMAP_SOURCE_DIR");
  return std::filesystem::path(env ? env : COGMAP_SOURCE_DIR_FALLBACK) / "worlds" / name;
}

struct RouteResult {
  std::size_t reached = 0;
  bool stalled = false;
};

// Turns towards the next waypoint (in place when far off heading), drives at 0.5 m/s.
RouteResult follow(const WorldSpec& world, const std::vector<mapper::Point2>& waypoints,
                   int max_cycles) {
  SimRobot robot(world, SimRobotOptions{}, 11);
  RouteResult result;
  for (int i = 0; i < max_cycles && result.reached < waypoints.size(); ++i) {
    const mapper::Pose2 pose = robot.true_pose();
    const mapper::Point2 to = waypoints[result.reached] - pose.translation();
    if (to.norm() < 0.3) {
      ++result.reached;
      continue;
    }
    const double err = mapper::wrap_angle_rad(std::atan2(to.y(), to.x()) - pose.theta_rad);
    const double v = std::abs(err) > 0.5 ? 0.0 : 0.5 * std::cos(err);
    robot.command({v, std::clamp(2.0 * err, -1.0, 1.0)});
    const auto frame = robot.next_frame();
    result.stalled = result.stalled || frame->stall_left || frame->stall_right;
  }
  return result;
}

RouteResult follow(const char* world_name, const std::vector<mapper::Point2>& waypoints,
                   int max_cycles) {
  return follow(load_world(world_path(world_name)), waypoints, max_cycles);
}

TEST(Routes, NineRoomsSnakeVisitsEveryRoom) {
  const std::vector<mapper::Point2> route{
      {2.5, 12.5}, {5, 12.5}, {7.5, 12.5}, {10, 12.5}, {12.5, 12.5}, {12.5, 10},
      {12.5, 7.5}, {10, 7.5}, {7.5, 7.5},  {5, 7.5},   {2.5, 7.5},   {2.5, 5},
      {2.5, 2.5},  {5, 2.5},  {7.5, 2.5},  {10, 2.5},  {12.5, 2.5}};
  const RouteResult r = follow("nine_rooms.yaml", route, 4000);
  EXPECT_EQ(r.reached, route.size());
  EXPECT_FALSE(r.stalled);
}

TEST(Routes, AClosedDoorStopsTheRouteAndStalls) {
  WorldSpec world = load_world(world_path("nine_rooms.yaml"));
  WallPolyline door;
  door.points = {{5.0, 12.0}, {5.0, 13.0}};  // close the door between rooms 1 and 2
  world.walls.push_back(door);
  const RouteResult r = follow(world, {{2.5, 12.5}, {5, 12.5}, {7.5, 12.5}}, 300);
  EXPECT_EQ(r.reached, 1u);
  EXPECT_TRUE(r.stalled);
}

TEST(Routes, HallwayLoopGoesRound) {
  const std::vector<mapper::Point2> route{
      {76.8, 1.2}, {76.8, 76.8}, {1.2, 76.8}, {1.2, 1.2}, {5.0, 1.2}};
  const RouteResult r = follow("hallway_loop.yaml", route, 8000);
  EXPECT_EQ(r.reached, route.size());
  EXPECT_FALSE(r.stalled);
}

TEST(Routes, SmallClutterLaneIsFree) {
  const RouteResult r = follow("small_clutter.yaml", {{11.0, 3.3}, {0.8, 3.3}}, 1000);
  EXPECT_EQ(r.reached, 2u);
  EXPECT_FALSE(r.stalled);
}

TEST(Routes, TwoRoomsThroughTheDoor) {
  const RouteResult r = follow("two_rooms.yaml", {{4.0, 3.0}, {6.0, 3.0}, {8.0, 2.5}}, 1000);
  EXPECT_EQ(r.reached, 3u);
  EXPECT_FALSE(r.stalled);
}

}  // namespace
}  // namespace cogmap::sim
