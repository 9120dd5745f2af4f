#include "sonar_fan_surfaces.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <utility>

namespace cogmap::sim::sonar_detail {
namespace {

using mapper::Point2;

// A surface is skipped once its distance from the origin exceeds the nearest hit by this much.
// A hit at t lies on the surface t from the origin, so the surface is no farther than t; the
// margin is far above the rounding of the distances (~1e-15 m) and the same as the cell walk's
// padding (sonar_scene_index.h), which rests on the same argument.
constexpr double kNearSlackM = 1e-3;

// A surface end counts as ahead of the origin when its distance along the axis is at least this
// fraction of its distance (about 90° − 0.06°); a surface reaching nearer the side is tested by
// every ray.
constexpr double kAheadRatio = 1e-3;
// Tangents are compared with this relative margin: the rays' and ends' directions are rounded to
// ~1e-16, the test itself decides only within that, so nothing it could accept is skipped.
constexpr double kTanSlack = 1e-9;
constexpr double kAll = std::numeric_limits<double>::infinity();
// A fan with fewer surfaces than this is scanned whole (cutting it would cost more than it saves);
// a crowded one is cut into kSectors sectors of equal angle.
constexpr std::size_t kSectorMinSurfaces = 64;
constexpr int kSectors = 32;

}  // namespace

double FanSurfaces::tangent_of(const Point2& dir) const {
  const double x = axis_.dot(dir);
  return x > kAheadRatio ? cross(axis_, dir) / x : std::numeric_limits<double>::quiet_NaN();
}

void FanSurfaces::gather(const SceneIndex& index, const Point2& origin, const Point2& axis,
                         double cos_half, double sin_half, double reach_m) {
  scene_ = &index.scene();
  origin_ = origin;
  axis_ = axis;
  // The fan's bounding box: the origin, both edges' far ends, and the far point of every
  // compass direction inside the fan (where the arc bulges furthest along x or y).
  Point2 lo = origin, hi = origin;
  const auto grow = [&](const Point2& p) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  };
  for (const double side : {-1.0, 1.0}) {
    const Point2 edge(axis_.x() * cos_half - side * axis_.y() * sin_half,
                      axis_.y() * cos_half + side * axis_.x() * sin_half);
    grow(origin + reach_m * edge);
  }
  const double inside = cos_half - 1e-9;
  if (axis_.x() >= inside) grow(origin + Point2(reach_m, 0.0));
  if (axis_.y() >= inside) grow(origin + Point2(0.0, reach_m));
  if (-axis_.x() >= inside) grow(origin - Point2(reach_m, 0.0));
  if (-axis_.y() >= inside) grow(origin - Point2(0.0, reach_m));
  // Rays are made from rounded sines and cosines: a margin far above their rounding.
  const double pad = 1e-3 + 1e-9 * (std::abs(origin.x()) + std::abs(origin.y()) + reach_m);
  lo -= Point2(pad, pad);
  hi += Point2(pad, pad);

  index.surfaces_in_box(lo, hi, ids_);
  // What lies wholly beside the fan, or beyond its reach, no ray of it can meet.
  const double fan_tan = sin_half / cos_half * (1.0 + kTanSlack) + kTanSlack;
  const double far_sq = (reach_m + kNearSlackM) * (reach_m + kNearSlackM);
  surfaces_.clear();
  for (const int id : ids_) {
    const mapper::Segment& s = scene_->surfaces[static_cast<std::size_t>(id)];
    const Point2 a = s.a - origin, b = s.b - origin;
    Near n{0.0, id, -kAll, kAll};
    const double xa = axis_.dot(a), xb = axis_.dot(b);
    // Both ends clearly ahead: the segment lies ahead too, between its ends' directions.
    if (xa > 0.0 && xb > 0.0 && xa * xa > kAheadRatio * kAheadRatio * a.squaredNorm() &&
        xb * xb > kAheadRatio * kAheadRatio * b.squaredNorm()) {
      const double ta = cross(axis_, a) / xa, tb = cross(axis_, b) / xb;
      n.tan_lo = std::min(ta, tb);
      n.tan_hi = std::max(ta, tb);
      n.tan_lo -= kTanSlack * (1.0 + std::abs(n.tan_lo));
      n.tan_hi += kTanSlack * (1.0 + std::abs(n.tan_hi));
      if (n.tan_hi < -fan_tan || n.tan_lo > fan_tan) continue;
    }
    // The squared distance from the origin to the segment's nearest point.
    const Point2 e = b - a;
    const double len_sq = e.squaredNorm();
    const double along = len_sq > 0.0 ? std::clamp(-a.dot(e) / len_sq, 0.0, 1.0) : 0.0;
    n.distance_sq = (a + along * e).squaredNorm();
    if (n.distance_sq > far_sq) continue;
    surfaces_.push_back(n);
  }
  std::sort(surfaces_.begin(), surfaces_.end(),
            [](const Near& x, const Near& y) { return x.distance_sq < y.distance_sq; });
  build_sectors(cos_half, sin_half);
  index.corners_in_box(lo, hi, corners_);
}

