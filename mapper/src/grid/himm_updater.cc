// HIMM exactly as the thesis prints it in Fig. A.2: only readings whose hit lies within the
// window w update the grid; the hit cell gets hit_increment and then each cell of its 3x3 block
// (itself included) neighbour_increment, capped at 15; the Bresenham line from the robot centre
// up to, not including, the hit loses miss_decrement, floored at 0. Robot path cells are kept in
// a separate mask (plain HIMM has no path marker), shown as kRobotPathValue by histogram().

#include <cstdint>

#include "grid/histogram_ops.h"
#include "grid/reading_filter.h"
#include "grid/room_grid.h"
#include "grid/sonar_projection.h"
#include "grid/updaters.h"

namespace cogmap::mapper {
namespace {

class HimmUpdater final : public GridUpdater {
 public:
  HimmUpdater(const GridOptions& options, const RobotGeometry& robot)
      : options_(options), projector_(robot), max_range_m_(robot.sonar_max_range_m) {
    reset({0.0, 0.0});
  }

  GridKind kind() const override { return GridKind::kHimm; }

  void reset(const Point2& center) override {
    const GridGeometry g = room_geometry(center, options_);
    cells_ = HistogramGrid(g, 0.0f);
    path_ = Grid<std::uint8_t>(g, 0);
  }

  void mark_robot(const Pose2& robot_pose) override {
    const Point2 p = robot_pose.translation();
    grow_to_hold(p, cells_, path_);
    path_.set(path_.geometry().cell_of(p), 1);
  }

  bool integrate(const Pose2& robot_pose, const SonarReading& reading) override {
    if (!accept_reading(reading, projector_.count(), max_range_m_, rejected_)) return false;
    const SonarBeam beam = projector_.beam(robot_pose, reading.index);
    const Point2 centre = robot_pose.translation();
    const Point2 end = beam.at(reading.range_m);
    // Fig. A.2: If (dist(x_i, y_i, x_0, y_0) < w) Then Update; farther readings are dropped.
    if ((end - centre).squaredNorm() >= options_.window_m * options_.window_m) return true;
    const auto [from, to] = hold_pair(centre, end, cells_, path_);
    const auto decrement = static_cast<float>(options_.miss_decrement);
    if (reading.echo) {
      increment_hit(cells_, to, static_cast<float>(options_.hit_increment),
                    static_cast<float>(options_.neighbour_increment), kLimits);
      decrement_line(cells_, from, to, /*include_to=*/false, decrement, kLimits);
    } else {
      // No echo: nothing was hit, so the whole beam, its end included, is evidence of free space.
      decrement_line(cells_, from, to, /*include_to=*/true, decrement, kLimits);
    }
    return true;
  }

  HistogramGrid histogram() const override {
    HistogramGrid out = cells_;
    const std::size_t n = out.geometry().cell_count();
    for (std::size_t i = 0; i < n; ++i) {
      if (path_.data()[i] != 0) out.data()[i] = kRobotPathValue;
    }
    return out;
  }

  float histogram_at(CellIndex cell) const override {
    return path_.get(cell) != 0 ? kRobotPathValue : cells_.get(cell);
  }

  const GridGeometry& geometry() const override { return cells_.geometry(); }
  std::size_t grid_bytes() const override { return cells_.bytes() + path_.bytes(); }
  const RejectedReadings& rejected() const override { return rejected_; }

 private:
  static constexpr HistogramLimits kLimits{0.0f, kHistogramMax, false};  ///< 0..15, §2.2.3

  GridOptions options_;
  SonarProjector projector_;
  double max_range_m_;
  HistogramGrid cells_;
  Grid<std::uint8_t> path_;
  RejectedReadings rejected_;
};

}  // namespace

std::unique_ptr<GridUpdater> make_himm_updater(const GridOptions& options,
                                               const RobotGeometry& robot) {
  return std::make_unique<HimmUpdater>(options, robot);
}

}  // namespace cogmap::mapper
