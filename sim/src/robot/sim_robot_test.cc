#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>

#include "cogmap/sim/seed.h"
#include "cogmap/sim/sim_robot.h"
#include "world/world_test_support.h"

namespace cogmap::sim {
namespace {

using testing::parse;

using testing::source_dir;

// FNV-1a over the exact bit patterns of everything a frame carries.
struct FrameHash {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  void add(std::uint64_t v) {
    for (int i = 0; i < 8; ++i) {
      h ^= (v >> (8 * i)) & 0xff;
      h *= 0x100000001b3ULL;
    }
  }
  void add(double v) { add(std::bit_cast<std::uint64_t>(v)); }
  void add(const mapper::Pose2& p) {
    add(p.x_m);
    add(p.y_m);
    add(p.theta_rad);
  }
  void add(const mapper::SensorFrame& f) {
    add(f.time_s);
    add(f.odometry);
    for (const auto& r : f.sonar) {
      add(static_cast<std::uint64_t>(r.index));
      add(r.range_m);
      add(static_cast<std::uint64_t>(r.echo));
      add(r.time_s);
    }
    add(static_cast<std::uint64_t>(f.stall_left) * 2 + f.stall_right);
    add(*f.true_pose);
  }
};

// A fixed drive schedule that turns, stops and reverses, so every code path runs.
mapper::VelocityCommand schedule(int cycle) {
  switch ((cycle / 40) % 4) {
    case 0:
      return {0.5, 0.0};
    case 1:
      return {0.3, 0.6};
    case 2:
      return {0.0, -1.0};
    default:
      return {-0.2, 0.2};
  }
}

std::uint64_t run_hash(const WorldSpec& world, std::uint64_t seed, int cycles) {
  SimRobot robot(world, SimRobotOptions{}, seed);
  FrameHash hash;
  for (int i = 0; i < cycles; ++i) {
    robot.command(schedule(i));
    hash.add(*robot.next_frame());
  }
  return hash.h;
}

TEST(SimRobot, SameSeedGivesBitIdenticalFrames) {
  const WorldSpec world = load_world(source_dir() / "worlds" / "two_rooms.yaml");
  const std::uint64_t a = run_hash(world, 7, 300);
  EXPECT_EQ(a, run_hash(world, 7, 300));
  EXPECT_NE(a, run_hash(world, 8, 300));
}

TEST(SimRobot, FramesCarryTimeSonarAndTruth) {
  const WorldSpec world = load_world(source_dir() / "worlds" / "two_rooms.yaml");
  SimRobot robot(world, SimRobotOptions{}, 1);
  std::size_t readings = 0;
  for (int i = 1; i <= 50; ++i) {
    const auto frame = robot.next_frame();
    ASSERT_TRUE(frame.has_value());
    EXPECT_DOUBLE_EQ(frame->time_s, i * 0.1);
    ASSERT_TRUE(frame->true_pose.has_value());
    for (const auto& r : frame->sonar) {
      EXPECT_GT(r.time_s, frame->time_s - 0.1 - 1e-12);
      EXPECT_LE(r.time_s, frame->time_s + 1e-12);
    }
    readings += frame->sonar.size();
  }
  // Each of the two arrays fires one transducer every 40 ms: 5 s bring 2 x 125 pings.
  EXPECT_EQ(readings, 250u);
  EXPECT_DOUBLE_EQ(robot.sim_time_s(), 5.0);
  EXPECT_EQ(robot.geometry().sonars.size(), 16u);
}

TEST(SimRobot, IdealOdometryEqualsTruthInOpenSpace) {
  const WorldSpec world =
      parse("name: open\nwalls: {polylines: []}\nstart: {x_m: 2, y_m: -1, theta_deg: 30}\n");
  SimRobotOptions options;
  options.odometry = ideal_odometry_options();
  SimRobot robot(world, options, 3);
  for (int i = 0; i < 300; ++i) {
    robot.command(schedule(i));
    const auto f = robot.next_frame();
    const mapper::Pose2 odom_in_world = world.start.compose(f->odometry);
    ASSERT_NEAR(odom_in_world.x_m, f->true_pose->x_m, 1e-9) << "cycle " << i;
    ASSERT_NEAR(odom_in_world.y_m, f->true_pose->y_m, 1e-9) << "cycle " << i;
    ASSERT_NEAR(mapper::wrap_angle_rad(odom_in_world.theta_rad - f->true_pose->theta_rad), 0.0,
                1e-9);
    EXPECT_FALSE(f->stall_left || f->stall_right);
  }
}

TEST(SimRobot, DrivingIntoAWallStallsWhileOdometryRunsOn) {
  const WorldSpec world = parse(
      "name: wall\nwalls: {thickness_m: 0.12, polylines: [[[3, -2], [3, 2]]]}\n"
      "start: {x_m: 1, y_m: 0}\n");
  SimRobotOptions options;
  options.odometry = ideal_odometry_options();
  SimRobot robot(world, options, 5);
  robot.command({0.5, 0.0});
  double last_odom_x = 0.0;
  bool stalled_early = false;
  for (int i = 0; i < 100; ++i) {  // 10 s: free run of ~1.6 m, then the wall
    const auto f = robot.next_frame();
    if (i < 20) stalled_early = stalled_early || f->stall_left || f->stall_right;
    EXPECT_LT(f->true_pose->x_m, 2.94 - 0.313 + 0.011);
    if (i > 0) {
      EXPECT_GT(f->odometry.x_m, last_odom_x);  // the wheels keep turning
    }
    last_odom_x = f->odometry.x_m;
    if (i == 99) {
      EXPECT_TRUE(f->stall_left);
      EXPECT_TRUE(f->stall_right);
    }
  }
  EXPECT_FALSE(stalled_early);
  EXPECT_GT(last_odom_x, 4.0);  // 10 s at up to 0.5 m/s, counted though the body stood still
  EXPECT_GT(robot.true_pose().x_m, 2.5);
  robot.stop();
  for (int i = 0; i < 20; ++i) robot.next_frame();
  const auto f = robot.next_frame();
  EXPECT_FALSE(f->stall_left || f->stall_right);  // stopped: no longer driven
}

TEST(SimRobotOptions, ParsesTheRobotBlock) {
  const auto node = yaml::Node::load_string(
      "robot:\n  source: sim\n  model: p2at\n  cycle_s: 0.05\n  physics_substeps: 4\n", "e.yaml");
  const SimRobotOptions o = parse_sim_robot_options(node["robot"]);
  EXPECT_DOUBLE_EQ(o.cycle_s, 0.05);
  EXPECT_EQ(o.physics_substeps, 4);
  auto error = [](const std::string& text) -> std::string {
    try {
      parse_sim_robot_options(yaml::Node::load_string(text, "e.yaml")["robot"]);
    } catch (const yaml::ConfigError& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_EQ(error("robot:\n  cycle: 0.1\n").rfind("e.yaml:2: robot.cycle: unknown key", 0), 0u);
  EXPECT_NE(error("robot:\n  physics_substeps: 0\n").find("robot.physics_substeps"),
            std::string::npos);
  EXPECT_NE(error("robot:\n  source: p2os\n").find("source: sim"), std::string::npos);
  EXPECT_NE(error("robot:\n  model: r2d2\n").find("robot.model: unknown robot model 'r2d2'"),
            std::string::npos);
  EXPECT_NE(error("robot:\n  cycle_s: fast\n").find("e.yaml:2: robot.cycle_s"), std::string::npos);
}

TEST(Seed, DerivedStreamsDiffer) {
  EXPECT_NE(derive_seed(1, 1), derive_seed(1, 2));
  EXPECT_NE(derive_seed(1, 1), derive_seed(2, 1));
  EXPECT_EQ(derive_seed(9, 1), derive_seed(9, 1));
}

}  // namespace
}  // namespace cogmap::sim
