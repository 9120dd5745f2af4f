// The heading explorer (thesis §1.1.4, Fig. 1.2; ExploreStrategy::kHeading): always head for the
// free direction that promises the most unexplored cells of the current room, keep going the same
// way unless another direction is clearly better, and avoid going back over the recent path.

#include <cmath>
#include <deque>
#include <numbers>
#include <vector>

#include "cogmap/mapper/nav/controller.h"
#include "nav/explore_budget.h"
#include "nav/frontier_explorer.h"
#include "nav/nav_constants.h"
#include "nav/nav_core.h"

namespace cogmap::mapper::nav {
namespace {

class Explorer final : public Controller {
 public:
  explicit Explorer(const ExploreOptions& options)
      : options_(options),
        core_(core_options_of(options)),
        budget_(options.time_budget_s, options.distance_budget_m) {}

  VelocityCommand step(const NavInput& input) override {
    if (!core_.sense(input)) return core_.stop(NavMode::kIdle);
    if (budget_spent_ || budget_.spent(input.frame->time_s, input.frame->odometry.translation())) {
      budget_spent_ = true;  // the only way this explorer ends (never complete)
      return core_.stop(NavMode::kExploreDone);
    }
    if (!started_) {
      heading_rad_ = input.pose.theta_rad;
      started_ = true;
    }
    remember_path(input.pose.translation());
    const bool stuck = core_.check_stuck(input);
    // Commit to a goal direction for a while: re-scoring every cycle flips between nearly
    // equal directions and the robot spins on the spot.
    const double now = input.frame->time_s;
    if (!committed_ || stuck || core_.vfh().blocked(core_.vfh().sector_of(heading_rad_)) ||
        (input.pose.translation() - chosen_at_).norm() >= options_.commit_m ||
        now - chosen_s_ >= options_.commit_s) {
      heading_rad_ = choose_direction(input);
      committed_ = true;
      chosen_at_ = input.pose.translation();
      chosen_s_ = now;
    }
    if (const auto cmd = core_.recover(input, heading_rad_)) return *cmd;
    return core_.drive_toward(input, heading_rad_);
  }

  bool done() const override { return budget_spent_; }
  const NavTrace& trace() const override { return core_.trace(); }

 private:
  void remember_path(const Point2& p) {
    if (!path_.empty() && (path_.back() - p).norm() < options_.path_spacing_m) return;
    path_.push_back(p);
    while (path_.size() > options_.path_points) path_.pop_front();
  }

  /// Unexplored (exactly 0) cells along the ray from the robot in `direction_rad` out to the
  /// horizon, stopping at the first obstacle: space behind a wall is not reachable from here.
  /// Each cell weighs 1 - t/(horizon + cell), so nearer unexplored space (less travel, seen
  /// sooner by the sonar) counts more (§1.1.4). The ray is sampled every cell side rather than
  /// walked cell by cell, so a diagonal counts the same length as an axis-parallel ray.
  double unexplored_along(const NavInput& input, double direction_rad) const {
    const GridGeometry& g = core_.field().geometry();
    const Point2 from = input.pose.translation();
    const Point2 step = g.cell_size_m() * Point2(std::cos(direction_rad), std::sin(direction_rad));
    const int samples = static_cast<int>(options_.horizon_m / g.cell_size_m());
    double count = 0.0;
    for (int i = 1; i <= samples; ++i) {
      const CellIndex c = g.cell_of(from + i * step);
      if (core_.field().occupied(c)) break;
      // Cells beyond the room grid's current extent were never seen: unexplored.
      const float value = input.grid && g.contains(c) ? input.grid->histogram_at(c) : 0.0f;
      if (value > options_.vfh.occupied_above) break;
      if (value == 0.0f) count += 1.0 - static_cast<double>(i) / (samples + 1);
    }
    return count;
  }

  double choose_direction(const NavInput& input) {
    const Vfh& vfh = core_.vfh();
    const int n = vfh.sector_count();
    // Recent path points seen from here, by sector (spread over the neighbours: a 5° sector
    // is narrower than the trail at a metre or two).
    std::vector<int> path_count(n, 0);
    for (const Point2& p : path_) {
      const Point2 d = p - input.pose.translation();
      const double dist = d.norm();
      if (dist < options_.path_ignore_m || dist > options_.horizon_m) continue;
      const int k = vfh.sector_of(std::atan2(d.y(), d.x()));
      for (int i = -1; i <= 1; ++i) ++path_count[(k + i + n) % n];
    }
    const double hysteresis_rad = options_.hysteresis_deg * kPi / 180.0;
    int best = -1;
    double best_score = 0.0, best_turn = 0.0;
    for (int k = 0; k < n; ++k) {
      if (vfh.blocked(k)) continue;
      const double center = vfh.sector_center_rad(k);
      const double turn = std::abs(wrap_angle_rad(center - heading_rad_));
      double score = unexplored_along(input, center) - options_.path_penalty * path_count[k];
      if (turn <= hysteresis_rad) score += options_.hysteresis_bonus;
      // Ties keep the smaller change of direction.
      if (best < 0 || score > best_score || (score == best_score && turn < best_turn)) {
        best = k;
        best_score = score;
        best_turn = turn;
      }
    }
    return best < 0 ? heading_rad_ : vfh.sector_center_rad(best);
  }

  ExploreOptions options_;
  NavCore core_;
  ExploreBudget budget_;
  bool budget_spent_ = false;
  bool started_ = false;
  bool committed_ = false;      // a goal direction has been chosen
  Point2 chosen_at_{0.0, 0.0};  // where, and when, it was chosen
  double chosen_s_ = 0.0;
  double heading_rad_ = 0.0;  // the exploring direction chosen last cycle, world
  std::deque<Point2> path_;   // recent positions, every path_spacing_m
};

}  // namespace

std::unique_ptr<Controller> make_explorer(const ExploreOptions& options) {
  if (options.strategy == ExploreStrategy::kFrontier) return make_frontier_explorer(options);
  if (options.strategy == ExploreStrategy::kEdge) return make_edge_explorer(options);
  return std::make_unique<Explorer>(options);
}

}  // namespace cogmap::mapper::nav
