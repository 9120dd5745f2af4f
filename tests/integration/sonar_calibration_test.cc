// The simulator's sonar against a real Pioneer (docs/sonar-model.md "Calibration"): the P2-AT
// drives the centre line of the 2.2 m corridor of worlds/corridor_calibration.yaml at 0.57 m/s,
// and every front transducer must answer as often as the real ones did (within 0.10 of the echo
// fraction per firing) at about the same range (median within 20 %), fired at the real rate.
#include <gtest/gtest.h>

#include "source_dir.h"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <numbers>

#include "cogmap/experiments/sonar_stats.h"
#include "cogmap/sim/sim_robot.h"
#include "cogmap/sim/world_spec.h"

namespace cogmap::experiments {
namespace {

namespace fs = std::filesystem;

using integration::source_dir;

// Facts, not tuning targets chosen here: a public RosAria recording of a Pioneer 3-DX (front
// ring of 8, the P2-AT's front mount angles) driving a ~2.2 m office corridor at a median
// 0.57 m/s, counted per firing over the 46.9 s it moved (issue "A simulator calibrated against
// a real Pioneer", table 1; ranges from the transducer; echoes are readings under 4.9 m).
struct RealRow {
  double bearing_deg;
  double echo_fraction;
  double p10_m, p50_m, p90_m;
};
constexpr RealRow kReal[] = {
    {90, 1.00, 0.86, 1.03, 1.45},  {50, 0.95, 1.10, 1.47, 2.21},  {30, 0.96, 1.43, 2.33, 4.17},
    {10, 0.61, 2.05, 3.14, 4.92},  {-10, 0.61, 1.76, 3.36, 4.97}, {-30, 0.89, 1.21, 1.84, 3.35},
    {-50, 0.94, 0.89, 1.25, 3.48}, {-90, 0.99, 0.68, 0.87, 1.18},
};
// Each transducer fired every 320 ms (8 discs x 40 ms): 0.3125 firings per 100 ms.
constexpr double kRealFiringsPer100ms = 0.3125;
constexpr double kSpeedMps = 0.57;
constexpr double kMovingS = 46.9;

// Drives one seed's run into `stats`. The harness keeps the body on the centre line with the
// true pose, as the calibration protocol prescribes: what is calibrated here is the sensor, not
// the robot's autonomy (which never sees the true pose).
void simulate(std::uint64_t seed, SonarStatsCollector& stats) {
  const sim::WorldSpec world = sim::load_world(source_dir() / "worlds/corridor_calibration.yaml");
  sim::SimRobot robot(world, sim::SimRobotOptions{}, seed);
  // Accelerate (0.3 m/s² takes ~2 s), then the recording's moving time.
  while (robot.sim_time_s() < kMovingS + 3.0) {
    const mapper::Pose2& p = robot.true_pose();
    robot.command({kSpeedMps, -1.5 * p.y_m - 2.0 * p.theta_rad});
    stats.add(*robot.next_frame());
  }
  EXPECT_LT(std::abs(robot.true_pose().y_m), 0.05) << "seed " << seed;
}

TEST(SonarCalibration, CorridorRunMatchesTheRealPioneerRecording) {
  // Three seeds pooled: 3 x ~155 firings a transducer, so the echo fraction's sampling error
  // (sd ~0.02) stays well inside the 0.10 tolerance.
  SonarStatsCollector stats(mapper::p2at_geometry());
  for (const std::uint64_t seed : {1u, 2u, 3u}) simulate(seed, stats);
  const SonarStats s = stats.result();
  write_sonar_stats_text(std::cout, s);
  for (const RealRow& real : kReal) {
    // The front array's transducer at this bearing (indices 0-7).
    const TransducerStats* sim = nullptr;
    for (int i = 0; i < 8; ++i) {
      const TransducerStats& t = s.transducers[static_cast<std::size_t>(i)];
      if (std::abs(t.bearing_deg - real.bearing_deg) < 0.5) sim = &t;
    }
    ASSERT_NE(sim, nullptr) << real.bearing_deg;
    EXPECT_NEAR(sim->echo_fraction, real.echo_fraction, 0.10)
        << "transducer at " << real.bearing_deg << " deg";
    EXPECT_NEAR(sim->p50_m / real.p50_m, 1.0, 0.20)
        << "transducer at " << real.bearing_deg << " deg: sim p50 " << sim->p50_m << " m, real "
        << real.p50_m << " m";
  }
  for (const TransducerStats& t : s.transducers) {
    // The schedule is exact: two arrays, one disc each per 40 ms, eight discs per array.
    EXPECT_NEAR(t.firings_per_100ms, kRealFiringsPer100ms, 0.005) << t.index;
  }
}

}  // namespace
}  // namespace cogmap::experiments
