#include <gtest/gtest.h>

#include "cogmap/mapper/asr/stages.h"

namespace cogmap::mapper {
namespace {

using Indices = std::vector<std::size_t>;

TEST(DouglasPeucker, CollinearRunKeepsOnlyTheEnds) {
  Polyline line;
  for (int i = 0; i <= 10; ++i) line.push_back({i, 0});
  EXPECT_EQ(douglas_peucker_indices(line, 0.1), (Indices{0, 10}));
}

TEST(DouglasPeucker, LShapeKeepsTheCorner) {
  const Polyline line{{0, 0}, {1, 0}, {2, 0}, {3, 0}, {3, 1}, {3, 2}, {3, 3}};
  EXPECT_EQ(douglas_peucker_indices(line, 0.5), (Indices{0, 3, 6}));
  const Polyline out = douglas_peucker(line, 0.5);
  ASSERT_EQ(out.size(), 3u);
  EXPECT_EQ(out[1], Point2(3, 0));
}

TEST(DouglasPeucker, ZigZagDependsOnTolerance) {
  // Chord (0,0)-(4,0): peaks at distance 1. Sub-chord (1,1)-(4,0): (2,0) and (3,1) at 2/√10.
  const Polyline line{{0, 0}, {1, 1}, {2, 0}, {3, 1}, {4, 0}};
  EXPECT_EQ(douglas_peucker_indices(line, 0.5), (Indices{0, 1, 2, 3, 4}));
  EXPECT_EQ(douglas_peucker_indices(line, 0.8), (Indices{0, 1, 4}));
  EXPECT_EQ(douglas_peucker_indices(line, 1.0), (Indices{0, 4}));  // d > η splits, d = η not
}

TEST(DouglasPeucker, DistanceIsToTheFiniteSegment) {
  // (4,0) lies on the infinite line through (0,0) and (-2,0) but 4 away from the segment.
  const Polyline line{{0, 0}, {4, 0}, {-2, 0}};
  EXPECT_EQ(douglas_peucker_indices(line, 1.0), (Indices{0, 1, 2}));
}

TEST(DouglasPeucker, ClosedLoopKeepsItsCorners) {
  const Polyline line{{0, 0}, {1, 0}, {2, 0}, {2, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}, {0, 0}};
  EXPECT_EQ(douglas_peucker_indices(line, 0.5), (Indices{0, 2, 4, 6, 8}));
}

TEST(DouglasPeucker, ShortLines) {
  EXPECT_TRUE(douglas_peucker_indices({}, 1.0).empty());
  EXPECT_EQ(douglas_peucker_indices({{1, 1}}, 1.0), (Indices{0}));
  EXPECT_EQ(douglas_peucker_indices({{1, 1}, {2, 2}}, 1.0), (Indices{0, 1}));
}

}  // namespace
}  // namespace cogmap::mapper
