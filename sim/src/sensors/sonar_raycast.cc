#include "sonar_raycast.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace cogmap::sim::sonar_detail {
namespace {

using mapper::Point2;

// Rays start this far beyond their origin so a bounce never re-hits the surface it leaves.
constexpr double kMinT = 1e-9;
// Line-of-sight slack: a target counts as visible if nothing blocks it this much nearer.
constexpr double kSightSlackM = 1e-6;

double cross(const Point2& a, const Point2& b) { return a.x() * b.y() - a.y() * b.x(); }

double heading_of(const Point2& v) { return std::atan2(v.y(), v.x()); }

bool inside_cone(const Cone& cone, const Point2& dir) {
  return std::abs(mapper::wrap_angle_rad(heading_of(dir) - cone.axis_rad)) <=
         cone.half_beam_rad + 1e-12;
}

// True when nothing in the scene (but `skip_surface`) is hit before `dist_m - slack` on the way
// from `from` in unit direction `dir`.
bool clear_line(const SonarScene& scene, const Point2& from, const Point2& dir, double dist_m,
                double slack_m, int skip_surface, const SceneIndex* index) {
  const double reach = dist_m - slack_m;
  if (reach <= kMinT) return true;
  return !first_hit(scene, from, dir, reach, skip_surface, index).has_value();
}

}  // namespace

std::optional<RayHit> first_hit(const SonarScene& scene, const Point2& origin, const Point2& dir,
                                double max_t_m, int skip_surface, const SceneIndex* index) {
  std::optional<RayHit> best;
  double best_t = max_t_m;
  // One surface's test, shared by the full scan and the indexed scan so both run the very same
  // floating-point operations in the same order.
  auto test = [&](int i) {
    if (i == skip_surface) return;
    const mapper::Segment& s = scene.surfaces[static_cast<std::size_t>(i)];
    const Point2 e = s.b - s.a;
    const double denom = cross(dir, e);
    if (std::abs(denom) < 1e-15) return;  // parallel: a grazing ray never echoes anyway
    const Point2 ao = s.a - origin;
    const double t = cross(ao, e) / denom;
    const double u = cross(ao, dir) / denom;
    if (t <= kMinT || t > best_t || u < 0.0 || u > 1.0) return;
    const double len = e.norm();
    best_t = t;
    best = RayHit{t, i, origin + t * dir, Point2(-e.y() / len, e.x() / len)};
  };
  if (index == nullptr) {
    for (int i = 0; i < static_cast<int>(scene.surfaces.size()); ++i) test(i);
    return best;
  }
  // Candidates come ascending, so ties (equal t: the later surface wins) resolve as in the full
  // scan. thread_local keeps the buffer's allocation across the ~30 rays of every ping.
  thread_local std::vector<int> candidates;
  index->surfaces_near_ray(origin, dir, max_t_m, candidates);
  for (const int i : candidates) test(i);
  return best;
}

double incidence_rad(const Point2& dir, const Point2& normal) {
  return std::acos(std::min(1.0, std::abs(dir.dot(normal))));
}

Point2 reflect(const Point2& dir, const Point2& normal) {
  return dir - 2.0 * dir.dot(normal) * normal;
}

SonarEcho first_echo(const SonarScene& scene, const Cone& cone, const SonarModelOptions& options,
                     const SceneIndex* index) {
  const double critical_rad = options.critical_angle_deg * std::numbers::pi / 180.0;
  double best = std::numeric_limits<double>::infinity();
  bool best_multipath = false;
  auto offer = [&](double range_m, bool multipath) {
    if (range_m <= cone.max_range_m && range_m < best) {
      best = range_m;
      best_multipath = multipath;
    }
  };

  // The wavefront first reaches a flat surface at the foot of the perpendicular; if that foot lies
  // on the segment, inside the cone and in sight, it is the nearest echo from that surface.
  for (const mapper::Segment& s : scene.surfaces) {
    const Point2 e = s.b - s.a;
    const double len2 = e.squaredNorm();
    if (len2 <= 0.0) continue;
    const double u = (cone.origin - s.a).dot(e) / len2;
    if (u < 0.0 || u > 1.0) continue;
    const Point2 foot = s.a + u * e;
    const double dist = (foot - cone.origin).norm();
    if (dist <= kMinT || dist >= best || dist > cone.max_range_m) continue;
    const Point2 dir = (foot - cone.origin) / dist;
    if (!inside_cone(cone, dir)) continue;
    if (clear_line(scene, cone.origin, dir, dist, kSightSlackM, -1, index)) offer(dist, false);
  }

  // Convex corners and edges scatter the pulse in every direction.
  for (const Point2& c : scene.corners) {
    const double dist = (c - cone.origin).norm();
    if (dist <= kMinT || dist >= best || dist > cone.max_range_m) continue;
    const Point2 dir = (c - cone.origin) / dist;
    if (!inside_cone(cone, dir)) continue;
    if (clear_line(scene, cone.origin, dir, dist, options.corner_radius_m, -1, index))
      offer(dist, false);
  }

  const int n = options.rays_per_cone;
  for (int i = 0; i < n; ++i) {
    const double offset =
        n == 1 ? 0.0 : -cone.half_beam_rad + 2.0 * cone.half_beam_rad * i / (n - 1);
    const double angle = cone.axis_rad + offset;
    const Point2 d(std::cos(angle), std::sin(angle));
    const auto h1 = first_hit(scene, cone.origin, d, cone.max_range_m, -1, index);
    if (!h1) continue;
    if (incidence_rad(d, h1->normal) <= critical_rad) {
      offer(h1->t_m, false);
      continue;
    }
    bool near_corner = false;
    if (index != nullptr) {
      near_corner = index->corner_within(h1->point, options.corner_radius_m);
    } else {
      for (const Point2& c : scene.corners) {
        near_corner = near_corner || (c - h1->point).norm() <= options.corner_radius_m;
      }
    }
    if (near_corner) {
      offer(h1->t_m, false);
      continue;
    }
    if (!options.multipath) continue;

    // Specular miss: follow one bounce. The half path can be at most max range, so the second
    // leg can be at most 2 * max range - t1 long.
    const Point2 d2 = reflect(d, h1->normal);
    const auto h2 =
        first_hit(scene, h1->point, d2, 2.0 * cone.max_range_m - h1->t_m, h1->surface, index);
    if (!h2) continue;
    if (incidence_rad(d2, h2->normal) <= critical_rad) {
      // The second surface scatters back along the bounce path: range = t1 + t2.
      offer(h1->t_m + h2->t_m, true);
      continue;
    }
    // Otherwise the second surface mirrors it again; it is heard if it heads back at the
    // transducer (a concave corner acts as a retro-reflector) and arrives inside the cone.
    const Point2 d3 = reflect(d2, h2->normal);
    const Point2 back = cone.origin - h2->point;
    const double t3 = back.norm();
    if (t3 <= kMinT) continue;
    const Point2 back_dir = back / t3;
    if (std::acos(std::clamp(d3.dot(back_dir), -1.0, 1.0)) > critical_rad) continue;
    if (!inside_cone(cone, -back_dir)) continue;
    if (!clear_line(scene, h2->point, back_dir, t3, kSightSlackM, h2->surface, index)) continue;
    offer(0.5 * (h1->t_m + h2->t_m + t3), true);
  }

  SonarEcho out;
  if (std::isfinite(best)) {
    out.echo = true;
    out.range_m = best;
    out.multipath = best_multipath;
  }
  return out;
}

}  // namespace cogmap::sim::sonar_detail
