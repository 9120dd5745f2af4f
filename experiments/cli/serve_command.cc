// `cogmap serve`: the simulator behind the robot side of P2OS, on a pseudo-terminal or a TCP
// port, so `cogmap drive` (or any P2OS client: ARIA, Player's p2os driver) can connect to a
// simulated P2-AT as to a real one (docs/robot-driver.md).
#include <CLI/CLI.hpp>

#include <atomic>
#include <csignal>
#include <iostream>
#include <memory>
#include <optional>
#include <stop_token>
#include <thread>

#include "cogmap/experiments/experiment_config.h"
#include "cogmap/hw/fd_stream.h"
#include "cogmap/hw/p2os_server.h"
#include "cogmap/sim/sim_robot.h"
#include "cogmap/sim/world_spec.h"
#include "command_registry.h"
#include "option_checks.h"

namespace cogmap::cli {
namespace {

using namespace std::chrono_literals;

std::atomic<bool> g_stop{false};
extern "C" void on_stop_signal(int) { g_stop = true; }

// Turns Ctrl-C, SIGTERM and --duration into the server's stop flag, from two threads. Its
// destructor raises the flag, joins them (std::jthread; they also end on its stop request, so a
// failed construction joins too) and restores the signals, so an exception thrown while serving
// unwinds through it to the CLI's report instead of ending in std::terminate (a joinable
// std::thread destroyed).
class StopThreads {
 public:
  StopThreads(std::atomic<bool>& stop, std::optional<double> duration_s) {
    g_stop = false;
    std::signal(SIGINT, on_stop_signal);
    std::signal(SIGTERM, on_stop_signal);
    if (duration_s) {
      timer_ = std::jthread([seconds = *duration_s](std::stop_token quit) {
        const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
        while (!g_stop && !quit.stop_requested() && std::chrono::steady_clock::now() < end) {
          std::this_thread::sleep_for(50ms);
        }
        g_stop = true;
      });
    }
    forward_ = std::jthread([&stop](std::stop_token quit) {
      while (!g_stop && !quit.stop_requested()) std::this_thread::sleep_for(20ms);
      stop = true;
    });
  }
  StopThreads(const StopThreads&) = delete;
  StopThreads& operator=(const StopThreads&) = delete;
  ~StopThreads() {
    g_stop = true;
    forward_ = {};  // joins
    timer_ = {};
    std::signal(SIGINT, SIG_DFL);
    std::signal(SIGTERM, SIG_DFL);
  }

 private:
  std::jthread timer_;
  std::jthread forward_;
};

struct ServeArgs {
  std::string experiment;
  std::vector<std::string> sets;
  bool pty = false;
  std::string tcp;
  int cycle_ms = 100;
  std::optional<double> duration_s;
};

int serve(const ServeArgs& args) {
  if (args.pty == !args.tcp.empty()) {
    std::cerr << "cogmap serve: give exactly one of --pty or --tcp HOST:PORT\n";
    return kExitBadInput;
  }
  experiments::Experiment experiment;
  sim::WorldSpec world;
  sim::SimRobotOptions sim_options;
  try {
    experiment = experiments::load_experiment(args.experiment, args.sets);
    world = sim::load_world(experiment.world);
    if (experiment.start) world.start = *experiment.start;
    const yaml::Node block = experiment.robot
                                 ? *experiment.robot
                                 : yaml::Node::load_string("{}", experiment.file.string());
    sim_options = sim::parse_sim_robot_options(block);
  } catch (const yaml::ConfigError& e) {
    std::cerr << "cogmap serve: " << e.what() << "\n";
    return kExitBadInput;
  }
  sim::SimRobot body(world, sim_options, experiment.seed);

  hw::P2osServerOptions server_options;
  server_options.cycle = std::chrono::milliseconds(args.cycle_ms);
  server_options.log = [](const std::string& m) { std::cerr << "cogmap serve: " << m << "\n"; };
  // A client may re-time and re-sequence the sonar as on a real P2OS controller.
  server_options.set_sonar_cycle_ms = [&body](int ms) { body.set_sonar_cycle_ms(ms); };
  server_options.set_sonar_polling = [&body](int array, const std::vector<int>& sequence) {
    body.set_sonar_polling(array, sequence);
  };

  std::atomic<bool> stop{false};
  const StopThreads stop_threads(stop, args.duration_s);
  int code = kExitOk;
  try {
    if (args.pty) {
      auto pty = hw::open_pty();
      std::cout << pty->slave_path << std::endl;  // for scripts: the device to drive
      std::cerr << "cogmap serve: " << experiment.name << " as a p2at on " << pty->slave_path
                << " (Ctrl-C to stop)\n";
      hw::P2osServer server(*pty->master, body, server_options);
      server.run(stop);
    } else {
      hw::TcpListener listener(args.tcp);
      std::cout << "tcp:" << listener.port() << std::endl;
      std::cerr << "cogmap serve: " << experiment.name << " as a p2at on " << args.tcp
                << " (Ctrl-C to stop)\n";
      // One client at a time; the next may connect when it hangs up (as with MobileSim).
      while (!stop) {
        auto client = listener.accept(200ms);
        if (!client) continue;
        std::cerr << "cogmap serve: client connected\n";
        hw::P2osServer server(*client, body, server_options);
        server.run(stop);
        std::cerr << "cogmap serve: client gone\n";
      }
    }
  } catch (const std::invalid_argument& e) {
    std::cerr << "cogmap serve: " << e.what() << "\n";
    code = kExitBadInput;
  } catch (const hw::StreamError& e) {
    std::cerr << "cogmap serve: " << e.what() << "\n";
    code = kExitFailed;
  }
  return code;
}

const CommandRegistrar kServeRegistrar{
    "serve", [](CLI::App& app, int& exit_code) {
      auto args = std::make_shared<ServeArgs>();
      CLI::App* sub = app.add_subcommand(
          "serve", "Serve a simulated P2-AT over P2OS on a pseudo-terminal or TCP port");
      sub->add_option("--experiment", args->experiment, "experiment file (world, robot, seed)")
          ->required()
          ->check(CLI::ExistingFile);
      sub->add_option("--set", args->sets, "override any key")->take_all()->allow_extra_args(false);
      sub->add_flag("--pty", args->pty, "serve on a new pseudo-terminal (its path is printed)");
      sub->add_option("--tcp", args->tcp, "serve on HOST:PORT, e.g. 127.0.0.1:8101")
          ->check(non_empty());
      sub->add_option("--cycle-ms", args->cycle_ms,
                      "wall-clock ms per 100 ms SIP cycle (< 100 runs faster than real time)")
          ->check(CLI::Range(5, 1000));
      sub->add_option("--duration", args->duration_s, "stop after this many wall seconds")
          ->check(finite_positive());
      sub->callback([&exit_code, args] { exit_code = serve(*args); });
    }};

}  // namespace
}  // namespace cogmap::cli
