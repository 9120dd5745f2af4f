// Issue 10's map figures on the shipped route and explore experiments, steering by the
// estimate, seeds 1-5:
// every seed's median and p90 wall error, coverage, spurious fraction and final heading error
// held to what was measured (docs/results.md, 2026-12-02: each bound 1.25x the worst seed,
// coverage 0.8x), and EM never worse than odometry alone on the mean over the seeds (one of
// the targets, met on every one of these worlds). The other targets
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
  /// error_breakdown.aligned_map's median: the map's shape once laid onto the building as a
  /// whole (2026-12-05, release build, 1.25x the worst seed; docs/results.md, "What the
  /// world-frame error is made of").
  double max_aligned_median_m;
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
    EXPECT_LE(m["error_breakdown"]["aligned_map"]["median_m"].get<double>(),
              c.max_aligned_median_m);
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
        // Worst seeds (2026-12-04: the door search, EM's posterior against the last 32 rooms,
        // "Looking past a close waypoint", the end-of-run relaxation of the rooms' positions):
        // median 0.228 m, p90 0.633 m, coverage 0.290, spurious 0.370, 8.53°; mean heading error
        // 7.36° (odometry) -> 3.99° (corrected). Without the relaxation 0.257 m, 0.667 m, 0.291,
        // 0.402.
        // Aligned as a whole (2026-12-05): 0.059, 0.049, 0.046, 0.068, 0.080 m.
        FidelityCase{"nine_rooms", "nine_rooms", {}, 0.29, 0.79, 0.23, 0.46, 10.7, 0.10},
        // 0.073 m, 0.309 m, 0.422, 0.101, 6.94°; mean 3.57° -> 3.47° (without the relaxation
        // 0.079 m, 0.336 m, 0.397, 0.134).
        // Aligned: 0.035, 0.051, 0.043, 0.039, 0.044 m.
        FidelityCase{
            "three_room_slam", "three_room_slam", {}, 0.091, 0.39, 0.34, 0.126, 8.7, 0.064},
        // ε = 5 (the shipped value), every route completed since the probe looks only for a
        // waypoint within 5 m (docs/algorithms.md, "Probe"): 0.434 m (seed 5), 1.013 m, 0.158,
        // 0.650, 2.77° (seed 4); mean 10.41° -> 1.63° (without the relaxation 0.483 m, 1.179 m,
        // 0.175, 0.649).
        // Aligned: 0.130, 0.155, 0.147, 0.064, 0.060 m (the loop's scale is no rigid motion).
        FidelityCase{"hallway_loop", "hallway_loop", {}, 0.54, 1.27, 0.13, 0.81, 3.5, 0.194},
        // ℘ = 55 mm, one room (no EM correction): 0.064 m, 0.214 m, 0.153, 0.067.
        FidelityCase{"small_clutter_55",
                     "small_clutter",
                     {"mapper.cell_scale_mm=55"},
                     0.080,
                     0.267,
                     0.122,
                     0.083,
                     std::nullopt,
                     0.063}),  // aligned: 0.050, 0.038, 0.037, 0.048, 0.032 m
    [](const auto& info) { return info.param.name; });

