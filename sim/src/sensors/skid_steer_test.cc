#include "cogmap/sim/skid_steer.h"

#include <gtest/gtest.h>

#include "yaml/config_error_test_support.h"

#include <cmath>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

namespace cogmap::sim {
namespace {

using mapper::Pose2;
using mapper::VelocityCommand;

constexpr double kDt = 0.02;

// One simulated step as the simulator does it: firmware, floor, truth, encoders.
struct Rig {
  SkidSteerDrive drive;
  Pose2 truth;
  double true_turn_rad = 0.0;  // unwrapped
  double true_distance_m = 0.0;

  void step(const VelocityCommand& cmd) {
    const WheelSpeeds w = drive.wheel_speeds(cmd);
    const BodyTwist b = drive.body_twist(w, kDt);
    truth = advance_pose(truth, b.v_mps * kDt, b.w_radps * kDt);
    true_turn_rad += b.w_radps * kDt;
    true_distance_m += std::abs(b.v_mps) * kDt;
    drive.integrate_encoders(w, kDt);
  }
  // Odometry heading without wrapping, from the encoder counts.
  double odom_turn_rad() const {
    return (drive.right_counted_m() - drive.left_counted_m()) / drive.calibrated_track_m();
  }
};

struct Stats {
  double mean = 0.0, sd = 0.0;
};
Stats stats_of(const std::vector<double>& x) {
  double s = 0.0, s2 = 0.0;
  for (double v : x) s += v;
  const double n = static_cast<double>(x.size());
  const double mean = s / n;
  for (double v : x) s2 += (v - mean) * (v - mean);
  return {mean, std::sqrt(s2 / (n - 1.0))};
}

TEST(SkidSteer, FirmwareUsesCalibratedTrack) {
  const SkidSteerDrive drive(OdometryOptions{}, 1);
  EXPECT_NEAR(drive.calibrated_track_m(), 0.394 * 1.5, 1e-15);
  const WheelSpeeds w = drive.wheel_speeds({0.5, 1.0});
  EXPECT_NEAR(w.left_mps, 0.5 - 0.591 / 2, 1e-12);
  EXPECT_NEAR(w.right_mps, 0.5 + 0.591 / 2, 1e-12);
}

TEST(SkidSteer, IdealSettingsGiveOdometryEqualToTruth) {
  Rig rig{SkidSteerDrive(ideal_odometry_options(), 5), {}};
  const std::vector<VelocityCommand> legs{{0.5, 0.0}, {0.4, 0.3}, {0.0, 1.2}, {-0.3, -0.5}};
  for (const VelocityCommand& cmd : legs) {
    for (int i = 0; i < 1500; ++i) rig.step(cmd);
  }
  const Pose2& odom = rig.drive.odometry();
  EXPECT_NEAR(odom.x_m, rig.truth.x_m, 1e-9);
  EXPECT_NEAR(odom.y_m, rig.truth.y_m, 1e-9);
  EXPECT_NEAR(mapper::wrap_angle_rad(odom.theta_rad - rig.truth.theta_rad), 0.0, 1e-9);
  EXPECT_GT(std::hypot(rig.truth.x_m, rig.truth.y_m), 1.0);  // it really went somewhere
}

TEST(SkidSteer, EffectiveTrackShrinksOnGentleArcs) {
  OdometryOptions o = ideal_odometry_options();
  o.effective_track_factor = 1.6;
  o.curvature_gain = 0.05;
  SkidSteerDrive drive(o, 1);
  const double spin_track = 0.394 * 1.6;
  EXPECT_NEAR(drive.effective_track_m({-0.2, 0.2}), spin_track, 1e-12);
  EXPECT_NEAR(drive.effective_track_m({0.0, 0.3}), spin_track, 1e-12);  // pivot on one side
  // l = 0.3, r = 0.5: spin fraction 0.2 / 0.8 = 0.25.
  const double arc_track = spin_track * (1.0 + 0.05 * (0.25 - 1.0));
  EXPECT_NEAR(drive.effective_track_m({0.3, 0.5}), arc_track, 1e-12);
  const BodyTwist b = drive.body_twist({0.3, 0.5}, kDt);
  EXPECT_NEAR(b.v_mps, 0.4, 1e-12);
  EXPECT_NEAR(b.w_radps, 0.2 / arc_track, 1e-12);
}

TEST(SkidSteer, StraightRunHeadingErrorIsARandomWalkInDistance) {
  OdometryOptions o;  // the P2-AT defaults
  constexpr int kSeeds = 400;
  std::vector<double> err;
  double distance = 0.0;
  for (int seed = 0; seed < kSeeds; ++seed) {
    Rig rig{SkidSteerDrive(o, static_cast<std::uint64_t>(seed)), {}};
    for (int i = 0; i < 1000; ++i) rig.step({0.5, 0.0});  // 20 s at 0.5 m/s: 10 m
    EXPECT_EQ(rig.drive.odometry().theta_rad, 0.0);       // equal wheels: odometry sees no turn
    err.push_back(rig.true_turn_rad - rig.odom_turn_rad());
    distance += rig.true_distance_m / kSeeds;
  }
  EXPECT_NEAR(distance, 10.0, 0.01);
  const Stats s = stats_of(err);
  const double expected_sd = o.heading_walk_sd_rad_per_sqrt_m * std::sqrt(distance);
  EXPECT_NEAR(s.mean, 0.0, 4.0 * expected_sd / std::sqrt(kSeeds));
  EXPECT_NEAR(s.sd / expected_sd, 1.0, 4.0 / std::sqrt(2.0 * (kSeeds - 1)));
}

TEST(SkidSteer, SpinInPlaceHeadingErrorFollowsTrackRatio) {
  OdometryOptions o;
  o.effective_track_factor = 1.55;  // floor slips more than the calibration assumed
  const double b_cal = o.track_m * o.calibrated_track_factor;
  const double b_eff = o.track_m * o.effective_track_factor;
  const double w_cmd = 1.0;
  // Spin long enough for 10 true turns at the mean effective track.
  const double duration_s = 10.0 * 2.0 * std::numbers::pi * b_eff / (b_cal * w_cmd);
  const int steps = static_cast<int>(std::lround(duration_s / kDt));
  const double t = steps * kDt;
  constexpr int kSeeds = 300;
  std::vector<double> residual, err;
  for (int seed = 0; seed < kSeeds; ++seed) {
    Rig rig{SkidSteerDrive(o, static_cast<std::uint64_t>(1000 + seed)), {}};
    for (int i = 0; i < steps; ++i) rig.step({0.0, w_cmd});
    // Odometry believes the command, to one encoder tick per side.
    EXPECT_NEAR(rig.odom_turn_rad(), w_cmd * t, 2.0 * o.encoder_tick_m / b_cal);
    const double e = rig.odom_turn_rad() - rig.true_turn_rad;
    err.push_back(e);
    residual.push_back(e - rig.true_turn_rad * (b_eff / b_cal - 1.0));
  }
  // Mean error: 10 turns x (B_eff / B_cal - 1) = 2.09 rad, accumulated, not white noise.
  const double tau = o.track_noise_correlation_s, sigma = o.track_noise_sd;
  // residual = w ∫ x/(1+x) dt for the OU track error x; its sd follows from the OU integral
  // variance 2 σ² τ (T - τ (1 - e^{-T/τ})), its mean from E[x/(1+x)] ≈ -σ².
  const double expected_sd =
      w_cmd * sigma * std::sqrt(2.0 * tau * (t - tau * (1.0 - std::exp(-t / tau))));
  const double expected_mean = -w_cmd * t * sigma * sigma;
  const Stats r = stats_of(residual);
  EXPECT_NEAR(r.mean, expected_mean, 4.0 * expected_sd / std::sqrt(kSeeds));
  EXPECT_NEAR(r.sd / expected_sd, 1.0, 4.0 / std::sqrt(2.0 * (kSeeds - 1)));
  const Stats e = stats_of(err);
  EXPECT_NEAR(e.mean, 10.0 * 2.0 * std::numbers::pi * (b_eff / b_cal - 1.0),
              5.0 * expected_sd / std::sqrt(kSeeds));
}

TEST(SkidSteer, StalledRobotEncodersStillCount) {
  SkidSteerDrive drive(OdometryOptions{}, 3);
  const Pose2 truth{};  // the world holds the body: a wall in front, wheels spinning
  const WheelSpeeds w = drive.wheel_speeds({0.4, 0.0});
  for (int i = 0; i < 100; ++i) drive.integrate_encoders(w, kDt);  // 2 s
  const double tick = OdometryOptions{}.encoder_tick_m;
  EXPECT_NEAR(drive.left_counted_m(), 0.8, tick);
  EXPECT_NEAR(drive.right_counted_m(), 0.8, tick);
  EXPECT_NEAR(drive.odometry().x_m, 0.8, tick);
  EXPECT_EQ(truth.x_m, 0.0);
  // Counts are whole ticks.
  EXPECT_NEAR(std::remainder(drive.left_counted_m(), tick), 0.0, 1e-12);
}

TEST(SkidSteer, SameSeedSameRun) {
  auto run = [](std::uint64_t seed) {
    Rig rig{SkidSteerDrive(OdometryOptions{}, seed), {}};
    for (int i = 0; i < 500; ++i) rig.step({0.3, 0.4});
    return rig.truth;
  };
  EXPECT_EQ(run(9).x_m, run(9).x_m);
  EXPECT_EQ(run(9).theta_rad, run(9).theta_rad);
  EXPECT_NE(run(9).theta_rad, run(10).theta_rad);
}

using yaml::testing::config_error_of;

TEST(OdometryOptions, ParsesPresetsAndKeys) {
  const auto root = yaml::Node::load_string(
      "odometry:\n  preset: ideal\n  effective_track_factor: 1.6\n  encoder_tick_m: 0.001\n",
      "exp.yaml");
  const OdometryOptions o = parse_odometry_options(root["odometry"]);
  EXPECT_EQ(o.effective_track_factor, 1.6);
  EXPECT_EQ(o.encoder_tick_m, 0.001);
  EXPECT_EQ(o.track_noise_sd, 0.0);  // from the ideal preset
  const auto all = yaml::Node::load_string(
      "{track_m: 0.4, calibrated_track_factor: 1.4, effective_track_factor: 1.45,"
      " curvature_gain: 0.1, track_noise_sd: 0.03, track_noise_correlation_s: 2,"
      " heading_walk_sd_rad_per_sqrt_m: 0.01, speed_scale_bias: 0.01, speed_scale_sd: 0.002,"
      " encoder_tick_m: 0}",
      "e.yaml");
  const OdometryOptions a = parse_odometry_options(all);
  EXPECT_EQ(a.track_m, 0.4);
  EXPECT_EQ(a.calibrated_track_factor, 1.4);
  EXPECT_EQ(a.effective_track_factor, 1.45);
  EXPECT_EQ(a.curvature_gain, 0.1);
  EXPECT_EQ(a.track_noise_sd, 0.03);
  EXPECT_EQ(a.track_noise_correlation_s, 2.0);
  EXPECT_EQ(a.heading_walk_sd_rad_per_sqrt_m, 0.01);
  EXPECT_EQ(a.speed_scale_bias, 0.01);
  EXPECT_EQ(a.speed_scale_sd, 0.002);
  EXPECT_EQ(a.encoder_tick_m, 0.0);
}

TEST(OdometryOptions, RejectsUnknownKeysWrongTypesAndBadValues) {
  const auto root = yaml::Node::load_string("robot:\n  odometry:\n    trak_m: 0.4\n", "exp.yaml");
  std::string msg = config_error_of([&] { parse_odometry_options(root["robot"]["odometry"]); });
  EXPECT_EQ(msg.rfind("exp.yaml:3: robot.odometry.trak_m: unknown key", 0), 0u) << msg;
  const auto typed = yaml::Node::load_string("odometry:\n  track_m: wide\n", "t.yaml");
  msg = config_error_of([&] { parse_odometry_options(typed["odometry"]); });
  EXPECT_EQ(msg.rfind("t.yaml:2: odometry.track_m: expected a finite number", 0), 0u) << msg;
  const auto preset = yaml::Node::load_string("odometry:\n  preset: perfect\n", "p.yaml");
  msg = config_error_of([&] { parse_odometry_options(preset["odometry"]); });
  EXPECT_EQ(msg.rfind("p.yaml:2: odometry.preset: unknown preset", 0), 0u) << msg;
  const auto neg = yaml::Node::load_string("odometry:\n  track_noise_sd: -1\n", "n.yaml");
  msg = config_error_of([&] { parse_odometry_options(neg["odometry"]); });
  EXPECT_EQ(msg.rfind("n.yaml:2: odometry.track_noise_sd: must be", 0), 0u) << msg;
}

}  // namespace
}  // namespace cogmap::sim
