// robot.model: the simulator builds any Pioneer of the model table.
#include <gtest/gtest.h>

#include <algorithm>

#include "cogmap/sim/sim_robot.h"

namespace cogmap::sim {
namespace {

SimRobotOptions parse_robot(const std::string& block) {
  return parse_sim_robot_options(yaml::Node::load_string("robot:\n" + block, "e.yaml")["robot"]);
}

// A square room, walls `half_m` from the start on every side.
WorldSpec box_world(int half_m = 3) {
  const std::string a = std::to_string(-half_m), b = std::to_string(half_m);
  const std::string square = "[[" + a + ", " + a + "], [" + b + ", " + a + "], [" + b + ", " + b +
                             "], [" + a + ", " + b + "], [" + a + ", " + a + "]]";
  return parse_world(
      yaml::Node::load_string("name: box\nwalls:\n  thickness_m: 0.1\n"
                              "  polylines:\n    - " +
                                  square + "\nstart: {x_m: 0, y_m: 0, theta_deg: 0}\n",
                              "w.yaml"));
}

TEST(SimRobotModel, DefaultIsTheP2at) {
  const SimRobotOptions o = parse_robot("  source: sim\n");
  EXPECT_EQ(o.model, "p2at");
  EXPECT_DOUBLE_EQ(o.odometry.track_m, OdometryOptions{}.track_m);
  EXPECT_DOUBLE_EQ(o.odometry.calibrated_track_factor, 1.5);
}

TEST(SimRobotModel, P3dxIsADifferentialDrive) {
  const SimRobotOptions o = parse_robot("  model: p3dx\n");
  EXPECT_EQ(o.model, "p3dx");
  // ARIA p3dx.p DiffConvFactor 0.0056: track 2 / 0.0056 mm, no skid.
  EXPECT_NEAR(o.odometry.track_m, 0.35714, 1e-5);
  EXPECT_DOUBLE_EQ(o.odometry.calibrated_track_factor, 1.0);
  EXPECT_DOUBLE_EQ(o.odometry.effective_track_factor, 1.0);
  EXPECT_DOUBLE_EQ(o.odometry.curvature_gain, 0.0);
  // robot.odometry keys still win.
  const SimRobotOptions custom = parse_robot("  model: p3dx\n  odometry: {track_m: 0.33}\n");
  EXPECT_DOUBLE_EQ(custom.odometry.track_m, 0.33);
  EXPECT_DOUBLE_EQ(custom.odometry.calibrated_track_factor, 1.0);
  const SimRobotOptions ideal = parse_robot("  model: p3dx\n  odometry: {preset: ideal}\n");
  EXPECT_DOUBLE_EQ(ideal.odometry.track_m, ideal_odometry_options().track_m);
}

TEST(SimRobotModel, P3dxBodyAndSonarRing) {
  SimRobotOptions o = parse_robot("  model: p3dx\n");
  SimRobot robot(box_world(20), o, 1);
  const mapper::RobotGeometry& g = robot.geometry();
  ASSERT_EQ(g.sonars.size(), 16u);
  EXPECT_DOUBLE_EQ(g.sonars[3].x_m, 0.166);  // p3dx.p SonarUnit 3 166 27 10
  EXPECT_DOUBLE_EQ(g.width_m, 0.425);
  EXPECT_DOUBLE_EQ(g.max_speed_mps, 1.0);
  // Commands are clamped to the P3-DX's 1.0 m/s, not the P2-AT's 0.75: after the 0.3 m/s²
  // ramp (3.3 s) the last of 5 s covers 1.0 m.
  robot.command({2.0, 0.0});
  for (int i = 0; i < 40; ++i) robot.next_frame();
  const double x4 = robot.true_pose().x_m;
  for (int i = 0; i < 10; ++i) robot.next_frame();
  EXPECT_NEAR(robot.true_pose().x_m - x4, 1.0, 0.02);
}

TEST(SimRobotModel, PeopleBotFiresAllFourArrays) {
  SimRobot robot(box_world(), parse_robot("  model: peoplebot\n"), 2);
  ASSERT_EQ(robot.geometry().sonars.size(), 32u);
  int max_index = -1;
  for (int i = 0; i < 10; ++i) {
    const auto frame = robot.next_frame();
    for (const auto& r : frame->sonar) max_index = std::max(max_index, r.index);
  }
  // 40 ms per disc, 8 discs per array: in 1 s every array fires every disc, up to 31.
  EXPECT_EQ(max_index, 31);
}

TEST(SimRobotModel, PollingMustFitTheModelsArrays) {
  // A P2-AT has two arrays (0-7, 8-15): both may be sequenced.
  EXPECT_EQ(parse_robot("  model: p2at\n  sonar: {polling: [[0, 7], [8, 15]]}\n").sonar.polling,
            (std::vector<std::vector<int>>{{0, 7}, {8, 15}}));
  // It has no third array (16-23): a sequence for one is refused at its line, not later when
  // the robot is built.
  try {
    parse_robot("  model: p2at\n  sonar:\n    polling: [[0, 1], [8, 9], [16]]\n");
    FAIL() << "a third array on a p2at was accepted";
  } catch (const yaml::ConfigError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("e.yaml:4:"), std::string::npos) << msg;
    EXPECT_NE(msg.find("transducer 16 is not on a p2at (16 sonars)"), std::string::npos) << msg;
  }
}

}  // namespace
}  // namespace cogmap::sim
