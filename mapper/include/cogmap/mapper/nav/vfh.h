#pragma once
/// The polar histogram of thesis §2.2.3 (Eqs. 2.15-2.17) and the VFH valley selection.
/// Sectors are fixed in the world (estimate) frame: sector k is centred on k·sector_deg and
/// covers [k·α - α/2, k·α + α/2), so sector 0 is centred on the world +x axis.

#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include "cogmap/mapper/nav/controller.h"
#include "cogmap/mapper/seam/geometry.h"

namespace cogmap::mapper::nav {

/// One obstacle cell or remembered echo: offset from the robot centre along the world axes
/// (not rotated into the robot frame), metres, and its HIMM-scale certainty c (0-15).
struct ObstaclePoint {
  Point2 offset_m{0.0, 0.0};
  float certainty = 0.0f;
};

/// The outcome of the valley selection.
struct VfhChoice {
  bool found = false;          ///< false when every sector is blocked
  double direction_rad = 0.0;  ///< chosen world direction, (-π, π]
  int valley_sectors = 0;      ///< width of the valley it lies in, sectors
};

/// Builds the polar histogram every cycle and keeps the binary state for hysteresis.
class Vfh {
 public:
  explicit Vfh(const VfhOptions& options);

  /// Eqs. 2.15-2.17 over `obstacles` (those beyond window_m or `range_m` are ignored), each
  /// enlarged over the sectors within asin(r/d); then smoothing and the hysteresis threshold.
  /// `range_m` lets a route follower ignore what lies beyond its waypoint.
  void build(const std::vector<ObstaclePoint>& obstacles,
             double range_m = std::numeric_limits<double>::infinity());

  /// The candidate direction (world) of least cost |target - c| + heading_weight·|heading - c|:
  /// candidates are the target itself when it lies inside a wide valley away from its edges,
  /// each wide valley's edges offset inward, and each narrow valley's centre.
  /// With `previous_rad` (last cycle's choice) the cost gains previous_weight·|previous - c|
  /// (VFH+'s μ3): near a wall the two valley edges cost about the same, and without it the
  /// choice flips between them every few cycles (the robot swings left and right in front of
  /// a doorway). It also gains VfhOptions::side_switch_rad for leaving the side of a detour,
  /// and with `hold_way` (after repeated turn-backs, nav/turn_backs.h) a candidate more than
  /// 90° from `previous_rad` gains VfhOptions::turn_back_cost_rad.
  VfhChoice select(double target_rad, double heading_rad,
                   std::optional<double> previous_rad = std::nullopt, bool hold_way = false) const;
  /// select() with the heading equal to the target (no turning preference).
  VfhChoice select(double target_rad) const { return select(target_rad, target_rad); }

  /// The sector of lowest smoothed density; ties go to the one nearest `prefer_rad`.
  int freest_sector(double prefer_rad) const;

  int sector_count() const { return static_cast<int>(density_.size()); }
  /// VfhOptions::side_switch_rad when `direction` and `previous_rad` go round the target on
  /// opposite sides (each more than detour_rad off it), else 0.
  double side_switch_cost(double direction, double target_rad,
                          std::optional<double> previous_rad) const;
  /// Sector index of a world angle (any value; wrapped).
  int sector_of(double angle_rad) const;
  /// World angle of a sector's centre, (-π, π].
  double sector_center_rad(int sector) const;
  bool blocked(int sector) const { return blocked_[wrap(sector)] != 0; }
  /// Enlarged density per sector, h_k of Eq. 2.17 (before smoothing).
  const std::vector<double>& density() const { return density_; }
  /// Density after Borenstein's smoothing with window l = smoothing_sectors.
  const std::vector<double>& smoothed() const { return smoothed_; }
  /// 1 for blocked sectors.
  const std::vector<std::uint8_t>& blocked_mask() const { return blocked_; }
  /// τ_high actually used (options.threshold, or the automatic value).
  double threshold() const { return threshold_; }
  /// κ(d) of Eq. 2.16: kappa·(1 - d/window_m), zero outside the window.
  double kappa_at(double distance_m) const;

 private:
  int wrap(int sector) const;
  /// The sector holding unit direction `v`, found from the sectors' borders by cross products
  /// (no trigonometry); -1 when `v` lies within a rounding margin of a border, where only
  /// sector_of decides exactly as it does for the angle.
  int sector_of_direction(const Point2& v) const;

  VfhOptions options_;
  double sector_rad_;
  double threshold_;
  std::vector<double> density_;
  std::vector<double> smoothed_;
  std::vector<std::uint8_t> blocked_;
  // Unit vector of each sector's lower border, (k - ½)·sector, and the first one again.
  std::vector<Point2> borders_;
};

}  // namespace cogmap::mapper::nav
