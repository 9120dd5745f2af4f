// run_experiment: the simulator side of the runner (world + SimRobot), kept apart from the
// robot-agnostic loop in runner.cc.
#include <memory>
#include <stdexcept>

#include "cogmap/experiments/runner.h"
#include "cogmap/sim/sim_robot.h"
#include "cogmap/sim/world_enclosure.h"
#include "cogmap/sim/world_geometry.h"
#include "cogmap/sim/world_spec.h"

namespace cogmap::experiments {
namespace {

// An absent `robot` block means every sim default.
yaml::Node robot_block_of(const Experiment& experiment) {
  return experiment.robot ? *experiment.robot
                          : yaml::Node::load_string("{}", experiment.file.string());
}

// The world named by `world:`; when the file itself cannot be read (missing, a device, too
// large) the error names the experiment's `world` key and line rather than the bare path.
sim::WorldSpec load_world_of(const Experiment& experiment) {
  try {
    return sim::load_world(experiment.world);
  } catch (const yaml::ConfigError& e) {
    if (e.line() > 0 || e.file() != experiment.world.string()) throw;
    throw yaml::ConfigError(experiment.file.string(), experiment.world_line, "world",
                            "world file " + experiment.world.string() + ": " + bare_message(e) +
                                (experiment.world_override.empty() ? "" : " ") +
                                experiment.world_override);
  }
}

}  // namespace

void validate_experiment(const Experiment& experiment) {
  if (experiment.robot_source != RobotSource::kSim) return;  // the hw module checks its own
  (void)load_world_of(experiment);
  (void)sim::parse_sim_robot_options(robot_block_of(experiment));
}

RunSummary run_experiment(const Experiment& experiment, const RunOptions& options) {
  const yaml::Node robot_block = robot_block_of(experiment);
  if (experiment.robot_source != RobotSource::kSim) {
    const auto src = robot_block.child("source");
    throw yaml::ConfigError(experiment.file.string(), src ? src->line() : robot_block.line(),
                            "robot.source",
                            "'cogmap run' simulates; use 'cogmap drive' or 'cogmap replay' for '" +
                                std::string(to_string(experiment.robot_source)) + "'");
  }
  sim::WorldSpec world = load_world_of(experiment);
  if (experiment.start) world.start = *experiment.start;
  if (options.on_warning) {
    if (const auto w = sim::start_enclosure_warning(world, world.start.translation())) {
      // The world's own start at its line; an experiment's `start` (no line kept) at its file.
      options.on_warning(
          (experiment.start ? experiment.file.string()
                            : world.file.string() + ":" + std::to_string(world.start_source.line)) +
          ": warning: " + *w);
    }
  }
  const sim::SimRobotOptions robot_options = sim::parse_sim_robot_options(robot_block);
  std::unique_ptr<sim::SimRobot> robot;
  try {
    robot = std::make_unique<sim::SimRobot>(world, robot_options, experiment.seed);
    robot->set_sonar_threads(options.sonar_threads);
  } catch (const std::invalid_argument& e) {
    throw yaml::ConfigError(experiment.file.string(), robot_block.line(), "robot", e.what());
  }
  const GroundTruth truth{sim::true_surfaces(world), world.start};
  return run_robot_session(*robot, experiment, &truth, options);
}

}  // namespace cogmap::experiments
