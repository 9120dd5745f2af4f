#include <gtest/gtest.h>

#include <string>

#include "cogmap/mapper/asr/stages.h"

namespace cogmap::mapper {
namespace {

constexpr double kCleanEpsilon = 7.0;  // ε, Table 4.1

HistogramGrid empty_grid(int width, int height) {
  return HistogramGrid(GridGeometry(0.0, 0.0, 100.0, width, height), kHistogramFloor);
}

// Rows top (high y) first: '#' occupied, 'P' path, '.' anything else.
std::string occupancy_picture(const HistogramGrid& grid) {
  std::string out;
  for (int y = grid.height() - 1; y >= 0; --y) {
    for (int x = 0; x < grid.width(); ++x) {
      const float v = grid.get({x, y});
      out += v == kRobotPathValue ? 'P' : (v > kCleanEpsilon ? '#' : '.');
    }
    out += '\n';
  }
  return out;
}

TEST(CleanMap, KeepsTheFaceOfAThickWallAndDropsWhatItHides) {
  HistogramGrid grid = empty_grid(12, 10);
  for (int x = 2; x <= 9; ++x) grid.set({x, 1}, kRobotPathValue);  // the path
  for (int x = 1; x <= 10; ++x) {
    grid.set({x, 5}, 15.0f);  // wall face
    grid.set({x, 6}, 12.0f);  // its second layer
  }
  grid.set({4, 8}, 15.0f);  // a blob behind the wall
  grid.set({5, 8}, 9.0f);
  grid.set({5, 9}, 15.0f);
  const HistogramGrid cleaned = clean_map(grid, kCleanEpsilon, 50.0);
  EXPECT_EQ(occupancy_picture(cleaned),
            "............\n"
            "............\n"
            "............\n"
            "............\n"
            ".##########.\n"
            "............\n"
            "............\n"
            "............\n"
            "..PPPPPPPP..\n"
            "............\n");
  // Removed cells become unexplored; everything else is copied.
  EXPECT_EQ(cleaned.get({4, 6}), 0.0f);
  EXPECT_EQ(cleaned.get({5, 9}), 0.0f);
  EXPECT_EQ(cleaned.get({0, 0}), kHistogramFloor);
  EXPECT_EQ(cleaned.get({3, 1}), kRobotPathValue);
  EXPECT_EQ(cleaned.get({3, 5}), 15.0f);
}

TEST(CleanMap, CellsBeyondMaxRangeAreRemoved) {
  HistogramGrid grid = empty_grid(30, 3);
  grid.set({0, 1}, kRobotPathValue);
  grid.set({8, 2}, 15.0f);   // about 8 cells away
  grid.set({20, 0}, 15.0f);  // about 20 cells away, nothing in between but it is too far
  const HistogramGrid cleaned = clean_map(grid, kCleanEpsilon, 10.0);
  EXPECT_EQ(cleaned.get({8, 2}), 15.0f);
  EXPECT_EQ(cleaned.get({20, 0}), 0.0f);
  // With enough range the far cell is seen (its ray runs along rows 0 and 1).
  EXPECT_EQ(clean_map(grid, kCleanEpsilon, 25.0).get({20, 0}), 15.0f);
}

TEST(CleanMap, RangeIsInclusive) {
  HistogramGrid grid = empty_grid(10, 1);
  grid.set({0, 0}, kRobotPathValue);
  grid.set({5, 0}, 15.0f);
  EXPECT_EQ(clean_map(grid, kCleanEpsilon, 5.0).get({5, 0}), 15.0f);
  EXPECT_EQ(clean_map(grid, kCleanEpsilon, 4.99).get({5, 0}), 0.0f);
}

TEST(CleanMap, WithoutAPathEverythingOccupiedGoes) {
  HistogramGrid grid = empty_grid(5, 5);
  grid.set({2, 2}, 15.0f);
  grid.set({3, 3}, 5.0f);  // below ε: not occupied, untouched
  const HistogramGrid cleaned = clean_map(grid, kCleanEpsilon, 50.0);
  EXPECT_EQ(cleaned.get({2, 2}), 0.0f);
  EXPECT_EQ(cleaned.get({3, 3}), 5.0f);
}

TEST(CleanMap, AnyVisiblePathCellIsEnough) {
  // The near path cell is hidden behind a pillar, the far one is in the open.
  HistogramGrid grid = empty_grid(9, 9);
  grid.set({4, 0}, kRobotPathValue);
  grid.set({0, 8}, kRobotPathValue);
  grid.set({4, 4}, 15.0f);  // pillar between (4,6) and (4,0)
  grid.set({4, 6}, 15.0f);
  const HistogramGrid cleaned = clean_map(grid, kCleanEpsilon, 50.0);
  EXPECT_EQ(cleaned.get({4, 6}), 15.0f);
  EXPECT_EQ(cleaned.get({4, 4}), 15.0f);
}

}  // namespace
}  // namespace cogmap::mapper
