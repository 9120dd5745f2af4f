#include <gtest/gtest.h>

#include "cogmap/mapper/asr/stages.h"

namespace cogmap::mapper {
namespace {

using Indices = std::vector<std::size_t>;

TEST(VertexSimplify, EvenRunKeepsEveryTauApart) {
  const Polyline line{{0, 0}, {1, 0}, {2, 0}, {3, 0}, {4, 0}, {5, 0}, {6, 0}};
  EXPECT_EQ(vertex_simplify_indices(line, 2.0), (Indices{0, 2, 4, 6}));
}

TEST(VertexSimplify, KeepsTheLastVertexEvenWhenClose) {
  const Polyline line{{0, 0}, {1, 0}, {2, 0}, {3, 0}, {4, 0}, {5, 0}};
  EXPECT_EQ(vertex_simplify_indices(line, 2.0), (Indices{0, 2, 4, 5}));
}

TEST(VertexSimplify, DistanceExactlyTauIsKept) {
  // Fig. A.4 removes only d < τ.
  const Polyline line{{0, 0}, {1.5, 0}, {1.5, 1.5}};
  EXPECT_EQ(vertex_simplify_indices(line, 1.5), (Indices{0, 1, 2}));
  EXPECT_EQ(vertex_simplify_indices(line, 1.6), (Indices{0, 2}));
}

TEST(VertexSimplify, ClustersCollapseToTheirFirstVertex) {
  const Polyline line{{0, 0}, {0.5, 0}, {0.2, 0.3}, {3, 0}, {3.1, 0.1}, {6, 0}};
  const Polyline out = vertex_simplify(line, 1.0);
  ASSERT_EQ(out.size(), 3u);
  EXPECT_EQ(out[0], Point2(0, 0));
  EXPECT_EQ(out[1], Point2(3, 0));
  EXPECT_EQ(out[2], Point2(6, 0));
}

TEST(VertexSimplify, DistanceIsToTheLastKeptNotThePrevious) {
  // Steps of 0.6 never reach τ = 1 from their predecessor, but do from the last kept vertex.
  const Polyline line{{0, 0}, {0.6, 0}, {1.2, 0}, {1.8, 0}, {2.4, 0}};
  EXPECT_EQ(vertex_simplify_indices(line, 1.0), (Indices{0, 2, 4}));
}

TEST(VertexSimplify, EmptyAndSingle) {
  EXPECT_TRUE(vertex_simplify_indices({}, 1.0).empty());
  EXPECT_EQ(vertex_simplify_indices({{1, 1}}, 1.0), (Indices{0}));
}

}  // namespace
}  // namespace cogmap::mapper
