#pragma once
/// Expectation Maximization over wall directions (thesis §3.1.9-3.1.10, Figs. A.6-A.7).
/// docs/algorithms.md maps every equation to the code below.

#include <span>
#include <vector>

#include "cogmap/mapper/localization/directions.h"
#include "cogmap/mapper/seam/geometry.h"

namespace cogmap::mapper {

/// A wall direction folded into [-45°, 45°) (Fig. A.7), radians, with the segment's length.
struct LineDirection {
  double angle_rad = 0.0;  ///< CCW from the frame's +x axis, folded modulo π/2
  double length_m = 0.0;   ///< segment length, metres (the weight of the direction)
};

/// Fig. A.7 / Eqs. 3.25-3.31: the direction of every segment of every polyline, folded so
/// parallel and perpendicular walls share one value in [-π/4, π/4). Zero-length segments
/// (repeated vertices) have no direction and are skipped.
std::vector<LineDirection> line_directions(std::span<const Polyline> polylines);

/// Two-component Gaussian mixture: s (sonar, the new ASR) and m (motor, the reference), plus an
/// optional uniform clutter component (our extension, weight 0 = the thesis's pure mixture).
struct GaussianMixture2 {
  double pi_s = 0.5;        ///< π_s, mixing weight of component s
  double mu_s = 0.0;        ///< μ_s, radians
  double sigma_s = 0.05;    ///< σ_s, radians
  double pi_m = 0.5;        ///< π_m, mixing weight of component m
  double mu_m = 0.0;        ///< μ_m, radians
  double sigma_m = 0.05;    ///< σ_m, radians
  double pi_clutter = 0.0;  ///< weight of the uniform clutter component (used only if enabled)
};

/// Options of Fig. A.6.
struct EmOptions {
  int max_iterations = 200;     ///< bound on E/M rounds (the thesis loops until convergence)
  double tolerance_rad = 1e-9;  ///< ε of Fig. A.6: stop when |Δμ_s| + |Δμ_m| falls below
  double min_sigma_rad = 1e-4;  ///< variance floor so a component never collapses to a point
  /// Support (radians) of a uniform clutter density 1/clutter_range_rad that competes for every
  /// sample in the E-step; 0 disables it (the thesis's two components only).
  double clutter_range_rad = 0.0;
};

/// What EM found.
struct EmResult {
  GaussianMixture2 mixture;     ///< parameters after the last M-step
  int iterations = 0;           ///< E/M rounds run
  bool converged = false;       ///< |Δμ_s| + |Δμ_m| < tolerance before max_iterations
  double log_likelihood = 0.0;  ///< Σ w_i log p(x_i) at the final parameters
};

/// Where a sample came from. The thesis pools s and m and lets EM sort them out; when the
/// source is known (it always is in the Localizer) a labelled sample is explained only by its
/// own component or by clutter. docs/algorithms.md says why.
enum class EmSource : unsigned char { kUnknown, kS, kM };

/// Runs E- and M-steps (Eqs. 3.13-3.14, 3.19-3.21) from `initial` on weighted samples.
/// `weights` may be empty (all 1); otherwise one non-negative weight per sample, and N of
/// Eq. 3.19 becomes Σ w_i. Samples are plain reals: centre circular data before calling.
EmResult expectation_maximization(std::span<const double> samples, std::span<const double> weights,
                                  const GaussianMixture2& initial, const EmOptions& options);

/// The same with one source label per sample (`sources` empty = all kUnknown, the overload
/// above). For a kS sample the m term drops out of Eq. 3.14's sum over k, and vice versa.
EmResult expectation_maximization(std::span<const double> samples, std::span<const double> weights,
                                  std::span<const EmSource> sources,
                                  const GaussianMixture2& initial, const EmOptions& options);

/// The same where sample i may stand for several directions pooled in a bin (a binned
/// reference, direction_bins.h): `spreads_rad2[i]` is their weighted variance about samples[i],
/// which the σ̂² of Eq. 3.21 adds (Σ_j w_j (x_j − μ)² = W ((x̄ − μ)² + spread)). Empty = all 0,
/// the overload above.
EmResult expectation_maximization(std::span<const double> samples, std::span<const double> weights,
                                  std::span<const EmSource> sources,
                                  std::span<const double> spreads_rad2,
                                  const GaussianMixture2& initial, const EmOptions& options);

}  // namespace cogmap::mapper
