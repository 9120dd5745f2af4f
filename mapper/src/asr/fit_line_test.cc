#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "cogmap/mapper/asr/stages.h"

namespace cogmap::mapper {
namespace {

// A fixed noise pattern across a 2 m wall: offsets in metres, one per 10 cm station.
const double kNoise[] = {0.03, -0.02, 0.05,  -0.04, 0.00, 0.02,  -0.05, 0.04,  -0.01, 0.03, -0.03,
                         0.01, 0.04,  -0.02, -0.04, 0.05, -0.01, 0.02,  -0.03, 0.00,  0.01};

// The noisy wall along the x axis, rotated by `angle_rad` and moved to `offset`.
std::vector<Point2> noisy_wall(double angle_rad, const Point2& offset) {
  const double c = std::cos(angle_rad), s = std::sin(angle_rad);
  std::vector<Point2> points;
  for (int i = 0; i < static_cast<int>(std::size(kNoise)); ++i) {
    const double x = 0.1 * i, y = kNoise[i];
    points.push_back(offset + Point2(c * x - s * y, s * x + c * y));
  }
  return points;
}

double line_angle_error(const LineFit& fit, double angle_rad) {
  // Directions are unsigned: compare modulo π.
  return std::abs(std::sin(std::atan2(fit.direction.y(), fit.direction.x()) - angle_rad));
}

TEST(FitLine, ExactPointsGiveTheirLine) {
  std::vector<Point2> points;
  for (int i = -3; i <= 5; ++i) points.push_back({i, 2.0 + 0.5 * i});
  const LineFit fit = fit_line(points);
  ASSERT_TRUE(fit.valid);
  EXPECT_NEAR(fit.correlation, 1.0, 1e-12);
  const double b1 = fit.direction.y() / fit.direction.x();
  EXPECT_NEAR(b1, 0.5, 1e-12);
  EXPECT_NEAR(fit.point.y() - b1 * fit.point.x(), 2.0, 1e-12);  // b0
  const RegressionFit eq = regress_y_on_x(points);
  ASSERT_TRUE(eq.valid);
  EXPECT_NEAR(eq.b1, 0.5, 1e-12);
  EXPECT_NEAR(eq.b0, 2.0, 1e-12);
  EXPECT_NEAR(eq.correlation, 1.0, 1e-12);
}

TEST(FitLine, HorizontalVerticalAndThirtyDegreeWallsAgree) {
  const double angles[] = {0.0, std::numbers::pi / 2, std::numbers::pi / 6};
  const LineFit reference = fit_line(noisy_wall(0.0, {0, 0}));
  ASSERT_TRUE(reference.valid);
  EXPECT_GT(reference.correlation, 0.9);
  EXPECT_LT(reference.correlation, 1.0);
  for (const double angle : angles) {
    const LineFit fit = fit_line(noisy_wall(angle, {3.7, -1.2}));
    ASSERT_TRUE(fit.valid);
    EXPECT_NEAR(fit.correlation, reference.correlation, 1e-12) << "angle " << angle;
    EXPECT_LT(line_angle_error(fit, angle), 0.02) << "angle " << angle;
  }
}

TEST(FitLine, EquationThreeTenIsDegenerateForAxisAlignedWalls) {
  // Why fit_line does not use Eq. 3.10 directly: the same good wall scores low when horizontal
  // and has no defined ρ when exactly vertical.
  const RegressionFit horizontal = regress_y_on_x(noisy_wall(0.0, {0, 0}));
  ASSERT_TRUE(horizontal.valid);
  EXPECT_LT(std::abs(horizontal.correlation), 0.9);
  const std::vector<Point2> vertical{{1, 0}, {1, 1}, {1, 2}, {1, 3}};
  EXPECT_FALSE(regress_y_on_x(vertical).valid);
  const LineFit fit = fit_line(vertical);
  ASSERT_TRUE(fit.valid);
  EXPECT_NEAR(fit.correlation, 1.0, 1e-12);
  EXPECT_NEAR(std::abs(fit.direction.y()), 1.0, 1e-12);
}

TEST(FitLine, EqualsEquationThreeTenWithTheLineAtFortyFiveDegrees) {
  for (const double angle : {0.0, 0.4, std::numbers::pi / 2, 2.5}) {
    const std::vector<Point2> points = noisy_wall(angle, {1.0, 2.0});
    const LineFit fit = fit_line(points);
    ASSERT_TRUE(fit.valid);
    // Rotate the points so that the fitted line runs at 45°, then apply Eq. 3.10 as printed.
    const double rotation = std::numbers::pi / 4 - std::atan2(fit.direction.y(), fit.direction.x());
    const double c = std::cos(rotation), s = std::sin(rotation);
    std::vector<Point2> rotated;
    for (const Point2& p : points)
      rotated.push_back({c * p.x() - s * p.y(), s * p.x() + c * p.y()});
    const RegressionFit eq = regress_y_on_x(rotated);
    ASSERT_TRUE(eq.valid);
    EXPECT_NEAR(std::abs(eq.correlation), fit.correlation, 1e-12) << "angle " << angle;
  }
}

TEST(FitLine, IsotropicCloudHasNoCorrelation) {
  const std::vector<Point2> square{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const LineFit fit = fit_line(square);
  ASSERT_TRUE(fit.valid);
  EXPECT_NEAR(fit.correlation, 0.0, 1e-12);
}

TEST(FitLine, TooFewOrIdenticalPointsAreInvalid) {
  EXPECT_FALSE(fit_line(std::vector<Point2>{}).valid);
  EXPECT_FALSE(fit_line(std::vector<Point2>{{1, 1}}).valid);
  EXPECT_FALSE(fit_line(std::vector<Point2>{{1, 1}, {1, 1}, {1, 1}}).valid);
  EXPECT_FALSE(regress_y_on_x(std::vector<Point2>{{1, 1}}).valid);
}

TEST(FitLine, ProjectDropsThePerpendicular) {
  const LineFit fit = fit_line(std::vector<Point2>{{0, 1}, {2, 1}});
  const Point2 p = fit.project({5, 4});
  EXPECT_NEAR(p.x(), 5.0, 1e-12);
  EXPECT_NEAR(p.y(), 1.0, 1e-12);
}

}  // namespace
}  // namespace cogmap::mapper
