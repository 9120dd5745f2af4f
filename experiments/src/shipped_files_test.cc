// Every experiment and sweep file shipped in experiments/ goes through the real parsers
// (experiment, sweep, world, sim robot block), so a broken file fails CI, not a user's run.
#include <gtest/gtest.h>

#include <cstdlib>

#include "cogmap/experiments/experiment_config.h"
#include "cogmap/experiments/runner.h"
#include "cogmap/experiments/sweep_runner.h"

namespace cogmap::experiments {
namespace {

namespace fs = std::filesystem;

fs::path experiments_dir() {
  const char* src = std::getenv("COGMAP_SOURCE_DIR");
  // ctest sets COGMAP_SOURCE_DIR; fall back to this file's checkout when run by hand.
  return (src ? fs::path(src) : fs::path(__FILE__).parent_path().parent_path().parent_path()) /
         "experiments";
}

TEST(ShippedFiles, EveryExperimentAndSweepParses) {
  std::size_t experiments = 0, sweeps = 0;
  for (const auto& entry : fs::directory_iterator(experiments_dir())) {
    const fs::path p = entry.path();
    if (p.extension() != ".yaml") continue;
    SCOPED_TRACE(p.string());
    try {
      if (p.filename().string().ends_with(".sweep.yaml")) {
        const SweepSpec spec = load_sweep(p);
        SweepOptions options;
        options.out_dir = "unused";
        const auto planned = plan_sweep(spec, options);
        EXPECT_EQ(planned.size(), expand_sweep(spec).size());
        for (const auto& run : planned) validate_experiment(run.experiment);
        EXPECT_EQ(spec.seeds, (std::vector<std::uint64_t>{1, 2, 3, 4, 5}));
        ++sweeps;
      } else {
        const Experiment e = load_experiment(p);
        validate_experiment(e);
        EXPECT_EQ(p.stem().string(), e.name) << "the file name and `name` should agree";
        ++experiments;
      }
    } catch (const std::exception& e) {
      ADD_FAILURE() << e.what();
    }
  }
  EXPECT_GE(experiments, 5u);
  EXPECT_GE(sweeps, 3u);
}

}  // namespace
}  // namespace cogmap::experiments
