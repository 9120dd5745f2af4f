#include "cogmap/experiments/sweep_runner.h"

#include <gtest/gtest.h>

#include <atomic>
#include <fstream>
#include <sstream>

#include "cogmap/experiments/sweep_plots.h"
#include "cogmap/mapper/io/asr_json.h"
#include "cogmap/test_support/scratch_dir.h"

namespace cogmap::experiments {
namespace {

namespace fs = std::filesystem;

struct Fixture {
  fs::path dir;
  SweepSpec spec;
};

Fixture make_fixture(const std::string& name) {
  Fixture f;
  f.dir = test_support::fresh_scratch("sweep_runner_test_" + name);
  std::ofstream(f.dir / "base.yaml") << "name: base\nworld: w.yaml\n";
  // plan_sweep loads each run's world: a square room.
  std::ofstream(f.dir / "w.yaml")
      << "name: w\nwalls: {polylines: [[[0, 0], [5, 0], [5, 5], [0, 5], [0, 0]]]}\n"
         "start: {x_m: 2, y_m: 2}\n";
  std::ofstream(f.dir / "s.sweep.yaml")
      << "base: base.yaml\nseeds: [1, 2]\nvary:\n  mapper.cell_scale_mm: [55, 100]\n";
  f.spec = load_sweep(f.dir / "s.sweep.yaml");
  return f;
}

// A stand-in run: metrics depend only on the run's inputs.
void fake_run(const PlannedRun& p) {
  const double cell = p.experiment.mapper.grid_options.cell_scale_mm;
  mapper::io::write_file_atomic(
      p.dir / "metrics.json",
      "{\"asr_count\": " + std::to_string(p.experiment.seed) +
          ", \"map\": {\"wall_error_median_m\": " + std::to_string(cell / 1000.0) + "}}\n");
}

TEST(SweepRunner, RunsEveryRunInParallelAndWritesResults) {
  Fixture f = make_fixture("all");
  SweepOptions o;
  o.out_dir = f.dir / "out";
  o.jobs = 3;
  const auto planned = plan_sweep(f.spec, o);
  ASSERT_EQ(planned.size(), 4u);
  EXPECT_EQ(planned[0].dir, o.out_dir / "runs" / "mapper.cell_scale_mm=55,seed=1");
  EXPECT_EQ(planned[2].experiment.seed, 1u);
  EXPECT_DOUBLE_EQ(planned[2].experiment.mapper.grid_options.cell_scale_mm, 100.0);
  const SweepOutcome out = run_sweep(f.spec, planned, o, fake_run);
  EXPECT_EQ(out.finished, 4u);
  EXPECT_TRUE(out.failures.empty());
  EXPECT_EQ(out.results_csv, o.out_dir / "results.csv");
  std::ifstream in(out.results_csv);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(),
            "run,mapper.cell_scale_mm,seed,asr_count,map.wall_error_median_m\n"
            "0,55,1,1,0.055\n"
            "1,55,2,2,0.055\n"
            "2,100,1,1,0.1\n"
            "3,100,2,2,0.1\n");
  const auto series = metric_series(out.results, "asr_count");
  ASSERT_EQ(series.size(), 1u);
  EXPECT_EQ(series[0].x, (std::vector<double>{55, 100}));
  EXPECT_EQ(series[0].mean, (std::vector<double>{1.5, 1.5}));
  EXPECT_NEAR(series[0].sd[0], std::sqrt(0.5), 1e-12);
}

TEST(SweepRunner, ResumesSkippingFinishedRunsAndReportsFailures) {
  Fixture f = make_fixture("resume");
  SweepOptions o;
  o.out_dir = f.dir / "out";
  const auto planned = plan_sweep(f.spec, o);
  fake_run(planned[1]);  // finished earlier
  std::atomic<int> calls{0};
  const SweepOutcome out = run_sweep(f.spec, planned, o, [&](const PlannedRun& p) {
    ++calls;
    if (p.run.index == 3) throw std::runtime_error("robot fell over");
    fake_run(p);
  });
  EXPECT_EQ(calls.load(), 3);
  EXPECT_EQ(out.skipped, 1u);
  EXPECT_EQ(out.finished, 2u);
  ASSERT_EQ(out.failures.size(), 1u);
  EXPECT_EQ(out.failures[0], "mapper.cell_scale_mm=100,seed=2: robot fell over");
  EXPECT_EQ(out.results.rows.size(), 3u);  // the failed run has no row
}

// A results file that cannot be written (a full disk fails the runs too) was the only error
// shown: the runs' own failures were lost with the outcome.
TEST(SweepRunner, UnwritableResultsStillNamesTheFailedRuns) {
  Fixture f = make_fixture("unwritable_results");
  SweepOptions o;
  o.out_dir = f.dir / "out";
  const auto planned = plan_sweep(f.spec, o);
  fs::create_directories(o.out_dir / "results.csv" / "in_the_way");  // rename(2) fails over it
  try {
    (void)run_sweep(f.spec, planned, o, [](const PlannedRun& p) {
      if (p.run.index == 3) throw std::runtime_error("No space left on device");
      fake_run(p);
    });
    FAIL() << "expected the results file's write to fail";
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("results.csv"), std::string::npos) << what;
    EXPECT_NE(what.find("failed: mapper.cell_scale_mm=100,seed=2: No space left on device"),
              std::string::npos)
        << what;
  }
  EXPECT_TRUE(fs::is_directory(o.out_dir / "results.csv" / "in_the_way"));
}

