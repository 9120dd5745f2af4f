#include "sonar_scene_index.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <limits>

namespace cogmap::sim::sonar_detail {
namespace {

using mapper::Point2;

// Every cell a segment comes within this distance of is listed, on both the surface side and the
// query side. Rounding in the rasterisation is ~1e-14 m, so 1 mm is a wide margin: a surface the
// brute-force test could accept always shares a listed cell with the query. Extra candidates only
// cost time; the exact test still decides.
constexpr double kPadM = 1e-3;
// Beyond this the per-cell lists stop paying for themselves; the pitch doubles until it fits.
constexpr double kMaxCells = 65536.0;

// The byte comparison below relies on a segment being exactly four packed doubles.
static_assert(sizeof(mapper::Segment) == 4 * sizeof(double));
static_assert(sizeof(Point2) == 2 * sizeof(double));

// Each index's thread scratch is told apart by this number (never 0, never reused).
std::uint64_t next_index_id() {
  static std::atomic<std::uint64_t> last{0};
  return last.fetch_add(1, std::memory_order_relaxed) + 1;
}

}  // namespace

template <class Visit>
void SceneIndex::for_cells_of_segment(const Point2& a, const Point2& b, Visit&& visit) const {
  const int r0 = row_of(std::min(a.y(), b.y()) - kPadM);
  const int r1 = row_of(std::max(a.y(), b.y()) + kPadM);
  const double dx = b.x() - a.x();
  const double dy = b.y() - a.y();
  // A (nearly) horizontal segment spans its whole x range in each of its one or two rows.
  const bool flat = std::abs(dy) <= 1e-12;
  for (int r = r0; r <= r1; ++r) {
    double xa = a.x(), xb = b.x();
    if (!flat) {
      // The part of the segment inside this row's band, widened by the padding.
      const double ylo = y0_ + r * cell_m_ - kPadM;
      const double yhi = y0_ + (r + 1) * cell_m_ + kPadM;
      double s0 = (ylo - a.y()) / dy;
      double s1 = (yhi - a.y()) / dy;
      if (s0 > s1) std::swap(s0, s1);
      s0 = std::clamp(s0, 0.0, 1.0);
      s1 = std::clamp(s1, 0.0, 1.0);
      xa = a.x() + s0 * dx;
      xb = a.x() + s1 * dx;
    }
    const int c0 = column_of(std::min(xa, xb) - kPadM);
    const int c1 = column_of(std::max(xa, xb) + kPadM);
    for (int c = c0; c <= c1; ++c) visit(r * nx_ + c);
  }
}

SceneIndex::SceneIndex(const SonarScene& scene, double cell_m)
    : scene_(scene), cell_m_(cell_m), id_(next_index_id()) {
  double xmin = std::numeric_limits<double>::infinity(), ymin = xmin;
  double xmax = -xmin, ymax = -xmin;
  auto grow = [&](const Point2& p) {
    xmin = std::min(xmin, p.x());
    ymin = std::min(ymin, p.y());
    xmax = std::max(xmax, p.x());
    ymax = std::max(ymax, p.y());
  };
  for (const mapper::Segment& s : scene_.surfaces) {
    grow(s.a);
    grow(s.b);
  }
  for (const Point2& c : scene_.corners) grow(c);
  if (!(xmin <= xmax && ymin <= ymax)) xmin = xmax = ymin = ymax = 0.0;  // empty scene
  x0_ = xmin - 2.0 * kPadM;
  y0_ = ymin - 2.0 * kPadM;
  const double w = xmax - xmin + 4.0 * kPadM;
  const double h = ymax - ymin + 4.0 * kPadM;
  if (!(cell_m_ > 0.0)) cell_m_ = 1.0;
  while (std::ceil(w / cell_m_) * std::ceil(h / cell_m_) > kMaxCells) cell_m_ *= 2.0;
  nx_ = std::max(1, static_cast<int>(std::ceil(w / cell_m_)));
  ny_ = std::max(1, static_cast<int>(std::ceil(h / cell_m_)));
  const std::size_t cells = static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_);

