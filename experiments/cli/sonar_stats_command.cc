// `cogmap sonar-stats RECORDING... [--compare OTHER] [--csv FILE]`: per-transducer echo
// fractions, range quantiles and firing rates of any recording `replay` reads, to hold a real
// robot's sonar against the simulator's (docs/sonar-model.md "Holding a recording against the
// simulator").
#include <CLI/CLI.hpp>

#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>

#include "cogmap/experiments/recording.h"
#include "cogmap/experiments/sonar_stats.h"
#include "cogmap/hw/robot_log.h"
#include "cogmap/mapper/io/asr_json.h"
#include "command_registry.h"
#include "option_checks.h"

namespace cogmap::cli {
namespace {

namespace fs = std::filesystem;

struct SonarStatsArgs {
  std::vector<std::string> recordings;
  std::string compare;
  std::string csv;
  bool force = false;
  experiments::RecordingOptions recording;
  experiments::SonarStatsOptions stats;
};

// Pools every recording's frames into one set of statistics (all must share a geometry).
experiments::SonarStats pooled_stats(const std::vector<std::string>& paths,
                                     const SonarStatsArgs& args) {
  std::unique_ptr<experiments::SonarStatsCollector> collector;
  std::size_t sonar_count = 0;
  for (const std::string& path : paths) {
    experiments::Recording r = experiments::open_recording(path, args.recording);
    if (!r.description.empty())
      std::cerr << "cogmap sonar-stats: " << path << ": " << r.description << "\n";
    if (!collector) {
      collector =
          std::make_unique<experiments::SonarStatsCollector>(r.robot->geometry(), args.stats);
      sonar_count = r.robot->geometry().sonars.size();
    } else if (r.robot->geometry().sonars.size() != sonar_count) {
      throw hw::LogError(path + ": " + std::to_string(r.robot->geometry().sonars.size()) +
                         " sonars, but the first recording has " + std::to_string(sonar_count));
    }
    while (const auto frame = r.robot->next_frame()) collector->add(*frame);
  }
  return collector->result();
}

// --csv, checked before any recording is read: never one of the recordings (the table once
// went over its own log), never an existing file unless --force.
void check_csv_path(const SonarStatsArgs& args) {
  if (args.csv.empty()) return;
  std::vector<fs::path> inputs(args.recordings.begin(), args.recordings.end());
  if (!args.compare.empty()) inputs.emplace_back(args.compare);
  check_output_file(args.csv, "--csv", inputs, args.force);
}

int sonar_stats(const SonarStatsArgs& args) {
  try {
    check_csv_path(args);
  } catch (const OutputPathError& e) {
    std::cerr << "cogmap sonar-stats: " << e.what() << "\n";
    return kExitBadInput;
  }
  experiments::SonarStats stats, other;
  try {
    stats = pooled_stats(args.recordings, args);
    if (!args.compare.empty()) other = pooled_stats({args.compare}, args);
  } catch (const std::exception& e) {
    std::cerr << "cogmap sonar-stats: " << e.what() << "\n";
    return kExitBadInput;
  }
  if (args.compare.empty()) {
    experiments::write_sonar_stats_text(std::cout, stats);
  } else {
    std::string first;
    for (const std::string& r : args.recordings) first += (first.empty() ? "" : " + ") + r;
    experiments::write_sonar_stats_comparison(std::cout, stats, other, first, args.compare);
  }
  if (!args.csv.empty()) {
    std::ostringstream csv;
    experiments::write_sonar_stats_csv(csv, stats);
    try {
      mapper::io::write_file_atomic(args.csv, csv.str());  // temp file + rename
    } catch (const std::exception& e) {
      std::cerr << "cogmap sonar-stats: " << e.what() << "\n";
      return kExitFailed;
    }
  }
  return kExitOk;
}

const CommandRegistrar kSonarStatsRegistrar{
    "sonar-stats", [](CLI::App& app, int& exit_code) {
      auto args = std::make_shared<SonarStatsArgs>();
      CLI::App* sub = app.add_subcommand(
          "sonar-stats",
          "Per-transducer echo fraction, range quantiles and firing rate of recordings "
          "(cogmap, CARMEN, Player logs, ROS bags), counted while the robot moves");
      sub->add_option("recordings", args->recordings, "recordings, pooled")
          ->required()
          ->check(CLI::ExistingFile);
      sub->add_option("--compare", args->compare, "a second recording, shown side by side")
          ->check(CLI::ExistingFile);
      sub->add_option("--csv", args->csv,
                      "also write the table of the first as CSV here (a new file; never one of "
                      "the recordings)")
          ->check(non_empty());
      sub->add_flag("--force", args->force, "replace an existing --csv file");
      sub->add_option("--format", args->recording.format, "recording format (default: detected)")
          ->check(CLI::IsMember({"auto", "cogmap", "carmen", "player", "rosbag"}));
      sub->add_option("--robot", args->recording.bag.robot, "robot model of a bag (e.g. p3dx)");
      sub->add_option("--sonar-topic", args->recording.bag.sonar_topic, "bag sonar topic");
      sub->add_option("--odom-topic", args->recording.bag.odom_topic, "bag odometry topic");
      sub->add_option("--min-speed", args->stats.min_speed_mps,
                      "count frames only above this speed, m/s (default 0.1)")
          ->check(finite_range(0.0, 10.0));
      sub->add_option("--max-echo", args->stats.max_echo_range_m,
                      "an echo is a reading below this range, m (default 4.9)")
          ->check(finite_range(0.0, 100.0));
      sub->callback([&exit_code, args] { exit_code = sonar_stats(*args); });
    }};

}  // namespace
}  // namespace cogmap::cli
