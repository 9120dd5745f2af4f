#pragma once
/// Test support: a GridUpdater over a HistogramGrid the test fills by hand, so navigation
/// tests control every cell exactly and do not depend on a sonar model.

#include "cogmap/mapper/grid/grid_updater.h"

namespace cogmap::mapper::nav::testing {

class FakeGridUpdater final : public GridUpdater {
 public:
  /// A `side_m` x `side_m` grid of 10 cm cells with its lower-left corner at (x0, y0), every
  /// cell set to `fill` (0 = unexplored, -1 = seen empty).
  FakeGridUpdater(double x0_m, double y0_m, double side_m, float fill)
      : grid_(GridGeometry(x0_m, y0_m, 100.0, static_cast<int>(side_m * 10.0 + 0.5),
                           static_cast<int>(side_m * 10.0 + 0.5)),
              fill) {}

  /// Sets the cell containing world point (x, y).
  void set(double x_m, double y_m, float value) {
    grid_.set(grid_.geometry().cell_of(Point2(x_m, y_m)), value);
  }
  /// Sets every cell whose centre lies in [x0, x1] x [y0, y1].
  void fill_box(double x0_m, double y0_m, double x1_m, double y1_m, float value) {
    const GridGeometry& g = grid_.geometry();
    for (int y = 0; y < g.height(); ++y) {
      for (int x = 0; x < g.width(); ++x) {
        const Point2 c = g.center_of({x, y});
        if (c.x() >= x0_m && c.x() <= x1_m && c.y() >= y0_m && c.y() <= y1_m) {
          grid_.set({x, y}, value);
        }
      }
    }
  }

  /// Marks unexplored cells within `radius_m` of `p` as seen empty (-1): a crude stand-in for
  /// the sonar sweeping the floor around a moving robot. Returns how many cells changed.
  int reveal(const Point2& p, double radius_m) {
    const GridGeometry& g = grid_.geometry();
    int changed = 0;
    for (int y = 0; y < g.height(); ++y) {
      for (int x = 0; x < g.width(); ++x) {
        if (grid_.get({x, y}) == 0.0f && (g.center_of({x, y}) - p).norm() <= radius_m) {
          grid_.set({x, y}, -1.0f);
          ++changed;
        }
      }
    }
    return changed;
  }

  GridKind kind() const override { return GridKind::kHimm; }
  void reset(const Point2&) override {}
  void mark_robot(const Pose2&) override {}
  bool integrate(const Pose2&, const SonarReading&) override { return false; }
  HistogramGrid histogram() const override { return grid_; }
  float histogram_at(CellIndex cell) const override { return grid_.get(cell); }
  const GridGeometry& geometry() const override { return grid_.geometry(); }
  std::size_t grid_bytes() const override { return grid_.bytes(); }
  const RejectedReadings& rejected() const override { return rejected_; }

 private:
  HistogramGrid grid_;
  RejectedReadings rejected_;
};

}  // namespace cogmap::mapper::nav::testing
