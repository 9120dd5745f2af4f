// Bayes occupancy grid, thesis §2.2.1: each cell holds Pr(H), prior 0.5. A reading's cone
// (half-angle β/2) is rasterised; cells in region I take Table 2.2's region I likelihoods,
// cells in region II its region II ones, and Eq. 2.9 turns them into the new Pr(H). No window w:
// the model already discounts far evidence through (R - r)/R. No-echo readings are all region II.

#include <algorithm>
#include <cstdint>

#include "grid/reading_filter.h"
#include "grid/room_grid.h"
#include "grid/sensor_models.h"
#include "grid/sonar_cone.h"
#include "grid/updaters.h"

namespace cogmap::mapper {
namespace {

class BayesUpdater final : public GridUpdater {
 public:
  BayesUpdater(const GridOptions& options, const RobotGeometry& robot)
      : options_(options),
        projector_(robot),
        max_range_m_(robot.sonar_max_range_m),
        half_width_rad_(0.5 * robot.sonar_beam_width_rad) {
    reset({0.0, 0.0});
  }

  GridKind kind() const override { return GridKind::kBayes; }

  void reset(const Point2& center) override {
    const GridGeometry g = room_geometry(center, options_);
    probability_ = Grid<float>(g, 0.5f);
    path_ = Grid<std::uint8_t>(g, 0);
  }

  void mark_robot(const Pose2& robot_pose) override {
    const Point2 p = robot_pose.translation();
    grow_to_hold(p, probability_, path_);
    path_.set(path_.geometry().cell_of(p), 1);
  }

  bool integrate(const Pose2& robot_pose, const SonarReading& reading) override {
    if (!accept_reading(reading, projector_.count(), max_range_m_, rejected_)) return false;
    SonarCone cone;
    cone.beam = projector_.beam(robot_pose, reading.index);
    cone.range_m = reading.range_m;
    cone.half_width_rad = half_width_rad_;
    cone.tolerance_m = std::max(probability_.geometry().cell_size_m(),
                                options_.region_one_range_fraction * reading.range_m);
    cone.has_region_one = reading.echo;
    Point2 lo, hi;
    cone_bounds(cone, lo, hi);
    grow_to_hold(lo, probability_, path_);
    grow_to_hold(hi, probability_, path_);
    for_each_cone_cell(
        probability_.geometry(), cone,
        [&](CellIndex c, double distance_m, double alpha_rad, bool region_one) {
          const double w = table_weight(distance_m, max_range_m_, alpha_rad, half_width_rad_);
          const SensorLikelihood l =
              region_one ? bayes_region_one(w, options_.bayes_max_occupied) : bayes_region_two(w);
          float& p = probability_.at(c);
          p = static_cast<float>(bayes_posterior(p, l));
        });
    return true;
  }

  HistogramGrid histogram() const override {
    HistogramGrid out(probability_.geometry(), 0.0f);
    const std::size_t n = out.geometry().cell_count();
    for (std::size_t i = 0; i < n; ++i) {
      out.data()[i] =
          path_.data()[i] != 0 ? kRobotPathValue : bayes_to_histogram(probability_.data()[i]);
    }
    return out;
  }

  float histogram_at(CellIndex cell) const override {
    if (path_.get(cell) != 0) return kRobotPathValue;
    return bayes_to_histogram(probability_.get(cell));
  }

  const GridGeometry& geometry() const override { return probability_.geometry(); }
  std::size_t grid_bytes() const override { return probability_.bytes() + path_.bytes(); }
  const RejectedReadings& rejected() const override { return rejected_; }

 private:
  GridOptions options_;
  SonarProjector projector_;
  double max_range_m_;     ///< R, Table 2.1
  double half_width_rad_;  ///< β of Table 2.2 (the cone's half-angle)
  Grid<float> probability_;
  Grid<std::uint8_t> path_;
  RejectedReadings rejected_;
};

}  // namespace

std::unique_ptr<GridUpdater> make_bayes_updater(const GridOptions& options,
                                                const RobotGeometry& robot) {
  return std::make_unique<BayesUpdater>(options, robot);
}

}  // namespace cogmap::mapper
