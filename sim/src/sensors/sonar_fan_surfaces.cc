#include "sonar_fan_surfaces.h"

#include <algorithm>
#include <cmath>
#include <limits>

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
  index.corners_in_box(lo, hi, corners_);
}

std::optional<RayHit> FanSurfaces::first_hit(const Point2& dir, double max_t_m) const {
  int best_i = -1;
  double best_t = max_t_m;
  double within_sq = (best_t + kNearSlackM) * (best_t + kNearSlackM);
  const double tan_dir = tangent_of(dir);
  const bool ahead = !std::isnan(tan_dir);
  for (const Near& n : surfaces_) {
    if (n.distance_sq > within_sq) break;
    if (ahead && (tan_dir < n.tan_lo || tan_dir > n.tan_hi)) continue;
    if (test_surface(*scene_, n.surface, origin_, dir, best_t, best_i)) {
      within_sq = (best_t + kNearSlackM) * (best_t + kNearSlackM);
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
  for (const Near& n : surfaces_) {
    if (n.distance_sq > within_sq) return false;
    if (ahead && (tan_dir < n.tan_lo || tan_dir > n.tan_hi)) continue;
    if (test_surface(*scene_, n.surface, origin_, dir, best_t, best_i)) return true;
  }
  return false;
}

}  // namespace cogmap::sim::sonar_detail