int FanSurfaces::sector_of(double t) const {
  return static_cast<int>(std::upper_bound(sector_edges_.begin(), sector_edges_.end(), t) -
                          sector_edges_.begin());
}

void FanSurfaces::build_sectors(double cos_half, double sin_half) {
  sector_edges_.clear();
  sector_start_.clear();
  sector_items_.clear();
  if (surfaces_.size() < kSectorMinSurfaces) return;
  // Inner edges at equal angles; only their order matters for correctness (sector_of is a
  // count of edges at or below t, so it is monotone whatever their rounding).
  const double half = std::atan2(sin_half, cos_half);
  for (int k = 1; k < kSectors; ++k) {
    sector_edges_.push_back(std::tan(-half + 2.0 * half * k / kSectors));
  }
  sector_start_.assign(kSectors + 1, 0);
  const auto span_of = [&](const Near& n) {
    return std::pair(sector_of(n.tan_lo), sector_of(n.tan_hi));
  };
  for (const Near& n : surfaces_) {
    const auto [first, last] = span_of(n);
    for (int k = first; k <= last; ++k) ++sector_start_[static_cast<std::size_t>(k) + 1];
  }
  for (int k = 0; k < kSectors; ++k) {
    sector_start_[static_cast<std::size_t>(k) + 1] += sector_start_[static_cast<std::size_t>(k)];
  }
  sector_items_.resize(static_cast<std::size_t>(sector_start_.back()));
  sector_fill_.assign(sector_start_.begin(), sector_start_.end() - 1);
  // Surfaces in distance order, so every sector's list is nearest first too; copied, so a ray
  // reads its sector's list in one sweep of memory.
  for (const Near& n : surfaces_) {
    const auto [first, last] = span_of(n);
    for (int k = first; k <= last; ++k) {
      sector_items_[static_cast<std::size_t>(sector_fill_[static_cast<std::size_t>(k)]++)] = n;
    }
  }
}

std::span<const FanSurfaces::Near> FanSurfaces::sector_list(double t) const {
  const auto k = static_cast<std::size_t>(sector_of(t));
  return std::span<const Near>(sector_items_)
      .subspan(static_cast<std::size_t>(sector_start_[k]),
               static_cast<std::size_t>(sector_start_[k + 1] - sector_start_[k]));
}

std::optional<RayHit> FanSurfaces::first_hit(const Point2& dir, double max_t_m) const {
  int best_i = -1;
  double best_t = max_t_m;
  double within_sq = (best_t + kNearSlackM) * (best_t + kNearSlackM);
  const double tan_dir = tangent_of(dir);
  const bool ahead = !std::isnan(tan_dir);
  const auto visit = [&](const Near& n) {
    if (n.distance_sq > within_sq) return false;
    if (ahead && (tan_dir < n.tan_lo || tan_dir > n.tan_hi)) return true;
    if (test_surface(*scene_, n.surface, origin_, dir, best_t, best_i)) {
      within_sq = (best_t + kNearSlackM) * (best_t + kNearSlackM);
    }
    return true;
  };
  if (!sector_start_.empty() && ahead) {
    for (const Near& n : sector_list(tan_dir)) {
      if (!visit(n)) break;
    }
  } else {
    for (const Near& n : surfaces_) {
      if (!visit(n)) break;
    }
  }
  return finish_hit(*scene_, origin_, dir, best_t, best_i);
}

bool FanSurfaces::blocked(const Point2& dir, double reach_m) const {
  int best_i = -1;
  double best_t = reach_m;
  const double within_sq = (reach_m + kNearSlackM) * (reach_m + kNearSlackM);
  const double tan_dir = tangent_of(dir);
  const bool ahead = !std::isnan(tan_dir);
  // 1: a hit, 0: beyond reach, -1: go on.
  const auto visit = [&](const Near& n) {
    if (n.distance_sq > within_sq) return 0;
    if (ahead && (tan_dir < n.tan_lo || tan_dir > n.tan_hi)) return -1;
    return test_surface(*scene_, n.surface, origin_, dir, best_t, best_i) ? 1 : -1;
  };
  if (!sector_start_.empty() && ahead) {
    for (const Near& n : sector_list(tan_dir)) {
      const int r = visit(n);
      if (r >= 0) return r == 1;
    }
    return false;
  }
  for (const Near& n : surfaces_) {
    const int r = visit(n);
    if (r >= 0) return r == 1;
  }
  return false;
}

}  // namespace cogmap::sim::sonar_detail
