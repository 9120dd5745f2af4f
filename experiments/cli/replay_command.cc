// `cogmap replay LOG`: runs the mapper over a recorded log (cogmap, CARMEN, Player, ROS 1 bag)
// through the same session loop as live runs (docs/robot-driver.md). Ground truth is used only
// when the log carries true poses and --experiment names the world they belong to.
#include <CLI/CLI.hpp>

#include <unistd.h>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>

#include "cogmap/experiments/experiment_config.h"
#include "cogmap/experiments/recording.h"
#include "cogmap/experiments/run_directory.h"
#include "cogmap/experiments/runner.h"
#include "cogmap/hw/bag_import.h"
#include "cogmap/hw/log_import.h"
#include "cogmap/render/renderer.h"
#include "cogmap/sim/world_geometry.h"
#include "cogmap/sim/world_spec.h"
#include "command_registry.h"
#include "option_checks.h"

namespace cogmap::cli {
namespace {

namespace fs = std::filesystem;

struct ReplayArgs {
  std::string log;
  std::string out;
  std::string experiment;
  std::vector<std::string> sets;
  std::string format = "auto";
  bool no_figures = false;
  bool force = false;
  hw::BagImportOptions bag;  ///< --sonar-topic, --odom-topic, --robot (ROS bags only)
};

// Without --experiment: a minimal document, so --set and the mapper defaults work as in files.
// The name (from the log's file name, which may hold any byte) is set after parsing, never
// pasted into YAML text: a name with ": " or a newline must not become keys.
experiments::Experiment replay_default_experiment(const std::string& name,
                                                  const std::vector<std::string>& sets) {
  experiments::Experiment e = experiments::load_experiment_text(
      "name: replay\nworld: none\nrobot: {source: log}\ncontroller: {type: none}\n",
      "replay-defaults.yaml", sets);
  e.name = name;
  YAML::Node doc = YAML::Load(e.resolved_yaml);
  doc["name"] = name;  // the emitter quotes whatever the name holds
  YAML::Emitter out;
  out << doc;
  e.resolved_yaml = std::string(out.c_str()) + "\n";
  return e;
}

int replay(const ReplayArgs& args) {
  // The robot: a cogmap log streams; foreign logs and bags are imported into memory.
  experiments::Recording recording;
  try {
    recording = experiments::open_recording(args.log, {args.format, args.bag});
  } catch (const hw::LogError& e) {
    std::cerr << "cogmap replay: " << e.what() << "\n";
    return kExitBadInput;
  }
  if (!recording.description.empty()) {
    std::cerr << "cogmap replay: " << recording.description << "\n";
  }
  mapper::Robot& robot = *recording.robot;
  const double last_time_s = recording.last_time_s;

  experiments::Experiment experiment;
  std::unique_ptr<experiments::GroundTruth> truth;
  experiments::RunOptions options;
  try {
    if (args.experiment.empty()) {
      experiment = replay_default_experiment(
          "replay_" + experiments::safe_path_component(fs::path(args.log).stem().string()),
          args.sets);
    } else {
      experiment = experiments::load_experiment(args.experiment, args.sets);
      sim::WorldSpec world = sim::load_world(experiment.world);
      if (experiment.start) world.start = *experiment.start;
      // Without ground truth the odometry frame is placed like `cogmap drive` places it.
      if (experiment.start) options.start_pose = *experiment.start;
      if (recording.has_true_poses) {
        truth = std::make_unique<experiments::GroundTruth>(
            experiments::GroundTruth{sim::true_surfaces(world), world.start});
      }
    }
  } catch (const yaml::ConfigError& e) {
    std::cerr << "cogmap replay: " << e.what() << "\n";
    return kExitBadInput;
  }
  if (recording.has_true_poses && !truth) {
    std::cerr << "cogmap replay: the log carries true poses but no --experiment names their "
                 "world: map metrics are omitted\n";
  }
  // The log decides what happens: every frame is replayed and commands are not needed.
  experiment.controller.type = experiments::ControllerKind::kNone;
  experiment.controller.steer_by_truth = false;
  experiment.controller.steer_by_plain_estimate = false;  // nothing steers: no second mapper
  experiment.duration_s = last_time_s + 1.0;
  options.out_dir = args.out.empty()
                        ? fs::path("runs") / experiments::safe_path_component(experiment.name)
                        : fs::path(args.out);
  try {
    experiments::check_run_directory(
        options.out_dir, {experiment.file, fs::path(args.log)},
        args.force ? experiments::FinishedRun::kReplace : experiments::FinishedRun::kKeep);
  } catch (const experiments::RunDirectoryError& e) {
    std::cerr << "cogmap replay: " << e.what() << "\n";
    return kExitBadInput;
  }
  if (args.no_figures) options.figures = false;
  try {
    const auto summary = experiments::run_robot_session(robot, experiment, truth.get(), options);
    std::cout << "cogmap replay: " << args.log << ": " << summary.metrics.asr_count
              << " rooms, outputs in " << summary.out_dir.string() << "\n";
    return kExitOk;
  } catch (const experiments::RunDirectoryError& e) {
    std::cerr << "cogmap replay: " << e.what() << "\n";
    return kExitBadInput;
  } catch (const render::RendererUnavailable& e) {
    std::cerr << "cogmap replay: " << e.what() << "\n";  // before any frame is replayed
    return kExitBadInput;
  } catch (const std::exception& e) {
    std::cerr << "cogmap replay: " << e.what() << "\n";
    return kExitFailed;
  }
}

const CommandRegistrar kReplayRegistrar{
    "replay", [](CLI::App& app, int& exit_code) {
      auto args = std::make_shared<ReplayArgs>();
      CLI::App* sub = app.add_subcommand("replay",
                                         "Map a recorded log (cogmap, CARMEN, Player 2.x-3.x or "
                                         "ROS 1 bag) and write a run directory");
      sub->add_option("log", args->log, "the log file")->required()->check(CLI::ExistingFile);
      sub->add_option("--out", args->out, "run directory (default runs/replay_<log name>)")
          ->check(non_empty());
      sub->add_option("--experiment", args->experiment,
                      "experiment file: mapper settings, and the world for ground truth")
          ->check(CLI::ExistingFile);
      sub->add_option("--set", args->sets, "override any key, e.g. --set mapper.grid=bayes")
          ->take_all()
          ->allow_extra_args(false);
      sub->add_option("--format", args->format, "log format (default: detected)")
          ->check(CLI::IsMember({"auto", "cogmap", "carmen", "player", "rosbag"}));
      sub->add_option("--robot", args->bag.robot,
                      "ROS bag: the robot model (p2at, p2at8, p3at, p3dx, p2dx, p2de, peoplebot)");
      sub->add_option("--sonar-topic", args->bag.sonar_topic,
                      "ROS bag: the sonar topic (default: detected by type)");
      sub->add_option("--odom-topic", args->bag.odom_topic,
                      "ROS bag: the nav_msgs/Odometry or /tf topic (default: detected)");
      sub->add_flag("--no-figures", args->no_figures, "skip the PNG figures (faster)");
      sub->add_flag("--force", args->force, "replace a finished run in --out");
      sub->callback([&exit_code, args] { exit_code = replay(*args); });
    }};

}  // namespace
}  // namespace cogmap::cli