  // Two passes (count, then fill) give compact per-cell lists; surfaces are visited in ascending
  // index, so every list comes out ascending.
  auto fill = [&](auto&& each_item, std::size_t count, std::vector<std::uint32_t>& start,
                  std::vector<int>& ids) {
    start.assign(cells + 1, 0);
    for (std::size_t i = 0; i < count; ++i) each_item(i, [&](int cell) { ++start[cell + 1]; });
    for (std::size_t c = 0; c < cells; ++c) start[c + 1] += start[c];
    ids.assign(start[cells], 0);
    std::vector<std::uint32_t> next(start.begin(), start.end() - 1);
    for (std::size_t i = 0; i < count; ++i) {
      each_item(i, [&](int cell) { ids[next[cell]++] = static_cast<int>(i); });
    }
  };
  fill(
      [&](std::size_t i, auto&& visit) {
        const mapper::Segment& s = scene_.surfaces[i];
        for_cells_of_segment(s.a, s.b, visit);
      },
      scene_.surfaces.size(), surface_start_, surface_ids_);
  fill([&](std::size_t i,
           auto&& visit) { for_cells_of_segment(scene_.corners[i], scene_.corners[i], visit); },
       scene_.corners.size(), corner_start_, corner_ids_);
}

bool SceneIndex::matches(const SonarScene& scene) const {
  // Bitwise, not ==: -0.0 and 0.0 (or two NaNs) must count as different scenes, since only a
  // bit-identical scene is guaranteed the same answers.
  return scene.surfaces.size() == scene_.surfaces.size() &&
         scene.corners.size() == scene_.corners.size() &&
         (scene.surfaces.empty() ||
          std::memcmp(scene.surfaces.data(), scene_.surfaces.data(),
                      scene.surfaces.size() * sizeof(mapper::Segment)) == 0) &&
         (scene.corners.empty() || std::memcmp(scene.corners.data(), scene_.corners.data(),
                                               scene.corners.size() * sizeof(Point2)) == 0);
}

void SceneIndex::surfaces_near_ray(const Point2& origin, const Point2& dir, double max_t_m,
                                   std::vector<int>& out) const {
  out.clear();
  // Each surface once (a long wall lies in many cells), in cell order: first_hit breaks ties by
  // surface index, so the order does not change its answer. A stamp per surface replaces the
  // sort + unique that cost 40 % of all sonar instructions.
  QueryScratch& q = next_query();
  const Point2 end = origin + max_t_m * dir;
  for_cells_of_segment(origin, end, [&](int cell) {
    for_new_surfaces_of_cell(cell, q, [&](int id) { out.push_back(id); });
  });
}

void SceneIndex::surfaces_in_box(const Point2& lo, const Point2& hi, std::vector<int>& out) const {
  out.clear();
  QueryScratch& q = next_query();
  const Point2 pad(kPadM, kPadM);
  for_cells_of_box(lo - pad, hi + pad, [&](int cell) {
    for_new_surfaces_of_cell(cell, q, [&](int id) { out.push_back(id); });
  });
}

void SceneIndex::corners_in_box(const Point2& lo, const Point2& hi, std::vector<int>& out) const {
  out.clear();
  const Point2 pad(kPadM, kPadM);
  for_cells_of_box(lo - pad, hi + pad, [&](int cell) {
    out.insert(out.end(), corner_ids_.begin() + corner_start_[cell],
               corner_ids_.begin() + corner_start_[cell + 1]);
  });
  // A corner within the padding of a cell border is listed in each cell it touches.
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
}

bool SceneIndex::corner_within(const Point2& p, double radius_m) const {
  const double reach = radius_m + kPadM;
  const int r0 = row_of(p.y() - reach), r1 = row_of(p.y() + reach);
  const int c0 = column_of(p.x() - reach), c1 = column_of(p.x() + reach);
  for (int r = r0; r <= r1; ++r) {
    for (int c = c0; c <= c1; ++c) {
      const int cell = r * nx_ + c;
      for (std::uint32_t k = corner_start_[cell]; k < corner_start_[cell + 1]; ++k) {
        const Point2& q = scene_.corners[static_cast<std::size_t>(corner_ids_[k])];
        if ((q - p).norm() <= radius_m) return true;
      }
    }
  }
  return false;
}

}  // namespace cogmap::sim::sonar_detail