// The shipped explore experiments (release build, 2026-12-07, since the explorer's moves on an
// arc are checked against the sensed points for 0.5 s, docs/algorithms.md "Turning on the
// spot", and it plans again when its path has run into a wall for 10 s, "A path run into a
// wall"; before, 2026-12-06, with the explorer's long rooms
// cut every 4.5 m of travel, docs/algorithms.md "Long rooms cut", the door's view limit,
// "Door passage" 7, the position fixes at doorways passed again, "Position fixes at doorways
// passed again", the end-of-run relaxation, the room grid's last look before stopping and the
// echo matcher in the map alone, "The matcher in the map only"; seeds 1-5; worst seeds in the
// comments; same rules: 1.25x the worst, coverage 0.8x). The tours are chaotic (a changed look
// reshuffles every later turn and with it the skid-steer drift), so the bounds move with any
// change of the explorer; docs/results.md has the 5-seed tables. The matcher changes the map
// and not the drive, so the rooms and times of explore_test.cc did not move with it.
INSTANTIATE_TEST_SUITE_P(
    ShippedExplore, MapFidelity,
    ::testing::Values(
        // Worst seeds (median, p90, coverage, spurious, corrected heading), 2026-12-07 with the
        // arc guard: 0.167 m, 0.448 m, 0.638, 0.279, 2.63°; mean 13.29° -> 1.07° (before it, the
        // same day: 0.167 m, 0.448 m, 0.638, 0.279, 1.68°; mean 8.28° -> 1.00°; 2026-12-06:
        // 0.176 m, 0.522 m, 0.615, 0.317, 4.42°; mean 16.51° -> 2.24°). Without the matcher
        // (2026-12-04): 0.151 m, 0.474 m, 0.695, 0.243, 5.45°; mean 16.51° -> 3.63°.
        // Aligned as a whole: 0.049, 0.042, 0.047, 0.050, 0.048 m.
        FidelityCase{
            "explore_nine_rooms", "explore_nine_rooms", {}, 0.209, 0.56, 0.51, 0.35, 3.3, 0.063},
        // 2026-12-07 with the arc guard: 0.215 m, 0.512 m, 0.536, 0.375, 4.00°; mean 20.70° ->
        // 2.31° (seed 5 stops after 5 of the 9 rooms: a door goal given up). Before it, the same
        // day: 0.212 m, 0.511 m, 0.539, 0.375, 5.85°; mean 20.43° -> 3.34°. 2026-12-06:
        // 0.248 m, 0.543 m, 0.493, 0.432, 11.31°; mean 7.33° -> 3.30° (without the matcher
        // 0.278 m, 0.671 m, 0.496, 0.473, 6.01°; mean 8.24° -> 2.28°).
        // Aligned: 0.041, 0.052, 0.047, 0.091, 0.042 m.
        FidelityCase{"explore_three_room_slam",
                     "explore_three_room_slam",
                     {},
                     0.268,
                     0.64,
                     0.43,
                     0.47,
                     5.0,
                     0.113},
        // 2026-12-07 with the arc guard: 0.172 m, 0.477 m, 0.711, 0.255, 6.74°; mean 12.40° ->
        // 3.27° (before it, the same day: 0.169 m, 0.640 m, 0.682, 0.298, 6.21°; mean 7.51° ->
        // 2.04°; 2026-12-06: 0.172 m, 0.640 m, 0.682, 0.298, 7.02°; mean 9.85° -> 2.00°;
        // without the matcher 0.198 m, 0.635 m, 0.710, 0.335, 7.26°; mean 9.85° -> 3.73°). One
        // room, cut into ASRs among the desks, whose short faces make EM's measurements noisy.
        // Aligned: 0.082, 0.069, 0.074, 0.137, 0.074 m (its cuts drift against one another).
        FidelityCase{"explore_small_clutter",
                     "explore_small_clutter",
                     {},
                     0.215,
                     0.60,
                     0.569,
                     0.319,
                     8.4,
                     0.172},
        // 2026-12-07: 0.101 m, 0.342 m, 0.780, 0.159, 3.24°; mean 9.15° -> 2.04° (2026-12-06:
        // 0.098 m, 0.339 m, 0.770, 0.148, 10.37°; mean 6.74° -> 4.90°; without the matcher
        // 0.121 m, 0.555 m, 0.800, 0.250, 4.53°; mean 6.74° -> 2.53°).
        // Aligned: 0.039, 0.046, 0.040, 0.046, 0.048 m.
        FidelityCase{
            "explore_two_rooms", "explore_two_rooms", {}, 0.126, 0.43, 0.62, 0.198, 4.1, 0.060}),
    [](const auto& info) { return info.param.name; });

}  // namespace
}  // namespace cogmap::experiments
