#pragma once
/// The explorers' time and distance budgets (ExploreOptions::time_budget_s, distance_budget_m).

#include <optional>

#include "cogmap/mapper/nav/controller.h"

namespace cogmap::mapper::nav {

class ExploreBudget {
 public:
  ExploreBudget(double time_s, double distance_m) : time_s_(time_s), distance_m_(distance_m) {}

  /// Counts this cycle's travel from the odometry (`odometry_m`: the encoders' position, not
  /// the estimate, which jumps when EM turns it); true once either budget (0 = none) is spent.
  bool spent(double now_s, const Point2& odometry_m) {
    if (!start_s_) start_s_ = now_s;
    if (odometry_m.allFinite()) {
      if (last_) travelled_m_ += (odometry_m - *last_).norm();
      last_ = odometry_m;
    }
    return (time_s_ > 0.0 && now_s - *start_s_ >= time_s_) ||
           (distance_m_ > 0.0 && travelled_m_ >= distance_m_);
  }
  /// Travel so far by the odometry, metres.
  double travelled_m() const { return travelled_m_; }

 private:
  double time_s_;
  double distance_m_;
  std::optional<double> start_s_;
  std::optional<Point2> last_;
  double travelled_m_ = 0.0;
};

}  // namespace cogmap::mapper::nav
