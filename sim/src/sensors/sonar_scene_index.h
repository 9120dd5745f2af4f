#pragma once
/// A uniform-grid spatial index of a SonarScene (internal to the sonar model), built once per
/// scene. It only narrows which surfaces and corners a query has to test; the tests themselves are
/// the brute-force ones, run over the candidates in ascending surface index, so every result is
/// bit-identical to testing the whole scene.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "cogmap/mapper/seam/geometry.h"
#include "cogmap/sim/sonar_model.h"

namespace cogmap::sim::sonar_detail {

/// Cells of a uniform grid holding the surfaces and corners that come near them. Several threads
/// may query one index at once: each query uses its own thread's scratch.
class SceneIndex {
 public:
  /// Builds the grid over `scene` (copied, so the index can tell when a scene has changed).
  /// `cell_m` is the grid pitch; the grid is coarsened if it would exceed ~65k cells.
  explicit SceneIndex(const SonarScene& scene, double cell_m = 1.0);

  /// True when `scene` holds bit for bit the surfaces and corners this index was built from.
  bool matches(const SonarScene& scene) const;

  /// Surface indices of every surface passing within the padding of the segment
  /// origin + t·dir, t in [0, max_t_m] (a superset of the surfaces it can hit), each once, in
  /// cell order. `out` is cleared first.
  void surfaces_near_ray(const mapper::Point2& origin, const mapper::Point2& dir, double max_t_m,
                         std::vector<int>& out) const;

  /// Calls `test(id)` once for each surface listed in the cells the ray origin + t·dir,
  /// t in [0, max_t_m], crosses, nearest cell first (an Amanatides-Woo walk); `test` returns the
  /// distance t of the nearest hit found so far (anything >= max_t_m for none). The walk stops
  /// after a cell the ray leaves more than the padding beyond that hit: a surface listed only
  /// further on cannot be hit nearer, so a test that keeps the nearest hit (ties to one fixed
  /// surface, whatever the order) answers exactly as over surfaces_near_ray.
  template <class Test>
  void walk_ray(const mapper::Point2& origin, const mapper::Point2& dir, double max_t_m,
                Test&& test) const;

  /// Surface indices of every surface listed in a cell the box [lo, hi] touches (a superset of
  /// the surfaces passing through the box), each once, in no particular order. `out` is cleared
  /// first.
  void surfaces_in_box(const mapper::Point2& lo, const mapper::Point2& hi,
                       std::vector<int>& out) const;

