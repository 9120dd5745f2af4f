#include "cogmap/mapper/localization/door_fixes.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace cogmap::mapper {
namespace {

/// The angle between two headings taken as axes (a door is passed both ways), in [0, π/2].
double axis_difference_rad(double a_rad, double b_rad) {
  const double d = std::fmod(std::abs(a_rad - b_rad), std::numbers::pi);
  return std::min(d, std::numbers::pi - d);
}

}  // namespace

std::optional<Point2> DoorMemory::pass(const DoorPassage& passage) {
  if (!(passage.width_m > 0.0 && passage.width_m <= options_.max_width_m) ||
      !passage.center.allFinite() || !std::isfinite(passage.heading_rad) ||
      !std::isfinite(passage.travel_m)) {
    return std::nullopt;
  }
  const double max_axis_rad = options_.max_axis_difference_deg * std::numbers::pi / 180.0;
  double nearest_m = std::numeric_limits<double>::infinity();
  double second_m = std::numeric_limits<double>::infinity();
  DoorPassage* match = nullptr;
  for (DoorPassage& door : doors_) {
    const double d = (door.center - passage.center).norm();
    // Every known door counts against the match's uniqueness, whatever its width and axis: a
    // wrong fix moves the robot by a door's spacing.
    if (d < nearest_m) {
      second_m = nearest_m;
      nearest_m = d;
      const bool alike =
          std::abs(door.width_m - passage.width_m) <= options_.max_width_difference_m &&
          axis_difference_rad(door.heading_rad, passage.heading_rad) <= max_axis_rad;
      match = alike ? &door : nullptr;
    } else if (d < second_m) {
      second_m = d;
    }
  }
  if (nearest_m > options_.match_radius_m) {
    doors_.push_back(passage);  // a door not passed before (or drifted beyond recognition)
    return std::nullopt;
  }
  if (match == nullptr || second_m < options_.ambiguity_ratio * nearest_m) return std::nullopt;
  // Drift since the door was last passed (sd growing with the path) against the scatter of
  // the two passages' centres; the door stays where it was first measured.
  const double drift_m =
      options_.drift_sd_per_m * std::max(0.0, passage.travel_m - match->travel_m);
  const double drift_var = drift_m * drift_m;
  const double noise_var = 2.0 * options_.door_sd_m * options_.door_sd_m;
  const double gain = drift_var + noise_var > 0.0 ? drift_var / (drift_var + noise_var) : 1.0;
  match->travel_m = passage.travel_m;
  return gain * (match->center - passage.center);
}

}  // namespace cogmap::mapper
