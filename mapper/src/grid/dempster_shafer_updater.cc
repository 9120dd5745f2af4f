// Dempster-Shafer evidence grid, thesis §2.2.2: each cell holds masses m(O), m(E), m(Θ),
// starting (0, 0, 1). A reading's cone is rasterised as for Bayes; region I and II cells get
// Table 2.3's masses, combined with the cell's by Dempster's rule (Eqs. 2.11-2.13) with the
// conflict normalised away. m(Θ) is kept >= kMinUnknownMass so a cell can always be revised.

#include <algorithm>
#include <cstdint>

#include "grid/reading_filter.h"
#include "grid/room_grid.h"
#include "grid/sensor_models.h"
#include "grid/sonar_cone.h"
#include "grid/updaters.h"

namespace cogmap::mapper {
namespace {

constexpr double kMinUnknownMass = 0.001;  ///< mirrors the Bayes clamp [0.001, 0.999]

class DempsterShaferUpdater final : public GridUpdater {
 public:
  DempsterShaferUpdater(const GridOptions& options, const RobotGeometry& robot)
      : options_(options),
        projector_(robot),
        max_range_m_(robot.sonar_max_range_m),
        half_width_rad_(0.5 * robot.sonar_beam_width_rad) {
    reset({0.0, 0.0});
  }

  GridKind kind() const override { return GridKind::kDempsterShafer; }

  void reset(const Point2& center) override {
    const GridGeometry g = room_geometry(center, options_);
    mass_ = Grid<DsMass>(g, DsMass{});
    path_ = Grid<std::uint8_t>(g, 0);
  }

  void mark_robot(const Pose2& robot_pose) override {
    const Point2 p = robot_pose.translation();
    grow_to_hold(p, mass_, path_);
    path_.set(path_.geometry().cell_of(p), 1);
  }

  bool integrate(const Pose2& robot_pose, const SonarReading& reading) override {
    if (!accept_reading(reading, projector_.count(), max_range_m_, rejected_)) return false;
    SonarCone cone;
    cone.beam = projector_.beam(robot_pose, reading.index);
    cone.range_m = reading.range_m;
    cone.half_width_rad = half_width_rad_;
    cone.tolerance_m = std::max(mass_.geometry().cell_size_m(),
                                options_.region_one_range_fraction * reading.range_m);
    cone.has_region_one = reading.echo;
    Point2 lo, hi;
    cone_bounds(cone, lo, hi);
    grow_to_hold(lo, mass_, path_);
    grow_to_hold(hi, mass_, path_);
    for_each_cone_cell(
        mass_.geometry(), cone,
        [&](CellIndex c, double distance_m, double alpha_rad, bool region_one) {
          const double w = table_weight(distance_m, max_range_m_, alpha_rad, half_width_rad_);
          const DsMass evidence =
              region_one ? ds_region_one(w, options_.bayes_max_occupied) : ds_region_two(w);
          DsMass& m = mass_.at(c);
          m = keep_open(dempster_combine(m, evidence).mass, kMinUnknownMass);
        });
    return true;
  }

  HistogramGrid histogram() const override {
    HistogramGrid out(mass_.geometry(), 0.0f);
    const std::size_t n = out.geometry().cell_count();
    for (std::size_t i = 0; i < n; ++i) {
      out.data()[i] = path_.data()[i] != 0 ? kRobotPathValue : ds_to_histogram(mass_.data()[i]);
    }
    return out;
  }

  float histogram_at(CellIndex cell) const override {
    if (path_.get(cell) != 0) return kRobotPathValue;
    return ds_to_histogram(mass_.get(cell));
  }

  const GridGeometry& geometry() const override { return mass_.geometry(); }
  std::size_t grid_bytes() const override { return mass_.bytes() + path_.bytes(); }
  const RejectedReadings& rejected() const override { return rejected_; }

 private:
  GridOptions options_;
  SonarProjector projector_;
  double max_range_m_;     ///< R, Table 2.1
  double half_width_rad_;  ///< β of Table 2.3 (the cone's half-angle)
  Grid<DsMass> mass_;
  Grid<std::uint8_t> path_;
  RejectedReadings rejected_;
};

}  // namespace

std::unique_ptr<GridUpdater> make_dempster_shafer_updater(const GridOptions& options,
                                                          const RobotGeometry& robot) {
  return std::make_unique<DempsterShaferUpdater>(options, robot);
}

}  // namespace cogmap::mapper
