#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "cogmap/mapper/localization/em.h"
#include "cogmap/test_support/angles.h"

namespace cogmap::mapper {
namespace {

/// A one-segment polyline from the origin in direction `deg` with length `len`.
Polyline ray(double deg, double len = 1.0) {
  return {Point2{0.0, 0.0}, Point2{len * std::cos(deg * kDeg), len * std::sin(deg * kDeg)}};
}

double folded_deg(double deg) {
  const std::vector<Polyline> lines{ray(deg)};
  const auto d = line_directions(lines);
  EXPECT_EQ(d.size(), 1u);
  return d.empty() ? NAN : d[0].angle_rad / kDeg;
}

TEST(LineDirections, FoldsEveryQuadrantModuloNinetyDegrees) {
  // Quadrant I
  EXPECT_NEAR(folded_deg(10), 10, 1e-9);
  EXPECT_NEAR(folded_deg(60), -30, 1e-9);
  // Quadrant II
  EXPECT_NEAR(folded_deg(100), 10, 1e-9);
  EXPECT_NEAR(folded_deg(150), -30, 1e-9);
  // Quadrant III
  EXPECT_NEAR(folded_deg(-170), 10, 1e-9);
  EXPECT_NEAR(folded_deg(-120), -30, 1e-9);
  // Quadrant IV
  EXPECT_NEAR(folded_deg(-80), 10, 1e-9);
  EXPECT_NEAR(folded_deg(-30), -30, 1e-9);
  // The axes and the seam: [−45°, 45°) is half-open.
  EXPECT_NEAR(folded_deg(0), 0, 1e-9);
  EXPECT_NEAR(folded_deg(90), 0, 1e-9);
  EXPECT_NEAR(folded_deg(180), 0, 1e-9);
  EXPECT_NEAR(folded_deg(-90), 0, 1e-9);
  EXPECT_NEAR(folded_deg(45), -45, 1e-9);
  EXPECT_NEAR(folded_deg(-45), -45, 1e-9);
  EXPECT_NEAR(folded_deg(135), -45, 1e-9);
}

TEST(LineDirections, ARotatedRectangleGivesOneValue) {
  // The printed Eqs. 3.28-3.31 would reflect half of these walls to −7°; modulo 90° keeps 7°.
  const double c = std::cos(7 * kDeg), s = std::sin(7 * kDeg);
  auto rot = [&](double x, double y) { return Point2{c * x - s * y, s * x + c * y}; };
  const std::vector<Polyline> room{{rot(0, 0), rot(4, 0), rot(4, 3), rot(0, 3), rot(0, 0)}};
  const auto d = line_directions(room);
  ASSERT_EQ(d.size(), 4u);
  const double lengths[4] = {4, 3, 4, 3};
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(d[i].angle_rad, 7 * kDeg, 1e-12);
    EXPECT_NEAR(d[i].length_m, lengths[i], 1e-12);
  }
}

TEST(LineDirections, SkipsRepeatedVerticesAndSinglePoints) {
  const std::vector<Polyline> lines{{Point2{1, 1}, Point2{1, 1}, Point2{2, 1}}, {Point2{0, 0}}};
  const auto d = line_directions(lines);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_DOUBLE_EQ(d[0].length_m, 1.0);
}

TEST(Directions, MeanWrapsAcrossTheSeam) {
  // 44° and −44° are 2° apart modulo 90°: their mean is the seam, −45°, not 0°.
  const std::vector<double> a{44 * kDeg, -44 * kDeg};
  EXPECT_NEAR(mean_direction_rad(a, {}), -45 * kDeg, 1e-9);
  const std::vector<double> b{10 * kDeg, 20 * kDeg};
  const std::vector<double> w{1.0, 0.0};
  EXPECT_NEAR(mean_direction_rad(b, w), 10 * kDeg, 1e-12);
}

TEST(Directions, DominantDirectionIgnoresShortClutter) {
  std::vector<LineDirection> d{{3 * kDeg, 4.0}, {3 * kDeg, 3.0}, {3 * kDeg, 2.0}};
  for (double deg : {-40.0, -30.0, -20.0, -10.0, 15.0, 25.0, 35.0}) d.push_back({deg * kDeg, 0.3});
  EXPECT_NEAR(dominant_direction_rad(d), 3 * kDeg, 1e-9);
  // A plain weighted mean would be pulled away by the clutter.
  std::vector<double> angles, weights;
  for (const auto& x : d) {
    angles.push_back(x.angle_rad);
    weights.push_back(x.length_m);
  }
  EXPECT_GT(std::abs(mean_direction_rad(angles, weights) - 3 * kDeg), 0.05 * kDeg);
  EXPECT_NEAR(direction_spread_rad(d, 3 * kDeg, 5 * kDeg), 0.0, 1e-12);
}

TEST(Directions, DominantDirectionAtTheSeam) {
  const std::vector<LineDirection> d{{44 * kDeg, 1.0}, {-44 * kDeg, 1.0}, {-45 * kDeg, 1.0}};
  EXPECT_NEAR(std::abs(dominant_direction_rad(d)), 45 * kDeg, 0.5 * kDeg);
}

}  // namespace
}  // namespace cogmap::mapper
