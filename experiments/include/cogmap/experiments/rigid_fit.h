#pragma once
/// The rigid transform (SE(2)) that lays map samples best onto the true surfaces: gated
/// iterative closest points, for the error breakdown's "aligned" stages (docs/metrics.md).
/// A diagnostic of the truth-side metrics only; nothing the robot uses.

#include <cstddef>
#include <span>
#include <vector>

#include "cogmap/experiments/segment_index.h"
#include "cogmap/mapper/seam/geometry.h"
#include "cogmap/mapper/seam/pose2.h"

namespace cogmap::experiments {

struct RigidFitOptions {
  /// Each sample is paired with the nearest true surface point within the gate; the gates
  /// shrink in turn (a map displaced by up to the first gate is pulled in, and the last one
  /// leaves out phantoms and furniture the truth does not hold). Each gate is iterated until
  /// a step moves no sample by more than `converged_m`, at most `max_iterations` times.
  std::vector<double> gates_m = {1.0, 0.6, 0.4, 0.25};
  int max_iterations = 50;
  /// 0.1 mm: the samples lie 5 cm apart and their errors are centimetres; the last steps of
  /// a fit slide along walls slowly (1e-6 took 2 346 steps on explore nine rooms, 0.15 s).
  double converged_m = 1e-4;
  std::size_t min_pairs = 10;  ///< fewer pairs within a gate: no fit (identity)
};

struct RigidFit {
  mapper::Pose2 transform;  ///< world -> world: the aligned sample is transform.transform(p)
  std::size_t pairs = 0;    ///< samples paired within the last gate
  bool fitted = false;      ///< false: too few pairs at some gate, transform is the identity
};

/// The transform that minimises the squared distances of the samples paired within each gate
/// to their nearest true surface points (Procrustes in the plane at every step).
RigidFit fit_rigid(std::span<const mapper::Point2> points, const SegmentIndex& truth,
                   const RigidFitOptions& options = {});

}  // namespace cogmap::experiments
