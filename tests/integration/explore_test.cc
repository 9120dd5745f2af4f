// Issue 9's exploration, end to end: an explore experiment per world kind, driven by the
// robot's own estimate with the default (frontier) explorer, seeds 1-5: rooms entered
// (counted from the truth), stopping by itself (exploration_complete), contacts and time held
// to what was measured, so a regression shows.
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

namespace fs = std::filesystem;

using integration::source_dir;

struct ExploreCase {
  std::string name;  ///< for the test's name
  fs::path file;     ///< under the source tree
  int rooms;         ///< rooms_total_true of the world
  /// Over seeds 1-5, as measured (release build; RelWithDebInfo gives the same runs; the
  /// dates are in the cases below): seeds on which every room was entered, rooms entered
  /// summed, seeds that stopped by themselves, contact episodes.
  int all_rooms_seeds;
  int rooms_visited_sum;
  int completed_seeds;
  int max_contacts;
  double max_sim_time_s;  ///< 1.25x the longest seed measured
  /// The five seeds' simulated seconds over the rooms they entered: 1.25x the measured
  /// (issue 9's pace, 90 s a room; it fails when the explorer slows or enters fewer rooms
  /// even where every seed runs to its duration_s).
  double max_s_per_room;
};

void PrintTo(const ExploreCase& c, std::ostream* os) { *os << c.name; }

class Explore : public ::testing::TestWithParam<ExploreCase> {};

TEST_P(Explore, VisitsTheRoomsAndStopsByItself) {
  const ExploreCase& c = GetParam();
  Experiment e = load_experiment(source_dir() / c.file);
  ASSERT_EQ(e.controller.type, ControllerKind::kExplore);
  ASSERT_FALSE(e.controller.steer_by_truth);  // the robot's own estimate steers
  int all_rooms = 0, visited = 0, completed = 0, contacts = 0;
  double sim_time_s = 0.0;
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const nlohmann::json m = integration::run_seed_metrics(e, seed, "explore_" + c.name);
    const nlohmann::json& nav = m["nav"];
    EXPECT_EQ(nav["rooms_total_true"].get<int>(), c.rooms);
    const int v = nav["rooms_visited_true"].get<int>();
    all_rooms += v == c.rooms ? 1 : 0;
    visited += v;
    completed += nav["exploration_complete"].get<bool>() ? 1 : 0;
    contacts += nav["contacts"].get<int>();
    EXPECT_LE(m["timing"]["sim_time_s"].get<double>(), c.max_sim_time_s);
    sim_time_s += m["timing"]["sim_time_s"].get<double>();
  }
  EXPECT_GE(all_rooms, c.all_rooms_seeds);
  EXPECT_GE(visited, c.rooms_visited_sum);
  EXPECT_GE(completed, c.completed_seeds);
  EXPECT_LE(contacts, c.max_contacts);
  ASSERT_GT(visited, 0);
  EXPECT_LE(sim_time_s / visited, c.max_s_per_room);
}

INSTANTIATE_TEST_SUITE_P(
    Worlds, Explore,
    ::testing::Values(
        // Shipped (2026-12-04, with the room grid's last look before stopping): 263-442 s,
        // every seed complete and in both rooms, no contact (248-432 s without the last look).
        // 2026-12-06: 441.9, 381.5, 294.4, 277.4, 263.2 s, 165.8 s a room entered.
        // 2026-12-07, a path run into a wall planned again after 10 s (ExploreOptions::
        // blocked_path_s): 390.4, 353.4, 261.6, 277.4, 263.2 s, 154.6 s a room entered.
        ExploreCase{"explore_two_rooms", "experiments/explore_two_rooms.yaml", 2, 5, 10, 5, 0,
                    488.0, 193.3},
        // Generated 3 x 3 block (7°, two extra doors), 90 s per room (2026-12-04, with the
        // room grid's last look; the same without it but seeds 1 and 4 4 s and 2 s sooner):
        // rooms 9, 8, 9, 6, 9, no contact; seeds 1, 3 and 4 stopped by themselves (798, 779
        // and 519 s), seeds 2 and 5 ran out of their 810 s. The explorer is chaotic
        // (docs/algorithms.md, "How to measure a change"): a change moves these both ways.
        // Its per-seed time bound is the duration_s itself and cannot fail: seeds 2 and 5 run
        // to it (2026-12-06: 798.2, 810.0, 778.8, 518.9, 810.0 s), so 1.25x the longest is no
        // tighter; the pace carries the time check: 3 715.9 s over 41 rooms entered, 90.6 s a
        // room. 2026-12-07, blocked_path_s 10 s: rooms 9, 8, 9, 9, 6, no contact, seeds 1, 3
        // and 5 stopped by themselves (755.2, 782.4, 505.9 s), 3 663.5 s over 41 rooms, 89.4 s a
        // room. 2026-12-07, the explorer's arc guard (SafetyOptions::arc_guard_s 0.5 s): rooms
        // 9, 8, 9, 9, 6, no contact, seeds 1 and 5 stopped by themselves (733.1, 505.9 s), the
        // others ran to 810 s; 3 669.0 s over 41 rooms, 89.5 s a room.
        ExploreCase{"block_3x3_s15", "tests/integration/generated/block_3x3_s15.explore.yaml", 9, 3,
                    41, 2, 0, 810.0, 111.9}),
    [](const auto& info) { return info.param.name; });

}  // namespace
}  // namespace cogmap::experiments
