#include "cogmap/experiments/sweep_runner.h"

#include <algorithm>
#include <atomic>
#include <fstream>
#include <mutex>
#include <set>
#include <sstream>
#include <thread>

#include "cogmap/experiments/progress.h"
#include "cogmap/experiments/run_directory.h"
#include "cogmap/experiments/runner.h"
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

// Whether key path `inner` is `outer` or lies inside it ("mapper.grid" in "mapper").
bool axis_key_within(const std::string& inner, const std::string& outer) {
  return inner == outer ||
         (inner.size() > outer.size() && inner.starts_with(outer) && inner[outer.size()] == '.');
}

// Whether error `e`, caused by varying `axis_key`, is the key's fault rather than
// the value's: a key the experiment does not know (`mapper.gridd`), or a parent the key path
// could not go through (`mapper.grid.x` with `grid: himm`). Any other error at or inside the
// varied key is its value's (`duration_s: -1`, `world: missing.yaml`, `mapper: {gridd: 1}`).
bool blames_key(const yaml::ConfigError& e, const std::string& axis_key) {
  if (!axis_key_within(axis_key, e.key())) return false;
  if (e.key() != axis_key) return true;  // a parent the override made or changed
  const std::string message = bare_message(e);
  return message.starts_with("unknown key") ||
         message.find("is not a mapping") != std::string::npos;
}

// The line in the sweep file of `vary.<key>` (value_index < 0) or of its value_index-th value;
// 0 when it cannot be found. The sweep is read again: SweepSpec keeps no lines, and this runs
// only on the way to an error message.
int sweep_line(const fs::path& file, const std::string& key, int value_index) {
  try {
    const auto vary = yaml::Node::load_file(file).child("vary");
    if (!vary) return 0;
    if (value_index >= 0) return (*vary)[key].at(static_cast<std::size_t>(value_index)).line();
    for (const auto& kv : vary->raw()) {
      if (kv.first.IsScalar() && kv.first.Scalar() == key && !kv.first.Mark().is_null()) {
        return kv.first.Mark().line + 1;
      }
    }
  } catch (const std::exception&) {
  }
  return 0;
}

// The message without the " (from --set key=...)" load_experiment adds: in a sweep, the
// override is the sweep's `vary` entry, which the new location names. Found by its start: the
// value is shown escaped (a block scalar's --set text holds line breaks).
std::string without_set_suffix(const std::string& message, const std::string& key) {
  const std::size_t at = message.rfind(" (from --set " + key + "=");
  return at != std::string::npos && message.ends_with(")") ? message.substr(0, at) : message;
}

// Re-raises an error loading or validating one run. An error the run's `vary` values caused is
// reported in the sweep file, at the line of the varied key or of the offending value (the
// experiment file's line would point at a key the sweep replaced, or at line 1 of the value's
// own text); any other error keeps its place. Both name the sweep and the run.
[[noreturn]] void throw_in_sweep(const yaml::ConfigError& e, const SweepSpec& spec,
                                 const SweepRun& run) {
  const std::string in_run = "run " + run.dir_name() + ")";
  if (e.file() == spec.base.string()) {
    for (const auto& [key, value] : run.values) {
      if (!axis_key_within(e.key(), key) && !axis_key_within(key, e.key())) continue;
      const auto axis = std::find_if(spec.vary.begin(), spec.vary.end(),
                                     [&](const SweepAxis& a) { return a.key == key; });
      const auto at = std::find(axis->values.begin(), axis->values.end(), value);
      const int index = blames_key(e, key) || at == axis->values.end()
                            ? -1
                            : static_cast<int>(at - axis->values.begin());
      std::string message = without_set_suffix(bare_message(e), key);
      if (e.key() != key) message = e.key() + ": " + message;
      const std::string where =
          "vary." + key + (index < 0 ? "" : "[" + std::to_string(index) + "]");
      throw yaml::ConfigError(spec.file.string(), sweep_line(spec.file, key, index), where,
                              message + " (base " + spec.base.string() + ", " + in_run);
    }
  }
  throw yaml::ConfigError(e.file(), e.line(), e.key(),
                          bare_message(e) + " (in sweep " + spec.file.string() + ", " + in_run);
}

// Checks once per world and robot block what only a run would find (the world file loads, the
// robot block parses): a sweep whose second value names a missing world failed only after the
// first value's runs had run.
void validate_once(const Experiment& experiment, std::set<std::string>& validated) {
  std::string id = experiment.world.string();
  if (experiment.robot) {
    YAML::Emitter robot;
    robot << experiment.robot->raw();
    id += std::string("\n") + robot.c_str();
  }
  if (validated.insert(id).second) validate_experiment(experiment);
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
  if (const auto up = file_in_the_way(dir)) {
    throw SweepDirectoryError(dir.string() + ": " + up->string() +
                              " is not a directory; choose another --out");
  }
  const fs::path results = dir / outputs.results_file;
  const fs::file_status status = fs::status(results, ec);
  if (fs::exists(status) && !fs::is_regular_file(status)) {
    throw SweepDirectoryError(results.string() +
                              ": not a regular file (a directory, device or pipe); choose "
                              "another --out");
  }
  if (force || holds_marker(dir, kSweepMarkerName, kSweepMarkerText)) return;
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
  mapper::io::write_file_atomic(dir / kSweepMarkerName, kSweepMarkerText, durability);
}

std::string results_file_name(Shard shard) {
  if (shard.n <= 1) return "results.csv";
  return "results_shard_" + std::to_string(shard.k) + "_of_" + std::to_string(shard.n) + ".csv";
}

std::vector<PlannedRun> plan_sweep(const SweepSpec& spec, const SweepOptions& options) {
  std::vector<PlannedRun> planned;
  std::set<std::string> validated;
  for (const SweepRun& run : shard_runs(expand_sweep(spec), options.shard)) {
    PlannedRun p;
    p.run = run;
    try {
      p.experiment = load_experiment(spec.base, run.overrides(), run.seed);
      validate_once(p.experiment, validated);
    } catch (const yaml::ConfigError& e) {
      throw_in_sweep(e, spec, run);
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
  try {
    mapper::io::write_file_atomic(outcome.results_csv, to_csv(outcome.results));
  } catch (const std::exception& e) {
    // The outcome is lost with the throw: the runs that failed (a full disk fails them too)
    // must still be named, not only the results file.
    std::string message = e.what();
    for (const std::string& f : outcome.failures) message += "\nfailed: " + f;
    throw std::runtime_error(message);
  }
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
