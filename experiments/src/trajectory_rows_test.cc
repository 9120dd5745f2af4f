#include "cogmap/experiments/trajectory_rows.h"

#include <gtest/gtest.h>

#include <vector>

#include "cogmap/experiments/metrics.h"
#include "cogmap/experiments/nav_metrics.h"
#include "cogmap/experiments/run_outputs.h"

namespace cogmap::experiments {
namespace {

using mapper::Pose2;

TrajectoryRow indexed_row_at(std::size_t i) {
  TrajectoryRow r;
  r.t_s = 0.1 * static_cast<double>(i);
  r.truth = Pose2{static_cast<double>(i), 0.0, 0.0};
  r.odometry = Pose2{static_cast<double>(i), 1.0, 0.0};
  r.estimate = Pose2{static_cast<double>(i), 0.5, 0.0};
  return r;
}

// Every row once, in the order added, across chunk boundaries (one row short of, at and past
// them), whether the full chunks go to the spill file or stay in memory; the log's size is the
// view's.
TEST(TrajectoryLog, ReadsEveryRowInOrderAcrossChunks) {
  const std::size_t chunk = TrajectoryLog::kRowsPerChunk;
  for (const bool spill : {true, false}) {
    for (const std::size_t n :
         {std::size_t{0}, std::size_t{1}, chunk - 1, chunk, chunk + 1, 3 * chunk + 7}) {
      TrajectoryLog log(spill);
      for (std::size_t i = 0; i < n; ++i) log.push_back(indexed_row_at(i));
      EXPECT_EQ(log.spilled_rows(), spill ? (n / chunk) * chunk : 0u) << "rows " << n;
      const TrajectoryView view = log.view();
      EXPECT_EQ(log.size(), n);
      EXPECT_EQ(view.size(), n);
      EXPECT_EQ(view.empty(), n == 0);
      std::size_t i = 0;
      for (const TrajectoryRow& r : view) {
        ASSERT_LT(i, n);
        EXPECT_EQ(r.t_s, indexed_row_at(i).t_s);
        EXPECT_EQ(r.truth->x_m, static_cast<double>(i));
        EXPECT_EQ(r.estimate.y_m, 0.5);
        ++i;
      }
      EXPECT_EQ(i, n) << "rows " << n << (spill ? " spilled" : " in memory");
    }
  }
}

// Two readers at once (the metrics thread reads the true path while the main thread reads the
// rest): each has its own buffer, so one moving on to the next spilled chunk leaves the row the
// other is on as it was.
TEST(TrajectoryLog, ReadersDoNotDisturbEachOther) {
  const std::size_t chunk = TrajectoryLog::kRowsPerChunk;
  TrajectoryLog log;
  for (std::size_t i = 0; i < 3 * chunk; ++i) log.push_back(indexed_row_at(i));
  ASSERT_EQ(log.spilled_rows(), 3 * chunk);
  const TrajectoryView view = log.view();
  auto a = view.begin();
  for (std::size_t i = 0; i < chunk - 1; ++i) ++a;  // the first chunk's last row
  auto b = a;
  ++b;  // the second chunk's first row, read into b's own buffer
  ++b;
  EXPECT_EQ(a->t_s, indexed_row_at(chunk - 1).t_s);
  EXPECT_EQ(b->t_s, indexed_row_at(chunk + 1).t_s);
  ++a;
  EXPECT_EQ(a->t_s, indexed_row_at(chunk).t_s);
  EXPECT_EQ(b->t_s, indexed_row_at(chunk + 1).t_s);
}

// The metrics read a spilled log exactly as they read one vector of the same rows.
TEST(TrajectoryLog, MetricsReadASpilledLogAsTheSameRowsInMemory) {
  std::vector<TrajectoryRow> all;
  TrajectoryLog log;
  for (std::size_t i = 0; i < 2 * TrajectoryLog::kRowsPerChunk + 5; ++i) {
    TrajectoryRow r = indexed_row_at(i);
    r.odometry.y_m = (i % 3 == 0) ? 1.0 : 1.25;  // a path that is not a straight line
    r.estimate.theta_rad = 0.001 * static_cast<double>(i % 17);
    all.push_back(r);
    log.push_back(r);
  }
  ASSERT_GT(log.spilled_rows(), 0u);
  EXPECT_EQ(odometry_distance_m(log.view()), odometry_distance_m(all));
  EXPECT_EQ(trajectory_csv(log.view()), trajectory_csv(all));
  const auto spilled = evaluate_trajectory(log.view());
  const auto memory = evaluate_trajectory(all);
  ASSERT_TRUE(spilled && memory);
  EXPECT_EQ(spilled->ate_rmse_odometry_m, memory->ate_rmse_odometry_m);
  EXPECT_EQ(spilled->ate_rmse_corrected_m, memory->ate_rmse_corrected_m);
  EXPECT_EQ(spilled->heading_error_final_corrected_deg, memory->heading_error_final_corrected_deg);
  EXPECT_EQ(spilled->frames, all.size());
}

// A view made of pieces skips empty ones and reads as one sequence; the metrics read it as
// they read one vector of the same rows.
TEST(TrajectoryView, PiecesReadAsOneSequence) {
  std::vector<TrajectoryRow> all;
  for (std::size_t i = 0; i < 7; ++i) all.push_back(indexed_row_at(i));
  const std::span<const TrajectoryRow> rows(all);
  const std::vector<std::span<const TrajectoryRow>> pieces{rows.subspan(0, 3), rows.subspan(3, 0),
                                                           rows.subspan(3, 1), rows.subspan(4, 3)};
  const TrajectoryView split(pieces);
  EXPECT_EQ(split.size(), 7u);
  std::vector<double> times;
  for (const TrajectoryRow& r : split) times.push_back(r.t_s);
  ASSERT_EQ(times.size(), 7u);
  for (std::size_t i = 0; i < 7; ++i) EXPECT_EQ(times[i], indexed_row_at(i).t_s);
  // 6 steps of 1 m between odometry positions.
  EXPECT_DOUBLE_EQ(odometry_distance_m(split), 6.0);
  EXPECT_EQ(trajectory_csv(split), trajectory_csv(all));
  const auto a = evaluate_trajectory(split);
  ASSERT_TRUE(a.has_value());
  EXPECT_DOUBLE_EQ(a->ate_rmse_odometry_m, 1.0);
  EXPECT_DOUBLE_EQ(a->ate_rmse_corrected_m, 0.5);
  EXPECT_EQ(a->frames, 7u);
}

TEST(TrajectoryView, EmptyViewHasNoRows) {
  const TrajectoryView none;
  EXPECT_TRUE(none.empty());
  EXPECT_EQ(none.begin(), none.end());
  EXPECT_EQ(odometry_distance_m(none), 0.0);
}

}  // namespace
}  // namespace cogmap::experiments
