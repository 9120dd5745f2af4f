#include "cogmap/mapper/localization/held_turn.h"
#include "cogmap/test_support/angles.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <numbers>

namespace cogmap::mapper {
namespace {

// The P2-AT's ring, degrees from the robot's front (docs/p2at.md).
constexpr std::array<double, 16> kAxesDeg = {90,  50,   30,   10,   -10, -30, -50, -90,
                                             -90, -130, -150, -170, 170, 150, 130, 90};

/// Range from (x, y) along `angle` to the walls of the box [0, w] × [0, h] (no echo beyond 5 m).
double box_range(double x, double y, double angle, double w, double h) {
  const double c = std::cos(angle), s = std::sin(angle);
  double t = 5.0;
  if (c > 1e-12) t = std::min(t, (w - x) / c);
  if (c < -1e-12) t = std::min(t, -x / c);
  if (s > 1e-12) t = std::min(t, (h - y) / s);
  if (s < -1e-12) t = std::min(t, -y / s);
  return t;
}

/// Frames of 0.1 s, four transducers each in ring order, the odometry turning at rate_radps
/// on the spot at (x, y); `body_theta(t)` is where the body really faces (what the sonar
/// sees), the reported odometry always turns.
struct SpinRun {
  double x = 1.2, y = 1.0, w = 4.0, h = 6.0, rate_radps = 1.0;
  double seconds = 3.0;
  std::function<double(double)> body_theta;

  /// Feeds the filter and returns the output pose of every frame.
  std::vector<Pose2> feed(HeldTurnFilter& filter, std::vector<Pose2>* inputs = nullptr) const {
    std::vector<Pose2> out;
    int next = 0;
    for (int k = 0; k * 0.1 <= seconds + 1e-9; ++k) {
      const double t = 0.1 * k;
      SensorFrame frame;
      frame.time_s = t;
      frame.odometry = Pose2{x, y, wrap_angle_rad(rate_radps * t)};
      for (int j = 0; j < 4; ++j, next = (next + 1) % 16) {
        const double r = box_range(x, y, body_theta(t) + kAxesDeg[next] * kDeg, w, h);
        frame.sonar.push_back({next, std::min(r, 5.0), r < 5.0, t});
      }
      if (inputs) inputs->push_back(frame.odometry);
      out.push_back(filter.update(frame.odometry, frame));
    }
    return out;
  }
};

TEST(HeldTurnFilter, ARealTurnPassesThroughBitForBit) {
  SpinRun run;
  run.body_theta = [&](double t) { return run.rate_radps * t; };
  HeldTurnFilter filter;
  std::vector<Pose2> in;
  const std::vector<Pose2> out = run.feed(filter, &in);
  ASSERT_EQ(out.size(), in.size());
  for (std::size_t k = 0; k < out.size(); ++k) {
    EXPECT_EQ(out[k].x_m, in[k].x_m);
    EXPECT_EQ(out[k].y_m, in[k].y_m);
    EXPECT_EQ(out[k].theta_rad, in[k].theta_rad);
  }
  EXPECT_EQ(filter.detections(), 0u);
  EXPECT_EQ(filter.removed_abs_rad(), 0.0);
}

TEST(HeldTurnFilter, AHeldBodyKeepsItsHeading) {
  // The wheels spin at 1 rad/s for 3 s (172°), the body stays at 0 in a 2 × 2.6 m box where
  // every transducer hears a wall within 2 m: the first frame's readings are references,
  // every comparison after 40° of odometry turn finds the same range, and the turn is taken
  // back to the first frame's heading.
  SpinRun run;
  run.w = 2.0;
  run.h = 2.6;
  run.x = 0.9;
  run.y = 1.1;
  run.body_theta = [](double) { return 0.0; };
  HeldTurnFilter filter;
  const std::vector<Pose2> out = run.feed(filter);
  EXPECT_EQ(filter.detections(), 1u);
  EXPECT_TRUE(filter.held());
  EXPECT_NEAR(out.back().theta_rad, 0.0, 1e-9);
  EXPECT_NEAR(out.back().x_m, run.x, 1e-9);  // turned back about where the robot stands
  EXPECT_NEAR(out.back().y_m, run.y, 1e-9);
  EXPECT_NEAR(filter.removed_abs_rad(), 3.0, 1e-9);
  // Before the comparisons can tell (40° and six of them), the odometry is passed on.
  EXPECT_NEAR(out[5].theta_rad, 0.5, 1e-12);
}

TEST(HeldTurnFilter, FreedBodyTurnsAgainFromWhereItWasHeld) {
  // Held for 2 s, then the body turns with the wheels: the turn made while held stays out,
  // the later one is passed on (once the ranges change, after the last held comparisons).
  SpinRun run;
  run.seconds = 6.0;
  run.body_theta = [](double t) { return t < 2.0 ? 0.0 : t - 2.0; };
  HeldTurnFilter filter;
  const std::vector<Pose2> out = run.feed(filter);
  EXPECT_EQ(filter.detections(), 1u);
  EXPECT_FALSE(filter.held());
  // Removed: the 2 s held, and the body's first turn until two of the latest six comparisons
  // disagree (2.4 rad measured: a ring cycle, 0.4 s); not the whole 6 s.
  EXPECT_GT(filter.removed_abs_rad(), 2.0 - 1e-9);
  EXPECT_LT(filter.removed_abs_rad(), 2.5);
  EXPECT_NEAR(wrap_angle_rad(out.back().theta_rad - (6.0 - filter.removed_abs_rad())), 0.0, 1e-9);
}

TEST(HeldTurnFilter, NoJudgementWhileTheRobotMovesOrHearsNothingNear) {
  // Driving straight along a corridor the side ranges stay the same but nothing turns; in a
  // large hall nothing lies within max_range_m. Either way the odometry passes unchanged.
  HeldTurnFilter filter;
  for (int k = 0; k < 60; ++k) {
    SensorFrame frame;
    frame.time_s = 0.1 * k;
    frame.odometry = Pose2{0.05 * k, 0.0, wrap_angle_rad(0.2 * k)};  // moving while turning
    for (int j = 0; j < 16; ++j) frame.sonar.push_back({j, 1.0, true, frame.time_s});
    const Pose2 out = filter.update(frame.odometry, frame);
    EXPECT_EQ(out.theta_rad, frame.odometry.theta_rad);
  }
  HeldTurnFilter hall;
  for (int k = 0; k < 60; ++k) {
    SensorFrame frame;
    frame.time_s = 0.1 * k;
    frame.odometry = Pose2{0.0, 0.0, wrap_angle_rad(0.2 * k)};
    for (int j = 0; j < 16; ++j) frame.sonar.push_back({j, 3.5, true, frame.time_s});
    EXPECT_EQ(hall.update(frame.odometry, frame).theta_rad, frame.odometry.theta_rad);
  }
  EXPECT_EQ(filter.detections() + hall.detections(), 0u);
}

TEST(HeldTurnFilter, OffPassesEverything) {
  SpinRun run;
  run.body_theta = [](double) { return 0.0; };
  HeldTurnOptions off;
  off.enabled = false;
  HeldTurnFilter filter(off);
  std::vector<Pose2> in;
  const std::vector<Pose2> out = run.feed(filter, &in);
  EXPECT_EQ(out.back().theta_rad, in.back().theta_rad);
  EXPECT_EQ(filter.detections(), 0u);
}

}  // namespace
}  // namespace cogmap::mapper
