#include "cogmap/experiments/sweep.h"

#include <gtest/gtest.h>

#include <fstream>
#include <set>

#include "cogmap/sim/yaml_strict.h"

namespace cogmap::experiments {
namespace {

namespace fs = std::filesystem;

fs::path write_temp(const std::string& name, const std::string& text) {
  const fs::path dir = fs::path(::testing::TempDir()) / "sweep_test";
  fs::create_directories(dir);
  std::ofstream(dir / name) << text;
  return dir / name;
}

SweepSpec two_by_three() {
  return load_sweep(write_temp("s.sweep.yaml",
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
  const auto runs = expand_sweep(load_sweep(write_temp("n.yaml", "base: b.yaml\nseeds: [3, 4]\n")));
  ASSERT_EQ(runs.size(), 2u);
  EXPECT_EQ(runs[1].dir_name(), "seed=4");
}

TEST(Sweep, StrictErrors) {
  auto err = [](const std::string& text) -> std::string {
    try {
      (void)load_sweep(write_temp("bad.yaml", text));
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

}  // namespace
}  // namespace cogmap::experiments
