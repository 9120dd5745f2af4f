#pragma once
/// The reference rooms' wall directions summarised in fixed bins of the quarter circle, so that
/// EM's cost per room stops growing with the number of rooms it measures against (issue 13;
/// docs/algorithms.md, "A binned reference").

#include <span>
#include <vector>

#include "cogmap/mapper/localization/em.h"

namespace cogmap::mapper {

/// Directions pooled by bin. Entry i stands for every direction of its bin: `directions[i]` holds
/// their weighted mean angle and their summed length, `spread_rad2[i]` their length-weighted
/// variance about that mean and `length_sq[i]` the sum of their squared lengths (what the Kish
/// effective count of EM's measurement variance needs).
struct BinnedDirections {
  std::vector<LineDirection> directions;
  std::vector<double> spread_rad2;
  std::vector<double> length_sq;
};

/// Pools `directions` (folded into [−π/4, π/4)) into bins `bin_rad` wide that tile the quarter
/// circle from −π/4; empty bins are left out, the rest come in angle order. Sums are kept as
/// offsets from each bin's centre, so the mean and variance carry no cancellation. A bin_rad
/// of 0 or less, not finite, or so small the quarter circle would need more than a million
/// bins keeps every direction as its own entry (spread 0).
BinnedDirections bin_directions(std::span<const LineDirection> directions, double bin_rad);

}  // namespace cogmap::mapper
