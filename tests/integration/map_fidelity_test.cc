// Issue 10's map figures on the shipped route and explore experiments, steering by the
// estimate, seeds 1-5:
// every seed's median and p90 wall error, coverage, spurious fraction and final heading error
// held to what was measured (docs/results.md, 2026-12-02: each bound 1.25x the worst seed,
// coverage 0.8x), and EM never worse than odometry alone on the mean over the seeds (one of
// the targets, met on these worlds but explore_two_rooms). The other targets
// (median ≤ 0.10 m, p90 ≤ 0.30 m, spurious ≤ 0.15, ≤ 2° where odometry drifts ≥ 5°) are not met
// yet; these bounds make a regression show and are to be tightened as the maps improve.
#include <gtest/gtest.h>

#include "run_seed.h"
#include "source_dir.h"

#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "cogmap/experiments/experiment_config.h"
#include "cogmap/experiments/runner.h"

namespace cogmap::experiments {
namespace {

using integration::source_dir;

struct FidelityCase {
  std::string name;                    ///< for the test's name
  std::string experiment;              ///< experiments/NAME.yaml
  std::vector<std::string> overrides;  ///< as the sweep of docs/results.md sets them
  // Worst seed measured (release build, 2026-12-01) in the comments of each instance.
  double max_median_m;
  double max_p90_m;
  double min_coverage;
  double max_spurious;
  std::optional<double> max_heading_deg;  ///< corrected; none where EM has nothing to do
  /// EM's mean final heading error over the seeds no worse than odometry's (issue 10's target);
  /// false only where it is measured broken, with the reason at the instance.
  bool em_not_worse = true;
};

void PrintTo(const FidelityCase& c, std::ostream* os) { *os << c.name; }

class MapFidelity : public ::testing::TestWithParam<FidelityCase> {};

TEST_P(MapFidelity, EverySeedWithinWhatWasMeasured) {
  const FidelityCase& c = GetParam();
  Experiment e =
      load_experiment(source_dir() / "experiments" / (c.experiment + ".yaml"), c.overrides);
  ASSERT_FALSE(e.controller.steer_by_truth);
  double odometry_sum = 0.0, corrected_sum = 0.0;
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const nlohmann::json m = integration::run_seed_metrics(e, seed, "fidelity_" + c.name);
    const nlohmann::json& map = m["map"];
    EXPECT_LE(map["wall_error_median_m"].get<double>(), c.max_median_m);
    EXPECT_LE(map["wall_error_p90_m"].get<double>(), c.max_p90_m);
    EXPECT_GE(map["wall_coverage"].get<double>(), c.min_coverage);
    EXPECT_LE(map["spurious_fraction"].get<double>(), c.max_spurious);
    const nlohmann::json& heading = m["localization"]["heading_error_final_deg"];
    odometry_sum += heading["odometry"].get<double>();
    corrected_sum += heading["corrected"].get<double>();
    if (c.max_heading_deg) {
      EXPECT_LE(heading["corrected"].get<double>(), *c.max_heading_deg);
    }
  }
  if (c.em_not_worse) {
    EXPECT_LE(corrected_sum, odometry_sum) << "EM made the mean final heading error worse";
  }
}

INSTANTIATE_TEST_SUITE_P(
    ShippedRoutes, MapFidelity,
    ::testing::Values(
        // Worst seeds (2026-12-02: the door search, EM's posterior against the last 32 rooms):
        // median 0.257 m, p90 0.667 m, coverage 0.291, spurious 0.402, 8.53°; mean heading
        // error 7.69° (odometry) -> 5.21° (corrected).
        FidelityCase{"nine_rooms", "nine_rooms", {}, 0.32, 0.83, 0.23, 0.50, 10.7},
        // 0.079 m, 0.336 m, 0.397, 0.134, 6.94°; mean 3.57° -> 3.47°.
        FidelityCase{"three_room_slam", "three_room_slam", {}, 0.099, 0.42, 0.32, 0.168, 8.7},
        // ε = 5 (the shipped value): 0.377 m, 0.909 m, 0.194, 0.596, 2.46°; mean 9.32° -> 1.82°.
        FidelityCase{"hallway_loop", "hallway_loop", {}, 0.47, 1.14, 0.155, 0.75, 3.1},
        // ℘ = 55 mm, one room (no EM correction): 0.064 m, 0.214 m, 0.153, 0.067.
        FidelityCase{"small_clutter_55",
                     "small_clutter",
                     {"mapper.cell_scale_mm=55"},
                     0.080,
                     0.267,
                     0.122,
                     0.083,
                     std::nullopt}),
    [](const auto& info) { return info.param.name; });

// The shipped explore experiments (release build, 2026-12-02, seeds 1-5; worst seeds in the
// comments; same rules: 1.25x the worst, coverage 0.8x).
INSTANTIATE_TEST_SUITE_P(
    ShippedExplore, MapFidelity,
    ::testing::Values(
        // 0.379 m, 0.949 m, 0.481, 0.578, 4.22°; mean 14.98° -> 2.14°.
        FidelityCase{"explore_nine_rooms", "explore_nine_rooms", {}, 0.47, 1.19, 0.38, 0.72, 5.3},
        // 0.440 m, 1.070 m, 0.348, 0.625, 18.95°; mean 12.33° -> 6.97°.
        FidelityCase{
            "explore_three_room_slam", "explore_three_room_slam", {}, 0.55, 1.34, 0.28, 0.78, 23.7},
        // 0.391 m, 0.945 m, 0.450, 0.599, 7.29°; mean 10.83° -> 5.46°.
        FidelityCase{
            "explore_small_clutter", "explore_small_clutter", {}, 0.49, 1.18, 0.36, 0.75, 9.1},
        // 0.243 m, 0.861 m, 0.583, 0.447, 19.86°. EM is worse than odometry here on the mean
        // (8.99° -> 9.15°; seed 5: 1.02° -> 13.74°): a room toured for minutes is measured at its
        // mean heading error and that rotation is applied at the room's end, where the drift
        // may have swung back (traced on seed 5 with the short reference: -13° measured, -1.2° at
        // the end). An open failure of issue 10's target (docs/results.md), not asserted until
        // it is fixed.
        FidelityCase{
            "explore_two_rooms", "explore_two_rooms", {}, 0.30, 1.08, 0.47, 0.56, 24.8, false}),
    [](const auto& info) { return info.param.name; });

}  // namespace
}  // namespace cogmap::experiments
