// `cogmap drive`: maps with a real P2-AT (or MobileSim, or `cogmap serve`) over P2OS on a
// serial port or TCP, optionally recording a replayable log (docs/robot-driver.md).
#include <CLI/CLI.hpp>

#include <unistd.h>
#include <algorithm>
#include <atomic>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>

#include "cogmap/experiments/experiment_config.h"
#include "cogmap/experiments/run_directory.h"
#include "cogmap/experiments/runner.h"
#include "cogmap/hw/fd_stream.h"
#include "cogmap/hw/log_robot.h"
#include "cogmap/hw/p2os_robot.h"
#include "cogmap/render/renderer.h"
#include "command_registry.h"
#include "option_checks.h"

namespace cogmap::cli {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

std::atomic<bool> g_interrupted{false};
extern "C" void on_interrupt(int) { g_interrupted = true; }

// Ends the session (next_frame empty) after Ctrl-C or at a wall-clock deadline, so the runner
// stops the robot and still writes every output. The deadline bounds a session whose peer
// sends no usable frames (frame time then never reaches duration_s).
class InterruptibleRobot final : public mapper::Robot {
 public:
  InterruptibleRobot(mapper::Robot& inner, std::chrono::steady_clock::time_point deadline)
      : inner_(inner), deadline_(deadline) {}
  const mapper::RobotGeometry& geometry() const override { return inner_.geometry(); }
  std::optional<mapper::SensorFrame> next_frame() override {
    if (g_interrupted || std::chrono::steady_clock::now() > deadline_) return std::nullopt;
    return inner_.next_frame();
  }
  void command(const mapper::VelocityCommand& cmd) override { inner_.command(cmd); }
  void stop() override { inner_.stop(); }

