#include "cogmap/experiments/sweep.h"

#include <gtest/gtest.h>

#include <fstream>
#include <set>

#include "cogmap/sim/yaml_strict.h"
#include "cogmap/test_support/scratch_dir.h"

namespace cogmap::experiments {
namespace {

namespace fs = std::filesystem;

fs::path write_sweep_file(const std::string& name, const std::string& text) {
  // One directory per test: ctest runs the tests of this file as parallel processes.
  const fs::path dir = test_support::process_scratch() / "sweep_test" /
                       ::testing::UnitTest::GetInstance()->current_test_info()->name();
  fs::create_directories(dir);
  std::ofstream(dir / name) << text;
  return dir / name;
}

SweepSpec two_by_three() {
  return load_sweep(write_sweep_file("s.sweep.yaml",
                                     "base: nine_rooms.yaml\n"
                                     "seeds: [1, 2]\n"
                                     "vary:\n"
                                     "  mapper.cell_scale_mm: [55, 85, 100]\n"
                                     "  mapper.grid: [himm, mhimm]\n"));
}

TEST(Sweep, ParsesAndResolvesBase) {
  const SweepSpec s = two_by_three();
  EXPECT_EQ(s.base, s.file.parent_path() / "nine_rooms.yaml");
  EXPECT_EQ(s.seeds, (std::vector<std::uint64_t>{1, 2}));
  ASSERT_EQ(s.vary.size(), 2u);
  EXPECT_EQ(s.vary[0].key, "mapper.cell_scale_mm");
  EXPECT_EQ(s.vary[1].values, (std::vector<std::string>{"himm", "mhimm"}));
}

TEST(Sweep, CartesianProductOrder) {
  const auto runs = expand_sweep(two_by_three());
  ASSERT_EQ(runs.size(), 12u);
  std::vector<std::string> names;
  for (const auto& r : runs) names.push_back(r.dir_name());
  EXPECT_EQ(names[0], "mapper.cell_scale_mm=55,mapper.grid=himm,seed=1");
  EXPECT_EQ(names[1], "mapper.cell_scale_mm=55,mapper.grid=himm,seed=2");
  EXPECT_EQ(names[2], "mapper.cell_scale_mm=55,mapper.grid=mhimm,seed=1");
  EXPECT_EQ(names[4], "mapper.cell_scale_mm=85,mapper.grid=himm,seed=1");
  EXPECT_EQ(names[11], "mapper.cell_scale_mm=100,mapper.grid=mhimm,seed=2");
  for (std::size_t i = 0; i < runs.size(); ++i) EXPECT_EQ(runs[i].index, i);
  EXPECT_EQ(runs[5].overrides(),
            (std::vector<std::string>{"mapper.cell_scale_mm=85", "mapper.grid=himm"}));
  EXPECT_EQ(std::set<std::string>(names.begin(), names.end()).size(), 12u);
}

TEST(Sweep, ShardsPartitionEveryRunExactlyOnce) {
  const auto runs = expand_sweep(two_by_three());
  for (std::size_t n = 1; n <= 13; ++n) {
    std::vector<int> count(runs.size(), 0);
    for (std::size_t k = 1; k <= n; ++k) {
      for (const auto& r : shard_runs(runs, {k, n})) ++count[r.index];
    }
    for (int c : count) EXPECT_EQ(c, 1) << "N=" << n;
  }
  const auto second = shard_runs(runs, parse_shard("2/5"));
  ASSERT_EQ(second.size(), 3u);
  EXPECT_EQ(second[0].index, 1u);
  EXPECT_EQ(second[1].index, 6u);
  EXPECT_EQ(second[2].index, 11u);
}

TEST(Sweep, BadShardText) {
  EXPECT_THROW(parse_shard("0/4"), std::invalid_argument);
  EXPECT_THROW(parse_shard("5/4"), std::invalid_argument);
  EXPECT_THROW(parse_shard("2"), std::invalid_argument);
  EXPECT_THROW(parse_shard("a/b"), std::invalid_argument);
  EXPECT_EQ(parse_shard("3/4").k, 3u);
}

TEST(Sweep, NoVaryMeansSeedsOnly) {
  const auto runs =
      expand_sweep(load_sweep(write_sweep_file("n.yaml", "base: b.yaml\nseeds: [3, 4]\n")));
  ASSERT_EQ(runs.size(), 2u);
  EXPECT_EQ(runs[1].dir_name(), "seed=4");
}

TEST(Sweep, StrictErrors) {
  auto err = [](const std::string& text) -> std::string {
    try {
      (void)load_sweep(write_sweep_file("bad.yaml", text));
    } catch (const yaml::ConfigError& e) {
      return e.what();
    }
    return "no error";
  };
  EXPECT_NE(err("base: b.yaml\nseeds: [1]\nvaru: {}\n").find(":3: varu: unknown key"),
            std::string::npos);
  EXPECT_NE(err("base: b.yaml\nseeds: []\n").find("seeds: needs at least one seed"),
            std::string::npos);
  EXPECT_NE(err("base: b.yaml\nseeds: [-1]\n").find("seeds[0]: expected a non-negative"),
            std::string::npos);
  EXPECT_NE(err("base: b.yaml\nseeds: [1]\nvary:\n  mapper.grid: himm\n")
                .find(":4: vary.mapper.grid: expected a list"),
            std::string::npos);
}

std::string sweep_error(const std::string& text, SweepLimits limits = {}) {
  try {
    // A file per test: ctest -j runs the tests of this file in parallel processes.
    const std::string name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    (void)load_sweep(write_sweep_file(name + ".yaml", text), limits);
  } catch (const yaml::ConfigError& e) {
    return e.what();
  }
  return "no error";
}

TEST(Sweep, DuplicateSeedsAndValuesAreRefused) {
  EXPECT_NE(sweep_error("base: b.yaml\nseeds:\n  - 1\n  - 2\n  - 1\n")
                .find(":5: seeds[2]: seed 1 is listed twice (also line 3)"),
            std::string::npos);
  // 55 and "55" differ (a number and a string) but would write the same run directory.
  EXPECT_NE(sweep_error("base: b.yaml\nseeds: [1]\nvary:\n  mapper.cell_scale_mm: [55, \"55\"]\n")
                .find(":4: vary.mapper.cell_scale_mm[1]: value '55' repeats '55' (line 4)"),
            std::string::npos);
  // Distinct values whose directory names collide would have two threads write one directory.
  EXPECT_NE(sweep_error("base: b.yaml\nseeds: [1]\nvary:\n  name: [\"a b\", a_b]\n")
                .find("value 'a_b' repeats 'a b'"),
            std::string::npos);
}

// Each value's --set text reads back as the sweep file wrote it. yaml-cpp's emitter (and a
// scalar's bare text) dropped the quotes: '007' went to --set as 007, '0.5' as the number,
// 'false' as the boolean, 'a: b' as a mapping and '#x' as a comment.
TEST(Sweep, SetTextsReadBackAsTheSweepWroteThem) {
  const fs::path file = write_sweep_file(
      "q.sweep.yaml",
      "base: b.yaml\nseeds: [1]\nvary:\n"
      "  name: ['007', \"x y\", 'a: b', '#x', \"it's \\\"q\\\"\", plain words, !!str 12,\n"
      "         !!str '#y', !!str 'c: d']\n"
      "  duration_s: [55, '0.5', 0x10]\n"
      "  output.figures: [true, 'false', yes]\n"
      "  controller.waypoints: [[[1, '2']], [[3, 4]]]\n"
      "  description:\n    - |\n      two\n      lines\n    - >-\n      folded\n      line\n"
      "    - |2+\n         lead\n        x\n\n\n");
  const SweepSpec s = load_sweep(file);
  ASSERT_EQ(s.vary.size(), 5u);
  EXPECT_EQ(s.vary[0].values, (std::vector<std::string>{"007", "x y", "a: b", "#x", "it's \"q\"",
                                                        "plain words", "12", "#y", "c: d"}));
  EXPECT_EQ(s.vary[0].set_texts,
            (std::vector<std::string>{
                "\"007\"", "\"x y\"", "\"a: b\"", "\"#x\"", "\"it's \\\"q\\\"\"", "plain words",
                "!<tag:yaml.org,2002:str> \"12\"", "!<tag:yaml.org,2002:str> \"#y\"",
                "!<tag:yaml.org,2002:str> \"c: d\""}));
  EXPECT_EQ(s.vary[1].set_texts, (std::vector<std::string>{"55", "\"0.5\"", "0x10"}));
  EXPECT_EQ(s.vary[2].set_texts, (std::vector<std::string>{"true", "\"false\"", "yes"}));
  EXPECT_EQ(s.vary[3].set_texts, (std::vector<std::string>{"[[1, \"2\"]]", "[[3, 4]]"}));
  EXPECT_EQ(s.vary[4].set_texts,
            (std::vector<std::string>{"|2\n  two\n  lines\n", "|2-\n  folded line\n",
                                      "|2+\n     lead\n    x\n\n\n"}));
  // Set as --set sets them, every value is the node the sweep file holds: the same text, the
  // same tag (quoted "!", plain "?") and, for | and >, still a block scalar.
  const yaml::Node vary = yaml::Node::load_file(file)["vary"];
  for (const SweepAxis& axis : s.vary) {
    for (std::size_t i = 0; i < axis.values.size(); ++i) {
      yaml::Node doc = yaml::Node::load_string("x: 0\n", "d.yaml");
      yaml::apply_override(doc.raw(), "x=" + axis.set_texts[i]);
      const YAML::Node want = vary[axis.key].at(i).raw();
      const YAML::Node got = doc.raw()["x"];
      const std::string at = axis.key + "[" + std::to_string(i) + "]";
      if (!want.IsScalar()) {
        EXPECT_EQ(YAML::Dump(got), YAML::Dump(want)) << at;
        continue;
      }
      EXPECT_EQ(got.Scalar(), want.Scalar()) << at;
      EXPECT_EQ(got.Tag(), want.Tag()) << at;
      EXPECT_EQ(got.Style(), want.Style()) << at;
    }
  }
  const auto runs = expand_sweep(s);
  EXPECT_EQ(runs[0].overrides(),
            (std::vector<std::string>{"name=\"007\"", "duration_s=55", "output.figures=true",
                                      "controller.waypoints=[[1, \"2\"]]",
                                      "description=|2\n  two\n  lines\n"}));
  EXPECT_EQ(runs[0].dir_name(),
            "name=007,duration_s=55,output.figures=true,controller.waypoints=__1,_2__,"
            "description=two_lines_,seed=1");
}

TEST(Sweep, RunCountLimitIsCheckedBeforeExpansion) {
  // 10 seeds x 10^6 combinations: refused at the 4th axis (10^5 runs), none listed.
  std::string text = "base: b.yaml\nseeds: [1, 2, 3, 4, 5, 6, 7, 8, 9, 10]\nvary:\n";
  for (const char* key : {"a", "b", "c", "d", "e", "f"}) {
    text += std::string("  ") + key + ": [1, 2, 3, 4, 5, 6, 7, 8, 9, 10]\n";
  }
  EXPECT_NE(sweep_error(text).find(":7: vary.d: the sweep has more than 10000 runs"),
            std::string::npos)
      << sweep_error(text);
  // The limit is an option: exactly at it is fine, one above is not.
  const std::string six = "base: b.yaml\nseeds: [1, 2]\nvary:\n  a: [1, 2, 3]\n";
  EXPECT_EQ(sweep_error(six, SweepLimits{6}), "no error");
  EXPECT_NE(sweep_error(six, SweepLimits{5}).find("more than 5 runs"), std::string::npos);
}

TEST(Sweep, DirectoryNamesCannotLeaveRuns) {
  SweepRun run;
  run.values = {{"a/../../b", "../x y"}, {"c", "/etc"}};
  run.seed = 3;
  EXPECT_EQ(run.dir_name(), "a_.._.._b=_.._x_y,c=_etc,seed=3");
}

}  // namespace
}  // namespace cogmap::experiments
