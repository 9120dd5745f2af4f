#include "cogmap/experiments/error_breakdown.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <numbers>

#include "cogmap/experiments/run_metrics.h"
#include "cogmap/test_support/angles.h"

namespace cogmap::experiments {
namespace {

using mapper::Point2;
using mapper::Pose2;
using mapper::Segment;

constexpr double kEps = 1e-12;

// The room's local frame is placed in the world by this pose: turned 90° and moved to (1, 2),
// so local (x, y) lands at world (1 − y, 2 + x) and the local line y = 0 is the world line x = 1.
const Pose2 kRoomToWorld{1.0, 2.0, kPi / 2.0};
const std::vector<Segment> kTruth{{{1.0, -10.0}, {1.0, 20.0}}};  // local y = 0, world x = 1

// A 10 x 10 grid of 10 cm cells from the local origin: cell (x, y) has its centre at
// ((x + 0.5) / 10, (y + 0.5) / 10), so its distance to the true wall is (y + 0.5) / 10.
mapper::HistogramGrid empty_grid() {
  return mapper::HistogramGrid(mapper::GridGeometry(0.0, 0.0, 100.0, 10, 10), 0.0f);
}

// Raw grid: 5 occupied cells in row 0 (0.05 m off the wall), 3 in row 1 (0.15 m), 1 in
// row 3 (0.35 m). Cells at ε exactly (7) or on the robot path are not occupied (H > ε).
mapper::HistogramGrid raw_grid() {
  mapper::HistogramGrid g = empty_grid();
  for (int x = 0; x < 5; ++x) g.set({x, 0}, 10.0f);
  for (int x = 0; x < 3; ++x) g.set({x, 1}, 8.0f);
  g.set({0, 3}, 15.0f);
  g.set({6, 6}, 7.0f);
  g.set({7, 7}, mapper::kRobotPathValue);
  return g;
}

TEST(ErrorBreakdown, OccupiedCellsAreTheBuildersAndLandInTheWorld) {
  const auto cells = occupied_cells_world(raw_grid(), 7.0, kRoomToWorld);
  ASSERT_EQ(cells.size(), 9u);
  // Row-major from the bottom: cell (0, 0) centre local (0.05, 0.05) -> world (0.95, 2.05).
  EXPECT_NEAR(cells[0].x(), 0.95, kEps);
  EXPECT_NEAR(cells[0].y(), 2.05, kEps);
  EXPECT_NEAR(cells[8].x(), 0.65, kEps);  // cell (0, 3): local y 0.35
}

TEST(ErrorBreakdown, StagesMeasuredAgainstAKnownWall) {
  mapper::AsrTrace trace;
  trace.raw = raw_grid();
  trace.cleaned = empty_grid();
  for (int x = 0; x < 5; ++x) trace.cleaned.set({x, 0}, 10.0f);  // only the row on the wall
  trace.extracted = {{{0.5, 0.02}, {1.0, 0.1}}, {{2.0, 0.3}}};
  trace.fitted = {{{0.0, 0.1}, {1.0, 0.1}}};  // 1 m at 0.1 m off: 20 samples of 5 cm

  ErrorBreakdownBuilder builder(kTruth, 7.0);
  builder.add_room(0, kRoomToWorld, trace);
  const ErrorBreakdown b = builder.finish({});

  // Raw: sorted 0.05 x5, 0.15 x3, 0.35. Median: the 5th of 9 = 0.05. p90: position
  // 0.9 * 8 = 7.2, between 0.15 and 0.35: 0.15 + 0.2 * 0.2 = 0.19.
  EXPECT_EQ(b.grid.count, 9u);
  EXPECT_NEAR(*b.grid.median_m, 0.05, kEps);
  EXPECT_NEAR(*b.grid.p90_m, 0.19, kEps);
  EXPECT_EQ(b.cleaned.count, 5u);
  EXPECT_NEAR(*b.cleaned.median_m, 0.05, kEps);
  EXPECT_NEAR(*b.cleaned.p90_m, 0.05, kEps);
  // Points: 0.02, 0.1, 0.3. Median 0.1; p90 at position 1.8: 0.1 + 0.8 * 0.2 = 0.26.
  EXPECT_EQ(b.points.count, 3u);
  EXPECT_NEAR(*b.points.median_m, 0.1, kEps);
  EXPECT_NEAR(*b.points.p90_m, 0.26, kEps);
  EXPECT_EQ(b.lines.count, 20u);
  EXPECT_NEAR(*b.lines.median_m, 0.1, kEps);
  EXPECT_NEAR(*b.lines.p90_m, 0.1, kEps);
  EXPECT_EQ(b.heading.rooms, 0u);
  EXPECT_FALSE(b.heading.entry_error_deg_mean_abs.has_value());
}

// A room re-placed after it was added (the end-of-run relaxation) is measured where it ends:
// moved 0.1 m away from the wall (world −x), its rows 0.05, 0.15 and 0.35 m off become 0.15,
// 0.25 and 0.45 m off; the other room's points stay.
TEST(ErrorBreakdown, AMovedRoomIsMeasuredWhereItEnds) {
  mapper::AsrTrace trace;
  trace.raw = raw_grid();
  trace.cleaned = empty_grid();
  ErrorBreakdownBuilder builder(kTruth, 7.0);
  builder.add_room(3, kRoomToWorld, trace);
  builder.add_room(4, kRoomToWorld, trace);
  const std::vector<std::pair<int, Pose2>> moves = {{4, Pose2{-0.1, 0.0, 0.0}},
                                                    {7, Pose2{5.0, 0.0, 0.0}}};  // no room 7
  builder.move_rooms(moves);
  const ErrorBreakdown b = builder.finish({});
  ASSERT_EQ(b.grid.count, 18u);
  // Room 3: 0.05 x5, 0.15 x3, 0.35; room 4: 0.15 x5, 0.25 x3, 0.45. Sorted: 0.05 x5, 0.15 x8
  // (5-12), 0.25 x3 (13-15), 0.35, 0.45: median (positions 8 and 9) 0.15.
  EXPECT_NEAR(*b.grid.median_m, 0.15, kEps);
  // p90 at position 0.9 * 17 = 15.3: 0.25 + 0.3 * 0.1 = 0.28.
  EXPECT_NEAR(*b.grid.p90_m, 0.28, kEps);
}

TEST(ErrorBreakdown, RoomsAccumulateAndAnEmptyStageIsUndefined) {
  mapper::AsrTrace trace;
  trace.raw = raw_grid();
  trace.cleaned = empty_grid();
  ErrorBreakdownBuilder builder(kTruth, 7.0);
  builder.add_room(0, kRoomToWorld, trace);
  builder.add_room(1, kRoomToWorld, trace);
  const ErrorBreakdown b = builder.finish({});
  EXPECT_EQ(b.grid.count, 18u);
  // Sorted 0.05 x10 (positions 0-9), 0.15 x6 (10-15), 0.35 x2 (16, 17): median at 8.5: 0.05;
  // p90 at 0.9 * 17 = 15.3, between 0.15 and 0.35: 0.15 + 0.3 * 0.2 = 0.21.
  EXPECT_NEAR(*b.grid.median_m, 0.05, kEps);
  EXPECT_NEAR(*b.grid.p90_m, 0.21, kEps);
  EXPECT_EQ(b.cleaned.count, 0u);
  EXPECT_FALSE(b.cleaned.median_m.has_value());
  EXPECT_FALSE(b.points.p90_m.has_value());
}

TEST(ErrorBreakdown, ErrorPiecesAreTheMetricSamplesPieces) {
  const SegmentIndex truth(std::vector<Segment>{{{-1.0, 0.0}, {2.0, 0.0}}});
  const std::vector<Segment> map{{{0.0, 0.2}, {0.1, 0.2}}, {{0.0, 0.0}, {0.0, 0.0}}};
  const auto pieces = error_pieces(map, truth, 0.05);
  ASSERT_EQ(pieces.size(), 2u);  // the zero-length segment has no sample
  EXPECT_NEAR(pieces[0].piece.a.x(), 0.0, kEps);
  EXPECT_NEAR(pieces[0].piece.b.x(), 0.05, kEps);
  EXPECT_NEAR(pieces[1].piece.a.x(), 0.05, kEps);
  EXPECT_NEAR(pieces[1].piece.b.x(), 0.1, kEps);
  EXPECT_NEAR(pieces[1].piece.b.y(), 0.2, kEps);
  EXPECT_NEAR(pieces[0].error_m, 0.2, kEps);
  EXPECT_NEAR(pieces[1].error_m, 0.2, kEps);
}

TrajectoryRow row(double t_s, double estimate_deg, std::optional<double> truth_deg) {
  TrajectoryRow r;
  r.t_s = t_s;
  r.estimate = {0.0, 0.0, rad(estimate_deg)};
  r.odometry = {0.0, 0.0, rad(estimate_deg + 30.0)};  // not what the map was drawn with
  if (truth_deg) r.truth = Pose2{0.0, 0.0, rad(*truth_deg)};
  return r;
}

// Rows as the runner records them: the estimate after the frame. Room A ends at a boundary at
// t = 3 (that row already carries A's correction of 2°); room B is closed by the end of the
// run after its last row (its 1° correction is in no row).
TEST(ErrorBreakdown, HeadingAtEntryAndExitOfEachRoom) {
  const std::vector<TrajectoryRow> rows{
      row(0.0, 50.0, 0.0),          // before room A: ignored
      row(1.0, 10.0, 15.0),         // A entry: 10 + 2 − 15 = −3°
      row(2.0, 0.0, std::nullopt),  // no truth: skipped
      row(3.0, 22.0, 20.0),         // A exit, corrected already: 22 − 20 = +2°
      row(4.0, 179.0, -177.0),      // B entry: 179 + 1 − (−177) = 357°, wrapped −3°
      row(5.0, -176.0, -179.0),     // B exit: −176 + 1 − (−179) = +4°
      row(9.0, 0.0, std::nullopt),  // room C has no truth at all: not counted
  };
  const RoomSpan a{1.0, 3.0, rad(2.0), true};
  const RoomSpan b{4.0, 5.0, rad(1.0), false};
  const RoomSpan c{9.0, 9.0, 0.0, false};

  const auto ea = room_heading_error(rows, a);
  ASSERT_TRUE(ea.has_value());
  EXPECT_NEAR(ea->entry_deg, -3.0, 1e-9);
  EXPECT_NEAR(ea->exit_deg, 2.0, 1e-9);
  const auto eb = room_heading_error(rows, b);
  ASSERT_TRUE(eb.has_value());
  EXPECT_NEAR(eb->entry_deg, -3.0, 1e-9);
  EXPECT_NEAR(eb->exit_deg, 4.0, 1e-9);
  EXPECT_FALSE(room_heading_error(rows, c).has_value());

  const std::vector<RoomSpan> rooms{a, b, c};
  const HeadingBreakdown h = heading_breakdown(rows, rooms);
  EXPECT_EQ(h.rooms, 2u);
  EXPECT_NEAR(*h.entry_error_deg_mean_abs, (3.0 + 3.0) / 2.0, 1e-9);
  EXPECT_NEAR(*h.exit_error_deg_mean_abs, (2.0 + 4.0) / 2.0, 1e-9);
  EXPECT_NEAR(*h.exit_error_deg_max_abs, 4.0, 1e-9);  // room B as it was left
  // Drifts: A 2 − (−3) = 5°; B 4 − (−3) = 7°.
  EXPECT_NEAR(*h.within_room_drift_deg_mean_abs, (5.0 + 7.0) / 2.0, 1e-9);
  EXPECT_NEAR(*h.within_room_drift_deg_max_abs, 7.0, 1e-9);
}

// A room whose last row with truth comes before its boundary frame: that row is still in the
// room's own frame, so the correction is added even though the room ended at a boundary.
TEST(ErrorBreakdown, LastRowWithTruthBeforeTheBoundaryIsUncorrected) {
  const std::vector<TrajectoryRow> rows{row(0.0, 0.0, 0.0), row(1.0, 1.0, 0.0),
                                        row(2.0, 9.0, std::nullopt)};
  const auto e = room_heading_error(rows, RoomSpan{0.0, 2.0, rad(3.0), true});
  ASSERT_TRUE(e.has_value());
  EXPECT_NEAR(e->entry_deg, 3.0, 1e-9);
  EXPECT_NEAR(e->exit_deg, 4.0, 1e-9);
}

TEST(ErrorBreakdown, DriftIsWrappedAcrossTheCut) {
  // Entry −170°, exit +170°: the heading turned 20° the short way, not 340°.
  const std::vector<TrajectoryRow> rows{row(0.0, -170.0, 0.0), row(1.0, 170.0, 0.0)};
  const std::vector<RoomSpan> rooms{{0.0, 1.0, 0.0, false}};
  const HeadingBreakdown h = heading_breakdown(rows, rooms);
  EXPECT_NEAR(*h.within_room_drift_deg_max_abs, 20.0, 1e-9);
}

TEST(ErrorBreakdown, JsonBlockOnlyWithTruth) {
  RunMetrics m;
  EXPECT_EQ(metrics_json_text(m).find("error_breakdown"), std::string::npos);
  ErrorBreakdown b;
  b.grid = {0.25, 0.5, 12};
  b.lines = {0.04, 0.125, 80};
  b.heading.rooms = 3;
  b.heading.within_room_drift_deg_max_abs = 1.5;
  b.heading.exit_error_deg_max_abs = 14.5;
  m.error_breakdown = b;
  const auto j = nlohmann::json::parse(metrics_json_text(m))["error_breakdown"];
  EXPECT_EQ(j["grid"]["median_m"].get<double>(), 0.25);
  EXPECT_EQ(j["grid"]["p90_m"].get<double>(), 0.5);
  EXPECT_EQ(j["grid"]["count"].get<int>(), 12);
  EXPECT_TRUE(j["cleaned"]["median_m"].is_null());
  EXPECT_EQ(j["points"]["count"].get<int>(), 0);
  EXPECT_EQ(j["lines"]["p90_m"].get<double>(), 0.125);
  EXPECT_EQ(j["heading"]["rooms"].get<int>(), 3);
  EXPECT_TRUE(j["heading"]["entry_error_deg_mean_abs"].is_null());
  EXPECT_EQ(j["heading"]["within_room_drift_deg_max_abs"].get<double>(), 1.5);
  EXPECT_EQ(j["heading"]["exit_error_deg_max_abs"].get<double>(), 14.5);
}

}  // namespace
}  // namespace cogmap::experiments
