// MHIMM, thesis Fig. A.3 and §3.1.4. Three changes to HIMM: (1) the robot-centre cell holds
// kRobotPathValue (-100) and no update ever writes it; (2) cells may drop to -3 so explored
// empty space differs from unexplored 0; (3) a reading whose hit lies beyond the window w
// (every no-echo reading too) lowers the cells along its beam from the robot centre up to the
// window edge, edge cell included.

#include <algorithm>
#include <span>

#include "grid/histogram_ops.h"
#include "grid/reading_filter.h"
#include "grid/room_grid.h"
#include "grid/sonar_projection.h"
#include "grid/updaters.h"

namespace cogmap::mapper {
namespace {

class MhimmUpdater final : public GridUpdater {
 public:
  MhimmUpdater(const GridOptions& options, const RobotGeometry& robot)
      : options_(options),
        projector_(robot),
        max_range_m_(robot.sonar_max_range_m),
        window2_m2_(options.window_m * options.window_m),
        hit_increment_(static_cast<float>(options.hit_increment)),
        neighbour_increment_(static_cast<float>(options.neighbour_increment)),
        miss_decrement_(static_cast<float>(options.miss_decrement)) {
    reset({0.0, 0.0});
  }

  GridKind kind() const override { return GridKind::kMhimm; }

  void reset(const Point2& center) override {
    cells_ = HistogramGrid(room_geometry(center, options_), 0.0f);
  }

  void mark_robot(const Pose2& robot_pose) override {
    const Point2 p = robot_pose.translation();
    grow_to_hold(p, cells_);
    cells_.at(cells_.geometry().cell_of(p)) = kRobotPathValue;
  }

  bool integrate(const Pose2& robot_pose, const SonarReading& reading) override {
    if (!accept_reading(reading, projector_.count(), max_range_m_, rejected_)) return false;
    const SonarBeam beam = projector_.beam(robot_pose, reading.index);
    const Point2 centre = robot_pose.translation();
    const Point2 hit = beam.at(reading.range_m);
    if (reading.echo && (hit - centre).squaredNorm() < window2_m2_) {
      grow_to_hold(centre, cells_);
      grow_to_hold(hit, cells_);
      const GridGeometry& g = cells_.geometry();
      const CellIndex to = g.cell_of(hit);
      increment_hit(cells_, to, hit_increment_, neighbour_increment_, kLimits);
      decrement_line(cells_, g.cell_of(centre), to, /*include_to=*/false, miss_decrement_, kLimits);
      return true;
    }
    // Beyond w, or no echo: clear up to where the beam leaves the window (Fig. A.3's Else
    // branch), or up to the range itself if the beam ends inside the window without an echo.
    double exit_m = window_exit_m(beam, centre, options_.window_m);
    if (exit_m < 0.0) return true;  // transducer outside the window: nothing of the beam inside
    if (!reading.echo && options_.no_echo_clear_m >= 0.0) {
      exit_m = std::min(exit_m, options_.no_echo_clear_m);
      if (exit_m <= 0.0) return true;
    }
    const Point2 end = beam.at(std::min(exit_m, reading.range_m));
    grow_to_hold(centre, cells_);
    grow_to_hold(end, cells_);
    const GridGeometry& g = cells_.geometry();
    decrement_line(cells_, g.cell_of(centre), g.cell_of(end), /*include_to=*/true, miss_decrement_,
                   kLimits);
    return true;
  }

  HistogramGrid histogram() const override { return cells_; }
  float histogram_at(CellIndex cell) const override { return cells_.get(cell); }
  std::span<const float> histogram_row(int y) const override {
    return {cells_.row(y), static_cast<std::size_t>(cells_.width())};
  }
  const GridGeometry& geometry() const override { return cells_.geometry(); }
  std::size_t grid_bytes() const override { return cells_.bytes(); }
  const RejectedReadings& rejected() const override { return rejected_; }

 private:
  static constexpr HistogramLimits kLimits{kHistogramFloor, kHistogramMax, true};  ///< §3.1.4

  GridOptions options_;
  SonarProjector projector_;
  double max_range_m_;
  double window2_m2_;
  float hit_increment_;
  float neighbour_increment_;
  float miss_decrement_;
  HistogramGrid cells_;
  RejectedReadings rejected_;
};

}  // namespace

std::unique_ptr<GridUpdater> make_mhimm_updater(const GridOptions& options,
                                                const RobotGeometry& robot) {
  return std::make_unique<MhimmUpdater>(options, robot);
}

}  // namespace cogmap::mapper