 private:
  mapper::Robot& inner_;
  std::chrono::steady_clock::time_point deadline_;
};

// Slack past duration_s on the wall clock before a session is cut: covers connection set-up
// and a server whose clock runs slower than ours.
constexpr std::chrono::seconds kWallSlack{30};

struct DriveArgs {
  std::string port;
  int baud = 9600;
  std::string tcp;
  std::string record;
  std::string out;
  std::optional<double> duration_s;
  std::string controller;
  std::string experiment;
  std::vector<std::string> sets;
  bool no_figures = false;
  bool sip_clock = false;
  bool force = false;  // replace an existing --record file and a finished run in --out
};

experiments::Experiment drive_default_experiment(const std::vector<std::string>& sets) {
  // Without --experiment: mapper defaults, no world, stand still; --set works as in files.
  return experiments::load_experiment_text(
      "name: drive\nworld: none\nduration_s: 60\nrobot: {source: p2os}\ncontroller: {type: none}\n",
      "drive-defaults.yaml", sets);
}

// --record: never the experiment or its world (the experiment was truncated to a log), never
// an existing file unless --force: a recording cannot be redone, so none may be lost.
void check_record_path(const DriveArgs& args, const experiments::Experiment& experiment) {
  std::vector<fs::path> inputs;
  if (!args.experiment.empty()) inputs.emplace_back(args.experiment);
  if (!experiment.world.empty()) inputs.push_back(experiment.world);
  check_output_file(args.record, "--record", inputs, args.force);
}

// Bytes from the robot side that never decode are bad input (exit 2, the message names their
// stream offsets); silence, a closed link or an unsupported robot is a failed run (exit 1).
int exit_code_for(hw::P2osFailureKind kind) {
  return kind == hw::P2osFailureKind::kBadBytes ? kExitBadInput : kExitFailed;
}

int drive(const DriveArgs& args) {
  if (args.port.empty() == args.tcp.empty()) {
    std::cerr << "cogmap drive: give exactly one of --port DEV or --tcp HOST:PORT\n";
    return kExitBadInput;
  }
  experiments::Experiment experiment;
  try {
    experiment = args.experiment.empty() ? drive_default_experiment(args.sets)
                                         : experiments::load_experiment(args.experiment, args.sets);
  } catch (const yaml::ConfigError& e) {
    std::cerr << "cogmap drive: " << e.what() << "\n";
    return kExitBadInput;
  }
  if (args.duration_s) {
    if (*args.duration_s > experiments::ExperimentLimits{}.max_duration_s) {
      std::cerr << "cogmap drive: --duration " << *args.duration_s << " is above the "
                << experiments::ExperimentLimits{}.max_duration_s
                << " s run-duration limit (docs/reliability.md)\n";
      return kExitBadInput;
    }
    experiment.duration_s = *args.duration_s;
  }
  try {
    // The log is opened (and truncated) once the robot answers: refuse a bad path before.
    if (!args.record.empty()) check_record_path(args, experiment);
  } catch (const OutputPathError& e) {
    std::cerr << "cogmap drive: " << e.what() << "\n";
    return kExitBadInput;
  }
  const fs::path out_dir =
      args.out.empty() ? fs::path("runs") / experiments::safe_path_component(experiment.name)
                       : fs::path(args.out);
  try {
    std::vector<fs::path> inputs{experiment.file};
    if (!args.record.empty()) inputs.push_back(args.record);
    experiments::check_run_directory(
        out_dir, inputs,
        args.force ? experiments::FinishedRun::kReplace : experiments::FinishedRun::kKeep);
  } catch (const experiments::RunDirectoryError& e) {
    std::cerr << "cogmap drive: " << e.what() << "\n";
    return kExitBadInput;
  }
  if (experiment.controller.steer_by_truth) {
    // A real robot has no true pose: steer by the mapper's estimate, as a real run must.
    std::cerr << "cogmap drive: controller.pose: truth is for simulated runs; steering by the "
                 "estimate\n";
    experiment.controller.steer_by_truth = false;
    experiment.steering_given = false;  // what the controller steers by follows it
  }
  if (args.controller == "explore")
    experiment.controller.type = experiments::ControllerKind::kExplore;
  if (args.controller == "route") experiment.controller.type = experiments::ControllerKind::kRoute;
  if (args.controller == "idle") experiment.controller.type = experiments::ControllerKind::kNone;
  experiments::apply_controller_defaults(experiment);  // what follows the controller type
  if (experiment.controller.type == experiments::ControllerKind::kRoute &&
      experiment.controller.waypoints.empty()) {
    std::cerr << "cogmap drive: --controller route needs waypoints (controller.waypoints in "
                 "--experiment)\n";
    return kExitBadInput;
  }

  std::unique_ptr<hw::ByteStream> stream;
  try {
    if (!args.port.empty()) {
      stream = hw::open_serial_port(args.port, args.baud);
    } else {
      stream = hw::connect_tcp(args.tcp, 5000ms);
    }
  } catch (const std::invalid_argument& e) {
    std::cerr << "cogmap drive: " << e.what() << "\n";
    return kExitBadInput;
  } catch (const hw::StreamError& e) {
    std::cerr << "cogmap drive: " << e.what() << "\n";
    return kExitFailed;
  }

  hw::P2osRobotOptions robot_options;
  robot_options.log = [](const std::string& m) { std::cerr << "cogmap drive: " << m << "\n"; };
  if (args.sip_clock) robot_options.clock = hw::FrameClock::kSipCount;
  // --duration bounds the handshake too: a peer that never completes SYNC0-2 cannot hold a
  // 5 s drive for the default 30 s.
  const auto duration_ms = std::chrono::milliseconds(
      static_cast<std::int64_t>(std::ceil(std::min(experiment.duration_s, 1e6) * 1000.0)));
  robot_options.handshake_timeout = std::min(robot_options.handshake_timeout, duration_ms);
  std::unique_ptr<hw::P2osRobot> robot;
  try {
    robot = std::make_unique<hw::P2osRobot>(std::move(stream), robot_options);
  } catch (const hw::P2osHandshakeError& e) {
    std::cerr << "cogmap drive: " << e.what() << "\n";
    return exit_code_for(e.kind());
  } catch (const hw::StreamError& e) {  // the link failed under the handshake (closed, I/O)
    std::cerr << "cogmap drive: " << e.what() << "\n";
    return kExitFailed;
  }

  std::unique_ptr<hw::RecordingRobot> recorder;
  mapper::Robot* source = robot.get();
  if (!args.record.empty()) {
    try {
      const fs::path folder = fs::path(args.record).parent_path();
      if (!folder.empty()) fs::create_directories(folder);  // as --out and --csv do
      recorder = std::make_unique<hw::RecordingRobot>(*robot, args.record);
      source = recorder.get();
    } catch (const std::exception& e) {
      std::cerr << "cogmap drive: " << e.what() << "\n";
      return kExitBadInput;
    }
  }
  InterruptibleRobot interruptible(*source,
                                   std::chrono::steady_clock::now() + duration_ms + kWallSlack);
  g_interrupted = false;
  std::signal(SIGINT, on_interrupt);
  std::signal(SIGTERM, on_interrupt);

  experiments::RunOptions options;
  options.out_dir = out_dir;
  if (args.no_figures) options.figures = false;
  if (experiment.start) options.start_pose = *experiment.start;
  int code = kExitOk;
  try {
    const auto summary =
        experiments::run_robot_session(interruptible, experiment, nullptr, options);
    std::cout << "cogmap drive: " << summary.metrics.asr_count << " rooms, outputs in "
              << summary.out_dir.string() << "\n";
  } catch (const render::RendererUnavailable& e) {
    std::cerr << "cogmap drive: " << e.what() << "\n";  // before the robot moves
    code = kExitBadInput;
  } catch (const std::exception& e) {
    std::cerr << "cogmap drive: " << e.what() << "\n";
    code = kExitFailed;
  }
  robot->shutdown();
  const hw::P2osStats s = robot->stats();
  std::cerr << "cogmap drive: " << s.sips << " SIPs, " << s.dropped_bytes << " bytes dropped, "
            << s.connections - 1 << " reconnections\n";
  if (!robot->failure().empty() && code == kExitOk && !g_interrupted) {
    const bool bad_bytes = robot->failure_kind() == hw::P2osFailureKind::kBadBytes;
    std::cerr << "cogmap drive: "
              << (bad_bytes ? "bad bytes from the robot side: " : "connection lost: ")
              << robot->failure() << "\n";
    code = exit_code_for(robot->failure_kind());
  }
  std::signal(SIGINT, SIG_DFL);
  std::signal(SIGTERM, SIG_DFL);
  return code;
}

const CommandRegistrar kDriveRegistrar{
    "drive", [](CLI::App& app, int& exit_code) {
      auto args = std::make_shared<DriveArgs>();
      CLI::App* sub = app.add_subcommand(
          "drive", "Map with a P2-AT over P2OS (serial port or TCP) and write a run directory");
      sub->add_option("--port", args->port, "serial device, e.g. /dev/ttyUSB0")->check(non_empty());
      sub->add_option("--baud", args->baud, "serial rate (9600 at power-up)")
          ->check(CLI::IsMember({9600, 19200, 38400, 57600, 115200}));
      sub->add_option("--tcp", args->tcp, "HOST:PORT (MobileSim listens on 8101)")
          ->check(non_empty());
      sub->add_option("--record", args->record,
                      "also write a replayable cogmap log here (a new file)")
          ->check(non_empty());
      sub->add_flag("--force", args->force,
                    "replace an existing --record file and a finished run in --out");
      sub->add_option("--out", args->out, "run directory (default runs/<name>)")
          ->check(non_empty());
      sub->add_option("--duration", args->duration_s, "stop after this many seconds")
          ->check(finite_positive());
      sub->add_option("--controller", args->controller, "how to drive (default: experiment's)")
          ->check(CLI::IsMember({"explore", "route", "idle"}));
      sub->add_option("--experiment", args->experiment, "experiment file (mapper, controller)")
          ->check(CLI::ExistingFile);
      sub->add_option("--set", args->sets, "override any key, e.g. --set mapper.grid=bayes")
          ->take_all()
          ->allow_extra_args(false);
      sub->add_flag("--no-figures", args->no_figures, "skip the PNG figures");
      sub->add_flag("--sip-clock", args->sip_clock,
                    "time = 0.1 s per SIP, not the host clock (for `cogmap serve --cycle-ms` "
                    "faster than real time)");
      sub->callback([&exit_code, args] { exit_code = drive(*args); });
    }};

}  // namespace
}  // namespace cogmap::cli
