// Issue 10's map figures on the shipped route and explore experiments, steering by the
// estimate, seeds 1-5:
// every seed's median and p90 wall error, coverage, spurious fraction and final heading error
// held to what was measured (docs/results.md, 2026-12-01: each bound 1.25x the worst seed,
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
        // Worst seeds (2026-12-02, with the door search): median 0.307 m, p90 0.642 m,
        // coverage 0.240, spurious 0.518, 6.54°; mean heading error 6.23° (odometry) -> 3.32°.
        FidelityCase{"nine_rooms", "nine_rooms", {}, 0.38, 0.80, 0.19, 0.65, 8.2},
        // 0.093 m, 0.315 m, 0.399, 0.131, 6.82°; mean 3.56° -> 3.38°.
        FidelityCase{"three_room_slam", "three_room_slam", {}, 0.116, 0.39, 0.32, 0.164, 8.5},
        // ε = 5 (the shipped value): 0.618 m, 1.31 m, 0.135, 0.709, 2.31°; mean 9.38° -> 1.44°.
        FidelityCase{"hallway_loop", "hallway_loop", {}, 0.77, 1.64, 0.108, 0.89, 2.9},
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
        // 0.387 m, 0.871 m, 0.554, 0.564, 25.5°; mean 12.54° -> 8.91°.
        FidelityCase{"explore_nine_rooms", "explore_nine_rooms", {}, 0.48, 1.09, 0.44, 0.71, 31.9},
        // 0.409 m, 1.041 m, 0.501, 0.580, 18.1°; mean 30.68° -> 9.99°.
        FidelityCase{
            "explore_three_room_slam", "explore_three_room_slam", {}, 0.51, 1.30, 0.40, 0.73, 22.7},
        // 0.365 m, 1.067 m, 0.445, 0.569, 10.5°; mean 9.66° -> 5.61°.
        FidelityCase{
            "explore_small_clutter", "explore_small_clutter", {}, 0.46, 1.33, 0.36, 0.71, 13.1},
        // 0.276 m, 0.953 m, 0.573, 0.474, 31.8°. EM is worse than odometry here on the mean
        // (7.95° -> 9.74°): on seed 5 it measured room 1's mean heading error (-13°, the drift
        // swung from -6° to about -20° and back inside the room) and applied it at the room's
        // end, where the error was -1.2°: 14.9° -> 31.8° at the end of the run. An open
        // failure of issue 10's target (docs/results.md), not asserted until it is fixed.
        FidelityCase{
            "explore_two_rooms", "explore_two_rooms", {}, 0.35, 1.19, 0.46, 0.59, 39.8, false}),
    [](const auto& info) { return info.param.name; });

}  // namespace
}  // namespace cogmap::experiments
