#include "cogmap/mapper/localization/scan_match.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

#include "cogmap/test_support/angles.h"
#include "facade/mapper_test_support.h"

namespace cogmap::mapper {
namespace {

/// A 6 x 5 m room with a 1 x 0.6 m cabinet against its north wall (so no rotation or shift is
/// a symmetry of it).
std::vector<Segment> room_walls() {
  std::vector<Segment> walls = test::rectangle(0.0, 0.0, 6.0, 5.0);
  const std::vector<Segment> cabinet = test::rectangle(2.0, 4.4, 3.0, 5.0);
  walls.insert(walls.end(), cabinet.begin(), cabinet.end());
  return walls;
}

/// Every transducer fired at `truth` (ideal sonar: the axis ray), added at `estimate`.
void fire(ScanMatcher& matcher, const RobotGeometry& robot, const std::vector<Segment>& walls,
          const Pose2& truth, const Pose2& estimate, int room_id) {
  for (int s = 0; s < static_cast<int>(robot.sonars.size()); ++s) {
    const SonarMount& m = robot.sonars[s];
    const auto r = test::cast(truth.transform({m.x_m, m.y_m}), truth.theta_rad + m.heading_rad,
                              walls, robot.sonar_max_range_m);
    matcher.add(estimate, {s, r.value_or(robot.sonar_max_range_m), r.has_value(), 0.0}, room_id);
  }
}

/// Poses every 5 cm from `a` to `b`, heading along the leg.
std::vector<Pose2> leg(const Point2& a, const Point2& b) {
  std::vector<Pose2> poses;
  const double heading = std::atan2(b.y() - a.y(), b.x() - a.x());
  const int steps = static_cast<int>(std::round((b - a).norm() / 0.05));
  for (int i = 0; i <= steps; ++i) {
    const Point2 p = a + (b - a) * (static_cast<double>(i) / steps);
    poses.push_back({p.x(), p.y(), heading});
  }
  return poses;
}

/// The memory: a lap of the room (east along the south side, north, back west 0.3 m short of
/// the window's line) driven with a perfect estimate, as one window.
/// `error` ∘ truth is the estimate the memory is drawn with.
void draw_memory(ScanMatcher& matcher, const RobotGeometry& robot,
                 const std::vector<Segment>& walls, const Pose2& error = Pose2{}) {
  std::vector<Pose2> path;
  for (const auto& [a, b] : std::vector<std::pair<Point2, Point2>>{
           {{1.0, 1.0}, {5.0, 1.0}}, {{5.0, 1.0}, {5.0, 3.3}}, {{5.0, 3.3}, {1.0, 3.3}}}) {
    const std::vector<Pose2> l = leg(a, b);
    path.insert(path.end(), l.begin(), l.end());
  }
  for (const Pose2& p : path) fire(matcher, robot, walls, p, error.compose(p), 0);
  // Nothing to match against yet: the window joins the memory.
  matcher.match(error.compose(path.back()), 1e-6, 1e-6);
}

ScanMatchOptions scan_match_options() {
  ScanMatchOptions o;
  o.enabled = true;
  return o;
}

/// The window: the north side driven west, seen by an estimate that is `error` ∘ truth.
Pose2 draw_window(ScanMatcher& matcher, const RobotGeometry& robot,
                  const std::vector<Segment>& walls, const Pose2& error, int room_id = 0) {
  Pose2 estimate;
  for (const Pose2& truth : leg({5.0, 3.6}, {1.5, 3.6})) {
    estimate = error.compose(truth);
    fire(matcher, robot, walls, truth, estimate, room_id);
  }
  return estimate;
}

TEST(ScanMatch, FindsTheEstimatesRotationAndShift) {
  const RobotGeometry robot = p2at_geometry();
  const auto walls = room_walls();
  ScanMatcher matcher(scan_match_options(), robot);
  draw_memory(matcher, robot, walls);
  // The estimate turned 2° about the window's end and shifted (6, -4) cm.
  const Point2 end{1.5, 3.6};
  const Pose2 error = Pose2{0.06, -0.04, 0.0}.compose(rotation_about(end, 2.0 * kDeg));
  const Pose2 estimate = draw_window(matcher, robot, walls, error);
  // Wide priors (3°, 10 cm): the answer is the echoes'.
  const ScanMatchFix fix = matcher.match(estimate, std::pow(3.0 * kDeg, 2), 0.01);
  ASSERT_TRUE(fix.measured);
  EXPECT_GT(fix.matched_echoes, 100u);
  const Pose2 corrected = fix.transform().compose(estimate);
  EXPECT_NEAR(wrap_angle_rad(corrected.theta_rad - 0.0 - std::numbers::pi), 0.0, 0.3 * kDeg);
  EXPECT_NEAR(corrected.x_m, end.x(), 0.02);
  EXPECT_NEAR(corrected.y_m, end.y(), 0.02);
  EXPECT_NEAR(fix.rotation_rad, -2.0 * kDeg, 0.3 * kDeg);
  // The posterior is narrower than the prior.
  EXPECT_LT(fix.rotation_var_rad2, std::pow(1.0 * kDeg, 2));
  EXPECT_LT(fix.shift_var_m2, 0.01 / 4.0);
}

TEST(ScanMatch, TurningOnlyLeavesThePositionAlone) {
  const RobotGeometry robot = p2at_geometry();
  const auto walls = room_walls();
  ScanMatchOptions turning_only = scan_match_options();
  turning_only.shift = false;
  ScanMatcher matcher(turning_only, robot);
  draw_memory(matcher, robot, walls);
  const Point2 end{1.5, 3.6};
  const Pose2 estimate = draw_window(matcher, robot, walls, rotation_about(end, 2.0 * kDeg));
  const ScanMatchFix fix = matcher.match(estimate, std::pow(3.0 * kDeg, 2), 0.01);
  ASSERT_TRUE(fix.measured);
  EXPECT_NEAR(fix.rotation_rad, -2.0 * kDeg, 0.3 * kDeg);
  EXPECT_EQ(fix.shift_m, Point2::Zero());
  EXPECT_EQ(fix.shift_var_m2, 0.01);  // not measured: the prior's
}

TEST(ScanMatch, LeavesAnEstimateWithoutErrorAlone) {
  const RobotGeometry robot = p2at_geometry();
  const auto walls = room_walls();
  ScanMatcher matcher(scan_match_options(), robot);
  draw_memory(matcher, robot, walls);
  const Pose2 estimate = draw_window(matcher, robot, walls, Pose2{});
  const ScanMatchFix fix = matcher.match(estimate, std::pow(3.0 * kDeg, 2), 0.01);
  ASSERT_TRUE(fix.measured);
  // Measured 0.24° and 0.5 cm: the walls' ends and the cabinet's sides, seen once, are not
  // symmetric about the answer.
  EXPECT_LT(std::abs(fix.rotation_rad), 0.3 * kDeg);
  EXPECT_LT(fix.shift_m.norm(), 0.01);
}

TEST(ScanMatch, TheOdometryPriorHoldsTheAnswerBack) {
  const RobotGeometry robot = p2at_geometry();
  const auto walls = room_walls();
  const Point2 end{1.5, 3.6};
  const Pose2 error = rotation_about(end, 2.0 * kDeg);
  ScanMatcher wide(scan_match_options(), robot), narrow(scan_match_options(), robot);
  for (ScanMatcher* m : {&wide, &narrow}) draw_memory(*m, robot, walls);
  const Pose2 estimate = draw_window(wide, robot, walls, error);
  draw_window(narrow, robot, walls, error);
  const ScanMatchFix free = wide.match(estimate, std::pow(3.0 * kDeg, 2), 1e-4);
  // A prior of 0.2° says odometry cannot have drifted 2°: the posterior stays near it.
  const ScanMatchFix held = narrow.match(estimate, std::pow(0.2 * kDeg, 2), 1e-4);
  ASSERT_TRUE(free.measured && held.measured);
  EXPECT_LT(std::abs(held.rotation_rad), 0.5 * std::abs(free.rotation_rad));
  EXPECT_LE(held.rotation_var_rad2, std::pow(0.2 * kDeg, 2));
}

/// A corridor, two parallel walls 2.4 m apart: nothing tells one point along it from another.
/// The memory is drawn driving 0-14 m, the window driving back from 8 to 6 m with `error`.
ScanMatchFix match_in_corridor(const Pose2& error) {
  const RobotGeometry robot = p2at_geometry();
  const std::vector<Segment> walls{{{-5.0, -1.2}, {25.0, -1.2}}, {{-5.0, 1.2}, {25.0, 1.2}}};
  ScanMatcher matcher(scan_match_options(), robot);
  for (const Pose2& p : leg({0.0, 0.0}, {14.0, 0.0})) fire(matcher, robot, walls, p, p, 0);
  matcher.match({14.0, 0.0, 0.0}, 1e-6, 1e-6);
  Pose2 estimate;
  for (const Pose2& p : leg({8.0, 0.0}, {6.0, 0.0})) {
    estimate = error.compose(p);
    fire(matcher, robot, walls, p, estimate, 0);
  }
  return matcher.match(estimate, std::pow(1.0 * kDeg, 2), 0.01);
}

TEST(ScanMatch, ACorridorsLengthIsLeftUnmeasured) {
  // Drawn 10 cm too far along and 5 cm to the left: the sideways error is measured and
  // corrected, the one along the corridor is left as it is, with the prior's variance.
  const ScanMatchFix fix = match_in_corridor({0.1, 0.05, 0.0});
  ASSERT_TRUE(fix.measured);
  EXPECT_EQ(fix.degenerate_axes, 1);
  EXPECT_NEAR(fix.shift_m.y(), -0.05, 0.015);
  EXPECT_NEAR(fix.shift_m.x(), 0.0, 1e-3);
  EXPECT_GE(fix.shift_var_m2, 0.5 * 0.01 / 2.0);  // the mean of the axes' variances
  // Without an error nothing moves either way.
  const ScanMatchFix none = match_in_corridor(Pose2{});
  ASSERT_TRUE(none.measured);
  EXPECT_EQ(none.degenerate_axes, 1);
  EXPECT_LT(none.shift_m.norm(), 0.01);
}

TEST(ScanMatch, NothingIsMeasuredWithoutAMemoryOrNearItsWalls) {
  const RobotGeometry robot = p2at_geometry();
  const auto walls = room_walls();
  ScanMatcher matcher(scan_match_options(), robot);
  // No memory: the first window only joins it.
  const Pose2 estimate = draw_window(matcher, robot, walls, Pose2{});
  const ScanMatchFix first = matcher.match(estimate, 1e-4, 1e-3);
  EXPECT_FALSE(first.measured);
  EXPECT_GT(first.window_echoes, 100u);
  EXPECT_EQ(first.rotation_var_rad2, 1e-4);  // the prior, untouched
  EXPECT_EQ(first.shift_var_m2, 1e-3);
  EXPECT_EQ(matcher.memory_size(), first.window_echoes);
  // A window in another room 20 m away meets none of the memory's walls.
  std::vector<Segment> far;
  for (const Segment& w : walls) far.push_back({w.a + Point2{20.0, 0.0}, w.b + Point2{20.0, 0.0}});
  for (const Pose2& p : leg({22.0, 1.0}, {25.0, 1.0})) fire(matcher, robot, far, p, p, 1);
  const ScanMatchFix second = matcher.match({25.0, 1.0, 0.0}, 1e-4, 1e-3);
  EXPECT_FALSE(second.measured);
  EXPECT_EQ(second.matched_echoes, 0u);
  EXPECT_EQ(second.rotation_rad, 0.0);
}

TEST(ScanMatch, AWindowTooWideOrABrokenEstimateMeasuresNothing) {
  const RobotGeometry robot = p2at_geometry();
  const auto walls = room_walls();
  ScanMatcher matcher(scan_match_options(), robot);
  draw_memory(matcher, robot, walls);
  // The same window, but its last echoes drawn 60 m away (an odometry jump): not matched.
  const Pose2 estimate = draw_window(matcher, robot, walls, Pose2{});
  fire(matcher, robot, walls, {1.5, 3.6, 0.0}, {61.5, 3.6, 0.0}, 0);
  EXPECT_FALSE(matcher.match(estimate, 1e-4, 1e-3).measured);
  // Readings at a non-finite estimate are not kept; a non-finite prior measures nothing.
  const double nan = std::nan("");
  fire(matcher, robot, walls, {1.5, 3.6, 0.0}, {nan, 3.6, 0.0}, 0);
  EXPECT_EQ(matcher.match(estimate, 1e-4, 1e-3).window_echoes, 0u);
  draw_window(matcher, robot, walls, Pose2{});
  EXPECT_FALSE(matcher.match(estimate, nan, 1e-3).measured);
}

TEST(ScanMatch, MemoryFollowsItsRoomsCorrection) {
  const RobotGeometry robot = p2at_geometry();
  const auto walls = room_walls();
  // Room 0's echoes were drawn 3° off; its EM correction turns them back (move_room), and the
  // estimate with them: a window drawn with the corrected estimate then needs no fix. Without
  // the move the window would be matched 3° onto the uncorrected memory.
  const Pose2 drawn_off = rotation_about({3.0, 2.5}, 3.0 * kDeg);
  for (bool moved : {true, false}) {
    ScanMatcher matcher(scan_match_options(), robot);
    draw_memory(matcher, robot, walls, drawn_off);
    if (moved) matcher.move_room(0, drawn_off.inverse());
    matcher.move_room(7, Pose2{1.0, 1.0, 1.0});  // no echo of room 7: nothing moves
    const Pose2 estimate = draw_window(matcher, robot, walls, Pose2{}, 1);
    const ScanMatchFix fix = matcher.match(estimate, std::pow(4.0 * kDeg, 2), 0.04);
    ASSERT_TRUE(fix.measured);
    if (moved) {
      EXPECT_LT(std::abs(fix.rotation_rad), 0.3 * kDeg);
    } else {
      EXPECT_NEAR(fix.rotation_rad, 3.0 * kDeg, 0.5 * kDeg);
    }
  }
}

TEST(ScanMatch, MemoryFollowsAShiftOfTheEstimate) {
  const RobotGeometry robot = p2at_geometry();
  const auto walls = room_walls();
  ScanMatcher matcher(scan_match_options(), robot);
  // The memory was drawn 10 cm east; a doorway fix shifts the estimate back, and the memory too.
  const Pose2 east{0.1, 0.0, 0.0};
  draw_memory(matcher, robot, walls, east);
  matcher.shift_all({-0.1, 0.0});
  const Pose2 estimate = draw_window(matcher, robot, walls, Pose2{}, 1);
  const ScanMatchFix fix = matcher.match(estimate, std::pow(2.0 * kDeg, 2), 0.01);
  ASSERT_TRUE(fix.measured);
  EXPECT_LT(fix.shift_m.norm(), 0.015);
}

TEST(ScanMatch, AMatchIsDueAfterTravelOrTurningWithEnoughEchoes) {
  const RobotGeometry robot = p2at_geometry();
  const auto walls = room_walls();
  ScanMatchOptions o = scan_match_options();
  o.min_window_echoes = 20;
  ScanMatcher matcher(o, robot);
  EXPECT_FALSE(matcher.visit({1.0, 1.0, 0.0}, 0.0));
  EXPECT_FALSE(matcher.visit({1.9, 1.0, 0.0}, 0.0));  // 0.9 m
  EXPECT_FALSE(matcher.visit({2.1, 1.0, 0.0}, 0.0));  // 1.1 m, but no echo yet
  fire(matcher, robot, walls, {2.1, 1.0, 0.0}, {2.1, 1.0, 0.0}, 0);
  fire(matcher, robot, walls, {2.1, 1.0, 0.0}, {2.1, 1.0, 0.0}, 0);
  EXPECT_TRUE(matcher.visit({2.1, 1.0, 0.0}, 0.0));
  matcher.match({2.1, 1.0, 0.0}, 1e-4, 1e-4);
  EXPECT_EQ(matcher.travelled_m(), 0.0);
  fire(matcher, robot, walls, {2.1, 1.0, 0.0}, {2.1, 1.0, 0.0}, 0);
  fire(matcher, robot, walls, {2.1, 1.0, 0.0}, {2.1, 1.0, 0.0}, 0);
  EXPECT_FALSE(matcher.visit({2.1, 1.0, 0.3}, 0.3));
  EXPECT_TRUE(matcher.visit({2.1, 1.0, 0.6}, -0.3));  // turning counts both ways
  // Echoes beyond the range limit, without an echo, or of an unknown transducer are not kept.
  ScanMatcher empty(o, robot);
  empty.add({0.0, 0.0, 0.0}, {0, 3.5, true, 0.0}, 0);
  empty.add({0.0, 0.0, 0.0}, {0, 5.0, false, 0.0}, 0);
  empty.add({0.0, 0.0, 0.0}, {99, 1.0, true, 0.0}, 0);
  empty.add({0.0, 0.0, 0.0}, {0, std::nan(""), true, 0.0}, 0);
  EXPECT_EQ(empty.match({0.0, 0.0, 0.0}, 1e-4, 1e-4).window_echoes, 0u);
  empty.add({0.0, 0.0, 0.0}, {0, 2.5, true, 0.0}, 0);
  EXPECT_EQ(empty.match({0.0, 0.0, 0.0}, 1e-4, 1e-4).window_echoes, 1u);
}

}  // namespace
}  // namespace cogmap::mapper