TEST(SweepRunner, ShardsWriteTheirOwnResultsAndMergeBack) {
  Fixture f = make_fixture("shards");
  std::vector<std::pair<std::string, ResultsTable>> tables;
  for (std::size_t k = 1; k <= 3; ++k) {
    SweepOptions o;
    o.out_dir = f.dir / "out";
    o.shard = {k, 3};
    const auto out = run_sweep(f.spec, plan_sweep(f.spec, o), o, fake_run);
    EXPECT_EQ(out.results_csv.filename(), "results_shard_" + std::to_string(k) + "_of_3.csv");
    tables.emplace_back(out.results_csv.string(), out.results);
  }
  const auto files = results_files({f.dir / "out"});
  EXPECT_EQ(files.size(), 3u);
  const ResultsTable merged = merge_results(tables);
  ASSERT_EQ(merged.rows.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) EXPECT_EQ(merged.rows[i][0], std::to_string(i));
  EXPECT_THROW(results_files({f.dir / "nothing_here"}), std::runtime_error);
}

TEST(SweepRunner, BadVaryKeyFailsBeforeAnythingRuns) {
  Fixture f = make_fixture("bad");
  std::ofstream(f.dir / "bad.sweep.yaml")
      << "base: base.yaml\nseeds: [1]\nvary:\n  mapper.cell_scale: [55]\n";
  SweepOptions o;
  o.out_dir = f.dir / "out";
  try {
    (void)plan_sweep(load_sweep(f.dir / "bad.sweep.yaml"), o);
    FAIL() << "accepted an unknown key";
  } catch (const yaml::ConfigError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("mapper.cell_scale: unknown key"), std::string::npos) << what;
    EXPECT_NE(what.find("bad.sweep.yaml"), std::string::npos) << what;
  }
}

// The message of the ConfigError plan_sweep throws for the sweep file `text` ("" for none).
std::string plan_error(const Fixture& f, const std::string& text) {
  std::ofstream(f.dir / "bad.sweep.yaml") << text;
  SweepOptions o;
  o.out_dir = f.dir / "out";
  try {
    (void)plan_sweep(load_sweep(f.dir / "bad.sweep.yaml"), o);
  } catch (const yaml::ConfigError& e) {
    return e.what();
  }
  return "";
}

// A missing world as the second value of `vary` failed only at run time: the first value's runs
// had run, the sweep exited 1, and the message pointed at line 1 of the base experiment.
TEST(SweepRunner, BadValueFailsBeforeAnythingRunsAtItsLineInTheSweep) {
  Fixture f = make_fixture("badvalue");
  const std::string sweep = (f.dir / "bad.sweep.yaml").string();
  const std::string base = (f.dir / "base.yaml").string();
  EXPECT_EQ(plan_error(f,
                       "base: base.yaml\nseeds: [1]\nvary:\n  world:\n    - w.yaml\n    - "
                       "missing.yaml\n"),
            sweep + ":6: vary.world[1]: world file " + (f.dir / "missing.yaml").string() +
                ": cannot open file (base " + base + ", run world=missing.yaml,seed=1)");
  EXPECT_EQ(plan_error(f, "base: base.yaml\nseeds: [1]\nvary:\n  duration_s:\n    - 5\n    - -1\n"),
            sweep + ":6: vary.duration_s[1]: must be greater than 0, got -1 (base " + base +
                ", run duration_s=-1,seed=1)");
  // A key the value brings is the value's fault.
  const std::string nested =
      plan_error(f, "base: base.yaml\nseeds: [1]\nvary:\n  mapper:\n    - {gridd: 1}\n");
  EXPECT_EQ(nested.rfind(sweep + ":5: vary.mapper[0]: mapper.gridd: unknown key (allowed: ", 0), 0u)
      << nested;
}

