#include <gtest/gtest.h>

#include <cmath>

#include "cogmap/sim/motion_limiter.h"
#include "cogmap/sim/physics_world.h"
#include "cogmap/sim/stall_detector.h"
#include "world/world_test_support.h"

namespace cogmap::sim {
namespace {

using testing::parse;

TEST(MotionLimiter, RampsAtAccelAndDecelLimits) {
  MotionLimiter limiter;  // 0.3 m/s² up, 0.6 m/s² down, 0.75 m/s top
  for (int i = 0; i < 10; ++i) limiter.step({1.0, 0.0}, 0.1);
  EXPECT_NEAR(limiter.current().v_mps, 0.3, 1e-12);  // 1 s at 0.3 m/s²
  for (int i = 0; i < 100; ++i) limiter.step({1.0, 0.0}, 0.1);
  EXPECT_DOUBLE_EQ(limiter.current().v_mps, 0.75);  // clamped to the top speed
  limiter.step({0.0, 0.0}, 0.5);
  EXPECT_NEAR(limiter.current().v_mps, 0.45, 1e-12);  // braking at 0.6 m/s²
  limiter.step({-0.5, 0.0}, 1.0);
  EXPECT_NEAR(limiter.current().v_mps, -0.15, 1e-12);  // a reversal brakes through zero
  const auto c = limiter.clamp({-2.0, 5.0});
  EXPECT_DOUBLE_EQ(c.v_mps, -0.75);
  EXPECT_DOUBLE_EQ(c.w_radps, 1.74);
}

TEST(StallDetector, NeedsPersistenceOrContact) {
  StallDetector d;
  const WheelSpeeds wheels{0.5, 0.5};
  const BodyTwist expected{0.5, 0.0};
  const BodyTwist blocked{0.05, 0.0};  // 10 % of the expected speed
  // Steps of 1/16 s are exact in binary: 0.25 s is not yet a stall, 0.3125 s is.
  for (int i = 0; i < 4; ++i) d.update(wheels, expected, blocked, false, 0.0625);
  EXPECT_FALSE(d.left());
  d.update(wheels, expected, blocked, false, 0.0625);
  EXPECT_TRUE(d.left());
  EXPECT_TRUE(d.right());
  d.update(wheels, expected, {0.4, 0.0}, false, 0.01);  // moving again
  EXPECT_FALSE(d.left());
  d.update(wheels, expected, blocked, true, 0.01);  // pushing against a wall: at once
  EXPECT_TRUE(d.left());
  StallDetector idle;
  idle.update({0.0, 0.0}, {}, {}, true, 1.0);  // not driven: never stalled
  EXPECT_FALSE(idle.left());
  // Spinning left with the right side blocked: only the right flags.
  StallDetector spin;
  spin.update({-0.2, 0.2}, {0.0, 1.0}, {-0.0985, 0.5}, true, 0.01);
  EXPECT_FALSE(spin.left());
  EXPECT_TRUE(spin.right());
}

TEST(PhysicsWorld, FreeMotionFollowsTheArcExactly) {
  const WorldSpec w = parse("name: open\nwalls: {polylines: []}\nstart: {x_m: 1, y_m: 2}\n");
  PhysicsWorld physics(w);
  mapper::Pose2 expected = w.start;
  for (int i = 0; i < 500; ++i) {
    physics.step({0.5, 0.4}, 0.01);
    expected = advance_pose(expected, 0.5 * 0.01, 0.4 * 0.01);
  }
  EXPECT_FALSE(physics.in_contact());
  EXPECT_DOUBLE_EQ(physics.pose().x_m, expected.x_m);
  EXPECT_DOUBLE_EQ(physics.pose().y_m, expected.y_m);
  EXPECT_DOUBLE_EQ(physics.pose().theta_rad, expected.theta_rad);
}

TEST(PhysicsWorld, WallStopsTheBody) {
  const WorldSpec w = parse(
      "name: wall\nwalls: {thickness_m: 0.12, polylines: [[[3, -2], [3, 2]]]}\n"
      "start: {x_m: 1, y_m: 0}\n");
  PhysicsWorld physics(w);
  for (int i = 0; i < 1000; ++i) physics.step({0.5, 0.0}, 0.01);
  EXPECT_TRUE(physics.in_contact());
  // Front face at x + 0.313 m meets the wall face at 2.94 m (Box2D keeps a ~1 cm skin).
  EXPECT_LT(physics.pose().x_m, 2.94 - 0.313 + 0.011);
  EXPECT_GT(physics.pose().x_m, 2.94 - 0.313 - 0.02);
  EXPECT_NEAR(physics.pose().y_m, 0.0, 1e-3);
  EXPECT_NEAR(physics.pose().theta_rad, 0.0, 1e-3);
}

// One 10 ms step of both worlds with the same twist: the poses and contact flags must agree
// bit for bit.
::testing::AssertionResult steps_alike(PhysicsWorld& skipping, PhysicsWorld& stepping,
                                       const BodyTwist& twist) {
  const mapper::Pose2 a = skipping.step(twist, 0.01);
  const mapper::Pose2 b = stepping.step(twist, 0.01);
  if (a.x_m != b.x_m || a.y_m != b.y_m || a.theta_rad != b.theta_rad) {
    return ::testing::AssertionFailure()
           << "poses differ: (" << a.x_m << ", " << a.y_m << ", " << a.theta_rad << ") skipping, ("
           << b.x_m << ", " << b.y_m << ", " << b.theta_rad << ") stepping";
  }
  if (skipping.in_contact() != stepping.in_contact()) {
    return ::testing::AssertionFailure() << "contact flags differ: " << skipping.in_contact()
                                         << " skipping, " << stepping.in_contact() << " stepping";
  }
  return ::testing::AssertionSuccess();
}

// Skipping Box2D away from every fixture must change nothing: a drive that nears, scrapes and
// leaves walls, a corner and a pillar gives the same poses and contact flags, bit for bit, as
// stepping Box2D every time.
TEST(PhysicsWorld, SkippingFreeStepsChangesNothing) {
  const WorldSpec w = parse(
      "name: corner\nwalls: {thickness_m: 0.12, polylines: [[[-3, 5], [5, 5], [5, -3]]]}\n"
      "obstacles: [{circle: {center: [2, 1], radius_m: 0.2}}]\n"
      "start: {x_m: 0, y_m: 0}\n");
  PhysicsOptions always;
  always.skip_free_steps = false;
  PhysicsWorld skipping(w), stepping(w, always);
  int contact_steps = 0, free_steps = 0;
  for (int i = 0; i < 6000; ++i) {
    // Arcs, spins and straight runs at the corner (4, 4), the pillar and back out.
    const double t = 0.01 * i;
    const BodyTwist twist{0.5 * std::cos(0.37 * t) + 0.2, 0.8 * std::sin(0.23 * t)};
    ASSERT_TRUE(steps_alike(skipping, stepping, twist)) << "step " << i;
    (stepping.in_contact() ? contact_steps : free_steps)++;
  }
  EXPECT_GT(contact_steps, 100);              // the walls were really met
  EXPECT_GT(free_steps, 1000);                // and really left
  EXPECT_GT(skipping.skipped_steps(), 1000);  // and Box2D was skipped for much of the drive
  EXPECT_EQ(stepping.skipped_steps(), 0);
}

// A corridor 1.4 m wide: each wall lies 0.45 m from the body's side as it drives down the middle,
// within the reach of the old rule (no fixture within 0.95 m of the centre), which never skipped
// here. Measured clearances let Box2D rest until the body swerves toward a wall, and the poses
// stay those of stepping always.
TEST(PhysicsWorld, SkipsStepsBesideWallsItDoesNotTouch) {
  const WorldSpec w = parse(
      "name: corridor\nwalls: {thickness_m: 0.12, polylines: [[[-2, 0.76], [30, 0.76]], "
      "[[-2, -0.76], [30, -0.76]]]}\nstart: {x_m: 0, y_m: 0}\n");
  PhysicsOptions always;
  always.skip_free_steps = false;
  PhysicsWorld skipping(w), stepping(w, always);
  int contact_steps = 0;
  const int steps = 4000;
  for (int i = 0; i < steps; ++i) {
    // Straight at 0.5 m/s, then a slow weave whose swings end against the walls.
    const double t = 0.01 * i;
    const BodyTwist twist{0.5, t < 20.0 ? 0.0 : 1.2 * std::sin(0.8 * (t - 20.0))};
    ASSERT_TRUE(steps_alike(skipping, stepping, twist)) << "step " << i;
    if (stepping.in_contact()) ++contact_steps;
  }
  EXPECT_GT(contact_steps, 50);  // the weave really reached the walls
  // The straight 20 s are skipped whole but for the first step, which measures the clearance.
  EXPECT_GE(skipping.skipped_steps(), 1999);
}

}  // namespace
}  // namespace cogmap::sim
