#include "cogmap/experiments/run_directory.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <regex>
#include <system_error>

#include "cogmap/experiments/runner.h"
#include "cogmap/mapper/io/asr_json.h"

namespace cogmap::experiments {
namespace {

namespace fs = std::filesystem;

// The files a run writes at the top of its directory (docs/cli.md), besides the room grids.
constexpr const char* kRunProductFiles[] = {
    "metrics.json",    "trajectory.csv",  "map_segments.csv", "map_segments_odom.csv",
    "map.svg",         "asr_graph.json",  "experiment.yaml",  "nav_trace.csv",
    "explore_map.pgm", "explore_map.yaml"};

bool is_grid_file_name(const std::string& name) {
  static const std::regex kGrid(R"(grid_\d{3,}\.(pgm|yaml))");
  return std::regex_match(name, kGrid);
}

// What a run writes at the top of its directory: a directory holding only these was made by a
// run before the marker existed, and may be reused.
bool is_run_product(const fs::directory_entry& entry) {
  const std::string name = entry.path().filename().string();
  std::error_code ec;
  if (entry.is_directory(ec)) return name == "asrs" || name == "figures";
  for (const char* known : kRunProductFiles) {
    if (name == known) return true;
  }
  return name == kRunMarkerName || name == kRunLockName || is_grid_file_name(name) ||
         mapper::io::is_temp_file_name(name);
}

bool same_directory(const fs::path& a, const fs::path& b) {
  std::error_code ec;
  const bool same = fs::equivalent(a, b, ec);
  return !ec && same;
}

}  // namespace

void clear_run_outputs(const fs::path& dir) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return;
  static const std::regex kAsr(R"(\d{3,}\.json)");
  for (const char* name : kRunProductFiles) fs::remove(dir / name, ec);
  for (const auto& e : fs::directory_iterator(dir, ec)) {
    if (is_grid_file_name(e.path().filename().string())) fs::remove(e.path(), ec);
  }
  for (const auto& e : fs::directory_iterator(dir / "asrs", ec)) {
    if (std::regex_match(e.path().filename().string(), kAsr)) fs::remove(e.path(), ec);
  }
  for (const auto& e : fs::directory_iterator(dir / "figures", ec)) {
    if (e.path().extension() == ".png") fs::remove(e.path(), ec);
  }
}

std::string safe_path_component(std::string_view name) {
  std::string out;
  for (const char c : name.substr(0, 100)) {
    const bool keep = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                      c == '.' || c == '_' || c == '-' || c == '+' || c == '=' || c == ',';
    out.push_back(keep ? c : '_');
  }
  if (out.empty() || out.front() == '.') out.insert(out.begin(), '_');
  return out;
}

void check_run_directory(const fs::path& dir, const std::vector<fs::path>& inputs) {
  std::error_code ec;
  const fs::file_status status = fs::status(dir, ec);
  if (!fs::exists(status)) return;
  if (!fs::is_directory(status)) {
    throw RunDirectoryError(dir.string() + ": exists and is not a directory; choose another --out");
  }
  for (const fs::path& input : inputs) {
    const fs::path folder = input.has_parent_path() ? input.parent_path() : fs::path(".");
    if (same_directory(dir, folder)) {
      throw RunDirectoryError(dir.string() + ": is the folder of the input " + input.string() +
                              ", which a run would overwrite; choose another --out");
    }
  }
  if (fs::exists(dir / kRunMarkerName, ec)) return;
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    if (!is_run_product(entry)) {
      throw RunDirectoryError(dir.string() + ": holds " + entry.path().filename().string() +
                              ", which no cogmap run wrote; a run directory must be new, empty "
                              "or an earlier run's; choose another --out");
    }
  }
  if (ec) throw RunDirectoryError(dir.string() + ": cannot list: " + ec.message());
}

RunDirectoryLock::RunDirectoryLock(const fs::path& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw RunDirectoryError(dir.string() + ": cannot create directory: " + ec.message());
  const fs::path lock = dir / kRunLockName;
  fd_ = ::open(lock.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0) {
    throw RunDirectoryError(lock.string() + ": cannot open lock file: " + std::strerror(errno));
  }
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    const int saved = errno;
    ::close(fd_);
    fd_ = -1;
    throw RunDirectoryError(dir.string() + ": " +
                            (saved == EWOULDBLOCK
                                 ? std::string("another cogmap run is writing this directory")
                                 : std::string("cannot lock: ") + std::strerror(saved)));
  }
}

RunDirectoryLock::~RunDirectoryLock() {
  if (fd_ >= 0) ::close(fd_);  // closing releases the flock
}

std::string run_experiment_yaml(const Experiment& experiment, const fs::path& dir) {
  YAML::Node root = YAML::Load(experiment.resolved_yaml);
  const YAML::Node world = root["world"];
  if (world.IsScalar() && world.Scalar() != "none" && !fs::path(world.Scalar()).is_absolute()) {
    std::error_code ec;
    const fs::path from = fs::weakly_canonical(fs::absolute(dir, ec), ec);
    const fs::path to = fs::weakly_canonical(fs::absolute(experiment.world, ec), ec);
    fs::path rebased = ec ? fs::path() : to.lexically_relative(from);
    if (rebased.empty()) rebased = to;  // different roots: absolute is still correct
    root["world"] = rebased.generic_string();
  }
  YAML::Emitter emitter;
  emitter << root;
  return std::string(emitter.c_str()) + "\n";
}

void prepare_run_directory(const fs::path& dir, const Experiment& experiment,
                           mapper::io::Durability durability) {
  std::vector<fs::path> inputs{experiment.file};
  check_run_directory(dir, inputs);
  mapper::io::write_file_atomic(dir / kRunMarkerName,
                                "cogmap run directory (docs/reliability.md)\n", durability);
  for (const fs::path& d : {dir, dir / "asrs", dir / "figures"}) {
    mapper::io::remove_stale_temp_files(d);
  }
  clear_run_outputs(dir);
  mapper::io::write_file_atomic(dir / "experiment.yaml", run_experiment_yaml(experiment, dir),
                                durability);
}

}  // namespace cogmap::experiments
