// Issue 9, "truth stays out of the robot's head": the runner hands the mapper and the
// controller frames without the true pose, so scrambling the true pose a simulated robot
// reports changes the truth-based metrics and nothing else, bit for bit.
#include <gtest/gtest.h>

#include "source_dir.h"

#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "cogmap/experiments/experiment_config.h"
#include "cogmap/experiments/runner.h"
#include "cogmap/sim/sim_robot.h"
#include "cogmap/sim/world_geometry.h"
#include "cogmap/sim/world_spec.h"
#include "cogmap/test_support/scratch_dir.h"

namespace cogmap::experiments {
namespace {

namespace fs = std::filesystem;

using integration::source_dir;

using integration::read_file;

/// A simulated robot whose frames carry a wrong true pose (shifted 37 m, turned 1 rad).
class ScrambledTruth final : public mapper::Robot {
 public:
  explicit ScrambledTruth(mapper::Robot& inner) : inner_(inner) {}
  const mapper::RobotGeometry& geometry() const override { return inner_.geometry(); }
  std::optional<mapper::SensorFrame> next_frame() override {
    auto f = inner_.next_frame();
    if (f && f->true_pose) {
      f->true_pose = mapper::Pose2{f->true_pose->x_m + 37.0, f->true_pose->y_m - 11.0,
                                   mapper::wrap_angle_rad(f->true_pose->theta_rad + 1.0)};
    }
    return f;
  }
  void command(const mapper::VelocityCommand& cmd) override { inner_.command(cmd); }
  void stop() override { inner_.stop(); }

 private:
  mapper::Robot& inner_;
};

/// Runs `experiment` (two_rooms) for 60 s steering by `pose`; `scramble` wraps the robot.
fs::path run(bool scramble, const std::string& pose = "estimate",
             const std::string& experiment = "two_rooms", const std::string& extra = "") {
  std::vector<std::string> overrides{"controller.pose=" + pose, "duration_s=60",
                                     "output.figures=false"};
  if (!extra.empty()) overrides.push_back(extra);
  const Experiment e =
      load_experiment(source_dir() / "experiments" / (experiment + ".yaml"), overrides);
  sim::WorldSpec world = sim::load_world(e.world);
  sim::SimRobot sim(world, sim::parse_sim_robot_options(*e.robot), e.seed);
  ScrambledTruth scrambled(sim);
  const GroundTruth truth{sim::true_surfaces(world), world.start};
  RunOptions o;
  o.out_dir = test_support::process_scratch() /
              ((scramble ? "truth_scrambled_" : "truth_plain_") + experiment + "_" + pose);
  o.figures = false;
  fs::remove_all(o.out_dir);
  if (scramble) {
    (void)run_robot_session(scrambled, e, &truth, o);
  } else {
    (void)run_robot_session(sim, e, &truth, o);
  }
  return o.out_dir;
}

/// trajectory.csv without its three true-pose columns.
std::string robot_columns(const std::string& csv) {
  std::stringstream in(csv), out;
  std::string line;
  while (std::getline(in, line)) {
    std::stringstream fields(line);
    std::string f;
    for (int i = 0; std::getline(fields, f, ','); ++i) {
      if (i < 1 || i > 3) out << f << ',';
    }
    out << '\n';
  }
  return out.str();
}

TEST(TruthBlind, ScramblingTheTruePoseChangesOnlyTruthMetrics) {
  const fs::path a = run(false), b = run(true);
  for (const char* f : {"map_segments.csv", "map_segments_odom.csv", "asr_graph.json"}) {
    EXPECT_EQ(read_file(a / f), read_file(b / f)) << f;
  }
  for (const auto& e : fs::directory_iterator(a / "asrs")) {
    EXPECT_EQ(read_file(e.path()), read_file(b / "asrs" / e.path().filename())) << e.path();
  }
  EXPECT_EQ(robot_columns(read_file(a / "trajectory.csv")),
            robot_columns(read_file(b / "trajectory.csv")));
  EXPECT_NE(read_file(a / "trajectory.csv"),
            read_file(b / "trajectory.csv"));  // the truth did differ
  auto ma = nlohmann::json::parse(read_file(a / "metrics.json"));
  auto mb = nlohmann::json::parse(read_file(b / "metrics.json"));
  for (auto* m : {&ma, &mb}) {
    for (const char* k : {"map", "map_odometry", "localization", "error_breakdown", "timing"}) {
      m->erase(k);
    }
    (*m)["nav"].erase("contacts");
    (*m)["nav"].erase("contact_s");
    (*m)["nav"].erase("contact_start_s");
    (*m)["nav"].erase("contact_onsets");  // the modes are the robot's, the places the truth's
    (*m)["nav"].erase("heading_drift_deg_by_mode");  // odometry against the truth
  }
  EXPECT_EQ(ma.dump(), mb.dump());
  // It did drive: the whole route, 18.85 m (2026-12-06; bound 0.8x), not the first metres.
  EXPECT_GT(ma["nav"]["distance_m"].get<double>(), 15.0);
}

TEST(TruthBlind, TheExplorersOwnMapIgnoresTheTruth) {
  const std::string map = "output.explore_map=true";
  const fs::path a = run(false, "estimate", "explore_two_rooms", map);
  const fs::path b = run(true, "estimate", "explore_two_rooms", map);
  const std::string pgm = read_file(a / "explore_map.pgm");
  EXPECT_EQ(pgm.rfind("P5\n", 0), 0u);
  // A map of the first room at least: 10419 bytes in the 60 s (2026-12-06; bound 0.8x).
  EXPECT_GT(pgm.size(), 8300u);
  EXPECT_EQ(pgm, read_file(b / "explore_map.pgm"));
  EXPECT_EQ(read_file(a / "explore_map.yaml"), read_file(b / "explore_map.yaml"));
  // A route follower has no explore map: nothing is written for it.
  EXPECT_FALSE(fs::exists(run(false, "estimate", "two_rooms", map) / "explore_map.pgm"));
}

TEST(TruthBlind, TheTestSeesALeak) {
  // The diagnostic truth controller does read the true pose: there the same scrambling must
  // change the robot's path and so its map (else the test above could not see a leak).
  const fs::path a = run(false, "truth"), b = run(true, "truth");
  EXPECT_NE(read_file(a / "map_segments_odom.csv"), read_file(b / "map_segments_odom.csv"));
}

}  // namespace
}  // namespace cogmap::experiments
