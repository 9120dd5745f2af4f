#pragma once
// The machinery Bayes (§2.2.1) and Dempster-Shafer (§2.2.2) share: a per-cell evidence grid
// plus a robot-path mask, a reading's sonar cone rasterised into regions I and II with the
// weight of Tables 2.2/2.3, and the mapping onto the HIMM scale. A Model supplies only what
// differs: the cell type, its prior, how one cell absorbs one region's evidence, and how a cell
// reads on the HIMM scale.
//
//   struct Model {
//     using Cell = ...;
//     static constexpr GridKind kKind = ...;
//     static Cell prior();
//     static void absorb(Cell& cell, double weight, bool region_one, const GridOptions&);
//     static float to_histogram(const Cell& cell);
//   };

#include <algorithm>
#include <cstdint>

#include "grid/reading_filter.h"
#include "grid/room_grid.h"
#include "grid/sensor_models.h"
#include "grid/sonar_cone.h"
#include "grid/sonar_projection.h"

namespace cogmap::mapper {

template <typename Model>
class ConeEvidenceUpdater final : public GridUpdater {
 public:
  using Cell = typename Model::Cell;

  ConeEvidenceUpdater(const GridOptions& options, const RobotGeometry& robot)
      : options_(options),
        projector_(robot),
        max_range_m_(robot.sonar_max_range_m),
        half_width_rad_(0.5 * robot.sonar_beam_width_rad) {
    reset({0.0, 0.0});
  }

  GridKind kind() const override { return Model::kKind; }

  void reset(const Point2& center) override {
    const GridGeometry g = room_geometry(center, options_);
    cells_ = Grid<Cell>(g, Model::prior());
    path_ = Grid<std::uint8_t>(g, 0);
  }

  void mark_robot(const Pose2& robot_pose) override {
    const Point2 p = robot_pose.translation();
    grow_to_hold(p, cells_, path_);
    path_.set(path_.geometry().cell_of(p), 1);
  }

  bool integrate(const Pose2& robot_pose, const SonarReading& reading) override {
    if (!accept_reading(reading, projector_.count(), max_range_m_, rejected_)) return false;
    SonarCone cone;
    cone.beam = projector_.beam(robot_pose, reading.index);
    cone.range_m = reading.range_m;
    cone.half_width_rad = half_width_rad_;
    cone.tolerance_m = std::max(cells_.geometry().cell_size_m(),
                                options_.region_one_range_fraction * reading.range_m);
    cone.has_region_one = reading.echo;  // no echo: the whole cone is region II
    Point2 lo, hi;
    cone_bounds(cone, lo, hi);
    grow_to_hold(lo, cells_, path_);
    grow_to_hold(hi, cells_, path_);
    for_each_cone_cell(cells_.geometry(), cone,
                       [&](CellIndex c, double distance_m, double alpha_rad, bool region_one) {
                         const double w =
                             table_weight(distance_m, max_range_m_, alpha_rad, half_width_rad_);
                         Model::absorb(cells_.at(c), w, region_one, options_);
                       });
    return true;
  }

  HistogramGrid histogram() const override {
    HistogramGrid out(cells_.geometry(), 0.0f);
    const std::size_t n = out.geometry().cell_count();
    for (std::size_t i = 0; i < n; ++i) {
      out.data()[i] =
          path_.data()[i] != 0 ? kRobotPathValue : Model::to_histogram(cells_.data()[i]);
    }
    return out;
  }

  float histogram_at(CellIndex cell) const override {
    if (path_.get(cell) != 0) return kRobotPathValue;
    return Model::to_histogram(cells_.get(cell));
  }

  const GridGeometry& geometry() const override { return cells_.geometry(); }
  std::size_t grid_bytes() const override { return cells_.bytes() + path_.bytes(); }
  const RejectedReadings& rejected() const override { return rejected_; }

 private:
  GridOptions options_;
  SonarProjector projector_;
  double max_range_m_;     ///< R, Table 2.1
  double half_width_rad_;  ///< β of Tables 2.2-2.3 (the cone's half-angle)
  Grid<Cell> cells_;
  Grid<std::uint8_t> path_;
  RejectedReadings rejected_;
};

}  // namespace cogmap::mapper
