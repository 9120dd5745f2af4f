// Direction statistics modulo 90° used to initialise EM (docs/algorithms.md).

#include "cogmap/mapper/localization/directions.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "cogmap/mapper/localization/em.h"

namespace cogmap::mapper {

double fold_direction_rad(double angle_rad) {
  double folded = angle_rad - kQuarterTurnRad *
                                  std::floor((angle_rad + kQuarterTurnRad / 2.0) / kQuarterTurnRad);
  // Rounding can land exactly on the open end of [−π/4, π/4).
  if (folded >= kQuarterTurnRad / 2.0) folded -= kQuarterTurnRad;
  if (folded < -kQuarterTurnRad / 2.0) folded += kQuarterTurnRad;
  return folded;
}

double mean_direction_rad(std::span<const double> angles_rad, std::span<const double> weights) {
  // Directions modulo 90° become ordinary circular angles when multiplied by 4.
  double c = 0.0, s = 0.0;
  for (std::size_t i = 0; i < angles_rad.size(); ++i) {
    const double w = weights.empty() ? 1.0 : weights[i];
    c += w * std::cos(4.0 * angles_rad[i]);
    s += w * std::sin(4.0 * angles_rad[i]);
  }
  if (std::hypot(c, s) <= 1e-12) return 0.0;
  return fold_direction_rad(std::atan2(s, c) / 4.0);
}

double dominant_direction_rad(std::span<const LineDirection> directions,
                              const DominantDirectionOptions& options) {
  if (directions.empty()) return 0.0;
  const int bins = std::max(1, static_cast<int>(std::lround(kQuarterTurnRad / options.bin_rad)));
  const double bin_rad = kQuarterTurnRad / bins;
  std::vector<double> histogram(bins, 0.0);
  for (const LineDirection& d : directions) {
    const double u = (fold_direction_rad(d.angle_rad) + kQuarterTurnRad / 2.0) / bin_rad;
    histogram[std::clamp(static_cast<int>(u), 0, bins - 1)] += d.length_m;
  }
  // Circular triangular smoothing, so 1° noise spreading a wall over neighbouring bins still
  // makes one peak, and −45° and +45° are neighbours.
  const int half = std::max(0, static_cast<int>(options.smooth_rad / bin_rad));
  int best = 0;
  double best_mass = -1.0;
  for (int b = 0; b < bins; ++b) {
    double mass = 0.0;
    for (int k = -half; k <= half; ++k) {
      mass += histogram[((b + k) % bins + bins) % bins] * (half + 1 - std::abs(k));
    }
    if (mass > best_mass) {
      best_mass = mass;
      best = b;
    }
  }
  const double peak_rad = -kQuarterTurnRad / 2.0 + (best + 0.5) * bin_rad;
  std::vector<double> angles, weights;
  for (const LineDirection& d : directions) {
    if (std::abs(fold_direction_rad(d.angle_rad - peak_rad)) > options.window_rad) continue;
    angles.push_back(d.angle_rad);
    weights.push_back(d.length_m);
  }
  return angles.empty() ? peak_rad : mean_direction_rad(angles, weights);
}

double direction_spread_rad(std::span<const LineDirection> directions, double centre_rad,
                            double window_rad) {
  double sum_w = 0.0, sum_sq = 0.0;
  for (const LineDirection& d : directions) {
    const double delta = fold_direction_rad(d.angle_rad - centre_rad);
    if (std::abs(delta) > window_rad) continue;
    sum_w += d.length_m;
    sum_sq += d.length_m * delta * delta;
  }
  return sum_w > 0.0 ? std::sqrt(sum_sq / sum_w) : 0.0;
}

}  // namespace cogmap::mapper