// A vary value reaches the experiment as the sweep file wrote it: a quoted number or boolean
// for such a key is refused at its line in the sweep, as in the experiment file, and a quoted
// text stays that text. yaml-cpp's emitter dropped the quotes: '0.5' ran 0.5 s, 'false' was
// the boolean, 'a: b' a mapping ("expected a string") and '#x' nothing ("must not be empty").
TEST(SweepRunner, QuotedValuesStayStringsOnTheirWayToTheRun) {
  Fixture f = make_fixture("quoted");
  const std::string sweep = (f.dir / "bad.sweep.yaml").string();
  const std::string in_base = " (base " + (f.dir / "base.yaml").string() + ", run ";
  EXPECT_EQ(plan_error(f,
                       "base: base.yaml\nseeds: [1]\nvary:\n  duration_s:\n    - 5\n    - "
                       "'0.5'\n"),
            sweep +
                ":6: vary.duration_s[1]: expected a number, got the quoted string '0.5' (write it "
                "without quotes)" +
                in_base + "duration_s=0.5,seed=1)");
  EXPECT_EQ(
      plan_error(f, "base: base.yaml\nseeds: [1]\nvary:\n  output.figures: [true, 'false']\n"),
      sweep +
          ":4: vary.output.figures[1]: expected true or false, got the quoted string "
          "'false' (write it without quotes)" +
          in_base + "output.figures=false,seed=1)");
  EXPECT_EQ(plan_error(f, "base: base.yaml\nseeds: [1]\nvary:\n  output.figures: [yes]\n"),
            sweep +
                ":4: vary.output.figures[0]: expected true or false, got 'yes': a YAML 1.1 "
                "boolean, which YAML 1.2 reads as a string (write true)" +
                in_base + "output.figures=yes,seed=1)");
  EXPECT_EQ(plan_error(f, "base: base.yaml\nseeds: [1]\nvary:\n  duration_s:\n    - |\n      2\n"),
            sweep +
                ":5: vary.duration_s[0]: expected a number, got a block scalar (| or >) holding "
                "'2', a string in YAML (write the plain 2 instead)" +
                in_base + "duration_s=2_,seed=1)");
  std::ofstream(f.dir / "names.sweep.yaml")
      << "base: base.yaml\nseeds: [1]\nvary:\n  name: ['007', 'a: b', '#x', 'true', x y]\n"
         "  duration_s: [0x10]\n";
  SweepOptions o;
  o.out_dir = f.dir / "out";
  const auto planned = plan_sweep(load_sweep(f.dir / "names.sweep.yaml"), o);
  ASSERT_EQ(planned.size(), 5u);
  const std::vector<std::string> names = {"007", "a: b", "#x", "true", "x y"};
  for (std::size_t i = 0; i < names.size(); ++i) {
    EXPECT_EQ(planned[i].experiment.name, names[i]);
    EXPECT_DOUBLE_EQ(planned[i].experiment.duration_s, 16.0);
  }
}

// An unknown varied key was reported as "base.yaml: mapper.gridd: unknown key", at no line
// of the sweep (or at line 1 of the base experiment).
TEST(SweepRunner, UnknownVaryKeyIsReportedAtItsLineInTheSweep) {
  Fixture f = make_fixture("badkey");
  const std::string sweep = (f.dir / "bad.sweep.yaml").string();
  const std::string what =
      plan_error(f, "base: base.yaml\nseeds: [1]\nvary:\n  mapper.gridd:\n    - himm\n");
  EXPECT_EQ(what.rfind(sweep + ":4: vary.mapper.gridd: unknown key (allowed: grid,", 0), 0u)
      << what;
  EXPECT_TRUE(what.ends_with(" (base " + (f.dir / "base.yaml").string() +
                             ", run mapper.gridd=himm,seed=1)"))
      << what;
  // A key path through a value that is no mapping: the key's fault too.
  const std::string through =
      plan_error(f, "base: base.yaml\nseeds: [1]\nvary:\n  name.x:\n    - 1\n");
  EXPECT_EQ(through.rfind(sweep + ":4: vary.name.x: ", 0), 0u) << through;
}

