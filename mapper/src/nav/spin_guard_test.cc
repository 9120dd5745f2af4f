// Turning on the spot: which sensed point the body's corners would strike, and the guard
// that moves the robot away from it first.

#include "nav/spin_guard.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "cogmap/test_support/angles.h"
#include "nav/nav_core.h"

namespace cogmap::mapper::nav {
namespace {

// A point beside the front-left corner of the P2-AT (corner at x 0.313, y 0.2525): outside the
// outline grown by 0.04 m (|y| > 0.2925) but within its corners' reach (0.4585 m).
const Point2 kBesideCorner(0.30, 0.32);

Point2 to_world(const Point2& body, double heading_rad) {
  const double c = std::cos(heading_rad), s = std::sin(heading_rad);
  return {c * body.x() - s * body.y(), s * body.x() + c * body.y()};
}

TEST(SpinStrike, ATurnTowardAPointBesideACornerStrikesIt) {
  const RobotGeometry robot = p2at_geometry();
  for (const double heading : {0.0, M_PI / 2, -2.5}) {
    SCOPED_TRACE(heading);
    const std::vector<ObstaclePoint> pts = {{to_world(kBesideCorner, heading), 15.0f}};
    // Counter-clockwise the corner swings into it after 6° (y' = 0.32 cos a - 0.30 sin a falls
    // below 0.2925 between 5° and 6°); clockwise it swings away.
    const auto ccw = spin_strike(pts, heading, +1, robot, 0.04, 20.0 * kDeg);
    ASSERT_TRUE(ccw.has_value());
    EXPECT_NEAR(ccw->x(), kBesideCorner.x(), 1e-12);
    EXPECT_NEAR(ccw->y(), kBesideCorner.y(), 1e-12);
    EXPECT_FALSE(spin_strike(pts, heading, -1, robot, 0.04, 20.0 * kDeg).has_value());
    // Looking only 5° ahead, the counter-clockwise turn is still clear.
    EXPECT_FALSE(spin_strike(pts, heading, +1, robot, 0.04, 5.0 * kDeg).has_value());
    EXPECT_TRUE(spin_strike(pts, heading, +1, robot, 0.04, 6.0 * kDeg).has_value());
  }
}

TEST(SpinStrike, SkipsPointsOutOfReachOrAlreadyInsideAndPicksTheFirstStruck) {
  const RobotGeometry robot = p2at_geometry();
  // 0.5 m ahead is beyond every corner; 0.1 m ahead is inside the body (a contact or smear).
  const std::vector<ObstaclePoint> far_and_inside = {{Point2(0.5, 0.0), 15.0f},
                                                     {Point2(0.1, 0.1), 15.0f}};
  EXPECT_FALSE(spin_strike(far_and_inside, 0.0, +1, robot, 0.04, M_PI).has_value());
  EXPECT_FALSE(spin_strike(far_and_inside, 0.0, -1, robot, 0.04, M_PI).has_value());
  // One 0.4 m off the left flank, struck turning counter-clockwise after 43° (cos a ≤
  // 0.2925/0.4), and one beside the rear-right corner, struck after 6° (the mirror image of
  // kBesideCorner): the nearest in angle wins, whatever the order.
  const Point2 flank(0.0, 0.40), rear_right(-0.30, -0.32);
  const std::vector<ObstaclePoint> flank_only = {{flank, 15.0f}};
  EXPECT_FALSE(spin_strike(flank_only, 0.0, +1, robot, 0.04, 42.0 * kDeg).has_value());
  EXPECT_TRUE(spin_strike(flank_only, 0.0, +1, robot, 0.04, 44.0 * kDeg).has_value());
  for (const auto& two : {std::vector<ObstaclePoint>{{flank, 15.0f}, {rear_right, 15.0f}},
                          std::vector<ObstaclePoint>{{rear_right, 15.0f}, {flank, 15.0f}}}) {
    const auto first = spin_strike(two, 0.0, +1, robot, 0.04, 60.0 * kDeg);
    ASSERT_TRUE(first.has_value());
    EXPECT_NEAR(first->x(), rear_right.x(), 1e-12);
    EXPECT_NEAR(first->y(), rear_right.y(), 1e-12);
  }
}

TEST(ArcStrikes, APointAheadIsStruckOnceTheHorizonCoversTheGap) {
  const RobotGeometry robot = p2at_geometry();
  // 0.2 m beyond the grown front (0.313 + 0.04): 0.4 s at 0.5 m/s, whatever the heading.
  for (const double heading : {0.0, 2.0}) {
    SCOPED_TRACE(heading);
    const std::vector<ObstaclePoint> ahead = {{to_world(Point2(0.553, 0.0), heading), 15.0f}};
    EXPECT_TRUE(arc_strikes(ahead, heading, 0.5, 0.0, robot, 0.04, 0.45));
    EXPECT_FALSE(arc_strikes(ahead, heading, 0.5, 0.0, robot, 0.04, 0.35));
    // Backing away from it, or a zero horizon, strikes nothing.
    EXPECT_FALSE(arc_strikes(ahead, heading, -0.5, 0.0, robot, 0.04, 2.0));
    EXPECT_FALSE(arc_strikes(ahead, heading, 0.5, 0.0, robot, 0.04, 0.0));
    // Behind, reversing: the mirror image.
    const std::vector<ObstaclePoint> behind = {{to_world(Point2(-0.553, 0.0), heading), 15.0f}};
    EXPECT_TRUE(arc_strikes(behind, heading, -0.5, 0.0, robot, 0.04, 0.45));
    EXPECT_FALSE(arc_strikes(behind, heading, -0.5, 0.0, robot, 0.04, 0.35));
  }
}

TEST(ArcStrikes, ATurnSwingsTheFrontCornerIntoAPointBesideIt) {
  const RobotGeometry robot = p2at_geometry();
  // 0.0075 m outside the grown left flank (0.2525 + 0.04), beside the front-left corner: driving
  // straight past it never brings it inside; at 0.3 m/s turning left at 0.6 rad/s the corner
  // reaches it after 0.33 s (the arc's radius is 0.5 m); turning right swings the corner away.
  const std::vector<ObstaclePoint> beside = {{Point2(0.40, 0.30), 15.0f}};
  EXPECT_FALSE(arc_strikes(beside, 0.0, 0.3, 0.0, robot, 0.04, 2.0));
  EXPECT_TRUE(arc_strikes(beside, 0.0, 0.3, 0.6, robot, 0.04, 0.5));
  EXPECT_FALSE(arc_strikes(beside, 0.0, 0.3, 0.6, robot, 0.04, 0.2));
  EXPECT_FALSE(arc_strikes(beside, 0.0, 0.3, -0.6, robot, 0.04, 0.5));
  // Already inside the grown outline (a contact or a smear the arc cannot avoid): skipped; far
  // beyond the arc's reach: skipped.
  const std::vector<ObstaclePoint> inside_and_far = {{Point2(0.30, 0.28), 15.0f},
                                                     {Point2(3.0, 0.0), 15.0f}};
  EXPECT_FALSE(arc_strikes(inside_and_far, 0.0, 0.3, 0.6, robot, 0.04, 0.5));
  // Non-finite commands strike nothing (nothing is sent for them either).
  EXPECT_FALSE(
      arc_strikes(beside, 0.0, std::numeric_limits<double>::quiet_NaN(), 0.6, robot, 0.04, 0.5));
}

/// A core that has sensed one echo of the left transducer (90°, at x 0.147, y 0.136) 0.2 m
/// away: a point beside the left flank, near the front-left corner.
struct LeftEcho {
  RobotGeometry robot = p2at_geometry();
  SensorFrame frame;
  NavInput input;
  NavCore core;

