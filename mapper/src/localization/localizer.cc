// §3.1.9: the heading drift of a new ASR from the directions of its walls against those of the
// rooms before it, through the two-component mixture of Fig. A.6.

#include "cogmap/mapper/localization/localizer.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

namespace cogmap::mapper {
namespace {

constexpr double kQuarter = std::numbers::pi / 2.0;

double total_length_m(std::span<const LineDirection> directions) {
  double sum = 0.0;
  for (const LineDirection& d : directions) sum += d.length_m;
  return sum;
}

}  // namespace

Localization Localizer::estimate(std::span<const Polyline> reference_world,
                                 std::span<const Polyline> current_world) const {
  Localization out;
  // s: the new room's walls; m: the reference rooms' walls (the thesis's m is "the centre point
  // of the exit locations"; see docs for why we use the reference walls instead).
  const std::vector<LineDirection> s = line_directions(current_world);
  const std::vector<LineDirection> m = line_directions(reference_world);
  const double length_s_m = total_length_m(s), length_m_m = total_length_m(m);
  if (length_s_m < options_.min_wall_length_m || length_m_m < options_.min_wall_length_m) {
    return out;
  }

  // Robust initialisation: each component starts at its own set's dominant direction.
  const double mode_s = dominant_direction_rad(s, options_.dominant);
  const double mode_m = dominant_direction_rad(m, options_.dominant);
  out.reference_direction_rad = mode_m;
  out.current_direction_rad = mode_s;

  // Directions live on a circle of circumference 90°. Centring every sample on the reference
  // direction puts the interesting part of the data far from the ±45° seam, where the plain
  // real-valued Gaussians of Eq. 3.16 are valid.
  std::vector<double> samples, weights;
  std::vector<EmSource> sources;
  samples.reserve(s.size() + m.size());
  weights.reserve(s.size() + m.size());
  sources.reserve(s.size() + m.size());
  for (const auto& [set, source] : {std::pair{&s, EmSource::kS}, std::pair{&m, EmSource::kM}}) {
    for (const LineDirection& d : *set) {
      samples.push_back(fold_direction_rad(d.angle_rad - mode_m));
      weights.push_back(options_.weight_by_length ? d.length_m : 1.0);
      // The source of every direction is known, so each sample is explained by its own
      // component (or clutter); pooled unlabelled, two overlapping Gaussians are not identifiable.
      sources.push_back(options_.label_sources ? source : EmSource::kUnknown);
    }
  }

  GaussianMixture2 initial;
  const double clutter = std::clamp(options_.clutter_weight, 0.0, 0.9);
  const double share_s = options_.weight_by_length
                             ? length_s_m / (length_s_m + length_m_m)
                             : static_cast<double>(s.size()) / static_cast<double>(samples.size());
  initial.pi_s = (1.0 - clutter) * share_s;
  initial.pi_m = (1.0 - clutter) * (1.0 - share_s);
  initial.pi_clutter = clutter;
  initial.mu_s = fold_direction_rad(mode_s - mode_m);
  initial.mu_m = 0.0;
  const double window = options_.dominant.window_rad;
  initial.sigma_s =
      std::max(direction_spread_rad(s, mode_s, window), options_.min_initial_sigma_rad);
  initial.sigma_m =
      std::max(direction_spread_rad(m, mode_m, window), options_.min_initial_sigma_rad);

  EmOptions em_options = options_.em;
  em_options.clutter_range_rad = clutter > 0.0 ? kQuarter : 0.0;  // folded data span 90°
  out.em = expectation_maximization(samples, weights, sources, initial, em_options);

  // Undo the centring, and turn the new room's direction onto the reference's.
  out.reference_direction_rad = fold_direction_rad(out.em.mixture.mu_m + mode_m);
  out.current_direction_rad = fold_direction_rad(out.em.mixture.mu_s + mode_m);
  out.rotation_rad = fold_direction_rad(out.em.mixture.mu_m - out.em.mixture.mu_s);
  out.applied = std::abs(out.rotation_rad) <= options_.max_correction_rad;
  if (!out.applied) out.rotation_rad = 0.0;
  return out;
}

}  // namespace cogmap::mapper
