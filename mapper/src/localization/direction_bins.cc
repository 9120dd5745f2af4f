// Pooling of wall directions into fixed bins of the quarter circle (docs/algorithms.md,
// "A binned reference").

#include "cogmap/mapper/localization/direction_bins.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace cogmap::mapper {
namespace {

constexpr double kMaxBins = 1e6;

struct BinSums {
  double length = 0.0;     // Σ w
  double offset = 0.0;     // Σ w (a − centre)
  double offset_sq = 0.0;  // Σ w (a − centre)²
  double length_sq = 0.0;  // Σ w²
};

}  // namespace

BinnedDirections bin_directions(std::span<const LineDirection> directions, double bin_rad) {
  BinnedDirections out;
  // Past a million bins (under 0.00009° each) pooling saves nothing: every direction stays.
  if (!(bin_rad > 0.0) || !std::isfinite(bin_rad) || kQuarterTurnRad / bin_rad > kMaxBins) {
    out.directions.assign(directions.begin(), directions.end());
    out.spread_rad2.assign(directions.size(), 0.0);
    for (const LineDirection& d : directions) out.length_sq.push_back(d.length_m * d.length_m);
    return out;
  }
  const int count = std::max(1, static_cast<int>(std::ceil(kQuarterTurnRad / bin_rad)));
  const double width = kQuarterTurnRad / count;  // bins tile the quarter circle exactly
  std::vector<BinSums> bins(static_cast<std::size_t>(count));
  for (const LineDirection& d : directions) {
    if (!(d.length_m > 0.0) || !std::isfinite(d.angle_rad)) continue;
    const double from_start = fold_direction_rad(d.angle_rad) + kQuarterTurnRad / 2.0;
    const int i = std::clamp(static_cast<int>(from_start / width), 0, count - 1);
    const double offset = from_start - (i + 0.5) * width;
    BinSums& b = bins[static_cast<std::size_t>(i)];
    b.length += d.length_m;
    b.offset += d.length_m * offset;
    b.offset_sq += d.length_m * offset * offset;
    b.length_sq += d.length_m * d.length_m;
  }
  for (int i = 0; i < count; ++i) {
    const BinSums& b = bins[static_cast<std::size_t>(i)];
    if (b.length <= 0.0) continue;
    const double mean_offset = b.offset / b.length;
    const double centre = -kQuarterTurnRad / 2.0 + (i + 0.5) * width;
    out.directions.push_back({centre + mean_offset, b.length});
    out.spread_rad2.push_back(std::max(0.0, b.offset_sq / b.length - mean_offset * mean_offset));
    out.length_sq.push_back(b.length_sq);
  }
  return out;
}

}  // namespace cogmap::mapper
