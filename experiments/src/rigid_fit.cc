#include "cogmap/experiments/rigid_fit.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace cogmap::experiments {

using mapper::Point2;
using mapper::Pose2;

namespace {

/// The rigid transform taking `from[i]` nearest to `to[i]` in the least-squares sense.
Pose2 procrustes(const std::vector<Point2>& from, const std::vector<Point2>& to) {
  Point2 from_mean = Point2::Zero(), to_mean = Point2::Zero();
  for (std::size_t i = 0; i < from.size(); ++i) {
    from_mean += from[i];
    to_mean += to[i];
  }
  from_mean /= static_cast<double>(from.size());
  to_mean /= static_cast<double>(to.size());
  double dot = 0.0, cross = 0.0;  // Σ a·b and Σ a×b of the centred pairs
  for (std::size_t i = 0; i < from.size(); ++i) {
    const Point2 a = from[i] - from_mean, b = to[i] - to_mean;
    dot += a.dot(b);
    cross += mapper::cross(a, b);
  }
  const double theta = std::atan2(cross, dot);
  const double c = std::cos(theta), s = std::sin(theta);
  const Point2 rotated{c * from_mean.x() - s * from_mean.y(),
                       s * from_mean.x() + c * from_mean.y()};
  const Point2 t = to_mean - rotated;
  return {t.x(), t.y(), theta};
}

}  // namespace

RigidFit fit_rigid(std::span<const Point2> points, const SegmentIndex& truth,
                   const RigidFitOptions& options) {
  RigidFit fit;
  if (points.empty() || truth.empty()) return fit;
  std::vector<Point2> from, to;
  Pose2 total;  // identity
  for (const double gate_m : options.gates_m) {
    for (int iteration = 0; iteration < options.max_iterations; ++iteration) {
      from.clear();
      to.clear();
      for (const Point2& p : points) {
        const Point2 moved = total.transform(p);
        if (const std::optional<Point2> q = truth.nearest_point_within(moved, gate_m)) {
          from.push_back(moved);
          to.push_back(*q);
        }
      }
      if (from.size() < options.min_pairs) return RigidFit{};
      const Pose2 step = procrustes(from, to);
      total = step.compose(total);
      // The largest move of a paired sample under this step: a rotation about the pairs'
      // centroid moves the farthest sample most.
      double moved_m = 0.0;
      for (const Point2& p : from) moved_m = std::max(moved_m, (step.transform(p) - p).norm());
      if (moved_m < options.converged_m) break;
    }
    fit.pairs = from.size();
  }
  fit.transform = total;
  fit.fitted = true;
  return fit;
}

}  // namespace cogmap::experiments