  /// Corner indices of every corner listed in a cell the box [lo, hi] touches (a superset of
  /// the corners inside it), each once, ascending. `out` is cleared first.
  void corners_in_box(const mapper::Point2& lo, const mapper::Point2& hi,
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
  /// Calls `visit(cell)` for every cell the box [lo, hi] touches.
  template <class Visit>
  void for_cells_of_box(const mapper::Point2& lo, const mapper::Point2& hi, Visit&& visit) const;
  /// A thread's query scratch: the query number that last took each surface of one index.
  /// Kept per thread, so that several threads may query one index at once.
  struct QueryScratch {
    std::uint64_t index_id = 0;  // the index the stamps belong to (0: none yet)
    std::vector<std::uint32_t> stamp;
    std::uint32_t query = 0;
  };
  /// Calls `visit(id)` for each surface listed in `cell` that query `q` has not met.
  template <class Visit>
  void for_new_surfaces_of_cell(int cell, QueryScratch& q, Visit&& visit) const;
  int column_of(double x) const;
  int row_of(double y) const;
  /// Starts a query on this thread's scratch: afterwards no surface counts as taken.
  QueryScratch& next_query() const;

  SonarScene scene_;
  double x0_ = 0.0, y0_ = 0.0, cell_m_ = 1.0;
  int nx_ = 1, ny_ = 1;
  // Compressed rows: the surfaces of cell c are surface_ids_[surface_start_[c] ..
  // surface_start_[c + 1]), ascending; likewise for corners.
  std::vector<std::uint32_t> surface_start_, corner_start_;
  std::vector<int> surface_ids_, corner_ids_;
  // Which thread scratch is this index's (unique per index made in this process; a copy
  // shares it, as it shares the scene).
  std::uint64_t id_;
};

// Clamp in double before converting: far-away or non-finite query points map to the border cells
// (which are then merely extra candidates) instead of overflowing the cast. Inline: the ray walk
// calls them for every ray.
inline int SceneIndex::column_of(double x) const {
  const double v = std::floor((x - x0_) / cell_m_);
  if (!(v >= 0.0)) return 0;
  if (v >= static_cast<double>(nx_ - 1)) return nx_ - 1;
  return static_cast<int>(v);
}

inline int SceneIndex::row_of(double y) const {
  const double v = std::floor((y - y0_) / cell_m_);
  if (!(v >= 0.0)) return 0;
  if (v >= static_cast<double>(ny_ - 1)) return ny_ - 1;
  return static_cast<int>(v);
}

template <class Visit>
void SceneIndex::for_cells_of_box(const mapper::Point2& lo, const mapper::Point2& hi,
                                  Visit&& visit) const {
  const int r0 = row_of(lo.y()), r1 = row_of(hi.y());
  const int c0 = column_of(lo.x()), c1 = column_of(hi.x());
  for (int r = r0; r <= r1; ++r) {
    for (int c = c0; c <= c1; ++c) visit(r * nx_ + c);
  }
}

template <class Visit>
void SceneIndex::for_new_surfaces_of_cell(int cell, QueryScratch& q, Visit&& visit) const {
  for (std::uint32_t k = surface_start_[cell]; k < surface_start_[cell + 1]; ++k) {
    const int id = surface_ids_[k];
    std::uint32_t& seen = q.stamp[static_cast<std::size_t>(id)];
    if (seen == q.query) continue;
    seen = q.query;
    visit(id);
  }
}

inline SceneIndex::QueryScratch& SceneIndex::next_query() const {
  thread_local QueryScratch q;
  if (q.index_id != id_) {
    q.index_id = id_;
    q.stamp.assign(scene_.surfaces.size(), 0);
    q.query = 0;
  }
  if (++q.query == 0) {
    std::fill(q.stamp.begin(), q.stamp.end(), 0);
    q.query = 1;
  }
  return q;
}

template <class Test>
void SceneIndex::walk_ray(const mapper::Point2& origin, const mapper::Point2& dir, double max_t_m,
                          Test&& test) const {
  const double ox = origin.x(), oy = origin.y(), dx = dir.x(), dy = dir.y();
  if (!(std::isfinite(ox) && std::isfinite(oy) && std::isfinite(dx) && std::isfinite(dy) &&
        std::isfinite(max_t_m))) {
    // Nothing to walk on: the padded gather clamps such rays to the border cells.
    thread_local std::vector<int> all;
    surfaces_near_ray(origin, dir, max_t_m, all);
    for (const int id : all) test(id);
    return;
  }
  QueryScratch& q = next_query();
  // Clip [0, max_t_m] to the grid's box (it holds every surface with a margin), so a ray from
  // outside starts where it enters.
  constexpr double kInf = std::numeric_limits<double>::infinity();
  double t_in = 0.0, t_out = max_t_m;
  auto clip = [&](double o, double d, double lo, double hi) {
    if (d == 0.0) {
      if (o < lo || o > hi) t_out = -kInf;  // parallel to the slab and outside it
      return;
    }
    const double a = (lo - o) / d, b = (hi - o) / d;
    t_in = std::max(t_in, std::min(a, b));
    t_out = std::min(t_out, std::max(a, b));
  };
  clip(ox, dx, x0_, x0_ + nx_ * cell_m_);
  clip(oy, dy, y0_, y0_ + ny_ * cell_m_);
  if (!(t_in <= t_out)) return;
  int c = column_of(ox + t_in * dx), r = row_of(oy + t_in * dy);
  const int step_c = dx > 0.0 ? 1 : (dx < 0.0 ? -1 : 0);
  const int step_r = dy > 0.0 ? 1 : (dy < 0.0 ? -1 : 0);
  constexpr double kPadM = 1e-3;  // as the cell lists' padding (sonar_scene_index.cc)
  double nearest_m = kInf;
  // Where the ray leaves column c / row r, from the cell's own borders (no accumulated rounding).
  // Each is recomputed only when the walk steps along its axis: it depends on c (or r) alone.
  auto exit_c = [&](int col) {
    return step_c > 0   ? (x0_ + (col + 1) * cell_m_ - ox) / dx
           : step_c < 0 ? (x0_ + col * cell_m_ - ox) / dx
                        : kInf;
  };
  auto exit_r = [&](int row) {
    return step_r > 0   ? (y0_ + (row + 1) * cell_m_ - oy) / dy
           : step_r < 0 ? (y0_ + row * cell_m_ - oy) / dy
                        : kInf;
  };
  double t_c = exit_c(c), t_r = exit_r(r);
  for (;;) {
    for_new_surfaces_of_cell(r * nx_ + c, q, [&](int id) { nearest_m = test(id); });
    const double t_leave = std::min(t_c, t_r);
    if (t_leave >= t_out) return;  // the ray ends in this cell
    // A hit at t lies in the cell the walk is in at t, and its surface is listed in every cell
    // within the padding of it: nothing untested can be hit before t_leave - kPadM.
    if (nearest_m < t_leave - kPadM) return;
    const bool next_c = t_c <= t_r, next_r = t_r <= t_c;
    // Only the index that stepped can leave the grid.
    if (next_c) {
      c += step_c;
      if (c < 0 || c >= nx_) return;
      t_c = exit_c(c);
    }
    if (next_r) {
      r += step_r;
      if (r < 0 || r >= ny_) return;
      t_r = exit_r(r);
    }
  }
}

}  // namespace cogmap::sim::sonar_detail
