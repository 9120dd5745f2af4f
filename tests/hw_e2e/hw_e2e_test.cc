// The two-room experiment three ways: simulated directly, simulated behind P2OS on a pty and
// driven by P2osRobot (recorded), and the recording replayed. Over the wire the map must be
// about as good as direct; the replay must rebuild exactly the live run's rooms.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <thread>

#include "cogmap/experiments/experiment_config.h"
#include "cogmap/experiments/runner.h"
#include "cogmap/hw/fd_stream.h"
#include "cogmap/hw/log_robot.h"
#include "cogmap/hw/p2os_robot.h"
#include "cogmap/hw/p2os_server.h"
#include "cogmap/sim/sim_robot.h"
#include "cogmap/sim/world_geometry.h"
#include "cogmap/sim/world_spec.h"
#include "cogmap/test_support/scratch_dir.h"

namespace cogmap {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

fs::path source_dir() {
  const char* env = std::getenv("COGMAP_SOURCE_DIR");
  return env ? fs::path(env) : fs::path(COGMAP_SOURCE_DIR_FALLBACK);
}

fs::path out_dir(const std::string& name) {
  const fs::path d = test_support::process_scratch() / name;
  fs::create_directories(d);
  return d;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Bounded simulated time: the route's first room and the doorway.
constexpr double kDurationS = 75.0;

experiments::Experiment two_rooms() {
  return experiments::load_experiment(
      source_dir() / "experiments" / "two_rooms.yaml",
      {"duration_s=" + std::to_string(kDurationS), "output.figures=false",
       // Over the wire there is no true pose to steer by: both runs steer by the estimate.
       "controller.pose=estimate"});
}

TEST(HwEndToEnd, ServedOverP2osMapsLikeDirectAndReplaysIdentically) {
  const experiments::Experiment experiment = two_rooms();
  sim::WorldSpec world = sim::load_world(experiment.world);
  if (experiment.start) world.start = *experiment.start;
  const experiments::GroundTruth truth{sim::true_surfaces(world), world.start};

  // 1. Direct simulation.
  experiments::RunOptions direct_options;
  direct_options.out_dir = out_dir("direct");
  const auto direct = experiments::run_experiment(experiment, direct_options);
  ASSERT_TRUE(direct.metrics.map.has_value());
  ASSERT_TRUE(direct.metrics.map->wall_error_median_m.has_value());

  // 2. The same simulator behind P2OS on a pty, 2x faster than real time, recorded.
  const fs::path log_path = out_dir("live") / "live.cogmap.log";
  experiments::RunSummary live;
  hw::P2osStats stats;
  {
    sim::SimRobot body(
        world,
        sim::parse_sim_robot_options(experiment.robot ? *experiment.robot
                                                      : yaml::Node::load_string("{}", "inline")),
        experiment.seed);
    auto pty = hw::open_pty();
    hw::P2osServerOptions server_options;
    server_options.cycle = 50ms;
    hw::P2osServer server(*pty->master, body, server_options);
    std::atomic<bool> stop{false};
    std::thread serving([&] { server.run(stop); });

    hw::P2osRobotOptions robot_options;
    robot_options.clock = hw::FrameClock::kSipCount;  // simulated seconds, not wall seconds
    {
      hw::P2osRobot robot(hw::open_serial_port(pty->slave_path, 38400), robot_options);
      hw::RecordingRobot recorder(robot, log_path);
      experiments::RunOptions live_options;
      live_options.out_dir = out_dir("live_run");
      live = experiments::run_robot_session(recorder, experiment, &truth, live_options);
      stats = robot.stats();
      robot.shutdown();
    }
    stop = true;
    serving.join();
  }
  EXPECT_EQ(stats.connections, 1);
  EXPECT_EQ(stats.dropped_bytes, 0u);
  ASSERT_TRUE(live.metrics.map.has_value());
  ASSERT_TRUE(live.metrics.map->wall_error_median_m.has_value());
  // finish() always stores one ASR, so "at least one" could not fail. Over the wire the SIPs
  // carry the readings in other groupings, so a doorway crossed near the 75 s cut may close a
  // room on one side only: at most one room apart from the direct run (the replay below must
  // then match the live run exactly, room for room).
  EXPECT_LE(std::max(live.metrics.asr_count, direct.metrics.asr_count) -
                std::min(live.metrics.asr_count, direct.metrics.asr_count),
            1u);
  std::cout << "wall error median: direct " << *direct.metrics.map->wall_error_median_m
            << " m, over P2OS " << *live.metrics.map->wall_error_median_m << " m; rooms "
            << direct.metrics.asr_count << " / " << live.metrics.asr_count << "\n";
  // The served robot runs against the wall clock: a command that reaches it a cycle late
  // changes the drive, so the live map is not the direct one. Measured (2026-12-01, two_rooms
  // seed 7): direct 0.0565 m; over P2OS 0.0589 m on a quiet machine, 0.0865 m once during a
  // parallel test run (1.53x). Twice the direct run's error still catches a broken link
  // (wrong ranges, lost frames) while allowing that.
  EXPECT_LE(*live.metrics.map->wall_error_median_m, 2.0 * *direct.metrics.map->wall_error_median_m)
      << "direct " << *direct.metrics.map->wall_error_median_m;

  // 3. The recording replayed: the same frames, so the same rooms, byte for byte.
  hw::LogRobot replay(log_path);
  experiments::Experiment replay_experiment = experiment;
  replay_experiment.controller.type = experiments::ControllerKind::kNone;
  replay_experiment.controller.steer_by_truth = false;
  replay_experiment.duration_s = replay.last_time_s() + 1.0;
  experiments::RunOptions replay_options;
  replay_options.out_dir = out_dir("replay_run");
  const auto replayed =
      experiments::run_robot_session(replay, replay_experiment, &truth, replay_options);
  EXPECT_EQ(replayed.metrics.asr_count, live.metrics.asr_count);
  EXPECT_EQ(slurp(replay_options.out_dir / "map_segments.csv"),
            slurp(live.out_dir / "map_segments.csv"));
  std::size_t rooms = 0;
  for (const auto& entry : fs::directory_iterator(live.out_dir / "asrs")) {
    const fs::path twin = replay_options.out_dir / "asrs" / entry.path().filename();
    ASSERT_TRUE(fs::exists(twin)) << twin;
    EXPECT_EQ(slurp(entry.path()), slurp(twin)) << entry.path().filename();
    ++rooms;
  }
  EXPECT_EQ(rooms, live.metrics.asr_count);  // every ASR the metrics count is on disk, twinned
}

}  // namespace
}  // namespace cogmap
