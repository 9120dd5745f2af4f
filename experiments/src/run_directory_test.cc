// The run directory never hurts the user's files (issue 12): which directories may take a run,
// the lock, the clean-up of an interrupted run and the re-runnable experiment.yaml.
#include "cogmap/experiments/run_directory.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

#include "cogmap/mapper/io/asr_json.h"
#include "cogmap/test_support/scratch_dir.h"

namespace cogmap::experiments {
namespace {

namespace fs = std::filesystem;

fs::path fresh_dir(const std::string& name) {
  return test_support::fresh_scratch(fs::path("run_directory_test") / name);
}

void write(const fs::path& p, const std::string& text) {
  fs::create_directories(p.parent_path());
  std::ofstream(p) << text;
}

std::string run_dir_error_of(const fs::path& dir, const std::vector<fs::path>& inputs,
                             FinishedRun finished = FinishedRun::kKeep) {
  try {
    check_run_directory(dir, inputs, finished);
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
  EXPECT_EQ(run_dir_error_of(base / "missing", {}), "");
  EXPECT_EQ(run_dir_error_of(base, {}), "");  // empty
  // A run from before the marker existed: only run products.
  const fs::path old = base / "old";
  for (const char* f : {"metrics.json", "trajectory.csv", "grid_000.pgm", "grid_012.yaml",
                        "experiment.yaml", "asrs/000.json", "figures/graph.png"}) {
    write(old / f, "x");
  }
  EXPECT_EQ(run_dir_error_of(old, {}, FinishedRun::kReplace), "");
  // With the marker anything goes (later cogmap versions may add outputs).
  write(base / "marked" / kRunMarkerName, kRunMarkerText);
  write(base / "marked" / "future_output.bin", "");
  EXPECT_EQ(run_dir_error_of(base / "marked", {}), "");
  // A marker made by hand (empty, or other text) makes nothing ours: a user's grid image
  // beside it, with no run's record, is refused (found by fuzzing, session 56).
  for (const std::string& fake :
       std::vector<std::string>{"", "cogmap run directory\n", std::string(kRunMarkerText) + "x"}) {
    const fs::path d = fresh_dir("fake_marker");
    write(d / kRunMarkerName, fake);
    write(d / "grid_000.pgm", "mine");
    EXPECT_NE(run_dir_error_of(d, {}).find("holds neither the run marker nor"), std::string::npos)
        << "'" << fake << "'";
  }
}

TEST(RunDirectory, ForeignFilesAndInputFoldersAreRefused) {
  const fs::path home = fresh_dir("home");
  write(home / "thesis.tex", "mine");
  write(home / "map.svg", "mine");
  EXPECT_NE(run_dir_error_of(home, {}).find("holds thesis.tex, which no cogmap run wrote"),
            std::string::npos);
  // The folder of the experiment itself, even if it looks like a run directory.
  const fs::path run = fresh_dir("run");
  write(run / kRunMarkerName, kRunMarkerText);
  write(run / "experiment.yaml", "name: x\n");
  EXPECT_NE(run_dir_error_of(run, {run / "experiment.yaml"}).find("is the folder of the input"),
            std::string::npos);
  write(run / "file_not_dir", "");
  EXPECT_NE(run_dir_error_of(run / "file_not_dir", {}).find("exists and is not a directory"),
            std::string::npos);
}

TEST(RunDirectory, LinkedRunFoldersAreRefusedAndNeverClearedThrough) {
  // A user's photos behind DIR/figures, their JSON behind DIR/asrs: a run would write into
  // them and clear them, marker or not.
  const fs::path base = fresh_dir("linked");
  write(base / "photos" / "graph.png", "mine");
  write(base / "ujson" / "001.json", "mine");
  for (const bool marked : {false, true}) {
    const fs::path d = base / (marked ? "marked" : "plain");
    fs::create_directories(d);
    if (marked) write(d / kRunMarkerName, kRunMarkerText);
    write(d / "experiment.yaml", "name: x\n");
    fs::create_directory_symlink(base / "photos", d / "figures");
    EXPECT_NE(run_dir_error_of(d, {}).find("figures: is a symbolic link"), std::string::npos) << d;
    fs::remove(d / "figures");
    fs::create_directory_symlink(base / "ujson", d / "asrs");
    EXPECT_NE(run_dir_error_of(d, {}).find("asrs: is a symbolic link"), std::string::npos) << d;
    clear_run_outputs(d);
    fs::remove(d / "asrs");
  }
  EXPECT_TRUE(fs::exists(base / "photos" / "graph.png"));
  EXPECT_TRUE(fs::exists(base / "ujson" / "001.json"));
  // A link among the top-level files is no run product either.
  const fs::path top = base / "top";
  write(top / "experiment.yaml", "name: x\n");
  fs::create_symlink(base / "ujson" / "001.json", top / "metrics.json");
  EXPECT_NE(run_dir_error_of(top, {}, FinishedRun::kReplace).find("holds metrics.json"),
            std::string::npos);
}

TEST(RunDirectory, RunLikeNamesWithoutARunsRecordAreRefused) {
  // Without the marker, files named as a run's are a run's only beside its experiment.yaml or
  // metrics.json, and figures/ and asrs/ must hold only what a run draws and stores.
  const fs::path base = fresh_dir("lookalike");
  write(base / "grids" / "grid_123.pgm", "mine");
  EXPECT_NE(run_dir_error_of(base / "grids", {}).find("is not an earlier run's"),
            std::string::npos);
  // The lock file alone is a run's own (the runner checks again after taking it).
  write(base / "locked" / kRunLockName, "");
  EXPECT_EQ(run_dir_error_of(base / "locked", {}), "");
  write(base / "photos" / "experiment.yaml", "name: x\n");
  write(base / "photos" / "figures" / "IMG_0001.png", "mine");
  EXPECT_NE(run_dir_error_of(base / "photos", {}).find("holds figures"), std::string::npos);
  write(base / "store" / "experiment.yaml", "name: x\n");
  write(base / "store" / "asrs" / "notes.json", "mine");
  EXPECT_NE(run_dir_error_of(base / "store", {}).find("holds asrs"), std::string::npos);
}

TEST(RunDirectory, AFinishedRunIsReplacedOnlyWhenAskedTo) {
  const fs::path d = fresh_dir("finished");
  write(d / kRunMarkerName, kRunMarkerText);
  write(d / "metrics.json", "{}");
  EXPECT_NE(
      run_dir_error_of(d, {}).find("already holds a finished run (metrics.json); pass --force"),
      std::string::npos);
  EXPECT_EQ(run_dir_error_of(d, {}, FinishedRun::kReplace), "");
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
  write(d / kRunMarkerName, kRunMarkerText);
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
  for (const char* f :
       {"grid_01.pgm", "grid_000.png", "notes.csv", "metrics.json.bak", "asrs/readme.txt",
        "asrs/07.json", "figures/plot.svg", "figures/IMG_0001.png"}) {
    write(d / f, "mine");
  }
  clear_run_outputs(d);
  std::vector<std::string> left;
  for (const auto& entry : fs::recursive_directory_iterator(d)) {
    if (entry.is_regular_file()) left.push_back(fs::relative(entry.path(), d).string());
  }
  std::sort(left.begin(), left.end());
  EXPECT_EQ(left, (std::vector<std::string>{
                      "asrs/07.json", "asrs/readme.txt", "figures/IMG_0001.png", "figures/plot.svg",
                      "grid_000.png", "grid_01.pgm", "metrics.json.bak", "notes.csv"}));
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
