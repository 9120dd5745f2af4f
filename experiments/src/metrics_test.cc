#include "cogmap/experiments/metrics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <optional>

#include "cogmap/experiments/nav_metrics.h"
#include "cogmap/experiments/segment_index.h"

namespace cogmap::experiments {
namespace {

using mapper::Point2;
using mapper::Pose2;
using mapper::Segment;

// A closed 4 x 3 m box of single surfaces (inner faces only), and a path through its middle.
std::vector<Segment> box() {
  return {{{0, 0}, {4, 0}}, {{4, 0}, {4, 3}}, {{4, 3}, {0, 3}}, {{0, 3}, {0, 0}}};
}
std::vector<Point2> path_in_box() { return {{1.0, 1.5}, {2.0, 1.5}, {3.0, 1.5}}; }

TEST(Quantile, MedianAndP90Interpolate) {
  std::vector<double> v{4, 1, 3, 2};
  EXPECT_DOUBLE_EQ(quantile(v, 0.5), 2.5);
  std::vector<double> w{0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10};
  EXPECT_DOUBLE_EQ(quantile(w, 0.9), 9.0);
  std::vector<double> one{0.7};
  EXPECT_DOUBLE_EQ(quantile(one, 0.9), 0.7);
}

TEST(SampleSegments, EqualPiecesAtMidpoints) {
  const std::vector<Segment> s{{{0, 0}, {1, 0}}};
  const auto samples = sample_segments(s, 0.05);
  ASSERT_EQ(samples.size(), 20u);
  EXPECT_NEAR(samples.front().point.x(), 0.025, 1e-12);
  EXPECT_NEAR(samples.back().point.x(), 0.975, 1e-12);
  EXPECT_NEAR(samples[3].weight_m, 0.05, 1e-12);
}

TEST(PathSubsampler, KeepsFirstEveryStepAndLast) {
  // 0.03 m steps along x: with a 0.1 m step every fourth pose is kept (0.12 m from the last
  // kept one), and the last pose closes the path.
  const double step_m = 0.1;
  std::vector<Point2> path;
  for (int i = 0; i <= 10; ++i) path.emplace_back(0.03 * i, 0.0);
  PathSubsampler sampler(step_m);
  for (const Point2& p : path) sampler.add(p);
  const std::vector<Point2> kept = sampler.path();
  ASSERT_EQ(kept.size(), 4u);
  EXPECT_DOUBLE_EQ(kept[0].x(), 0.0);
  EXPECT_DOUBLE_EQ(kept[1].x(), 0.12);
  EXPECT_DOUBLE_EQ(kept[2].x(), 0.24);
  EXPECT_DOUBLE_EQ(kept[3].x(), 0.30);  // the last pose, 0.06 m after the last kept one
  EXPECT_EQ(subsample_path(path, step_m), kept);
  // Subsampling twice with the same step changes nothing (the runner relies on it).
  EXPECT_EQ(subsample_path(kept, step_m), kept);
  // The last pose is not appended twice when it was kept anyway, nor for a repeated pose.
  PathSubsampler still(step_m);
  still.add({1.0, 1.0});
  still.add({1.0, 1.0});
  EXPECT_EQ(still.path().size(), 1u);
  EXPECT_TRUE(PathSubsampler(step_m).path().empty());
}

// 40 short segments on a spiral about the origin, in every direction.
std::vector<Segment> spiral_of_segments() {
  std::vector<Segment> segs;
  for (int i = 0; i < 40; ++i) {
    const double a = i * 0.7;
    segs.push_back({{std::cos(a) * i * 0.3, std::sin(a) * i * 0.2},
                    {std::cos(a) * i * 0.3 + 0.5, std::sin(a) * i * 0.2 - 0.4}});
  }
  return segs;
}

TEST(SegmentIndex, NearestDistanceMatchesBruteForce) {
  const std::vector<Segment> segs = spiral_of_segments();
  const SegmentIndex index(segs, 0.5);
  for (int k = 0; k < 200; ++k) {
    const Point2 p(std::sin(k * 1.3) * 15.0, std::cos(k * 0.9) * 12.0 + k * 0.05);
    double brute = INFINITY;
    for (const auto& s : segs) brute = std::min(brute, mapper::distance_to_segment_m(p, s));
    EXPECT_DOUBLE_EQ(index.nearest_distance_m(p), brute) << k;
  }
  EXPECT_DOUBLE_EQ(index.nearest_distance_m({100.0, 0.0}), [&] {
    double b = INFINITY;
    for (const auto& s : segs) b = std::min(b, mapper::distance_to_segment_m({100.0, 0.0}, s));
    return b;
  }());
}

TEST(SegmentIndex, AnyWithinMatchesBruteForce) {
  const std::vector<Segment> segs = spiral_of_segments();
  const SegmentIndex index(segs, 0.5);
  int near = 0, far = 0;
  for (int k = 0; k < 400; ++k) {
    const Point2 p(std::sin(k * 1.3) * 8.0, std::cos(k * 0.9) * 6.0);
    double brute = INFINITY;
    for (const auto& s : segs) brute = std::min(brute, mapper::distance_to_segment_m(p, s));
    for (const double r : {0.05, 0.42, 1.3}) {
      EXPECT_EQ(index.any_within_m(p, r), brute <= r) << k << " r " << r;
      (brute <= r ? near : far)++;
    }
  }
  EXPECT_GT(near, 200);  // both answers were exercised (305 and 895 of 1200)
  EXPECT_GT(far, 600);
  // Exactly at the distance counts; outside the grid, and empty or negative, do not.
  const std::vector<Segment> wall{{{0, 0}, {0, 2}}};
  const SegmentIndex one(wall, 0.5);
  EXPECT_TRUE(one.any_within_m({0.5, 1.0}, 0.5));
  EXPECT_FALSE(one.any_within_m({0.5, 1.0}, 0.49));
  EXPECT_TRUE(one.any_within_m({-3.0, 3.0}, 3.2));  // (0, 2) is sqrt(10) = 3.16 m away
  EXPECT_FALSE(one.any_within_m({-3.0, 3.0}, 3.1));
  EXPECT_FALSE(one.any_within_m({0.5, 1.0}, -1.0));
  EXPECT_FALSE(SegmentIndex({}, 0.5).any_within_m({0.0, 0.0}, 10.0));
}

TEST(SegmentIndex, NearestPointWithinLiesOnTheNearestSegment) {
  const std::vector<Segment> segs = spiral_of_segments();
  const SegmentIndex index(segs, 0.5);
  int found = 0;
  for (int k = 0; k < 400; ++k) {
    const Point2 p(std::sin(k * 1.3) * 8.0, std::cos(k * 0.9) * 6.0);
    double brute = INFINITY;
    for (const auto& s : segs) brute = std::min(brute, mapper::distance_to_segment_m(p, s));
    const std::optional<Point2> q = index.nearest_point_within(p, 0.6);
    ASSERT_EQ(q.has_value(), brute <= 0.6) << k;
    if (!q) continue;
    ++found;
    EXPECT_NEAR((*q - p).norm(), brute, 1e-12) << k;
    double on = INFINITY;  // the point lies on some segment
    for (const auto& s : segs) on = std::min(on, mapper::distance_to_segment_m(*q, s));
    EXPECT_LT(on, 1e-12) << k;
  }
  EXPECT_GT(found, 50);  // both answers were exercised
  // The foot of the perpendicular, or the nearer end.
  const SegmentIndex one(std::vector<Segment>{{{0, 0}, {0, 2}}}, 0.5);
  EXPECT_TRUE(one.nearest_point_within({0.3, 1.5}, 0.3)->isApprox(Point2(0.0, 1.5)));
  EXPECT_TRUE(one.nearest_point_within({0.1, 2.2}, 0.3)->isApprox(Point2(0.0, 2.0)));
  EXPECT_FALSE(one.nearest_point_within({0.3, 1.5}, 0.29).has_value());
  EXPECT_FALSE(SegmentIndex({}, 0.5).nearest_point_within({0.0, 0.0}, 10.0).has_value());
}

TEST(SegmentIndex, FirstBlockerIsTheNearestOnTheWalkAndCrossesAgreesWithIt) {
  const std::vector<Segment> segs{{{1, -1}, {1, 1}}, {{3, -1}, {3, 1}}};
  const SegmentIndex index(segs, 0.5);
  EXPECT_EQ(index.first_blocker({0, 0}, {5, 0}, SegmentIndex::kNone), 0u);
  EXPECT_EQ(index.first_blocker({5, 0}, {0, 0}, SegmentIndex::kNone), 1u);  // walks from a
  EXPECT_EQ(index.first_blocker({0, 0}, {5, 0}, 0), 1u);
  EXPECT_EQ(index.first_blocker({0, 2}, {5, 2}, SegmentIndex::kNone), SegmentIndex::kNone);
  EXPECT_TRUE(index.crosses({0, 0}, {5, 0}, 1));
  EXPECT_FALSE(index.crosses({0, 0}, {2, 0}, 1));
}

TEST(SegmentIndex, BlockedHonoursExclusion) {
  const std::vector<Segment> segs{{{1, -1}, {1, 1}}, {{3, -1}, {3, 1}}};
  const SegmentIndex index(segs, 0.5);
  EXPECT_TRUE(index.blocked({0, 0}, {2, 0}, SegmentIndex::kNone));
  EXPECT_FALSE(index.blocked({0, 0}, {2, 0}, 0));
  EXPECT_FALSE(index.blocked({0, 2}, {5, 2}, SegmentIndex::kNone));
  EXPECT_TRUE(index.blocked({5, 0.5}, {0, 0.5}, 0));  // the other wall still blocks
}

TEST(MapMetrics, MapEqualToTruthIsPerfect) {
  const auto truth = box();
  const MapMetricsOptions opt;
  const auto visible = visible_truth_samples(truth, path_in_box(), opt);
  EXPECT_EQ(visible.size(), 280u);  // 14 m of surface in 5 cm pieces, all in view
  const MapAccuracy a = evaluate_map(truth, truth, visible, opt);
  EXPECT_DOUBLE_EQ(*a.wall_error_median_m, 0.0);
  EXPECT_DOUBLE_EQ(*a.wall_error_p90_m, 0.0);
  EXPECT_DOUBLE_EQ(*a.wall_coverage, 1.0);
  EXPECT_DOUBLE_EQ(*a.spurious_fraction, 0.0);
  EXPECT_NEAR(a.map_length_m, 14.0, 1e-9);
  EXPECT_EQ(a.segment_count, 4u);
}

TEST(MapMetrics, OffsetMapHasThatError) {
  // Two long parallel walls 4 m apart; the map shifts each 0.1 m into the corridor, so every
  // sample sits exactly 0.1 m from its true wall (and far from the other).
  const std::vector<Segment> truth{{{0, 0}, {10, 0}}, {{0, 4}, {10, 4}}};
  const std::vector<Segment> map{{{0, 0.1}, {10, 0.1}}, {{0, 3.9}, {10, 3.9}}};
  const MapMetricsOptions opt;
  const std::vector<Point2> path{{0, 2}, {10, 2}};
  const auto visible = visible_truth_samples(truth, path, opt);
  const MapAccuracy a = evaluate_map(map, truth, visible, opt);
  EXPECT_NEAR(*a.wall_error_median_m, 0.1, 1e-12);
  EXPECT_NEAR(*a.wall_error_p90_m, 0.1, 1e-12);
  EXPECT_DOUBLE_EQ(*a.spurious_fraction, 0.0);
  EXPECT_DOUBLE_EQ(*a.wall_coverage, 1.0);  // 0.1 m is within the 0.2 m coverage radius
  // Shifted by 0.25 m: still not spurious (< 0.3 m) but no longer covering.
  const std::vector<Segment> far{{{0, 0.25}, {10, 0.25}}, {{0, 3.75}, {10, 3.75}}};
  const MapAccuracy b = evaluate_map(far, truth, visible, opt);
  EXPECT_NEAR(*b.wall_error_median_m, 0.25, 1e-12);
  EXPECT_DOUBLE_EQ(*b.wall_coverage, 0.0);
  EXPECT_DOUBLE_EQ(*b.spurious_fraction, 0.0);
  // The same scores from an index of the truth built once, with cells of another size.
  const SegmentIndex truth_index(truth, 0.37);
  const MapAccuracy c = evaluate_map(map, truth_index, visible, opt);
  EXPECT_NEAR(*c.wall_error_median_m, 0.1, 1e-12);
  EXPECT_NEAR(*c.wall_error_p90_m, 0.1, 1e-12);
  EXPECT_DOUBLE_EQ(*c.spurious_fraction, 0.0);
  EXPECT_DOUBLE_EQ(*c.wall_coverage, 1.0);
  const MapAccuracy d = evaluate_map(far, truth_index, visible, opt);
  EXPECT_NEAR(*d.wall_error_median_m, 0.25, 1e-12);
  EXPECT_DOUBLE_EQ(*d.wall_coverage, 0.0);
}

TEST(MapMetrics, SpuriousSegmentOfKnownLength) {
  auto map = box();                         // 14 m of correct walls
  map.push_back({{1.0, 1.0}, {2.0, 1.0}});  // 1 m phantom wall, >= 1 m from every surface
  map.push_back({{1.0, 1.2}, {3.0, 1.2}});  // and 2 m more, 1.2 m away: 3 m spurious in all
  const auto truth = box();
  const MapMetricsOptions opt;
  const auto visible = visible_truth_samples(truth, path_in_box(), opt);
  const MapAccuracy a = evaluate_map(map, truth, visible, opt);
  EXPECT_NEAR(*a.spurious_fraction, 3.0 / 17.0, 1e-12);
  EXPECT_NEAR(a.map_length_m, 17.0, 1e-9);
  EXPECT_DOUBLE_EQ(*a.wall_coverage, 1.0);
}

TEST(MapMetrics, OccludedSurfaceIsExcludedFromCoverage) {
  // The robot drives along y = 1 below a 4 m wall at y = 2 (both faces as one segment). A
  // second 4 m wall at y = 3 hides behind it: its samples are within range but never in view.
  const std::vector<Segment> truth{{{0, 2}, {4, 2}}, {{0, 3}, {4, 3}}};
  const std::vector<Point2> path{{0.5, 1}, {2, 1}, {3.5, 1}};
  const MapMetricsOptions opt;
  const auto visible = visible_truth_samples(truth, path, opt);
  ASSERT_EQ(visible.size(), 80u);
  for (const Point2& p : visible) EXPECT_DOUBLE_EQ(p.y(), 2.0);  // all on the front wall
  // A map of just the front wall covers everything that could be seen.
  const std::vector<Segment> map{{{0, 2}, {4, 2}}};
  EXPECT_DOUBLE_EQ(*evaluate_map(map, truth, visible, opt).wall_coverage, 1.0);
  // Half of the front wall covers half.
  const std::vector<Segment> half{{{0, 2}, {2, 2}}};
  EXPECT_NEAR(*evaluate_map(half, truth, visible, opt).wall_coverage, 0.5 + 4.0 / 80.0, 1e-12);
}

TEST(MapMetrics, OutOfRangeSurfaceIsExcluded) {
  const std::vector<Segment> truth{{{0, 0}, {1, 0}}, {{0, 10}, {1, 10}}};
  const std::vector<Point2> path{{0.5, 1.0}};
  MapMetricsOptions opt;
  opt.sonar_max_range_m = 5.0;
  EXPECT_EQ(visible_truth_samples(truth, path, opt).size(), 20u);
}

TEST(MapMetrics, EmptyMapHasUndefinedErrorAndZeroCoverage) {
  const auto truth = box();
  const MapMetricsOptions opt;
  const auto visible = visible_truth_samples(truth, path_in_box(), opt);
  const MapAccuracy a = evaluate_map({}, truth, visible, opt);
  EXPECT_FALSE(a.wall_error_median_m.has_value());
  EXPECT_FALSE(a.spurious_fraction.has_value());
  EXPECT_DOUBLE_EQ(*a.wall_coverage, 0.0);
}

TEST(TrajectoryMetrics, AteAndFinalHeading) {
  std::vector<TrajectoryRow> rows;
  for (int i = 0; i < 4; ++i) {
    TrajectoryRow r;
    r.t_s = i * 0.1;
    r.truth = Pose2{double(i), 0.0, 0.0};
    r.odometry = Pose2{double(i), 3.0, 0.1};                           // always 3 m off
    r.estimate = Pose2{double(i) + (i % 2 ? 1.0 : -1.0), 0.0, -0.02};  // always 1 m off
    rows.push_back(r);
  }
  rows.back().truth->theta_rad = std::numbers::pi - 0.05;
  rows.back().odometry.theta_rad = -std::numbers::pi + 0.05;  // 0.1 rad across the wrap
  const auto m = evaluate_trajectory(rows);
  ASSERT_TRUE(m.has_value());
  EXPECT_DOUBLE_EQ(m->ate_rmse_odometry_m, 3.0);
  EXPECT_DOUBLE_EQ(m->ate_rmse_corrected_m, 1.0);
  EXPECT_NEAR(m->heading_error_final_odometry_deg, 0.1 * 180.0 / std::numbers::pi, 1e-9);
  EXPECT_NEAR(m->heading_error_final_corrected_deg,
              180.0 - (0.05 - 0.02) * 180.0 / std::numbers::pi, 1e-9);
  EXPECT_EQ(m->frames, 4u);
  EXPECT_FALSE(m->heading_error_final_closed_deg.has_value());
  // Once the last room is closed its correction turns the estimate; a heading given in any
  // number of turns (−3π + 0.02 ≡ π + 0.02) is 0.07 rad from the truth's π − 0.05.
  const auto closed = evaluate_trajectory(rows, -std::numbers::pi + 0.02 - 2.0 * std::numbers::pi);
  ASSERT_TRUE(closed.has_value());
  ASSERT_TRUE(closed->heading_error_final_closed_deg.has_value());
  EXPECT_NEAR(*closed->heading_error_final_closed_deg, 0.07 * 180.0 / std::numbers::pi, 1e-9);
  EXPECT_DOUBLE_EQ(closed->heading_error_final_corrected_deg, m->heading_error_final_corrected_deg);
}

// A path drawn 1 % too large and turned 2° about its start is all scale and rotation: the fit
// finds both, and nothing is left over.
TEST(TrajectoryMetrics, SimilarityFitFindsAScaledTurnedPathExactly) {
  const double scale = 1.01, turn = 2.0 * std::numbers::pi / 180.0;
  const Point2 start(3.0, -2.0);
  const Point2 corners[] = {{0, 0}, {10, 0}, {10, 6}, {0, 6}, {0, 1}};
  std::vector<TrajectoryRow> rows;
  for (int leg = 0; leg + 1 < 5; ++leg) {
    for (int k = 0; k < 10; ++k) {
      const Point2 off = corners[leg] + (corners[leg + 1] - corners[leg]) * (k / 10.0);
      const Point2 drawn(scale * (std::cos(turn) * off.x() - std::sin(turn) * off.y()),
                         scale * (std::sin(turn) * off.x() + std::cos(turn) * off.y()));
      TrajectoryRow r;
      r.truth = Pose2{start.x() + off.x(), start.y() + off.y(), 0.0};
      r.estimate = Pose2{start.x() + drawn.x(), start.y() + drawn.y(), 0.0};
      r.odometry = *r.truth;  // exact: scale 1, no turn
      rows.push_back(r);
    }
  }
  const auto m = evaluate_trajectory(rows);
  ASSERT_TRUE(m.has_value());
  EXPECT_NEAR(m->similarity_corrected.scale, 1.01, 1e-12);
  EXPECT_NEAR(m->similarity_corrected.rotation_deg, 2.0, 1e-10);
  EXPECT_NEAR(m->similarity_corrected.residual_rmse_m, 0.0, 1e-6);
  EXPECT_GT(m->ate_rmse_corrected_m, 0.1);  // the ATE itself is not small
  EXPECT_DOUBLE_EQ(m->similarity_odometry.scale, 1.0);
  EXPECT_DOUBLE_EQ(m->similarity_odometry.rotation_deg, 0.0);
  EXPECT_DOUBLE_EQ(m->similarity_odometry.residual_rmse_m, 0.0);
}

// An offset no scale or turn about the start explains stays in the residual: frames at ±1 m
// along x, each drawn 0.1 m to the left, fit a = 1 and leave 0.1 m on two of three frames.
TEST(TrajectoryMetrics, SimilarityFitLeavesAShiftInTheResidual) {
  std::vector<TrajectoryRow> rows(3);
  const double xs[] = {0.0, 1.0, -1.0}, ys[] = {0.0, 0.1, 0.1};
  for (int i = 0; i < 3; ++i) {
    rows[i].truth = Pose2{5.0 + xs[i], 7.0, 0.0};
    rows[i].estimate = Pose2{5.0 + xs[i], 7.0 + ys[i], 0.0};
    rows[i].odometry = *rows[i].truth;
  }
  const auto m = evaluate_trajectory(rows);
  ASSERT_TRUE(m.has_value());
  EXPECT_NEAR(m->similarity_corrected.scale, 1.0, 1e-12);
  EXPECT_NEAR(m->similarity_corrected.rotation_deg, 0.0, 1e-12);
  EXPECT_NEAR(m->similarity_corrected.residual_rmse_m, std::sqrt(0.02 / 3.0), 1e-12);
}

// A robot that never leaves its start has nothing to scale or turn: the fit is the identity and
// the residual is the ATE.
TEST(TrajectoryMetrics, SimilarityFitOfAPathThatNeverMovesIsTheIdentity) {
  std::vector<TrajectoryRow> rows(4);
  for (int i = 0; i < 4; ++i) {
    rows[i].truth = Pose2{1.0, 1.0, 0.0};
    rows[i].estimate = Pose2{1.0, 1.0 + (i == 0 ? 0.0 : 0.2), 0.0};
    rows[i].odometry = *rows[i].truth;
  }
  const auto m = evaluate_trajectory(rows);
  ASSERT_TRUE(m.has_value());
  EXPECT_DOUBLE_EQ(m->similarity_corrected.scale, 1.0);
  EXPECT_DOUBLE_EQ(m->similarity_corrected.rotation_deg, 0.0);
  EXPECT_NEAR(m->similarity_corrected.residual_rmse_m, m->ate_rmse_corrected_m, 1e-12);
}

TEST(TrajectoryMetrics, NoTruthNoMetrics) {
  std::vector<TrajectoryRow> rows(3);
  EXPECT_FALSE(evaluate_trajectory(rows).has_value());
}

TEST(MemoryMetrics, SumsPeakAndRatio) {
  const std::vector<RoomSize> rooms{{0, 2, 10, 80, 1000, 40000}, {1, 1, 4, 40, 500, 60000}};
  const MemoryMetrics m = memory_metrics(rooms);
  EXPECT_EQ(m.polyline_bytes, 1500u);
  EXPECT_EQ(m.grid_bytes, 60000u);
  EXPECT_EQ(m.grid_bytes_total, 100000u);
  EXPECT_EQ(m.vertex_count, 14u);
  EXPECT_EQ(m.extracted_vertex_count, 120u);
  EXPECT_EQ(m.extracted_vertex_bytes, 960u);
  EXPECT_DOUBLE_EQ(*m.compression_ratio, 0.015);
}

}  // namespace
}  // namespace cogmap::experiments

