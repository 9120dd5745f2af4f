// Issue 9's regression per world kind: buildings the navigation was not tuned on, made by
// scripts/gen-building (the command is the first line of each file in generated/), driven by
// the mapper's own estimate along straight centre-to-centre routes with no approach points.
// Five seeds per world: the robot must touch nothing, never circle until the time limit, map
// one ASR per room (or, in a corridor, per room and corridor piece the doorway detector cuts),
// complete the route on the measured number of seeds and draw walls no worse than measured.
#include <gtest/gtest.h>

#include "run_seed.h"
#include "source_dir.h"

#include <cstdint>
#include <nlohmann/json.hpp>
#include <ostream>
#include <string>

#include "cogmap/experiments/experiment_config.h"
#include "cogmap/experiments/runner.h"

namespace cogmap::experiments {
namespace {

using integration::source_dir;

struct BuildingCase {
  std::string name;  ///< generated/NAME.route.yaml
  int asrs;          ///< measured over seeds 1-5: the same on every seed
  /// Routes completed over seeds 1-5, measured (release build, 2026-12-03, with "Looking past
  /// a close waypoint", docs/algorithms.md): 5, 5 and 5 (5, 5 and 4 before it, the corridor's
  /// seed 5 giving one waypoint up; 5, 4 and 4 before the door search and EM's posterior).
  int completed;
  /// Bound on every seed's median wall error: 1.25x the worst seed measured (2026-12-04, with
  /// the end-of-run relaxation of the rooms' positions: 0.048, 0.290, 0.142 m; without it
  /// 0.049, 0.279, 0.144 m; the corridor 0.113 m without the door fixes, docs/algorithms.md
  /// "Position fixes at doorways passed again": its seeds move 0.087-0.111 -> 0.032-0.144 m,
  /// chaotically, on fixes of 1 cm, its offices entered and left within 5 m). block_3x3_s15 seed 5
  /// (0.062 m before the change of route) is EM turning good odometry wrong: room 2's short,
  /// smeared walls measure a 6.7° rotation with a 1.5° sd where odometry had drifted 0.1°, and the
  /// map by odometry alone is at 0.080 m (issue 10). Before the long reference seed 3's map was
  /// misregistered, 0.71 m.
  double max_median_wall_error_m;
  /// Bound on every seed's simulated time: 1.25x the longest seed measured (2026-12-06, the
  /// instances in order: 54.6 s of duration_s 360, 189.5 of 810, 144.1 of 360, 100.7 of 774,
  /// 263.2 of 720), so a route that circles for minutes before it completes fails, not only one
  /// that runs to the limit.
  double max_sim_time_s;
  /// The fewest ASRs a completed seed may map, where the doorway detector's cuts of a corridor
  /// vary from seed to seed (the offices are entered whatever it cuts); -1: exactly `asrs`.
  int fewest_asrs = -1;
};

void PrintTo(const BuildingCase& c, std::ostream* os) { *os << c.name; }

class GeneratedBuilding : public ::testing::TestWithParam<BuildingCase> {};

TEST_P(GeneratedBuilding, CompletesTheRouteByTheEstimateWithoutContact) {
  const BuildingCase& c = GetParam();
  Experiment e = load_experiment(source_dir() / "tests" / "integration" / "generated" /
                                 (c.name + ".route.yaml"));
  ASSERT_FALSE(e.controller.steer_by_truth);  // the robot's own estimate steers
  int completed = 0;
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const nlohmann::json m = integration::run_seed_metrics(e, seed, "generated_" + c.name);
    const nlohmann::json& nav = m["nav"];
    const bool done = nav["route_completed"].get<bool>();
    completed += done ? 1 : 0;
    // A route that is not completed gives at most one waypoint up, and never runs to the limit.
    EXPECT_LE(nav["waypoints_skipped"].get<int>(), done ? 0 : 1);
    EXPECT_EQ(nav["contacts"].get<int>(), 0);
    // A route given up at a waypoint may miss that room.
    const int fewest = c.fewest_asrs < 0 ? c.asrs : c.fewest_asrs;
    EXPECT_GE(m["asr_count"].get<int>(), done ? fewest : fewest - 1);
    EXPECT_LE(m["asr_count"].get<int>(), c.asrs);
    EXPECT_LT(m["timing"]["sim_time_s"].get<double>(), c.max_sim_time_s);
    EXPECT_LE(m["map"]["wall_error_median_m"].get<double>(), c.max_median_wall_error_m);
  }
  EXPECT_GE(completed, c.completed);
  EXPECT_LT(c.max_sim_time_s, e.duration_s);
}

INSTANTIATE_TEST_SUITE_P(
    Kinds, GeneratedBuilding,
    ::testing::Values(
        BuildingCase{"block_2x2_s11", 4, 5, 0.060, 68.0},   // rotated 15°
        BuildingCase{"block_3x3_s15", 9, 5, 0.363, 237.0},  // rotated 7°, 2 extra doors
        // 3 m corridor, 3 offices
        BuildingCase{"corridor_3_w3_s16", 7, 5, 0.178, 180.0},
        // Rooms of 6.2-8.3 m (`--room-sizes-m 4.9-8.4`), rotated 171°, an extra door: the route
        // passes the walls 3-4 m off. Measured 2026-12-05 (release build, seeds 1-5): completed
        // 5, 4 ASRs each, median wall error 0.111, 0.064, 0.066, 0.060, 0.099 m.
        BuildingCase{"block_2x2_s919240", 4, 5, 0.139, 126.0},
        // Rotated 45°, two clutter items a room. Seed 1 finds its third door only at the second
        // try, 40-60 s after the door-centre waypoint was counted reached: completed 4 of 5 with
        // `give_up_s` 40 s, 5 with 60 s (docs/algorithms.md, "A minute per waypoint"). Measured
        // 2026-12-05 (release build, seeds 1-5): 8 ASRs each, median wall error 0.134, 0.155,
        // 0.055, 0.171, 0.112 m.
        BuildingCase{"block_4x2_s13", 8, 5, 0.214, 329.0},
        // An L of two 2.6 m corridors, 3 offices south of the first leg and 2 east of the
        // second, rotated 200° (`gen-building lcorridor`, 2026-12-07). Measured (RelWithDebInfo,
        // seeds 1-5): completed 5, ASRs 11, 11, 11, 11, 10 (seed 5's doorway detector leaves one
        // corridor piece uncut), 310.4, 221.2, 273.8, 270.1, 283.1 s, median wall error 0.514,
        // 0.054, 0.108, 0.075, 0.409 m: seeds 1 and 5 draw the map turned 5.1° and 4.5° as a
        // whole (0.057 and 0.046 m once turned back), the rotation of docs/results.md "Kinds the
        // random sets never draw" and issue 10.
        BuildingCase{"lcorridor_5_w2_6_s72", 11, 5, 0.643, 388.0, 10}),
    [](const auto& info) { return info.param.name; });

}  // namespace
}  // namespace cogmap::experiments
