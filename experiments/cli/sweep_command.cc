// `cogmap sweep SWEEP.yaml` and `cogmap sweep --merge DIR...` (docs/sweeps.md).
#include <CLI/CLI.hpp>

#include <fstream>
#include <iostream>
#include <sstream>
#include <thread>

#include "cogmap/experiments/progress.h"
#include "cogmap/experiments/runner.h"
#include "cogmap/experiments/sweep_plots.h"
#include "cogmap/experiments/sweep_runner.h"
#include "cogmap/experiments/usable_cores.h"
#include "cogmap/mapper/io/asr_json.h"
#include "cogmap/render/renderer.h"
#include "command_registry.h"
#include "option_checks.h"

namespace cogmap::cli {
namespace {

namespace fs = std::filesystem;

struct SweepArgs {
  std::vector<std::string> inputs;
  unsigned jobs = 0;
  std::string shard = "1/1";
  std::string out;
  bool merge = false;
  bool no_figures = false;
  bool fsync = false;
  bool no_plots = false;
  bool force = false;  // write into an --out whose results file or plots/ no sweep wrote
  std::size_t max_runs = experiments::SweepLimits{}.max_runs;
};

std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  if (!in) throw std::runtime_error(p.string() + ": cannot read");
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// --jobs N, or one per core when it is 0.
unsigned job_count(unsigned jobs) { return jobs > 0 ? jobs : experiments::usable_cores(); }

// A job per core keeps every core busy already: llvmpipe's own helper threads would only take
// turns with the runs. Nine-room sweep, figures on, 2 cores, medians of 3: --jobs 2 3.14 ->
// 2.89 s, --jobs 1 5.33 / 5.39 s (docs/performance.md, "Sweeps on two cores"). Called before
// any thread of the sweep starts.
void draw_without_rasteriser_threads_if_cores_are_full(unsigned jobs) {
  if (jobs >= experiments::usable_cores()) {
    render::rasterise_on_drawing_threads_only();
  }
}

void plot(const experiments::ResultsTable& table, const fs::path& out, bool enabled,
          unsigned jobs) {
  if (!enabled) return;
  try {
    const auto files = experiments::write_sweep_plots(table, out / "plots", jobs);
    if (!files.empty()) std::cout << "plots in " << (out / "plots").string() << "\n";
  } catch (const std::exception& e) {
    // The results are safe on disk already; a missing plot is worth a warning, not a failure.
    std::cerr << "cogmap sweep: plots failed: " << e.what() << "\n";
  }
}

int merge(const SweepArgs& args) {
  const fs::path out = args.out.empty() ? fs::path(".") : fs::path(args.out);
  try {
    std::vector<fs::path> dirs(args.inputs.begin(), args.inputs.end());
    std::vector<std::pair<std::string, experiments::ResultsTable>> tables;
    for (const fs::path& f : experiments::results_files(dirs)) {
      if (fs::weakly_canonical(f) == fs::weakly_canonical(out / "results.csv")) continue;
      tables.emplace_back(f.string(), experiments::parse_csv(read_text(f), f.string()));
    }
    const experiments::ResultsTable merged = experiments::merge_results(tables);
    // The header line: an earlier merge of the same results wrote the same one.
    std::string header = experiments::to_csv({merged.header, {}, {}});
    header.pop_back();
    experiments::check_sweep_directory(out, {"results.csv", header, !args.no_plots}, args.force);
    try {
      mapper::io::write_file_atomic(out / "results.csv", experiments::to_csv(merged));
    } catch (const std::exception& e) {
      // The inputs were good: a write that fails (a full disk) is exit 1, not bad input (2).
      std::cerr << "cogmap sweep --merge: " << e.what() << "\n";
      return kExitFailed;
    }
    std::cout << "cogmap sweep: merged " << tables.size() << " files, " << merged.rows.size()
              << " runs into " << (out / "results.csv").string() << "\n";
    draw_without_rasteriser_threads_if_cores_are_full(job_count(args.jobs));
    plot(merged, out, !args.no_plots, job_count(args.jobs));
    return kExitOk;
  } catch (const std::exception& e) {
    std::cerr << "cogmap sweep --merge: " << e.what() << "\n";
    return kExitBadInput;
  }
}

int sweep(const SweepArgs& args) {
  if (args.inputs.size() != 1) {
    std::cerr << "cogmap sweep: expected exactly one SWEEP.yaml (or --merge DIR...)\n";
    return kExitBadInput;
  }
  experiments::SweepSpec spec;
  experiments::SweepOptions options;
  std::vector<experiments::PlannedRun> planned;
  try {
    options.shard = experiments::parse_shard(args.shard);
  } catch (const std::invalid_argument& e) {
    std::cerr << "cogmap sweep: " << e.what() << "\n";
    return kExitBadInput;
  }
  try {
    spec = experiments::load_sweep(args.inputs.front(), {args.max_runs});
    options.out_dir = args.out.empty() ? fs::path("sweeps") / fs::path(spec.file).stem().stem()
                                       : fs::path(args.out);
    options.jobs = job_count(args.jobs);
    options.progress = experiments::ProgressBar::stderr_is_terminal();
    // Every run's experiment, world and robot block, before any run starts.
    planned = experiments::plan_sweep(spec, options);
    // Only shard 1/1 draws the plots.
    const experiments::SweepOutputs outputs{experiments::results_file_name(options.shard),
                                            experiments::results_header_start(spec),
                                            !args.no_plots && options.shard.n == 1};
    experiments::check_sweep_directory(options.out_dir, outputs, args.force);
  } catch (const yaml::ConfigError& e) {
    std::cerr << "cogmap sweep: " << e.what() << "\n";
    return kExitBadInput;
  } catch (const experiments::SweepDirectoryError& e) {
    std::cerr << "cogmap sweep: " << e.what() << "\n";
    return kExitBadInput;
  }
  const bool no_figures = args.no_figures;
  // Simulated runs are redone from their seeds: no fsync per file unless asked for
  // (docs/performance.md "Durability").
  const auto durability =
      args.fsync ? mapper::io::Durability::kSynced : mapper::io::Durability::kAtomic;
  const bool runs_draw = !no_figures && !planned.empty() && planned.front().experiment.figures;
  draw_without_rasteriser_threads_if_cores_are_full(options.jobs);
  try {
    // Runs that draw figures need the renderer plugin: fail once, before any run starts.
    if (runs_draw) render::require_renderer();
  } catch (const render::RendererUnavailable& e) {
    std::cerr << "cogmap sweep: " << e.what() << "\n";
    return kExitBadInput;
  }
  // Only the plots need it: load it (~0.3 s, LLVM's relocations and llvmpipe's start) while the
  // runs go rather than after them. A failure here shows again, as a warning, when plotting.
  std::jthread preload;
  if (!runs_draw && !args.no_plots && options.shard.n == 1) {
    preload = std::jthread([] {
      try {
        render::require_renderer();
      } catch (const std::exception&) {
      }
    });
  }
  try {
    // Marked first: a rerun after an interruption or a failure resumes here.
    experiments::mark_sweep_directory(options.out_dir, durability);
    const auto outcome = experiments::run_sweep(
        spec, planned, options, [no_figures, durability](const experiments::PlannedRun& p) {
          experiments::RunOptions run_options;
          run_options.out_dir = p.dir;
          run_options.durability = durability;
          if (no_figures) run_options.figures = false;
          (void)experiments::run_experiment(p.experiment, run_options);
        });
    std::cout << "cogmap sweep: " << outcome.runs << " runs in shard " << options.shard.k << "/"
              << options.shard.n << ": " << outcome.finished << " run, " << outcome.skipped
              << " already finished, " << outcome.failures.size() << " failed\n"
              << "results in " << outcome.results_csv.string() << "\n";
    for (const auto& f : outcome.failures) std::cerr << "cogmap sweep: failed: " << f << "\n";
    if (preload.joinable()) preload.join();
    if (options.shard.n == 1) plot(outcome.results, options.out_dir, !args.no_plots, options.jobs);
    return outcome.failures.empty() ? kExitOk : kExitFailed;
  } catch (const std::exception& e) {
    // One line each: the error, then (from run_sweep) the runs that failed before it.
    std::istringstream lines(e.what());
    for (std::string line; std::getline(lines, line);)
      std::cerr << "cogmap sweep: " << line << "\n";
    return kExitFailed;
  }
}

const CommandRegistrar kSweepRegistrar{
    "sweep", [](CLI::App& app, int& exit_code) {
      auto args = std::make_shared<SweepArgs>();
      CLI::App* sub = app.add_subcommand(
          "sweep",
          "Run every combination of a sweep file (parallel, resumable, shardable), or "
          "merge shard results with --merge DIR...");
      sub->add_option("inputs", args->inputs, "SWEEP.yaml, or with --merge the shard output dirs")
          ->required();
      sub->add_option("--jobs,-j", args->jobs, "worker threads (default, or 0: one per core)");
      sub->add_option("--shard", args->shard, "run only shard K of N, e.g. 3/8 (default 1/1)");
      sub->add_option("--out", args->out,
                      "output directory (default sweeps/<sweep name>; for --merge the current one)")
          ->check(non_empty());
      sub->add_flag("--merge", args->merge, "join results files of shard outputs");
      sub->add_flag("--no-figures", args->no_figures, "skip each run's PNG figures");
      sub->add_flag("--no-plots", args->no_plots, "skip the per-metric plots");
      sub->add_flag("--fsync", args->fsync,
                    "fsync every room and result file as it is written (survives a power cut)");
      sub->add_flag("--force", args->force,
                    "write into an --out whose results file or plots/ no sweep wrote, "
                    "replacing them");
      sub->add_option("--max-runs", args->max_runs,
                      "refuse sweeps with more runs than this (default 10000)")
          ->check(count_of_one_or_more());
      sub->callback([&exit_code, args] { exit_code = args->merge ? merge(*args) : sweep(*args); });
    }};

}  // namespace
}  // namespace cogmap::cli
