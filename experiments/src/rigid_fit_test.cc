#include "cogmap/experiments/rigid_fit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "cogmap/experiments/error_breakdown.h"
#include "cogmap/test_support/angles.h"

namespace cogmap::experiments {
namespace {

using mapper::Point2;
using mapper::Pose2;
using mapper::Segment;

// A 5 x 4 m room with a 1.5 m partition off its south wall: no rigid motion but the identity
// lays it onto itself.
const std::vector<Segment> kRoom{{{0.0, 0.0}, {5.0, 0.0}},
                                 {{5.0, 0.0}, {5.0, 4.0}},
                                 {{5.0, 4.0}, {0.0, 4.0}},
                                 {{0.0, 4.0}, {0.0, 0.0}},
                                 {{2.0, 0.0}, {2.0, 1.5}}};

std::vector<Point2> samples(const std::vector<Segment>& walls, double step_m) {
  std::vector<Point2> out;
  for (const Segment& s : walls) {
    const int n = static_cast<int>(std::round(s.length_m() / step_m));
    for (int k = 0; k < n; ++k) out.push_back(s.a + (k + 0.5) / n * (s.b - s.a));
  }
  return out;
}

// Converged far below the default 0.1 mm: the fit's answer itself, to rounding.
RigidFitOptions exact() {
  RigidFitOptions o;
  o.converged_m = 1e-10;
  o.max_iterations = 1000;
  return o;
}

std::vector<Point2> moved(std::vector<Point2> points, const Pose2& by) {
  for (Point2& p : points) p = by.transform(p);
  return points;
}

TEST(RigidFit, UndoesAKnownMisplacement) {
  const SegmentIndex truth(kRoom);
  // The map drawn 4° turned about (1, 2) and 0.2 m east, 0.1 m south of the truth.
  const Pose2 misplaced =
      Pose2{0.2, -0.1, 0.0}.compose(mapper::rotation_about({1.0, 2.0}, rad(4.0)));
  const RigidFit fit = fit_rigid(moved(samples(kRoom, 0.05), misplaced), truth, exact());
  ASSERT_TRUE(fit.fitted);
  const Pose2 undo = misplaced.inverse();
  EXPECT_NEAR(fit.transform.theta_rad, undo.theta_rad, 1e-6);
  EXPECT_NEAR(fit.transform.x_m, undo.x_m, 1e-5);
  EXPECT_NEAR(fit.transform.y_m, undo.y_m, 1e-5);
  EXPECT_EQ(fit.pairs, samples(kRoom, 0.05).size());
}

TEST(RigidFit, PhantomsBeyondTheGatesDoNotPull) {
  const SegmentIndex truth(kRoom);
  const Pose2 misplaced{0.15, 0.05, rad(-2.0)};
  std::vector<Point2> points = moved(samples(kRoom, 0.05), misplaced);
  const std::size_t walls = points.size();
  // A phantom wall 2 m outside the east wall, 3 m long (multipath beyond the wall).
  for (int k = 0; k < 60; ++k) points.push_back(misplaced.transform({7.0, 0.5 + 0.05 * k}));
  const RigidFit fit = fit_rigid(points, truth, exact());
  ASSERT_TRUE(fit.fitted);
  const Pose2 undo = misplaced.inverse();
  EXPECT_NEAR(fit.transform.theta_rad, undo.theta_rad, 1e-6);
  EXPECT_NEAR(fit.transform.x_m, undo.x_m, 1e-5);
  EXPECT_NEAR(fit.transform.y_m, undo.y_m, 1e-5);
  EXPECT_EQ(fit.pairs, walls);  // the phantom's samples lie beyond the last gate
}

TEST(RigidFit, TooFewSamplesNearTheTruthFitNothing) {
  const SegmentIndex truth(kRoom);
  RigidFitOptions options;
  options.min_pairs = 10;
  // Nine samples on the south wall, the rest 3 m off every wall.
  std::vector<Point2> points;
  for (int k = 0; k < 9; ++k) points.push_back({0.5 + 0.1 * k, 0.05});
  for (int k = 0; k < 20; ++k) points.push_back({2.5 + 0.01 * k, 8.0});
  const RigidFit fit = fit_rigid(points, truth, options);
  EXPECT_FALSE(fit.fitted);
  EXPECT_EQ(fit.transform.x_m, 0.0);
  EXPECT_EQ(fit.transform.y_m, 0.0);
  EXPECT_EQ(fit.transform.theta_rad, 0.0);
  EXPECT_FALSE(fit_rigid({}, truth).fitted);
  EXPECT_FALSE(fit_rigid(points, SegmentIndex({})).fitted);
}

TEST(AlignedErrors, TheMapTurnedAboutItsStartIsTurnedBack) {
  const SegmentIndex truth(kRoom);
  const Point2 start{1.0, 1.0};
  // Drawn 3° anticlockwise about the start: the whole-map fit turns it back by 3°, leaving the
  // start where it was, and every sample on its wall.
  const std::vector<std::vector<Point2>> rooms{
      moved(samples(kRoom, 0.05), mapper::rotation_about(start, rad(3.0)))};
  const auto [map, by_room] = aligned_errors(rooms, truth, start);
  ASSERT_TRUE(map.rotation_deg.has_value());
  // The default fit stops once a step moves no sample 0.1 mm: it ends 0.0014° and 0.04 mm
  // short here, the samples 0.03 mm off their wall (median).
  EXPECT_NEAR(*map.rotation_deg, -3.0, 0.003);
  ASSERT_TRUE(map.start_shift_m.has_value());
  EXPECT_NEAR(map.start_shift_m->norm(), 0.0, 1e-4);
  ASSERT_TRUE(map.error.median_m.has_value());
  EXPECT_NEAR(*map.error.median_m, 0.0, 1e-4);
  EXPECT_EQ(map.error.count, rooms[0].size());
  EXPECT_EQ(by_room.rooms_fitted, 1u);
  EXPECT_NEAR(*by_room.error.median_m, 0.0, 1e-4);
}

TEST(AlignedErrors, RoomsPlacedApartAreEachLaidBack) {
  // Two rooms side by side sharing x = 5; the second drawn 0.2 m north of where it is. One
  // transform cannot lay both; one each can.
  std::vector<Segment> west = kRoom;
  std::vector<Segment> east;
  for (const Segment& s : kRoom) east.push_back({s.a + Point2(5.0, 0.0), s.b + Point2(5.0, 0.0)});
  std::vector<Segment> both = west;
  both.insert(both.end(), east.begin(), east.end());
  const SegmentIndex truth(both);
  const std::vector<std::vector<Point2>> rooms{samples(west, 0.05),
                                               moved(samples(east, 0.05), Pose2{0.0, 0.2, 0.0})};
  const auto [map, by_room] = aligned_errors(rooms, truth, {1.0, 1.0});
  ASSERT_TRUE(map.error.median_m.has_value());
  // The shared wall x = 5 takes the east room's west face wherever it slides along it, so the
  // lone fit leaves some samples off; each room's own fit leaves none.
  EXPECT_GT(*map.error.p90_m, 0.05);
  EXPECT_EQ(by_room.rooms_fitted, 2u);
  EXPECT_NEAR(*by_room.error.median_m, 0.0, 1e-4);  // 0.06 mm, the default fit's stop
  EXPECT_NEAR(*by_room.error.p90_m, 0.0, 2.5e-4);   // 0.11 mm
}

}  // namespace
}  // namespace cogmap::experiments
