#include <gtest/gtest.h>

#include <vector>

#include "cogmap/mapper/grid/bresenham.h"

namespace cogmap::mapper {
namespace {

std::vector<CellIndex> line(CellIndex a, CellIndex b) {
  std::vector<CellIndex> cells;
  for_each_line_cell(a, b, [&](CellIndex c) {
    cells.push_back(c);
    return true;
  });
  return cells;
}

TEST(Bresenham, VisitsEndpointsInOrder) {
  const auto cells = line({0, 0}, {5, 2});
  ASSERT_EQ(cells.size(), 6u);
  EXPECT_EQ(cells.front(), (CellIndex{0, 0}));
  EXPECT_EQ(cells.back(), (CellIndex{5, 2}));
  const std::vector<CellIndex> expected{{0, 0}, {1, 0}, {2, 1}, {3, 1}, {4, 2}, {5, 2}};
  EXPECT_EQ(cells, expected);
}

TEST(Bresenham, HandlesEveryOctantAndAPoint) {
  EXPECT_EQ(line({3, 3}, {3, 3}).size(), 1u);
  EXPECT_EQ(line({0, 0}, {-4, 0}).size(), 5u);
  EXPECT_EQ(line({0, 0}, {0, -7}).size(), 8u);
  EXPECT_EQ(line({0, 0}, {-3, 3}).size(), 4u);
  EXPECT_EQ(line({2, 9}, {-1, 1}).back(), (CellIndex{-1, 1}));
}

TEST(Bresenham, VisitorCanStopEarly) {
  int visited = 0;
  const bool finished = for_each_line_cell({0, 0}, {10, 0}, [&](CellIndex c) {
    ++visited;
    return c.x < 3;
  });
  EXPECT_FALSE(finished);
  EXPECT_EQ(visited, 4);
}

}  // namespace
}  // namespace cogmap::mapper