namespace cogmap::experiments {
namespace {

TEST(NavTurning, SumsAbsoluteTurnsPerModeAcrossTheWrap) {
  NavMetrics nav;
  const double deg = std::numbers::pi / 180.0;
  add_mode_interval(nav, "drive", 10.0 * deg, 0.1);
  add_mode_interval(nav, "drive", -4.0 * deg, 0.1);
  // +179° to -179° is a 2° turn, not 358°.
  add_mode_interval(nav, "door_cross", -358.0 * deg, 0.1);
  add_mode_interval(nav, "look", 0.0, 0.5);
  EXPECT_NEAR(nav.turn_deg, 16.0, 1e-9);
  EXPECT_NEAR(nav.turn_deg_by_mode.at("drive"), 14.0, 1e-9);
  EXPECT_NEAR(nav.turn_deg_by_mode.at("door_cross"), 2.0, 1e-9);
  EXPECT_DOUBLE_EQ(nav.turn_deg_by_mode.at("look"), 0.0);
  EXPECT_NEAR(nav.time_s_by_mode.at("drive"), 0.2, 1e-12);
  EXPECT_NEAR(nav.time_s_by_mode.at("look"), 0.5, 1e-12);
  EXPECT_EQ(nav.time_s_by_mode.count("turn"), 0u);
}

TEST(NavTurning, DriftByModeIsOdometryMinusTrueTurnSignedAcrossTheWrap) {
  NavMetrics nav;
  const double deg = std::numbers::pi / 180.0;
  add_mode_drift(nav, "drive", 10.0 * deg, 9.5 * deg);   // odometry saw 0.5° too much
  add_mode_drift(nav, "drive", -4.0 * deg, -4.2 * deg);  // ...and 0.2° too much the other way
  // Across ±180°: odometry -358° (a 2° turn), truth 1.9°: 0.1° too much.
  add_mode_drift(nav, "door_cross", -358.0 * deg, 1.9 * deg);
  add_mode_drift(nav, "look", 0.0, -0.3 * deg);  // standing, the body slipped 0.3° clockwise
  EXPECT_NEAR(nav.heading_drift_deg_by_mode.at("drive"), 0.7, 1e-9);
  EXPECT_NEAR(nav.heading_drift_deg_by_mode.at("door_cross"), 0.1, 1e-9);
  EXPECT_NEAR(nav.heading_drift_deg_by_mode.at("look"), 0.3, 1e-9);
  EXPECT_EQ(nav.heading_drift_deg_by_mode.count("turn"), 0u);
}

}  // namespace
}  // namespace cogmap::experiments
