// clearance_m decides most points by their offsets along and across the heading and only the
// ones near the cone's edge by their bearing: it must answer exactly as the plain bearing test
// it replaced (kept here as the reference), bit for bit.

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include "nav/nav_test_util.h"
#include "nav/steering.h"

namespace cogmap::mapper::nav {
namespace {

/// The test before 2026-12-03: every point's bearing by atan2.
double reference_clearance_m(const std::vector<ObstaclePoint>& obstacles, double heading_rad,
                             double half_angle_rad, double length_m) {
  double nearest = std::numeric_limits<double>::infinity();
  for (const ObstaclePoint& o : obstacles) {
    const double distance = o.offset_m.norm() - 0.5 * length_m;
    if (!(distance < nearest)) continue;
    const double bearing = std::atan2(o.offset_m.y(), o.offset_m.x());
    if (std::abs(wrap_angle_rad(bearing - heading_rad)) > half_angle_rad) continue;
    nearest = distance;
  }
  return nearest;
}

using testing::same_bits;

using testing::at;

TEST(SteeringClearance, MatchesTheBearingTestBitForBit) {
  std::mt19937_64 rng(20261203);
  std::uniform_real_distribution<double> u(-3.0, 3.0), range(0.05, 3.0), angle(-4.0, 4.0);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double halves[] = {0.5236, 0.1, 1.2, 1.5707963, 2.0, 0.0, 3.2};
  const double headings[] = {
      0.0, 1.0, -2.9, std::numbers::pi, 7.5, 1234.5, -0.5 * std::numbers::pi};
  int cases = 0, infinite = 0;
  for (int k = 0; k < 6000; ++k) {
    const double heading = k % 3 == 0 ? headings[k % 7] : angle(rng);
    const double half = halves[k % 7];
    std::vector<ObstaclePoint> points;
    const int n = 1 + static_cast<int>(unit(rng) * 40);
    for (int i = 0; i < n; ++i) {
      switch (i % 5) {
        case 0:  // anywhere
          points.push_back({Point2(u(rng), u(rng)), 1.0f});
          break;
        case 1:  // exactly on either edge of the cone, where rounding decides
          points.push_back({at(heading + (i % 2 ? half : -half), range(rng)), 1.0f});
          break;
        case 2:  // a hair inside or outside an edge
          points.push_back(
              {at(heading + half * (1.0 + (unit(rng) - 0.5) * 1e-12), range(rng)), 1.0f});
          break;
        case 3:  // straight ahead, straight across, straight behind
          points.push_back({at(heading + 0.5 * std::numbers::pi * (i % 3), range(rng)), 1.0f});
          break;
        default:  // on the grid's cell centres, as the obstacle field lists them
          points.push_back({Point2(0.1 * std::round(u(rng) * 10.0) + 0.05,
                                   0.1 * std::round(u(rng) * 10.0) - 0.05),
                            1.0f});
      }
    }
    if (k % 11 == 0) points.push_back({Point2(0.0, 0.0), 1.0f});  // the robot's own centre
    const double length = k % 2 ? 0.626 : 0.0;
    const double fast = clearance_m(points, heading, half, length);
    const double plain = reference_clearance_m(points, heading, half, length);
    ASSERT_TRUE(same_bits(fast, plain)) << "case " << k << ": " << fast << " vs " << plain;
    ++cases;
    infinite += std::isinf(plain);
  }
  EXPECT_EQ(cases, 6000);
  EXPECT_GT(infinite, 100);   // empty cones were compared...
  EXPECT_LT(infinite, 3000);  // ...and so were nearest obstacles
}

TEST(SteeringClearance, KnownAnswers) {
  // A 30° cone ahead: the point at 20° counts, the one at 40° and the one behind do not.
  const std::vector<ObstaclePoint> points = {
      {at(0.349, 1.0), 1.0f}, {at(0.698, 0.6), 1.0f}, {at(std::numbers::pi, 0.3), 1.0f}};
  EXPECT_DOUBLE_EQ(clearance_m(points, 0.0, 0.5236, 0.6), 1.0 - 0.3);
  EXPECT_DOUBLE_EQ(clearance_m(points, std::numbers::pi, 0.5236, 0.6), 0.3 - 0.3);
  EXPECT_TRUE(std::isinf(clearance_m(points, -1.5, 0.5236, 0.6)));
}

}  // namespace
}  // namespace cogmap::mapper::nav