  explicit LeftEcho(const CoreOptions& options) : core(options) {
    frame.sonar = {{0, 0.2, true, 0.0}};
    input.frame = &frame;
    input.robot = &robot;
    core.sense(input);
  }
};

TEST(SpinGuard, BacksAwayBeforeATurnThatWouldStrikeAndTurnsTheOtherWayFreely) {
  LeftEcho s{CoreOptions{}};
  const double speed = s.core.speed_mps();
  // A target 120° left: a turn on the spot counter-clockwise, toward the point.
  const VelocityCommand left = s.core.drive_direct(s.input, 120.0 * kDeg, speed, NavMode::kDirect);
  EXPECT_DOUBLE_EQ(left.v_mps, -CoreOptions{}.safety.spin_escape_mps);
  EXPECT_DOUBLE_EQ(left.w_radps, 0.0);
  // 120° right: the corner swings away from it, the turn goes ahead.
  const VelocityCommand right =
      s.core.drive_direct(s.input, -120.0 * kDeg, speed, NavMode::kDirect);
  EXPECT_DOUBLE_EQ(right.v_mps, 0.0);
  EXPECT_DOUBLE_EQ(right.w_radps, -s.core.max_turn_radps());
  // Guard off: the turn toward the point is sent as it is.
  CoreOptions off;
  off.safety.spin_guard_deg = 0.0;
  LeftEcho u{off};
  const VelocityCommand blind = u.core.drive_direct(u.input, 120.0 * kDeg, speed, NavMode::kDirect);
  EXPECT_DOUBLE_EQ(blind.v_mps, 0.0);
  EXPECT_DOUBLE_EQ(blind.w_radps, u.core.max_turn_radps());
}

TEST(ArcGuard, AnArcTowardAPointBesideTheCornerBecomesTheTurnAloneUnderTheSpinGuard) {
  // 30° left: the steering asks for a forward arc to the left, which swings the front-left
  // corner into the echo beside it; the guard drops the forward speed, and the turn alone
  // strikes it too, so the spin guard backs away first. 30° right: the corner swings away.
  CoreOptions on;
  on.safety.arc_guard_s = 0.5;
  LeftEcho s{on};
  const double speed = s.core.speed_mps();
  const VelocityCommand left = s.core.drive_direct(s.input, 30.0 * kDeg, speed, NavMode::kDirect);
  EXPECT_DOUBLE_EQ(left.v_mps, -on.safety.spin_escape_mps);
  EXPECT_DOUBLE_EQ(left.w_radps, 0.0);
  CoreOptions off;
  off.safety.arc_guard_s = 0.0;
  LeftEcho u{off};
  const VelocityCommand blind = u.core.drive_direct(u.input, 30.0 * kDeg, speed, NavMode::kDirect);
  EXPECT_GT(blind.v_mps, 0.1);
  EXPECT_GT(blind.w_radps, 0.5);
  const VelocityCommand right = s.core.drive_direct(s.input, -30.0 * kDeg, speed, NavMode::kDirect);
  const VelocityCommand right_blind =
      u.core.drive_direct(u.input, -30.0 * kDeg, speed, NavMode::kDirect);
  EXPECT_GT(right.v_mps, 0.1);
  EXPECT_DOUBLE_EQ(right.v_mps, right_blind.v_mps);
  EXPECT_DOUBLE_EQ(right.w_radps, right_blind.w_radps);
}

/// The left echo asks for a move back (as above) while a rear transducer hears something
/// behind; standing at (0.05, 0.05) puts a near rear echo's cell centre 0.087 m behind the
/// bumper: beyond the guard's margin (0.04 m), within a cell's uncertainty of it.
struct LeftAndRearEcho {
  RobotGeometry robot = p2at_geometry();
  SensorFrame frame;
  NavInput input;
  NavCore core{CoreOptions{}};

