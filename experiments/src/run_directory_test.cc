// The run directory never hurts the user's files (issue 12): which directories may take a run,
// the lock, the clean-up of an interrupted run and the re-runnable experiment.yaml.
#include "cogmap/experiments/run_directory.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

#include "cogmap/mapper/io/asr_json.h"

namespace cogmap::experiments {
namespace {

namespace fs = std::filesystem;

fs::path fresh_dir(const std::string& name) {
  const fs::path d = fs::path(::testing::TempDir()) / "run_directory_test" / name;
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

void write(const fs::path& p, const std::string& text) {
  fs::create_directories(p.parent_path());
  std::ofstream(p) << text;
}

std::string error_of(const fs::path& dir, const std::vector<fs::path>& inputs) {
  try {
    check_run_directory(dir, inputs);
  } catch (const RunDirectoryError& e) {
    return e.what();
  }
  return "";
}

TEST(RunDirectory, SafePathComponent) {
  EXPECT_EQ(safe_path_component("two_rooms_seed7"), "two_rooms_seed7");
  EXPECT_EQ(safe_path_component("../../x"), "_.._.._x");
  EXPECT_EQ(safe_path_component("/abs"), "_abs");
  EXPECT_EQ(safe_path_component(".hidden"), "_.hidden");
  EXPECT_EQ(safe_path_component(".."), "_..");
  EXPECT_EQ(safe_path_component("a: b\nmapper: {grid: bayes}"), "a__b_mapper___grid__bayes_");
  EXPECT_EQ(safe_path_component(""), "_");
  EXPECT_EQ(safe_path_component(std::string(300, 'x')).size(), 100u);
}

TEST(RunDirectory, NewEmptyAndEarlierRunDirectoriesAreAccepted) {
  const fs::path base = fresh_dir("accept");
  EXPECT_EQ(error_of(base / "missing", {}), "");
  EXPECT_EQ(error_of(base, {}), "");  // empty
  // A run from before the marker existed: only run products.
  const fs::path old = base / "old";
  for (const char* f : {"metrics.json", "trajectory.csv", "grid_000.pgm", "grid_012.yaml",
                        "experiment.yaml", "asrs/000.json", "figures/graph.png"}) {
    write(old / f, "x");
  }
  EXPECT_EQ(error_of(old, {}), "");
  // With the marker anything goes (later cogmap versions may add outputs).
  write(base / "marked" / kRunMarkerName, "");
  write(base / "marked" / "future_output.bin", "");
  EXPECT_EQ(error_of(base / "marked", {}), "");
}

TEST(RunDirectory, ForeignFilesAndInputFoldersAreRefused) {
  const fs::path home = fresh_dir("home");
  write(home / "thesis.tex", "mine");
  write(home / "map.svg", "mine");
  EXPECT_NE(error_of(home, {}).find("holds thesis.tex, which no cogmap run wrote"),
            std::string::npos);
  // The folder of the experiment itself, even if it looks like a run directory.
  const fs::path run = fresh_dir("run");
  write(run / kRunMarkerName, "");
  write(run / "experiment.yaml", "name: x\n");
  EXPECT_NE(error_of(run, {run / "experiment.yaml"}).find("is the folder of the input"),
            std::string::npos);
  write(run / "file_not_dir", "");
  EXPECT_NE(error_of(run / "file_not_dir", {}).find("exists and is not a directory"),
            std::string::npos);
}

TEST(RunDirectory, LockKeepsASecondWriterOut) {
  const fs::path d = fresh_dir("lock");
  {
    RunDirectoryLock first(d);
    try {
      RunDirectoryLock second(d);
      FAIL() << "second lock taken";
    } catch (const RunDirectoryError& e) {
      EXPECT_NE(std::string(e.what()).find("another cogmap run is writing"), std::string::npos);
    }
  }
  EXPECT_NO_THROW(RunDirectoryLock again(d));  // released with the first
}

TEST(RunDirectory, PrepareRemovesStaleTempFilesAndOldOutputsOnly) {
  const fs::path d = fresh_dir("prepare");
  write(d / kRunMarkerName, "");
  for (const char* f : {".grid_066.pgm.tmp-4242-7", "asrs/.003.json.tmp-1-0",
                        "figures/.room_001_stages.png.tmp.4242.3", "metrics.json", "asrs/003.json",
                        "figures/map_before_after.png"}) {
    write(d / f, "old");
  }
  write(d / "notes.tmp", "keep");  // not a writer's temp name
  Experiment e;
  e.file = fs::path(::testing::TempDir()) / "elsewhere" / "e.yaml";
  e.world = fs::path("/worlds/w.yaml");
  e.resolved_yaml = "name: x\nworld: /worlds/w.yaml\n";
  prepare_run_directory(d, e);
  std::vector<std::string> left;
  for (const auto& entry : fs::recursive_directory_iterator(d)) {
    if (entry.is_regular_file()) left.push_back(fs::relative(entry.path(), d).string());
  }
  std::sort(left.begin(), left.end());
  EXPECT_EQ(left, (std::vector<std::string>{".cogmap-run", "experiment.yaml", "notes.tmp"}));
}

TEST(RunDirectory, ClearRemovesEveryRunProductAndNothingElse) {
  const fs::path d = fresh_dir("clear");
  for (const char* f :
       {"metrics.json", "trajectory.csv", "map_segments.csv", "map_segments_odom.csv", "map.svg",
        "asr_graph.json", "experiment.yaml", "nav_trace.csv", "explore_map.pgm", "explore_map.yaml",
        "grid_000.pgm", "grid_1234.yaml", "asrs/007.json", "figures/graph.png"}) {
    write(d / f, "old");
  }
  // Names a run never writes: a user's own files stay.
  for (const char* f : {"grid_01.pgm", "grid_000.png", "notes.csv", "metrics.json.bak",
                        "asrs/readme.txt", "asrs/07.json", "figures/plot.svg"}) {
    write(d / f, "mine");
  }
  clear_run_outputs(d);
  std::vector<std::string> left;
  for (const auto& entry : fs::recursive_directory_iterator(d)) {
    if (entry.is_regular_file()) left.push_back(fs::relative(entry.path(), d).string());
  }
  std::sort(left.begin(), left.end());
  EXPECT_EQ(left, (std::vector<std::string>{"asrs/07.json", "asrs/readme.txt", "figures/plot.svg",
                                            "grid_000.png", "grid_01.pgm", "metrics.json.bak",
                                            "notes.csv"}));
}

TEST(RunDirectory, SavedExperimentRebasesARelativeWorld) {
  Experiment e;
  e.file = "/proj/experiments/two_rooms.yaml";
  e.world = "/proj/worlds/two_rooms.yaml";
  e.resolved_yaml = "name: two_rooms\nworld: ../worlds/two_rooms.yaml\nseed: 7\n";
  const std::string saved = run_experiment_yaml(e, "/proj/runs/two_rooms_seed7");
  EXPECT_NE(saved.find("world: ../../worlds/two_rooms.yaml"), std::string::npos) << saved;
  EXPECT_NE(saved.find("seed: 7"), std::string::npos);
  // `none` (drive, replay) and absolute paths stay as they are.
  e.resolved_yaml = "name: d\nworld: none\n";
  EXPECT_NE(run_experiment_yaml(e, "/x").find("world: none"), std::string::npos);
  e.resolved_yaml = "name: d\nworld: /abs/w.yaml\n";
  EXPECT_NE(run_experiment_yaml(e, "/x").find("world: /abs/w.yaml"), std::string::npos);
}

TEST(RunDirectory, TempFileNamesOfBothWriters) {
  using mapper::io::is_temp_file_name;
  EXPECT_TRUE(is_temp_file_name(".grid_066.pgm.tmp-4242-7"));
  EXPECT_TRUE(is_temp_file_name(".room_001_stages.png.tmp.4242.3"));
  EXPECT_FALSE(is_temp_file_name("grid_066.pgm.tmp-4242-7"));  // not hidden
  EXPECT_FALSE(is_temp_file_name(".grid_066.pgm"));
  EXPECT_FALSE(is_temp_file_name(".x.tmp-12"));  // one number only
  EXPECT_FALSE(is_temp_file_name("notes.tmp"));
}

}  // namespace
}  // namespace cogmap::experiments
