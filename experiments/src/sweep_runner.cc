#include "cogmap/experiments/sweep_runner.h"

#include <algorithm>
#include <atomic>
#include <fstream>
#include <mutex>
#include <sstream>
#include <thread>

#include "cogmap/experiments/progress.h"
#include "cogmap/mapper/io/asr_json.h"

namespace cogmap::experiments {
namespace {

namespace fs = std::filesystem;

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path.string() + ": cannot read");
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

std::string results_file_name(Shard shard) {
  if (shard.n <= 1) return "results.csv";
  return "results_shard_" + std::to_string(shard.k) + "_of_" + std::to_string(shard.n) + ".csv";
}

std::vector<PlannedRun> plan_sweep(const SweepSpec& spec, const SweepOptions& options) {
  std::vector<PlannedRun> planned;
  for (const SweepRun& run : shard_runs(expand_sweep(spec), options.shard)) {
    PlannedRun p;
    p.run = run;
    try {
      p.experiment = load_experiment(spec.base, run.overrides(), run.seed);
    } catch (const yaml::ConfigError& e) {
      // Name the sweep too: the key that failed came from its `vary` block.
      throw yaml::ConfigError(
          e.file(), e.line(), e.key(),
          bare_message(e) + " (in sweep " + spec.file.string() + ", run " + run.dir_name() + ")");
    }
    p.dir = options.out_dir / "runs" / run.dir_name();
    planned.push_back(std::move(p));
  }
  return planned;
}

SweepOutcome run_sweep(const SweepSpec& spec, const std::vector<PlannedRun>& planned,
                       const SweepOptions& options, const RunFunction& run_one) {
  SweepOutcome outcome;
  outcome.runs = planned.size();
  std::vector<const PlannedRun*> todo;
  for (const PlannedRun& p : planned) {
    if (fs::exists(p.dir / "metrics.json")) {
      ++outcome.skipped;
    } else {
      todo.push_back(&p);
    }
  }
  ProgressBar bar(options.progress);
  std::atomic<std::size_t> next{0};
  std::atomic<std::size_t> done{0};
  std::mutex failures_mutex;
  auto worker = [&] {
    for (std::size_t i = next.fetch_add(1); i < todo.size(); i = next.fetch_add(1)) {
      const PlannedRun& p = *todo[i];
      try {
        run_one(p);
      } catch (const std::exception& e) {
        const std::lock_guard lock(failures_mutex);
        outcome.failures.push_back(p.run.dir_name() + ": " + e.what());
      }
      const std::size_t d = done.fetch_add(1) + 1;
      bar.update(static_cast<double>(d) / static_cast<double>(todo.size()),
                 std::to_string(d) + "/" + std::to_string(todo.size()) + " runs");
    }
  };
  const unsigned jobs =
      std::max(1u, std::min<unsigned>(options.jobs, static_cast<unsigned>(todo.size())));
  std::vector<std::thread> threads;
  for (unsigned t = 1; t < jobs; ++t) threads.emplace_back(worker);
  worker();
  for (std::thread& t : threads) t.join();
  bar.finish();
  outcome.finished = todo.size() - outcome.failures.size();
  std::sort(outcome.failures.begin(), outcome.failures.end());

  std::vector<SweepRun> runs;
  std::vector<std::vector<std::pair<std::string, std::string>>> metrics;
  for (const PlannedRun& p : planned) {
    const fs::path m = p.dir / "metrics.json";
    if (!fs::exists(m)) continue;
    runs.push_back(p.run);
    metrics.push_back(flatten_metrics_json(read_text(m)));
  }
  std::vector<std::string> keys;
  for (const SweepAxis& a : spec.vary) keys.push_back(a.key);
  outcome.results = build_results_table(runs, keys, metrics);
  outcome.results_csv = options.out_dir / results_file_name(options.shard);
  mapper::io::write_file_atomic(outcome.results_csv, to_csv(outcome.results));
  return outcome;
}

std::vector<fs::path> results_files(const std::vector<fs::path>& args) {
  std::vector<fs::path> out;
  for (const fs::path& a : args) {
    if (fs::is_regular_file(a)) {
      out.push_back(a);
      continue;
    }
    if (!fs::is_directory(a)) throw std::runtime_error(a.string() + ": no such file or directory");
    std::vector<fs::path> found;
    for (const auto& e : fs::directory_iterator(a)) {
      const std::string name = e.path().filename().string();
      if (name == "results.csv" || (name.starts_with("results_shard_") && name.ends_with(".csv"))) {
        found.push_back(e.path());
      }
    }
    if (found.empty()) throw std::runtime_error(a.string() + ": holds no results*.csv");
    std::sort(found.begin(), found.end());
    out.insert(out.end(), found.begin(), found.end());
  }
  return out;
}

}  // namespace cogmap::experiments