std::string read_all(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(SweepRunner, HeaderStartIsWhatRunSweepWritesBeforeTheMetrics) {
  Fixture f = make_fixture("header");
  SweepOptions o;
  o.out_dir = f.dir / "out";
  const SweepOutcome out = run_sweep(f.spec, plan_sweep(f.spec, o), o, fake_run);
  EXPECT_EQ(results_header_start(f.spec), "run,mapper.cell_scale_mm,seed");
  EXPECT_EQ(read_all(out.results_csv).rfind(results_header_start(f.spec) + ",", 0), 0u);
}

// A user's results.csv or plots/ in --out were replaced silently (a sweep, or --merge with no
// --out in the current directory).
TEST(SweepRunner, DirectoryWithAUsersResultsOrPlotsIsRefused) {
  Fixture f = make_fixture("foreign");
  const fs::path home = f.dir / "home";
  fs::create_directories(home / "plots");
  std::ofstream(home / "results.csv") << "mine\n";
  std::ofstream(home / "plots" / "holiday.png") << "png";
  const SweepOutputs outputs{"results.csv", results_header_start(f.spec), true};
  try {
    check_sweep_directory(home, outputs, false);
    FAIL() << "accepted a directory holding a user's results.csv";
  } catch (const SweepDirectoryError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("home: holds results.csv and plots/, which no cogmap sweep wrote"),
              std::string::npos)
        << what;
    EXPECT_NE(what.find("--force"), std::string::npos) << what;
  }
  fs::remove(home / "results.csv");  // plots/ alone is refused too
  EXPECT_THROW(check_sweep_directory(home, outputs, false), SweepDirectoryError);
  EXPECT_NO_THROW(check_sweep_directory(home, {"results.csv", "run,seed", false}, false));
  EXPECT_NO_THROW(check_sweep_directory(home, outputs, true));  // --force
  // Another shard's file is not ours to judge: only the file this shard writes counts.
  std::ofstream(home / "results.csv") << "mine\n";
  EXPECT_NO_THROW(
      check_sweep_directory(home, {"results_shard_1_of_2.csv", "run,seed", false}, false));
  EXPECT_EQ(read_all(home / "results.csv"), "mine\n");
}

TEST(SweepRunner, OwnDirectoryIsAcceptedByMarkerOrByHeader) {
  Fixture f = make_fixture("own");
  SweepOptions o;
  o.out_dir = f.dir / "out";
  const SweepOutputs outputs{"results.csv", results_header_start(f.spec), true};
  check_sweep_directory(o.out_dir, outputs, false);  // new
  mark_sweep_directory(o.out_dir);
  EXPECT_TRUE(fs::exists(o.out_dir / kSweepMarkerName));
  (void)run_sweep(f.spec, plan_sweep(f.spec, o), o, fake_run);
  fs::create_directories(o.out_dir / "plots");
  std::ofstream(o.out_dir / "plots" / "asr_count.png") << "png";
  EXPECT_NO_THROW(check_sweep_directory(o.out_dir, outputs, false));  // the marker
  // A sweep made before the marker: its results file starts with this sweep's header.
  fs::remove(o.out_dir / kSweepMarkerName);
  EXPECT_NO_THROW(check_sweep_directory(o.out_dir, outputs, false));
  // ...but not another sweep's header.
  EXPECT_THROW(
      check_sweep_directory(o.out_dir, {"results.csv", "run,mapper.grid,seed", true}, false),
      SweepDirectoryError);
  // A header that merely begins like ours is not ours.
  EXPECT_THROW(check_sweep_directory(o.out_dir, {"results.csv", "run,mapper.cell", true}, false),
               SweepDirectoryError);
  // A marker made by hand (empty) makes another sweep's results no more ours (fuzzing, session
  // 56: an empty marker was enough).
  std::ofstream(o.out_dir / kSweepMarkerName) << "";
  EXPECT_THROW(
      check_sweep_directory(o.out_dir, {"results.csv", "run,mapper.grid,seed", true}, false),
      SweepDirectoryError);
}

TEST(SweepRunner, OutputThatIsNotADirectoryOrFileIsRefusedEvenWithForce) {
  Fixture f = make_fixture("notdir");
  std::ofstream(f.dir / "file") << "x\n";
  EXPECT_THROW(check_sweep_directory(f.dir / "file", {"results.csv", "run,seed", false}, true),
               SweepDirectoryError);
  fs::create_directories(f.dir / "out" / "results.csv");
  EXPECT_THROW(check_sweep_directory(f.dir / "out", {"results.csv", "run,seed", false}, true),
               SweepDirectoryError);
}

TEST(SweepRunner, MergeOfADeviceSaysWhatItIs) {
  try {
    (void)results_files({"/dev/zero"});
    FAIL() << "accepted /dev/zero";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "/dev/zero: not a regular file or directory (a device, pipe or socket)");
  }
}

}  // namespace
}  // namespace cogmap::experiments
