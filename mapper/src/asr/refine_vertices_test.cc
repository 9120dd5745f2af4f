#include <gtest/gtest.h>

#include "cogmap/mapper/asr/stages.h"

namespace cogmap::mapper {
namespace {

using Indices = std::vector<std::size_t>;

TEST(RefineVertices, ChamferedCornerMovesBackToTheCornerPoint) {
  const Polyline points{{0, 0}, {1, 0}, {2, 0}, {3, 0}, {3, 1}, {3, 2}, {3, 3}};
  // VertexSimplify (τ = 2) drops the corner (3,0) and (3,1); DP (η = 0.5) keeps (2,0).
  const Indices simplified = vertex_simplify_indices(points, 2.0);
  ASSERT_EQ(simplified, (Indices{0, 2, 5, 6}));
  Polyline simplified_points;
  for (const std::size_t i : simplified) simplified_points.push_back(points[i]);
  const Indices dp = douglas_peucker_indices(simplified_points, 0.5);
  ASSERT_EQ(dp, (Indices{0, 1, 3}));
  // (2,0) moves to the corner (3,0), the dropped point farthest from the chord (0,0)-(3,3).
  EXPECT_EQ(refine_vertices(points, simplified, dp, 0.5), (Indices{0, 3, 6}));
}

TEST(RefineVertices, SecondChamferVertexBecomesRedundant) {
  const Polyline points{{0, 0}, {1, 0}, {2, 0}, {3, 0}, {3, 1}, {3, 2}, {3, 3}};
  // Chamfer vertices (2,0) and (3,1) around the dropped corner (3,0).
  const Indices simplified{0, 2, 4, 6};
  // (2,0) moves to (3,0); (3,1) then lies on the chord (3,0)-(3,3) and goes.
  EXPECT_EQ(refine_vertices(points, simplified, Indices{0, 1, 2, 3}, 0.5), (Indices{0, 3, 6}));
}

TEST(RefineVertices, StraightRunsAndEndsAreUntouched) {
  const Polyline points{{0, 0}, {1, 0}, {2, 0}, {3, 0}, {4, 0}};
  EXPECT_EQ(refine_vertices(points, Indices{0, 2, 4}, Indices{0, 2}, 0.5), (Indices{0, 4}));
  EXPECT_EQ(refine_vertices(points, Indices{0, 2, 4}, Indices{0}, 0.5), (Indices{0}));
  EXPECT_TRUE(refine_vertices(points, Indices{0, 2, 4}, Indices{}, 0.5).empty());
}

TEST(RefineVertices, VertexStaysWhenItIsAlreadyFarthest) {
  const Polyline points{{0, 0}, {1, 0.5}, {2, 2}, {3, 0.5}, {4, 0}};
  EXPECT_EQ(refine_vertices(points, Indices{0, 2, 4}, Indices{0, 1, 2}, 0.5), (Indices{0, 2, 4}));
}

}  // namespace
}  // namespace cogmap::mapper
