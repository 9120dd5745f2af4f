#pragma once
/// Statistics of wall directions modulo 90° (thesis §3.1.10): indoor walls are parallel or
/// perpendicular, so a direction and the direction 90° away say the same thing about heading.

#include <numbers>
#include <span>
#include <vector>

namespace cogmap::mapper {

struct LineDirection;

/// The period of a wall direction: a quarter turn, π/2 radians.
inline constexpr double kQuarterTurnRad = std::numbers::pi / 2.0;

/// Folds an angle (radians) modulo π/2 into [−π/4, π/4): the direction equivalent to it under
/// a quarter turn. This is what Eqs. 3.28-3.31 intend (see docs/algorithms.md).
double fold_direction_rad(double angle_rad);

/// Weighted mean direction modulo π/2 (the "4θ trick": average unit vectors at 4θ, whose angle
/// divided by 4 is the mean), in [−π/4, π/4). `weights` empty means all 1. Returns 0 when the
/// directions cancel (no dominant direction).
double mean_direction_rad(std::span<const double> angles_rad, std::span<const double> weights);

/// Options of the outlier-robust dominant-direction estimate.
struct DominantDirectionOptions {
  double bin_rad = 0.008726646259971648;    ///< histogram bin, 0.5°
  double smooth_rad = 0.03490658503988659;  ///< half-width of the triangular smoothing, 2°
  double window_rad = 0.08726646259971647;  ///< samples within 5° of the peak refine the mean
};

/// The dominant wall direction modulo π/2: the peak of a length-weighted, circularly smoothed
/// histogram, refined by the weighted 4θ mean of the samples within `window_rad` of the peak.
/// Short clutter at random angles barely moves it, unlike the plain mean.
double dominant_direction_rad(std::span<const LineDirection> directions,
                              const DominantDirectionOptions& options = {});

/// Weighted root-mean-square deviation (radians, modulo π/2) of the directions within
/// `window_rad` of `centre_rad`; 0 when none lie there.
double direction_spread_rad(std::span<const LineDirection> directions, double centre_rad,
                            double window_rad);

}  // namespace cogmap::mapper
