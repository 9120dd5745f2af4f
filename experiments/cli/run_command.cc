// `cogmap run EXPERIMENT.yaml`: one simulated run into a run directory (docs/cli.md).
#include <CLI/CLI.hpp>

#include <charconv>
#include <cstdio>
#include <iostream>
#include <sstream>

#include "cogmap/experiments/experiment_config.h"
#include "cogmap/experiments/number_format.h"
#include "cogmap/experiments/progress.h"
#include "cogmap/experiments/run_directory.h"
#include "cogmap/experiments/runner.h"
#include "cogmap/experiments/usable_cores.h"
#include "cogmap/render/renderer.h"
#include "command_registry.h"
#include "option_checks.h"

namespace cogmap::cli {
namespace {

namespace fs = std::filesystem;
using experiments::format_double;

struct RunArgs {
  std::string experiment;
  std::string out;
  std::string seed;  // text: CLI11 would wrap "-1" to 2^64-1
  std::vector<std::string> sets;
  bool no_figures = false;
  bool force = false;
  bool fsync = false;
  int threads = 0;  // 0: two when the process may run on two cores or more
};

std::string opt_text(const std::optional<double>& v) { return v ? format_double(*v) : "n/a"; }

// The one-line summary: the figures a reader looks at first.
std::string summary_line(const experiments::RunMetrics& m) {
  std::ostringstream s;
  s << "asr_count=" << m.asr_count;
  if (m.map) {
    s << " wall_error_median_m=" << opt_text(m.map->wall_error_median_m)
      << " wall_coverage=" << opt_text(m.map->wall_coverage)
      << " spurious_fraction=" << opt_text(m.map->spurious_fraction);
  }
  s << " compression_ratio=" << opt_text(m.memory.compression_ratio);
  if (m.localization) {
    s << " ate_rmse_m(odom/corr)=" << format_double(m.localization->ate_rmse_odometry_m) << "/"
      << format_double(m.localization->ate_rmse_corrected_m)
      << " heading_error_final_deg(odom/corr)="
      << format_double(m.localization->heading_error_final_odometry_deg) << "/"
      << format_double(m.localization->heading_error_final_corrected_deg);
  }
  if (m.route_completed) s << " route_completed=" << (*m.route_completed ? "yes" : "no");
  s << " sim_time_s=" << format_double(m.sim_time_s);
  if (m.wall_time_s > 0.0) s << " real_time_factor=" << std::lround(m.sim_time_s / m.wall_time_s);
  return s.str();
}

// --seed N: a whole number in [0, 2^64 - 1], nothing else (no sign, no fraction, no wrap).
std::optional<std::uint64_t> parse_seed(const std::string& text) {
  if (text.empty()) return std::nullopt;
  std::uint64_t v = 0;
  const auto r = std::from_chars(text.data(), text.data() + text.size(), v);
  if (r.ec != std::errc() || r.ptr != text.data() + text.size()) {
    throw std::invalid_argument("--seed '" + text +
                                "': expected a whole number from 0 to 18446744073709551615");
  }
  return v;
}

int run(const RunArgs& args) {
  experiments::Experiment experiment;
  try {
    // The world and robot block are checked by run_experiment before anything is written,
    // so the world file is read once.
    experiment = experiments::load_experiment(args.experiment, args.sets, parse_seed(args.seed));
  } catch (const yaml::ConfigError& e) {
    std::cerr << "cogmap run: " << e.what() << "\n";
    return kExitBadInput;
  } catch (const std::invalid_argument& e) {
    std::cerr << "cogmap run: " << e.what() << "\n";
    return kExitBadInput;
  }
  fs::path out =
      args.out.empty()
          ? fs::path("runs") / experiments::safe_path_component(experiment.name + "_seed" +
                                                                std::to_string(experiment.seed))
          : fs::path(args.out);
  // `cogmap run DIR/experiment.yaml` (docs/cli.md) with DIR the default directory: the rerun
  // goes next to it, never over the file being read.
  std::error_code ec;
  if (args.out.empty() && fs::equivalent(out, fs::path(args.experiment).parent_path(), ec)) {
    out += "_rerun";
  }
  try {
    experiments::check_run_directory(
        out, {experiment.file},
        args.force ? experiments::FinishedRun::kReplace : experiments::FinishedRun::kKeep);
  } catch (const experiments::RunDirectoryError& e) {
    std::cerr << "cogmap run: " << e.what() << "\n";
    return kExitBadInput;
  }
  experiments::RunOptions options;
  options.out_dir = out;
  if (args.no_figures) options.figures = false;
  // A simulated run is redone bit for bit from its seed: fsyncing every file buys nothing a
  // rerun does not (docs/performance.md "Durability"), unless asked for.
  options.durability =
      args.fsync ? mapper::io::Durability::kSynced : mapper::io::Durability::kAtomic;
  // A helper thread traces half of each frame's sonar pings (bit-identical outputs): the
  // frame loop's one big piece of parallel work (docs/performance.md "Pings on two threads").
  options.sonar_threads =
      args.threads > 0 ? args.threads : (experiments::usable_cores() >= 2 ? 2 : 1);
  options.on_warning = [](const std::string& warning) {
    std::cerr << "cogmap run: " << warning << "\n";
  };
  experiments::ProgressBar bar(experiments::ProgressBar::stderr_is_terminal());
  options.on_progress = [&bar](double t_s, double duration_s) {
    bar.update(t_s / duration_s, "t = " + std::to_string(static_cast<long>(t_s)) + " s");
  };
  try {
    const experiments::RunSummary summary = experiments::run_experiment(experiment, options);
    bar.finish();
    std::cout << "cogmap run: " << experiment.name << " (seed " << experiment.seed
              << "): outputs in " << summary.out_dir.string() << "\n"
              << summary_line(summary.metrics) << "\n";
    return kExitOk;
  } catch (const yaml::ConfigError& e) {
    bar.finish();
    std::cerr << "cogmap run: " << e.what() << "\n";
    return kExitBadInput;
  } catch (const experiments::RunDirectoryError& e) {
    bar.finish();
    std::cerr << "cogmap run: " << e.what() << "\n";
    return kExitBadInput;
  } catch (const render::RendererUnavailable& e) {
    bar.finish();
    std::cerr << "cogmap run: " << e.what() << "\n";
    return kExitBadInput;
  } catch (const std::exception& e) {
    bar.finish();
    std::cerr << "cogmap run: " << e.what() << "\n";
    return kExitFailed;
  }
}

const CommandRegistrar kRunRegistrar{
    "run", [](CLI::App& app, int& exit_code) {
      auto args = std::make_shared<RunArgs>();
      CLI::App* sub = app.add_subcommand(
          "run", "Run one experiment in the simulator and write its run directory");
      sub->add_option("experiment", args->experiment, "experiment file (experiments/*.yaml)")
          ->required()
          ->check(CLI::ExistingFile);
      sub->add_option("--out", args->out, "run directory (default runs/<name>_seed<N>)")
          ->check(non_empty());
      sub->add_option("--seed", args->seed, "replaces the experiment's seed")
          ->check(non_empty());  // --seed "" (an unset variable) ran with the file's seed
      sub->add_option("--set", args->sets, "override any key, e.g. --set mapper.cell_scale_mm=55")
          ->take_all()
          ->allow_extra_args(false);
      sub->add_flag("--no-figures", args->no_figures, "skip the PNG figures (faster)");
      sub->add_flag("--force", args->force, "replace a finished run in --out");
      sub->add_flag("--fsync", args->fsync,
                    "fsync every room and result file as it is written (survives a power cut)");
      sub->add_option(
             "--threads", args->threads,
             "threads tracing the simulated sonar: 1 or 2 (default 2 on two usable cores or "
             "more; outputs are the same)")
          ->check(CLI::Range(1, 2));
      sub->callback([&exit_code, args] { exit_code = run(*args); });
    }};

}  // namespace
}  // namespace cogmap::cli
