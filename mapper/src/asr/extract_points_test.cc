#include <gtest/gtest.h>

#include <cmath>

#include "cogmap/mapper/asr/stages.h"

namespace cogmap::mapper {
namespace {

constexpr double kEpsilon = 7.0;
constexpr double kGamma = 4.0;
using Chain = std::vector<CellIndex>;

HistogramGrid grid_with(int width, int height, const Chain& cells) {
  HistogramGrid grid(GridGeometry(0.0, 0.0, 100.0, width, height), kHistogramFloor);
  for (const CellIndex& c : cells) grid.set(c, kHistogramMax);
  return grid;
}

Chain row(int y, int x0, int x1) {
  Chain out;
  for (int x = x0; x0 <= x1 ? x <= x1 : x >= x1; x += x0 <= x1 ? 1 : -1) out.push_back({x, y});
  return out;
}

TEST(ExtractPoints, TwoWallsFartherThanGammaApartGiveTwoOrderedPolylines) {
  Chain cells = row(2, 1, 8);
  const Chain upper = row(10, 1, 8);
  cells.insert(cells.end(), upper.begin(), upper.end());
  const auto lines = extract_points(grid_with(12, 12, cells), kEpsilon, kGamma);
  ASSERT_EQ(lines.size(), 2u);
  // The raster scan starts at (1,2) and follows the wall; the next polyline starts at the
  // remaining cell nearest to where the first ended, and runs back along its wall.
  EXPECT_EQ(lines[0], row(2, 1, 8));
  EXPECT_EQ(lines[1], row(10, 8, 1));
}

TEST(ExtractPoints, GapOfExactlyGammaDoesNotBreak) {
  Chain cells = row(2, 1, 4);
  const Chain right = row(2, 8, 11);  // (4,2) -> (8,2) is exactly γ
  cells.insert(cells.end(), right.begin(), right.end());
  const auto lines = extract_points(grid_with(14, 5, cells), kEpsilon, kGamma);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0], cells);
  const auto broken = extract_points(grid_with(14, 5, cells), kEpsilon, 3.9);
  ASSERT_EQ(broken.size(), 2u);
}

TEST(ExtractPoints, RectangleIsFollowedAroundInUnitSteps) {
  Chain ring;
  for (int x = 1; x <= 7; ++x) ring.push_back({x, 1}), ring.push_back({x, 5});
  for (int y = 2; y <= 4; ++y) ring.push_back({1, y}), ring.push_back({7, y});
  const auto lines = extract_points(grid_with(9, 7, ring), kEpsilon, kGamma);
  ASSERT_EQ(lines.size(), 1u);
  ASSERT_EQ(lines[0].size(), ring.size());
  EXPECT_EQ(lines[0].front(), (CellIndex{1, 1}));
  for (std::size_t i = 1; i < lines[0].size(); ++i) {
    const int dx = lines[0][i].x - lines[0][i - 1].x, dy = lines[0][i].y - lines[0][i - 1].y;
    EXPECT_EQ(dx * dx + dy * dy, 1) << "step " << i;
  }
}

TEST(ExtractPoints, TiesFollowTheDirectionOfTravel) {
  // At (4,2) both (5,2) ahead and (4,3) beside are at distance 1; the wall is followed first
  // and the stray cell, √5 from the wall's end, is picked up last.
  Chain cells = row(2, 1, 6);
  cells.push_back({4, 3});
  const auto lines = extract_points(grid_with(10, 6, cells), kEpsilon, kGamma);
  ASSERT_EQ(lines.size(), 1u);
  const Chain expected{{1, 2}, {2, 2}, {3, 2}, {4, 2}, {5, 2}, {6, 2}, {4, 3}};
  EXPECT_EQ(lines[0], expected);
}

TEST(ExtractPoints, FarCellsAreFoundBeyondTheRingSearch) {
  // (45,1) is 45 cells from (0,0), far outside the rings; (48,2) is √10 from (45,1).
  const auto lines = extract_points(grid_with(60, 3, {{0, 0}, {48, 2}, {45, 1}}), kEpsilon, kGamma);
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0], (Chain{{0, 0}}));
  EXPECT_EQ(lines[1], (Chain{{45, 1}, {48, 2}}));
}

TEST(ExtractPoints, TheWindowComesFirst) {
  // From (0,0) the ring search meets (16,16) in its last ring (d² = 512) and takes it, although
  // (17,0) just outside the 33 × 33 window is nearer (d² = 289): the documented rule
  // (docs/algorithms.md, Stage 2), not Fig. 3.9's literal "next closest". γ = 30 keeps the cells
  // in one polyline, so the order shows which was taken first.
  const auto lines = extract_points(grid_with(20, 20, {{0, 0}, {16, 16}, {17, 0}}), kEpsilon, 30.0);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0], (Chain{{0, 0}, {16, 16}, {17, 0}}));
  // Nothing in the window: the nearest anywhere.
  const auto far = extract_points(grid_with(40, 3, {{0, 0}, {30, 2}, {20, 0}}), kEpsilon, 30.0);
  ASSERT_EQ(far.size(), 1u);
  EXPECT_EQ(far[0], (Chain{{0, 0}, {20, 0}, {30, 2}}));
}

TEST(ExtractPoints, OnlyCellsAboveEpsilonAndEmptyGrid) {
  HistogramGrid grid(GridGeometry(0.0, 0.0, 100.0, 5, 5), 0.0f);
  grid.set({1, 1}, 7.0f);  // not > ε
  grid.set({2, 2}, kRobotPathValue);
  EXPECT_TRUE(extract_points(grid, kEpsilon, kGamma).empty());
  grid.set({3, 3}, 7.5f);
  const auto lines = extract_points(grid, kEpsilon, kGamma);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0], (Chain{{3, 3}}));
}

}  // namespace
}  // namespace cogmap::mapper
