#include "cogmap/experiments/visible_truth_tracker.h"

#include <gtest/gtest.h>

#include <limits>
#include <vector>

#include "cogmap/experiments/segment_index.h"

namespace cogmap::experiments {
namespace {

using mapper::Point2;
using mapper::Segment;

// A 30 m corridor (walls at y = ±1) with a second wall at y = 2 behind its north wall, and the
// robot walking its middle in 0.1 m steps: 301 positions, every third kept (0.3 m apart, the
// first at least 0.25 m on), 101 in all: one batch of 64 goes to the worker during the walk,
// the other 37 at the end.
std::vector<Segment> corridor() {
  return {{{0, -1}, {30, -1}}, {{0, 1}, {30, 1}}, {{0, 2}, {30, 2}}};
}
std::vector<Point2> walk() {
  std::vector<Point2> path;
  for (int i = 0; i <= 300; ++i) path.push_back({0.1 * i, 0.0});
  return path;
}

TEST(VisibleTruthTracker, SeesTheCorridorWallsNotTheWallBehindThem) {
  const auto truth = corridor();
  const MapMetricsOptions opt;
  VisibleTruthTracker tracker(truth, opt);
  for (const Point2& p : walk()) tracker.add(p);
  const std::vector<Point2> visible = tracker.finish();
  ASSERT_EQ(visible.size(), 1200u);  // both corridor walls, 30 m each in 5 cm pieces
  for (const Point2& p : visible) EXPECT_LT(p.y(), 1.5);
  EXPECT_EQ(visible, visible_truth_samples(truth, walk(), opt));
}

TEST(VisibleTruthTracker, TheLastPositionCountsThoughNearerThanAStep) {
  // Only the last position (0.2 m from the only kept one, under the 0.25 m step) is within
  // the 1 m range of the two samples of a 10 cm wall 1.1 m ahead.
  const std::vector<Segment> truth{{{1.1, 0.05}, {1.1, -0.05}}};
  MapMetricsOptions opt;
  opt.sonar_max_range_m = 1.0;
  VisibleTruthTracker tracker(truth, opt);
  for (const double x : {0.0, 0.1, 0.2}) tracker.add({x, 0.0});
  EXPECT_EQ(tracker.finish().size(), 2u);
  VisibleTruthTracker short_of_it(truth, opt);
  for (const double x : {0.0, 0.05}) short_of_it.add({x, 0.0});
  EXPECT_TRUE(short_of_it.finish().empty());
}

TEST(VisibleTruthTracker, NoPositionsSeeNothingAndAnUnfinishedTrackerStops) {
  const auto truth = corridor();
  VisibleTruthTracker idle(truth, MapMetricsOptions{});
  EXPECT_TRUE(idle.finish().empty());
  // Destroyed mid-run (a run that failed): the worker stops; the test would hang otherwise.
  VisibleTruthTracker abandoned(truth, MapMetricsOptions{});
  for (const Point2& p : walk()) abandoned.add(p);
}

TEST(MarkVisibleSamples, BatchesGiveTheSameAsOnePass) {
  const auto truth = corridor();
  const MapMetricsOptions opt;
  const SegmentIndex index(truth, opt.index_cell_m);
  const std::vector<Point2> poses{{1, 0}, {12, 0}, {25, 0}};
  std::vector<std::uint8_t> once, pieces;
  mark_visible_samples(truth, index, poses, opt, once);
  mark_visible_samples(truth, index, std::span(poses).subspan(2), opt, pieces);
  mark_visible_samples(truth, index, std::span(poses).first(2), opt, pieces);
  EXPECT_EQ(once, pieces);
  // The 5 m range reaches √24 = 4.899 m along a wall 1 m off: from x = 1, 12 and 25 the
  // samples (at 0.025 + 0.05 k) with x in [0, 5.899], [7.101, 16.899] and [20.101, 29.899]:
  // 118 + 196 + 196 on each corridor wall, none on the wall behind.
  const std::vector<Point2> seen = marked_samples(truth, opt.sample_step_m, once);
  EXPECT_EQ(seen.size(), 2u * (118u + 196u + 196u));
  for (const Point2& p : seen) EXPECT_LT(p.y(), 1.5);
}

TEST(MarkVisibleSamples, TheHidingSurfaceKeptChangesNoFlag) {
  const auto truth = corridor();
  const MapMetricsOptions opt;
  const SegmentIndex index(truth, opt.index_cell_m);
  const std::vector<Point2> poses{{1, 0}, {12, 0}, {25, 0}};
  std::vector<std::uint8_t> plain, kept;
  std::vector<std::uint32_t> hidden_by;
  mark_visible_samples(truth, index, poses, opt, plain);
  mark_visible_samples(truth, index, std::span(poses).first(1), opt, kept, &hidden_by);
  mark_visible_samples(truth, index, std::span(poses).subspan(1), opt, kept, &hidden_by);
  EXPECT_EQ(kept, plain);
  ASSERT_EQ(hidden_by.size(), kept.size());
  // The wall at y = 2 (samples 1200..1799) is hidden by the wall at y = 1 (segment 1) from
  // every position in range; a sample no position reached keeps no surface.
  const std::size_t behind_near_x1 = 1200 + 20;  // x = 1.025
  EXPECT_EQ(hidden_by[behind_near_x1], 1u);
  EXPECT_EQ(kept[behind_near_x1], 0);
  const std::size_t out_of_reach = 1200 + 380;  // x = 19.025, beyond 5 m of every position
  EXPECT_EQ(hidden_by[out_of_reach], std::numeric_limits<std::uint32_t>::max());
}

}  // namespace
}  // namespace cogmap::experiments
