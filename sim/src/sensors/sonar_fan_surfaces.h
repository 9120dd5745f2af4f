#pragma once
/// The surfaces and corners one ping's fan can meet (internal to the sonar model), gathered once
/// per ping from the scene index and listed nearest first. Each ray of the fan, and each line of
/// sight to a corner in it, then tests only the surfaces that can lie nearer than its nearest hit
/// so far, instead of walking the index's cells ray by ray. The test is the shared test_surface,
/// which keeps the nearest hit (ties to the higher index) whatever the order, so every answer is
/// bit-identical to the full scan. A surface is also skipped by a ray outside the directions it
/// spans as seen from the origin (within the fan, ahead of the origin, a segment is met only by
/// the rays between its ends). A crowded fan (hundreds of chair legs) is also cut into sectors,
/// each listing, nearest first, the surfaces whose directions reach into it, so a ray walks its
/// own sector's list instead of every surface nearer than its hit.

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "cogmap/mapper/seam/geometry.h"
#include "cogmap/sim/sonar_model.h"
#include "sonar_raycast.h"
#include "sonar_scene_index.h"

namespace cogmap::sim::sonar_detail {

class FanSurfaces {
 public:
  /// Gathers what rays from `origin` within the half width (its cosine and sine) of the unit
  /// `axis`, no longer than `reach_m`, can meet: every surface and corner the index lists in the
  /// cells of the fan's bounding box. The cone must be finite (the caller walks the cells
  /// otherwise). The caller's ping has the axis and the half width's cosine and sine already.
  void gather(const SceneIndex& index, const mapper::Point2& origin, const mapper::Point2& axis,
              double cos_half, double sin_half, double reach_m);

  /// first_hit(scene, origin, dir, max_t_m) for a ray of the fan (`dir` unit and within the
  /// fan's half width of its axis, max_t_m no more than the reach gathered for).
  std::optional<RayHit> first_hit(const mapper::Point2& dir, double max_t_m) const;

  /// True when first_hit(dir, reach_m) would find a surface; stops at the first one (the same
  /// conditions on `dir` and `reach_m`).
  bool blocked(const mapper::Point2& dir, double reach_m) const;

  /// Every corner in the fan's box, ascending (the order of SonarScene::corners).
  std::span<const int> corners() const { return corners_; }

  /// How many sectors the last gather cut the fan into (0: the fan is scanned whole).
  std::size_t sector_count() const { return sector_start_.empty() ? 0 : sector_start_.size() - 1; }

 private:
  struct Near {
    double distance_sq;  // squared distance from the origin to the surface's nearest point
    int surface;
    // The tangents, relative to the fan's axis, of the directions the surface spans (widened
    // far beyond rounding; everything when it reaches beside or behind the origin).
    double tan_lo, tan_hi;
  };
  /// The tangent of unit `dir`'s angle from the axis; NaN when `dir` does not point ahead.
  double tangent_of(const mapper::Point2& dir) const;
  /// The sector holding tangent `t` (monotone in t: a surface spanning [lo, hi] is listed in
  /// every sector from sector_of(lo) to sector_of(hi)).
  int sector_of(double t) const;
  /// Cuts the gathered surfaces into sectors of equal angle over the fan's half width.
  void build_sectors(double cos_half, double sin_half);
  /// The surfaces a ray of tangent `t` (not NaN) must test, nearest first; only for a fan that
  /// is cut (sector_count() > 0).
  std::span<const Near> sector_list(double t) const;
  const SonarScene* scene_ = nullptr;
  mapper::Point2 origin_{0.0, 0.0};
  mapper::Point2 axis_{1.0, 0.0};
  std::vector<Near> surfaces_;  // by distance
  std::vector<int> corners_;
  std::vector<int> ids_;  // gathering scratch
  // Sectors (empty when the fan holds few surfaces): the tangents of the inner sector edges,
  // ascending, and per sector the range [sector_start_[k], sector_start_[k + 1]) of
  // sector_items_ (copies of surfaces_, nearest first).
  std::vector<double> sector_edges_;
  std::vector<int> sector_start_;
  std::vector<Near> sector_items_;
  std::vector<int> sector_fill_;  // building scratch, kept so a ping allocates nothing
};

}  // namespace cogmap::sim::sonar_detail
