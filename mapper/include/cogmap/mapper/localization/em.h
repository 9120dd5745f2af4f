#pragma once
/// Expectation Maximization over wall directions (thesis §3.1.9-3.1.10, Figs. A.6-A.7).

#include <span>
#include <vector>

#include "cogmap/mapper/seam/geometry.h"

namespace cogmap::mapper {

/// A wall direction folded into [-45°, 45°] (Fig. A.7), radians, with the segment's length.
struct LineDirection {
  double angle_rad = 0.0;
  double length_m = 0.0;
};

/// Fig. A.7 / Eqs. 3.25-3.31: the direction of every segment of every polyline, folded so
/// parallel and perpendicular walls share one value in [-π/4, π/4].
std::vector<LineDirection> line_directions(std::span<const Polyline> polylines);

/// Two-component Gaussian mixture: s (sonar, the new ASR) and m (motor, the reference).
struct GaussianMixture2 {
  double pi_s = 0.5, mu_s = 0.0, sigma_s = 0.05;
  double pi_m = 0.5, mu_m = 0.0, sigma_m = 0.05;
};

struct EmOptions {
  int max_iterations = 200;
  double tolerance_rad = 1e-9;  ///< ε of Fig. A.6: stop when |Δμ_s| + |Δμ_m| falls below
  double min_sigma_rad = 1e-4;  ///< variance floor so a component never collapses to a point
};

struct EmResult {
  GaussianMixture2 mixture;
  int iterations = 0;
  bool converged = false;
  double log_likelihood = 0.0;
};

/// Runs E- and M-steps (Eqs. 3.13-3.14, 3.19-3.21) from `initial` on weighted samples.
/// `weights` may be empty (all 1); otherwise one non-negative weight per sample.
EmResult expectation_maximization(std::span<const double> samples, std::span<const double> weights,
                                  const GaussianMixture2& initial, const EmOptions& options);

}  // namespace cogmap::mapper
