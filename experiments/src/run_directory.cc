#include "cogmap/experiments/run_directory.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <regex>
#include <string_view>
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

bool is_asr_file_name(const std::string& name) {
  static const std::regex kAsr(R"(\d{3,}\.json)");
  return std::regex_match(name, kAsr);
}

// The figures a run writes (runner.cc): the rooms' stages, the map, its error, the graph.
bool is_figure_file_name(const std::string& name) {
  static const std::regex kFigure(R"((room_\d{3,}_stages|map_before_after|map_error|graph)\.png)");
  return std::regex_match(name, kFigure);
}

// The first entry of `dir` that `is_product` does not accept (a symbolic link never is one: a
// run writes none, and clearing through one would reach another folder), or "" if none.
template <typename Accept>
std::string first_foreign_entry(const fs::path& dir, Accept is_product) {
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    const std::string name = entry.path().filename().string();
    if (entry.is_symlink(ec) || !is_product(entry, name)) return name;
  }
  if (ec) throw RunDirectoryError(dir.string() + ": cannot list: " + ec.message());
  return "";
}

// What a run writes: a directory holding only these (and its own experiment.yaml or
// metrics.json) was made by a run before the marker existed, and may be reused.
bool is_run_product(const fs::directory_entry& entry, const std::string& name) {
  std::error_code ec;
  const bool temp = mapper::io::is_temp_file_name(name);
  if (entry.is_directory(ec)) {
    if (name == "asrs") {
      return first_foreign_entry(entry.path(),
                                 [](const auto&, const std::string& n) {
                                   return is_asr_file_name(n) || mapper::io::is_temp_file_name(n);
                                 })
          .empty();
    }
    if (name == "figures") {
      return first_foreign_entry(entry.path(),
                                 [](const auto&, const std::string& n) {
                                   return is_figure_file_name(n) ||
                                          mapper::io::is_temp_file_name(n);
                                 })
          .empty();
    }
    return false;
  }
  for (const char* known : kRunProductFiles) {
    if (name == known) return true;
  }
  return name == kRunMarkerName || name == kRunLockName || is_grid_file_name(name) || temp;
}

// A run writes into DIR/asrs and DIR/figures and clears them: neither may lead elsewhere.
void refuse_linked_subdirectories(const fs::path& dir) {
  std::error_code ec;
  for (const char* sub : {"asrs", "figures"}) {
    if (fs::is_symlink(dir / sub, ec)) {
      throw RunDirectoryError((dir / sub).string() +
                              ": is a symbolic link; a run writes and clears this folder, so it "
                              "must be the run directory's own; choose another --out");
    }
  }
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
  for (const char* name : kRunProductFiles) fs::remove(dir / name, ec);
  for (const auto& e : fs::directory_iterator(dir, ec)) {
    if (is_grid_file_name(e.path().filename().string())) fs::remove(e.path(), ec);
  }
  // Never through a link: what lies behind it is not this run's.
  if (!fs::is_symlink(dir / "asrs", ec)) {
    for (const auto& e : fs::directory_iterator(dir / "asrs", ec)) {
      if (is_asr_file_name(e.path().filename().string())) fs::remove(e.path(), ec);
    }
  }
  if (!fs::is_symlink(dir / "figures", ec)) {
    for (const auto& e : fs::directory_iterator(dir / "figures", ec)) {
      if (is_figure_file_name(e.path().filename().string())) fs::remove(e.path(), ec);
    }
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

void check_run_directory(const fs::path& dir, const std::vector<fs::path>& inputs,
                         FinishedRun finished) {
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
  refuse_linked_subdirectories(dir);
  if (finished == FinishedRun::kKeep && fs::exists(dir / "metrics.json", ec)) {
    throw RunDirectoryError(dir.string() +
                            " already holds a finished run (metrics.json); pass --force to "
                            "replace it or choose another --out");
  }
  if (holds_marker(dir, kRunMarkerName, kRunMarkerText)) return;
  const std::string foreign = first_foreign_entry(dir, is_run_product);
  if (!foreign.empty()) {
    throw RunDirectoryError(dir.string() + ": holds " + foreign +
                            ", which no cogmap run wrote; a run directory must be new, empty "
                            "or an earlier run's; choose another --out");
  }
  // Without the marker, only a run's own record makes the rest a run's (a lone grid_012.pgm
  // or figures/graph.png may be anybody's). The lock file alone is this run's own, taken
  // before the caller checked again.
  const std::string beyond_lock = first_foreign_entry(
      dir, [](const auto&, const std::string& name) { return name == kRunLockName; });
  if (!beyond_lock.empty() && !fs::exists(dir / "experiment.yaml", ec) &&
      !fs::exists(dir / "metrics.json", ec)) {
    throw RunDirectoryError(dir.string() +
                            ": is not empty and holds neither the run marker nor an "
                            "experiment.yaml or metrics.json, so it is not an earlier run's; "
                            "choose another --out");
  }
}

std::optional<fs::path> file_in_the_way(const fs::path& folder) {
  std::error_code ec;
  fs::path up = fs::absolute(folder, ec);
  while (!fs::exists(up, ec) && up.has_relative_path()) up = up.parent_path();
  if (fs::exists(up, ec) && !fs::is_directory(up, ec)) return up;
  return std::nullopt;
}

RunDirectoryLock::RunDirectoryLock(const fs::path& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) {
    // A link to nowhere reads as "File exists": say what is there instead.
    std::error_code link_ec;
    if (fs::is_symlink(fs::symlink_status(dir, link_ec))) {
      throw RunDirectoryError(dir.string() + ": is a symbolic link to " +
                              fs::read_symlink(dir, link_ec).string() +
                              ", which does not exist; create it or choose another --out");
    }
    throw RunDirectoryError(dir.string() + ": cannot create directory: " + ec.message());
  }
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

bool holds_marker(const fs::path& dir, const char* name, std::string_view text) {
  std::error_code ec;
  const fs::path marker = dir / name;
  if (!fs::is_regular_file(marker, ec) || fs::file_size(marker, ec) != text.size() || ec) {
    return false;
  }
  std::ifstream in(marker, std::ios::binary);
  std::string held(text.size(), '\0');
  return in.read(held.data(), static_cast<std::streamsize>(held.size())) && held == text;
}

void prepare_run_directory(const fs::path& dir, const Experiment& experiment,
                           mapper::io::Durability durability) {
  std::vector<fs::path> inputs{experiment.file};
  check_run_directory(dir, inputs, FinishedRun::kReplace);  // the caller decided on a finished run
  mapper::io::write_file_atomic(dir / kRunMarkerName, kRunMarkerText, durability);
  for (const fs::path& d : {dir, dir / "asrs", dir / "figures"}) {
    std::error_code ec;
    if (!fs::is_symlink(d, ec)) mapper::io::remove_stale_temp_files(d);
  }
  clear_run_outputs(dir);
  mapper::io::write_file_atomic(dir / "experiment.yaml", run_experiment_yaml(experiment, dir),
                                durability);
}

}  // namespace cogmap::experiments