  LeftAndRearEcho(int rear_sonar, double rear_range_m) {
    frame.sonar = {{0, 0.2, true, 0.0}, {rear_sonar, rear_range_m, true, 0.0}};
    input.frame = &frame;
    input.robot = &robot;
    input.pose = Pose2{0.05, 0.05, 0.0};
    core.sense(input);
  }
  /// The lane behind as the sensed points place it: the nearest point behind the rear bumper.
  double behind_m() const {
    const double half_lane = 0.5 * robot.width_m + CoreOptions{}.safety.spin_guard_margin_m;
    double nearest = std::numeric_limits<double>::infinity();
    for (const ObstaclePoint& p : core.field().points()) {
      if (p.offset_m.x() < 0.0 && std::abs(p.offset_m.y()) <= half_lane) {
        nearest = std::min(nearest, -p.offset_m.x() - 0.5 * robot.length_m);
      }
    }
    return nearest;
  }
  VelocityCommand turn_left_120() {
    return core.drive_direct(input, 120.0 * kDeg, core.speed_mps(), NavMode::kDirect);
  }
};

TEST(SpinGuard, EscapesOnlyIntoALaneClearByMoreThanAPointsUncertainty) {
  const SafetyOptions safety = CoreOptions{}.safety;
  // Behind clear (transducer 11, -170°, echo at 0.3 m): back away first.
  LeftAndRearEcho clear(11, 0.30);
  EXPECT_GT(clear.behind_m(), safety.spin_escape_clearance_m);
  const VelocityCommand back = clear.turn_left_120();
  EXPECT_DOUBLE_EQ(back.v_mps, -safety.spin_escape_mps);
  EXPECT_DOUBLE_EQ(back.w_radps, 0.0);
  // Behind within a cell of the bumper (transducer 12, 170°, at 0.14 m): no move back; the
  // clockwise turn strikes nothing, so the robot goes the long way round.
  LeftAndRearEcho near(12, 0.14);
  EXPECT_GT(near.behind_m(), safety.spin_guard_margin_m);
  EXPECT_LE(near.behind_m(), safety.spin_escape_clearance_m);
  const VelocityCommand long_way = near.turn_left_120();
  EXPECT_DOUBLE_EQ(long_way.v_mps, 0.0);
  EXPECT_DOUBLE_EQ(long_way.w_radps, -near.core.max_turn_radps());
  // Behind near and struck by the clockwise turn too (transducer 11 at 0.14 m): boxed in, the
  // turn goes as asked.
  LeftAndRearEcho boxed(11, 0.14);
  EXPECT_LE(boxed.behind_m(), safety.spin_escape_clearance_m);
  const VelocityCommand as_asked = boxed.turn_left_120();
  EXPECT_DOUBLE_EQ(as_asked.v_mps, 0.0);
  EXPECT_DOUBLE_EQ(as_asked.w_radps, boxed.core.max_turn_radps());
}

}  // namespace
}  // namespace cogmap::mapper::nav
