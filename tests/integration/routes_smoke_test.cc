// Issue #3's smoke test: in every thesis world the robot completes its experiment's route
// within the experiment's time limit, through the real simulator, navigation, mapper and runner
// (figures off), and leaves one ASR per room it was meant to map.
#include <gtest/gtest.h>

#include "source_dir.h"

#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <ostream>
#include <sstream>
#include <string>

#include "cogmap/experiments/experiment_config.h"
#include "cogmap/experiments/runner.h"
#include "cogmap/test_support/scratch_dir.h"

namespace cogmap::experiments {
namespace {

namespace fs = std::filesystem;

using integration::source_dir;

struct RouteCase {
  std::string experiment;
  int min_asrs;  ///< rooms the route visits (doorway ASRs) or its length / 4 m (distance ASRs)
  /// At most this many: an extra doorway ASR is a spurious boundary. A single room (small
  /// clutter) must give exactly one, which finish() alone would store: only the upper bound
  /// can fail there. Values: docs/results.md (9 ± 0, 3, 76.8 ± 0.4 over five seeds); the
  /// hallway loop measured 76 on each of seeds 1-5 on 2026-12-06.
  int max_asrs;
  /// 1.25x the simulated time the route took (2026-12-06, the experiment's own seed), well
  /// inside every duration_s: a route that completes only near its time limit fails.
  double max_sim_time_s;
};

/// Names the case in test output (gtest would print the struct's bytes).
void PrintTo(const RouteCase& c, std::ostream* os) { *os << c.experiment; }

class RouteSmoke : public ::testing::TestWithParam<RouteCase> {};

TEST_P(RouteSmoke, CompletesTheRouteWithinTheTimeLimit) {
  const RouteCase& c = GetParam();
  const Experiment e = load_experiment(source_dir() / "experiments" / (c.experiment + ".yaml"));
  RunOptions o;
  o.out_dir = test_support::process_scratch() / ("route_smoke_" + c.experiment);
  o.figures = false;
  fs::remove_all(o.out_dir);
  (void)run_experiment(e, o);
  std::ifstream in(o.out_dir / "metrics.json");
  std::stringstream text;
  text << in.rdbuf();
  const nlohmann::json m = nlohmann::json::parse(text.str());
  EXPECT_TRUE(m["route_completed"].get<bool>()) << c.experiment;
  EXPECT_LT(m["timing"]["sim_time_s"].get<double>(), c.max_sim_time_s) << c.experiment;
  EXPECT_LT(c.max_sim_time_s, e.duration_s) << c.experiment;
  EXPECT_GE(m["asr_count"].get<int>(), c.min_asrs) << c.experiment;
  EXPECT_LE(m["asr_count"].get<int>(), c.max_asrs) << c.experiment;
}

INSTANTIATE_TEST_SUITE_P(ThesisWorlds, RouteSmoke,
                         // Measured 2026-12-06: 54.4 s of 300, 170.3 of 900, 46.4 of 400,
                         // 622.0 of 900, 50.8 of 200.
                         ::testing::Values(RouteCase{"two_rooms", 2, 2, 68.0},
                                           RouteCase{"nine_rooms", 9, 9, 213.0},
                                           RouteCase{"three_room_slam", 3, 3, 58.0},
                                           RouteCase{"hallway_loop", 76, 76, 778.0},
                                           RouteCase{"small_clutter", 1, 1, 64.0}),
                         [](const auto& info) { return info.param.experiment; });

}  // namespace
}  // namespace cogmap::experiments
