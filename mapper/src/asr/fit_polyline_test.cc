#include <gtest/gtest.h>

#include "cogmap/mapper/asr/stages.h"

namespace cogmap::mapper {
namespace {

using Indices = std::vector<std::size_t>;

void expect_near(const Point2& a, const Point2& b) {
  EXPECT_NEAR(a.x(), b.x(), 1e-9) << a.transpose() << " vs " << b.transpose();
  EXPECT_NEAR(a.y(), b.y(), 1e-9) << a.transpose() << " vs " << b.transpose();
}

TEST(FitPolyline, NoisyLJoinsAtTheCornerOfTheFittedLines) {
  // Points alternate ±0.1 about y = 0 and about x = 4; the DP vertex (index 4) is off both.
  const Polyline points{{0, 0.1}, {1, -0.1}, {2, 0.1}, {3, -0.1}, {4.1, 0.1},
                        {3.9, 1}, {4.1, 2},  {3.9, 3}, {4.1, 4}};
  const PolylineFit fit = fit_polyline(points, Indices{0, 4, 8}, 0.9, 1.0);
  EXPECT_TRUE(fit.rejected.empty());
  ASSERT_EQ(fit.wall.size(), 3u);
  // Both lines are fitted to their own points including the shared corner point.
  const LineFit first = fit_line(std::span<const Point2>(points).subspan(0, 5));
  const LineFit second = fit_line(std::span<const Point2>(points).subspan(4, 5));
  expect_near(fit.wall[0], first.project(points[0]));
  expect_near(fit.wall[2], second.project(points[8]));
  // The corner lies on both fitted lines.
  EXPECT_NEAR((fit.wall[1] - first.project(fit.wall[1])).norm(), 0.0, 1e-9);
  EXPECT_NEAR((fit.wall[1] - second.project(fit.wall[1])).norm(), 0.0, 1e-9);
  EXPECT_LT((fit.wall[1] - Point2(4, 0)).norm(), 0.15);
}

TEST(FitPolyline, ExactLFitsExactly) {
  const Polyline points{{0, 0}, {1, 0}, {2, 0}, {2, 1}, {2, 2}};
  const PolylineFit fit = fit_polyline(points, Indices{0, 2, 4}, 0.9, 1.0);
  ASSERT_EQ(fit.wall.size(), 3u);
  expect_near(fit.wall[0], {0, 0});
  expect_near(fit.wall[1], {2, 0});
  expect_near(fit.wall[2], {2, 2});
}

TEST(FitPolyline, PoorCorrelationKeepsTheDouglasPeuckerSegment) {
  // Segment 0 is a straight run; segment 1 spans a square blob (|ρ| = 0 < 0.9).
  const Polyline points{{0, 0}, {1, 0}, {2, 0}, {3, 0}, {4, 0}, {4, 1}, {5, 1}, {5, 0}};
  const PolylineFit fit = fit_polyline(points, Indices{0, 4, 7}, 0.9, 1.0);
  ASSERT_EQ(fit.rejected.size(), 1u);
  expect_near(fit.rejected[0].a, {4, 0});
  expect_near(fit.rejected[0].b, {5, 0});
  // Fitted start, the shared DP vertex, and the rejected segment's own end.
  ASSERT_EQ(fit.wall.size(), 3u);
  expect_near(fit.wall[0], {0, 0});
  expect_near(fit.wall[1], {4, 0});
  expect_near(fit.wall[2], {5, 0});
}

TEST(FitPolyline, FarIntersectionFallsBackToProjections) {
  // Two nearly parallel runs: their lines cross far from the shared vertex.
  const Polyline points{{0, 0}, {1, 0}, {2, 0}, {3, 0.05}, {4, 0.15}};
  const PolylineFit fit = fit_polyline(points, Indices{0, 2, 4}, 0.9, 0.01);
  ASSERT_EQ(fit.wall.size(), 4u);
  expect_near(fit.wall[0], {0, 0});
  expect_near(fit.wall[1], {2, 0});  // projection onto y = 0
  const LineFit second = fit_line(std::span<const Point2>(points).subspan(2, 3));
  expect_near(fit.wall[2], second.project({2, 0}));
  expect_near(fit.wall[3], second.project({4, 0.15}));
}

TEST(FitPolyline, SingleVertexPassesThrough) {
  const PolylineFit fit = fit_polyline({{1, 2}}, Indices{0}, 0.9, 1.0);
  ASSERT_EQ(fit.wall.size(), 1u);
  EXPECT_TRUE(fit.rejected.empty());
}

}  // namespace
}  // namespace cogmap::mapper
