// experiments/two_rooms.yaml end to end (figures off): the run directory is complete, the
// metrics lie within honest bounds, and the same seed gives bit-identical results.
#include <gtest/gtest.h>

#include "source_dir.h"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <utility>

#include "cogmap/experiments/experiment_config.h"
#include "cogmap/experiments/runner.h"
#include "cogmap/test_support/scratch_dir.h"

namespace cogmap::experiments {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

using integration::source_dir;

using integration::read_file;

Json run_once(const std::string& name, int sonar_threads = 1) {
  const Experiment e = load_experiment(source_dir() / "experiments" / "two_rooms.yaml");
  RunOptions o;
  o.sonar_threads = sonar_threads;
  o.out_dir = test_support::process_scratch() / ("two_rooms_" + name);
  o.figures = false;
  fs::remove_all(o.out_dir);
  (void)run_experiment(e, o);
  return Json::parse(read_file(o.out_dir / "metrics.json"));
}

TEST(TwoRoomsEndToEnd, WritesEveryOutputWithinBoundsAndDeterministically) {
  const Json a = run_once("a");
  const fs::path dir = test_support::process_scratch() / "two_rooms_a";
  for (const char* f : {"metrics.json", "trajectory.csv", "asr_graph.json", "map.svg",
                        "map_segments.csv", "map_segments_odom.csv", "experiment.yaml",
                        "grid_000.pgm", "grid_000.yaml", "asrs/000.json"}) {
    EXPECT_TRUE(fs::exists(dir / f)) << f;
  }
  EXPECT_FALSE(fs::exists(dir / "figures")) << "figures were switched off";

  // Bounds (docs/results.md has the measured values). The route tours the west room, crosses
  // the 1 m doorway, tours the east room, and ends there: two ASRs.
  EXPECT_EQ(a["asr_count"].get<int>(), 2);
  EXPECT_TRUE(a["route_completed"].get<bool>());
  const Json& map = a["map"];
  // Seed 7 is deterministic. Steering by the estimate (the shipped setting since issue 9) it
  // measures wall error 0.079 m, coverage 0.531, spurious 0.090 (2026-12-08, wall lines carried
  // 20 m by the relaxation: a phantom of the west room 1.34 m along the dividing wall's line
  // pulls the east room 6 cm west; docs/algorithms.md "Relaxing the rooms' positions". 0.063 m,
  // 0.583, 0.068 on 2026-12-06; 0.064 m, 0.604, 0.059 when first measured; truth-steered with
  // the same sonar: 0.091 m, 0.397, 0.039). The bounds sit just outside those, so a worse map
  // fails.
  EXPECT_LT(map["wall_error_median_m"].get<double>(), 0.085);
  EXPECT_GT(map["wall_coverage"].get<double>(), 0.50);
  EXPECT_LT(map["spurious_fraction"].get<double>(), 0.10);
  // Measured 2026-12-06 (seed 7), each bound 1.25x the value (0.8x for "at least"): grid
  // 86400 bytes, compression ratio 0.00417 (polylines << grids, Table 4.2), ATE 0.160 m,
  // 544 frames (the route ends at 54.4 s, long before duration_s, 300 s).
  EXPECT_GT(map["grid_bytes"].get<double>(), 69000.0);
  EXPECT_LT(map["compression_ratio"].get<double>(), 0.0052);
  EXPECT_LT(a["localization"]["ate_rmse_m"]["corrected"].get<double>(), 0.20);
  EXPECT_LT(a["frames"].get<int>(), 680);
  // The per-stage breakdown: every stage measured, the fitted lines as many samples as the map.
  // Samples measured 2026-12-06: grid 411, cleaned 303, points 303, lines 652 (bounds 0.8x).
  const Json& bd = a["error_breakdown"];
  const std::pair<const char*, int> min_counts[] = {
      {"grid", 329}, {"cleaned", 242}, {"points", 242}, {"lines", 522}};
  for (const auto& [stage, min_count] : min_counts) {
    EXPECT_GE(bd[stage]["count"].get<int>(), min_count) << stage;
  }
  EXPECT_EQ(bd["lines"]["count"].get<int>(), map["error_samples"].get<int>());
  EXPECT_EQ(bd["heading"]["rooms"].get<int>(), 2);
  // The same samples laid onto the truth by one rigid transform of the map, then room by room:
  // 0.079 -> 0.055 -> 0.040 m here (0.063 -> 0.051 -> 0.040 m before the 20 m wall lines).
  for (const char* stage : {"aligned_map", "aligned_rooms"}) {
    EXPECT_EQ(bd[stage]["count"].get<int>(), map["error_samples"].get<int>()) << stage;
  }
  EXPECT_LT(bd["aligned_map"]["median_m"].get<double>(), 0.060);
  EXPECT_LT(bd["aligned_rooms"]["median_m"].get<double>(), 0.045);
  EXPECT_LT(std::abs(bd["aligned_map"]["rotation_deg"].get<double>()), 0.5);
  EXPECT_EQ(bd["aligned_map"]["start_shift_m"].size(), 2u);
  EXPECT_EQ(bd["aligned_rooms"]["rooms_fitted"].get<int>(), 2);
  // What EM measured: nothing for the first room; for the second, a measurement with its sd
  // and the odometry prior, and the rotation applied is the prior's share of it (Kalman gain).
  const Json& rooms = a["rooms"];
  ASSERT_EQ(rooms.size(), 2u);
  EXPECT_TRUE(rooms[0]["localization"].is_null());
  const Json& em = rooms[1]["localization"];
  ASSERT_TRUE(em.is_object());
  EXPECT_GT(em["measurement_sd_deg"].get<double>(), 0.0);
  EXPECT_GT(em["prior_sd_deg"].get<double>(), 0.0);
  // Applied here (2026-12-06: 3.46° measured, gain 0.721, 2.50° applied); had the check
  // accepted "not applied, 0°" as well, a lost correction would pass.
  EXPECT_TRUE(em["applied"].get<bool>());
  const double applied_deg = em["gain"].get<double>() * em["measured_rotation_deg"].get<double>();
  EXPECT_NEAR(rooms[1]["heading_correction_deg"].get<double>(), applied_deg, 1e-9);

  // Same experiment, same seed, the sonar traced on two threads (what `cogmap run` does on two
  // cores): every block except timing is identical bit for bit, and so are the trajectory and
  // the map.
  const Json b = run_once("b", 2);
  for (const char* key : {"asr_count", "map", "map_odometry", "localization", "error_breakdown",
                          "rooms", "readings", "frames"}) {
    EXPECT_EQ(a[key].dump(), b[key].dump()) << key;
  }
  const fs::path dir_b = test_support::process_scratch() / "two_rooms_b";
  EXPECT_EQ(read_file(dir / "trajectory.csv"), read_file(dir_b / "trajectory.csv"));
  EXPECT_EQ(read_file(dir / "map_segments.csv"), read_file(dir_b / "map_segments.csv"));
}

}  // namespace
}  // namespace cogmap::experiments
