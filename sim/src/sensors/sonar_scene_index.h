#pragma once
/// A uniform-grid spatial index of a SonarScene (internal to the sonar model), built once per
/// scene. It only narrows which surfaces and corners a query has to test; the tests themselves are
/// the brute-force ones, run over the candidates in ascending surface index, so every result is
/// bit-identical to testing the whole scene.

#include <cstdint>
#include <vector>

#include "cogmap/mapper/seam/geometry.h"
#include "cogmap/sim/sonar_model.h"

namespace cogmap::sim::sonar_detail {

/// Cells of a uniform grid holding the surfaces and corners that come near them.
class SceneIndex {
 public:
  /// Builds the grid over `scene` (copied, so the index can tell when a scene has changed).
  /// `cell_m` is the grid pitch; the grid is coarsened if it would exceed ~65k cells.
  explicit SceneIndex(const SonarScene& scene, double cell_m = 1.0);

  /// True when `scene` holds bit for bit the surfaces and corners this index was built from.
  bool matches(const SonarScene& scene) const;

  /// Surface indices of every surface passing within the padding of the segment
  /// origin + t·dir, t in [0, max_t_m] (a superset of the surfaces it can hit), each once, in
  /// cell order. `out` is cleared first. Not thread-safe (query scratch).
  void surfaces_near_ray(const mapper::Point2& origin, const mapper::Point2& dir, double max_t_m,
                         std::vector<int>& out) const;

  /// True when a corner lies within `radius_m` of `p` (the same test, `norm() <= radius_m`, as a
  /// scan over every corner).
  bool corner_within(const mapper::Point2& p, double radius_m) const;

  /// The scene the index was built from.
  const SonarScene& scene() const { return scene_; }

 private:
  /// Calls `visit(cell)` for every cell that the segment a-b, widened by the padding, touches.
  template <class Visit>
  void for_cells_of_segment(const mapper::Point2& a, const mapper::Point2& b, Visit&& visit) const;
  int column_of(double x) const;
  int row_of(double y) const;

  SonarScene scene_;
  double x0_ = 0.0, y0_ = 0.0, cell_m_ = 1.0;
  int nx_ = 1, ny_ = 1;
  // Compressed rows: the surfaces of cell c are surface_ids_[surface_start_[c] ..
  // surface_start_[c + 1]), ascending; likewise for corners.
  std::vector<std::uint32_t> surface_start_, corner_start_;
  std::vector<int> surface_ids_, corner_ids_;
  // Query scratch: the query number that last took each surface (one model per thread, as the
  // SonarModel that owns the index already requires).
  mutable std::vector<std::uint32_t> stamp_;
  mutable std::uint32_t query_ = 0;
};

}  // namespace cogmap::sim::sonar_detail
