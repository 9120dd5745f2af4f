// The experiment's `robot:` block for a simulated P2-AT (docs/simulator.md).
#include <string>

#include "cogmap/sim/sim_robot.h"

namespace cogmap::sim {

SimRobotOptions parse_sim_robot_options(const yaml::Node& robot_block) {
  robot_block.expect_keys(
      {"source", "model", "sonar", "odometry", "cycle_s", "physics_substeps", "rot_accel_radps2"});
  SimRobotOptions options;
  if (const auto source = robot_block.child("source")) {
    if (source->as<std::string>() != "sim") {
      source->fail("a simulated robot needs source: sim (got '" + source->as<std::string>() + "')");
    }
  }
  if (const auto model = robot_block.child("model")) {
    if (model->as<std::string>() != "p2at") {
      model->fail("the simulator models only the Pioneer P2-AT (model: p2at)");
    }
  }
  if (const auto sonar = robot_block.child("sonar")) options.sonar = parse_sonar_options(*sonar);
  if (const auto odometry = robot_block.child("odometry")) {
    options.odometry = parse_odometry_options(*odometry);
  }
  if (const auto cycle = robot_block.child("cycle_s")) {
    options.cycle_s = cycle->as<double>();
    if (options.cycle_s <= 0.0 || options.cycle_s > 10.0) {
      cycle->fail("cycle_s must be in (0, 10] seconds");
    }
  }
  if (const auto substeps = robot_block.child("physics_substeps")) {
    options.physics_substeps = substeps->as<int>();
    if (options.physics_substeps < 1 || options.physics_substeps > 1000) {
      substeps->fail("physics_substeps must be in 1..1000");
    }
  }
  if (const auto rot = robot_block.child("rot_accel_radps2")) {
    options.rot_accel_radps2 = rot->as<double>();
    if (options.rot_accel_radps2 <= 0.0) rot->fail("rot_accel_radps2 must be positive");
  }
  return options;
}

}  // namespace cogmap::sim
