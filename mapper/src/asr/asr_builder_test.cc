#include "cogmap/mapper/asr/asr_builder.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "test_rooms.h"

namespace cogmap::mapper {
namespace {

constexpr double kCellM = 0.1;
constexpr double kSampleStepM = 0.05;
constexpr double kTolM = kCellM + 1e-9;

test::RasterRoom square_room() {
  // 5 m x 4 m between wall centre lines, path along the middle.
  return test::rasterise_room(53, 43, {{1, 1}, {51, 1}, {51, 41}, {1, 41}}, {{6, 21}, {46, 21}});
}

test::RasterRoom l_room() {
  // 5 m x 4 m with the top-right 2.5 m x 2 m cut away; the path runs along both arms.
  return test::rasterise_room(53, 43, {{1, 1}, {51, 1}, {51, 21}, {26, 21}, {26, 41}, {1, 41}},
                              {{46, 11}, {13, 11}, {13, 36}});
}

std::vector<double> distances(const std::vector<Point2>& samples, const std::vector<Segment>& to) {
  std::vector<double> out;
  for (const Point2& p : samples) out.push_back(test::distance_to_segments(p, to));
  return out;
}

std::vector<Point2> samples_of(const std::vector<Polyline>& lines) {
  std::vector<Point2> out;
  for (const Polyline& line : lines) {
    const auto s = test::sample_polyline(line, kSampleStepM);
    out.insert(out.end(), s.begin(), s.end());
  }
  return out;
}

std::vector<Point2> samples_of(const std::vector<Segment>& segments) {
  std::vector<Point2> out;
  for (const Segment& s : segments) {
    const auto p = test::sample_polyline({s.a, s.b}, kSampleStepM);
    out.insert(out.end(), p.begin(), p.end());
  }
  return out;
}

double max_of(const std::vector<double>& v) { return *std::max_element(v.begin(), v.end()); }
double median_of(std::vector<double> v) {
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

void expect_walls_match(const test::RasterRoom& room) {
  const AsrTrace trace = build_room_polylines(room.grid, room.path, AsrBuilderOptions{});
  ASSERT_FALSE(trace.fitted.empty());
  EXPECT_TRUE(trace.rejected.empty());
  // Fitted walls lie on the true walls ...
  EXPECT_LE(max_of(distances(samples_of(trace.fitted), room.true_walls)), kTolM);
  // ... and cover every one of them.
  EXPECT_LE(max_of(distances(samples_of(room.true_walls), test::to_segments(trace.fitted))), kTolM);
}

TEST(BuildRoomPolylines, SquareRoomWallsAreRecovered) {
  const test::RasterRoom room = square_room();
  expect_walls_match(room);
  const AsrTrace trace = build_room_polylines(room.grid, room.path, AsrBuilderOptions{});
  // One closed chain, four corners (+ the two ends of the chain near the start corner).
  ASSERT_EQ(trace.fitted.size(), 1u);
  EXPECT_LE(trace.fitted[0].size(), 6u);
  EXPECT_GE(trace.fitted[0].size(), 5u);
}

TEST(BuildRoomPolylines, LShapedRoomWallsAreRecovered) { expect_walls_match(l_room()); }

TEST(BuildRoomPolylines, TraceHoldsEveryStage) {
  const test::RasterRoom room = square_room();
  const AsrTrace trace = build_room_polylines(room.grid, room.path, AsrBuilderOptions{});
  // The raw stage is the input grid, every cell of it (one cell, as before, was 0 in both).
  ASSERT_EQ(trace.raw.width(), room.grid.width());
  ASSERT_EQ(trace.raw.height(), room.grid.height());
  const std::size_t cells = static_cast<std::size_t>(room.grid.width()) * room.grid.height();
  EXPECT_TRUE(std::equal(trace.raw.data(), trace.raw.data() + cells, room.grid.data()));
  EXPECT_EQ(trace.cleaned.width(), room.grid.width());
  EXPECT_EQ(trace.robot_path.size(), room.path.size());
  ASSERT_EQ(trace.extracted.size(), 1u);
  // Every wall cell is extracted: the room's perimeter in cells.
  EXPECT_EQ(trace.extracted[0].size(), static_cast<std::size_t>(2 * 50 + 2 * 40));
  ASSERT_EQ(trace.vertex_simplified.size(), 1u);
  ASSERT_EQ(trace.douglas_peucker.size(), 1u);
  EXPECT_LT(trace.vertex_simplified[0].size(), trace.extracted[0].size());
  EXPECT_LT(trace.douglas_peucker[0].size(), trace.vertex_simplified[0].size());
  // Extracted points are cell centres in metres.
  EXPECT_NEAR(trace.extracted[0][0].x(), 0.15, 1e-12);
  EXPECT_NEAR(trace.extracted[0][0].y(), 0.15, 1e-12);
}

TEST(BuildRoomPolylines, NoisyRoomsStayNearTheTrueWalls) {
  for (const std::uint32_t seed : {1u, 2u, 3u}) {
    for (const bool l_shaped : {false, true}) {
      test::RasterRoom room = l_shaped ? l_room() : square_room();
      test::add_noise(room, seed, 40);
      const AsrTrace trace = build_room_polylines(room.grid, room.path, AsrBuilderOptions{});
      ASSERT_FALSE(trace.fitted.empty());
      const auto on_walls = distances(samples_of(trace.fitted), room.true_walls);
      const auto coverage = distances(samples_of(room.true_walls), test::to_segments(trace.fitted));
      EXPECT_LE(median_of(on_walls), kTolM) << "seed " << seed << " L " << l_shaped;
      EXPECT_LE(median_of(coverage), kTolM) << "seed " << seed << " L " << l_shaped;
    }
  }
}

TEST(BuildRoomPolylines, SpecksAreDroppedAndHiddenNoiseCleaned) {
  test::RasterRoom room = square_room();
  room.grid.set({25, 30}, 15.0f);  // a lone speck inside the room: extracted, then dropped
  room.grid.set({25, 42}, 15.0f);  // behind the top wall: cleaned away
  const AsrTrace trace = build_room_polylines(room.grid, room.path, AsrBuilderOptions{});
  EXPECT_EQ(trace.cleaned.get({25, 42}), 0.0f);
  EXPECT_EQ(trace.cleaned.get({25, 30}), 15.0f);
  EXPECT_EQ(trace.extracted.size(), 2u);
  EXPECT_EQ(trace.fitted.size(), 1u);
}

TEST(BuildRoomPolylines, EmptyGridGivesNothing) {
  const HistogramGrid grid(GridGeometry(0.0, 0.0, 100.0, 10, 10), 0.0f);
  const AsrTrace trace = build_room_polylines(grid, {}, AsrBuilderOptions{});
  EXPECT_TRUE(trace.extracted.empty());
  EXPECT_TRUE(trace.fitted.empty());
}

}  // namespace
}  // namespace cogmap::mapper
