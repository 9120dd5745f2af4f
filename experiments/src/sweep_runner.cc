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

// The first line of `path`, at most `limit` bytes of it: enough for any header, and a file
// that is not a results file (a binary, one huge line) is not read whole.
std::string first_line(const fs::path& path, std::size_t limit = 1 << 16) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  char c = 0;
  while (line.size() < limit && in.get(c) && c != '\n') line += c;
  return line;
}

// Whether the existing results file starts with the header this sweep writes.
bool has_header(const fs::path& results, const std::string& header) {
  if (header.empty()) return false;
  const std::string line = first_line(results, header.size() + 1);
  return line == header || line == header + ",";
}

// A non-empty plots/ (or a file of that name) is something a sweep would write over.
bool holds_plots(const fs::path& dir) {
  std::error_code ec;
  const fs::path plots = dir / "plots";
  if (!fs::exists(fs::symlink_status(plots, ec))) return false;
  return !fs::is_directory(plots, ec) || !fs::is_empty(plots, ec);
}

}  // namespace

std::string results_header_start(const SweepSpec& spec) {
  std::vector<std::string> keys;
  for (const SweepAxis& a : spec.vary) keys.push_back(a.key);
  std::string header = to_csv(build_results_table({}, keys, {}));
  if (!header.empty() && header.back() == '\n') header.pop_back();
  return header;
}

void check_sweep_directory(const fs::path& dir, const SweepOutputs& outputs, bool force) {
  std::error_code ec;
  // `dir`, or the nearest of its ancestors that exists (the rest is created), must be a folder.
  fs::path up = fs::absolute(dir, ec);
  while (!fs::exists(up, ec) && up.has_relative_path()) up = up.parent_path();
  if (fs::exists(up, ec) && !fs::is_directory(up, ec)) {
    throw SweepDirectoryError(dir.string() + ": " + up.string() +
                              " is not a directory; choose another --out");
  }
  const fs::path results = dir / outputs.results_file;
  const fs::file_status status = fs::status(results, ec);
  if (fs::exists(status) && !fs::is_regular_file(status)) {
    throw SweepDirectoryError(results.string() +
                              ": not a regular file (a directory, device or pipe); choose "
                              "another --out");
  }
  if (force || fs::exists(dir / kSweepMarkerName, ec)) return;
  std::vector<std::string> foreign;
  if (fs::exists(fs::symlink_status(results, ec))) {
    // A results file of this very sweep from before the marker: resuming it must still work.
    if (has_header(results, outputs.header)) return;
    foreign.push_back(outputs.results_file);
  }
  if (outputs.plots && holds_plots(dir)) foreign.push_back("plots/");
  if (foreign.empty()) return;
  std::string list = foreign.front();
  if (foreign.size() > 1) list += " and " + foreign.back();
  const std::string shown = dir == "." ? ". (the current directory)" : dir.string();
  throw SweepDirectoryError(
      shown + ": holds " + list + ", which no cogmap sweep wrote (no " + kSweepMarkerName +
      " marker, and not this sweep's header); choose another --out, or pass --force to "
      "replace them");
}

void mark_sweep_directory(const fs::path& dir, mapper::io::Durability durability) {
  mapper::io::write_file_atomic(
      dir / kSweepMarkerName,
      "cogmap sweep output directory: its results files and plots/ are replaced by the next "
      "sweep or --merge\n",
      durability);
}

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
    if (!fs::exists(a)) throw std::runtime_error(a.string() + ": no such file or directory");
    if (!fs::is_directory(a)) {
      throw std::runtime_error(a.string() +
                               ": not a regular file or directory (a device, pipe or socket)");
    }
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
