#include "sonar_raycast.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <span>

#include "sonar_fan_surfaces.h"

namespace cogmap::sim::sonar_detail {
namespace {

using mapper::Point2;

// Line-of-sight slack: a target counts as visible if nothing blocks it this much nearer.
constexpr double kSightSlackM = 1e-6;

// True when nothing in the scene (but `skip_surface`) is hit before `dist_m - slack` on the way
// from `from` in unit direction `dir`.
bool clear_line(const SonarScene& scene, const Point2& from, const Point2& dir, double dist_m,
                double slack_m, int skip_surface, const SceneIndex* index) {
  const double reach = dist_m - slack_m;
  if (reach <= kMinT) return true;
  return !first_hit(scene, from, dir, reach, skip_surface, index).has_value();
}

}  // namespace

std::optional<RayHit> finish_hit(const SonarScene& scene, const Point2& origin, const Point2& dir,
                                 double best_t, int best_i) {
  if (best_i < 0) return std::nullopt;
  const mapper::Segment& s = scene.surfaces[static_cast<std::size_t>(best_i)];
  const Point2 e = s.b - s.a;
  const double len = e.norm();
  return RayHit{best_t, best_i, origin + best_t * dir, Point2(-e.y() / len, e.x() / len)};
}

std::optional<RayHit> first_hit(const SonarScene& scene, const Point2& origin, const Point2& dir,
                                double max_t_m, int skip_surface, const SceneIndex* index) {
  int best_i = -1;
  double best_t = max_t_m;
  if (index == nullptr) {
    for (int i = 0; i < static_cast<int>(scene.surfaces.size()); ++i) {
      if (i != skip_surface) test_surface(scene, i, origin, dir, best_t, best_i);
    }
    return finish_hit(scene, origin, dir, best_t, best_i);
  }
  // Cell by cell outwards from the origin, stopping once the nearest hit lies before the next
  // cell: test_surface keeps the nearest hit (ties to the higher index) whatever the order.
  index->walk_ray(origin, dir, max_t_m, [&](int i) {
    if (i != skip_surface) test_surface(scene, i, origin, dir, best_t, best_i);
    return best_t;
  });
  return finish_hit(scene, origin, dir, best_t, best_i);
}

Point2 reflect(const Point2& dir, const Point2& normal) {
  return dir - 2.0 * dir.dot(normal) * normal;
}

namespace {

// A candidate this strong is heard with probability exactly 1.0 in double precision
// (1 - exp(-37) rounds to 1), so no later echo can ever be the first heard.
constexpr double kCertainStrength = 37.0;

// The two-way beam pattern at `offset_rad` from the axis (1 on the axis).
double beam_pattern(double offset_rad, double sigma_rad) {
  const double z = offset_rad / sigma_rad;
  return std::exp(-0.5 * z * z);
}

// Expected detections of one ray's share (width dphi_rad) of a surface hit at incidence
// incidence acos(cos_incidence) after a path whose one-way length is range_m: the mirror lobe
// (normalised so that the rays across it add up to specular_strength) plus the diffuse backscatter.
// x^e with the exponents the defaults use done exactly and cheaply (pow is ~5 % of a ping).
double power(double x, double e) {
  if (e == 0.0) return 1.0;
  if (e == 1.0) return x;
  if (e == 0.5) return std::sqrt(x);
  if (e == 2.0) return x * x;
  return std::pow(x, e);
}

// `cos_incidence` = |ray · normal|.
double surface_strength(const SonarMaterial& m, double cos_incidence, double range_m,
                        double range_gain_exponent, double dphi_rad) {
  const double lobe_rad = m.specular_lobe_deg * std::numbers::pi / 180.0;
  double mirror = 0.0;
  // Beyond 8 lobe widths exp(-32) adds nothing: skip the acos and exp. The cut-off's cosine is
  // remembered for the last few lobe widths (a scene has a handful of materials): the same double.
  constexpr int kCutoffCache = 4;
  constexpr double kNone = std::numeric_limits<double>::quiet_NaN();  // equal to nothing
  thread_local double cached_lobe[kCutoffCache] = {kNone, kNone, kNone, kNone};
  thread_local double cached_cos[kCutoffCache] = {};
  thread_local int cached_next = 0;
  double cutoff = 0.0;
  int k = 0;
  while (k < kCutoffCache && !(cached_lobe[k] == lobe_rad)) ++k;
  if (k < kCutoffCache) {
    cutoff = cached_cos[k];
  } else {
    cutoff = std::cos(std::min(8.0 * lobe_rad, std::numbers::pi / 2));
    cached_lobe[cached_next] = lobe_rad;
    cached_cos[cached_next] = cutoff;
    cached_next = (cached_next + 1) % kCutoffCache;
  }
  if (cos_incidence > cutoff) {
    const double z = std::acos(std::min(1.0, cos_incidence)) / lobe_rad;
    mirror = m.specular_strength * std::exp(-0.5 * z * z) /
             (std::sqrt(2.0 * std::numbers::pi) * lobe_rad);
  }
  const double diffuse = m.diffuse_strength * power(cos_incidence, m.diffuse_incidence_exponent) *
                         power(std::max(range_m, 0.1), range_gain_exponent);
  return (mirror + diffuse) * dphi_rad;
}

}  // namespace

namespace {

// What every ray of one ping shares.
struct Fan {
  double sigma_rad, fan_rad, cos_fan, sin_fan, gain, g_exp, dphi;
  Point2 axis;
  /// False only for a direction surely outside the fan (its cosine with the axis below the
  /// edge's by far more than rounding): offset_of would put it beyond fan_rad too, without the
  /// atan2.
  bool may_be_inside(const Point2& dir) const { return axis.dot(dir) >= cos_fan - 1e-12; }
  double offset_of(const Point2& dir) const { return std::atan2(cross(axis, dir), axis.dot(dir)); }
};

Fan fan_of(const Cone& cone, const SonarModelOptions& options) {
  Fan f;
  f.sigma_rad = options.beam_sigma_deg * std::numbers::pi / 180.0;
  f.fan_rad = options.fan_half_width_deg * std::numbers::pi / 180.0;
  f.cos_fan = std::cos(f.fan_rad);
  f.sin_fan = std::sin(f.fan_rad);
  f.gain = std::pow(10.0, options.detection_gain_db / 10.0);
  f.g_exp = options.diffuse_range_gain_exponent;
  const int n = options.rays_per_cone;
  f.dphi = n == 1 ? 2.0 * f.fan_rad : 2.0 * f.fan_rad / (n - 1);
  f.axis = Point2(std::cos(cone.axis_rad), std::sin(cone.axis_rad));
  return f;
}

struct Ray {
  Point2 d;
  double offset, beam;
  std::optional<RayHit> hit;
};

// The direct hit of every ray of the fan, then every convex corner in sight, appended to `out` in
// that order; `rays` gets every ray. Returns the range of the nearest candidate heard for certain
// (probability exactly 1 in double precision: nothing beyond it can be the first heard), or
// infinity.
double direct_candidates(const SonarScene& scene, const Cone& cone,
                         const SonarModelOptions& options, const SceneIndex* index, const Fan& f,
                         std::vector<Ray>& rays, std::vector<EchoCandidate>& out) {
  const int n = options.rays_per_cone;
  // The offset and beam weight of each ray depend only on the options: kept from the last ping
  // whose options were the same (the same doubles as computing them again).
  struct FanTable {
    int n = -1;
    double fan_rad = 0.0, sigma_rad = 0.0, gain = 0.0;
    std::vector<double> offset, beam;
  };
  thread_local FanTable table;
  if (!(table.n == n && table.fan_rad == f.fan_rad && table.sigma_rad == f.sigma_rad &&
        table.gain == f.gain)) {
    table.n = n;
    table.fan_rad = f.fan_rad;
    table.sigma_rad = f.sigma_rad;
    table.gain = f.gain;
    table.offset.clear();
    table.beam.clear();
    for (int i = 0; i < n; ++i) {
      const double offset = n == 1 ? 0.0 : -f.fan_rad + 2.0 * f.fan_rad * i / (n - 1);
      table.offset.push_back(offset);
      table.beam.push_back(f.gain * beam_pattern(offset, f.sigma_rad));
    }
  }
  // With an index, what the whole fan can meet is gathered once, nearest first (a finite cone
  // only: the cell walk clamps anything else to the grid's border).
  thread_local FanSurfaces fan;
  const bool by_fan = index != nullptr && std::isfinite(cone.origin.x()) &&
                      std::isfinite(cone.origin.y()) && std::isfinite(cone.axis_rad) &&
                      std::isfinite(cone.max_range_m);
  if (by_fan) fan.gather(*index, cone.origin, f.axis, f.cos_fan, f.sin_fan, cone.max_range_m);
  double certain_m = std::numeric_limits<double>::infinity();
  for (int i = 0; i < n; ++i) {
    const double offset = table.offset[static_cast<std::size_t>(i)];
    const double angle = cone.axis_rad + offset;
    Ray ray{Point2(std::cos(angle), std::sin(angle)), offset,
            table.beam[static_cast<std::size_t>(i)], std::nullopt};
    ray.hit = by_fan ? fan.first_hit(ray.d, cone.max_range_m)
                     : first_hit(scene, cone.origin, ray.d, cone.max_range_m, -1, index);
    if (ray.hit) {
      const SonarMaterial& m1 = scene.material_of(ray.hit->surface);
      const double strength = ray.beam * surface_strength(m1, std::abs(ray.d.dot(ray.hit->normal)),
                                                          ray.hit->t_m, f.g_exp, f.dphi);
      out.push_back({ray.hit->t_m, strength, false});
      if (strength >= kCertainStrength) certain_m = std::min(certain_m, ray.hit->t_m);
    }
    rays.push_back(ray);
  }
  // Convex corners and edges diffract the pulse in every direction (none beyond a certain
  // echo can be heard first, so their line of sight is not tested).
  // clear_line, through the fan's list when there is one.
  const auto in_sight = [&](const Point2& dir, double dist) {
    if (!by_fan)
      return clear_line(scene, cone.origin, dir, dist, options.corner_radius_m, -1, index);
    const double reach = dist - options.corner_radius_m;
    return reach <= kMinT || !fan.blocked(dir, reach);
  };
  // The corners in the fan's box, in the scene's order (any other corner is out of the fan or
  // out of range, and skipped below).
  thread_local std::vector<int> all_corners;
  std::span<const int> corner_ids;
  if (by_fan) {
    corner_ids = fan.corners();
  } else {
    if (all_corners.size() != scene.corners.size()) {
      all_corners.resize(scene.corners.size());
      for (std::size_t k = 0; k < all_corners.size(); ++k) all_corners[k] = static_cast<int>(k);
    }
    corner_ids = all_corners;
  }
  for (const int id : corner_ids) {
    const Point2& c = scene.corners[static_cast<std::size_t>(id)];
    // A corner more than `reach` away along x or y is further than max range or a certain echo:
    // its norm is at least |dx| (1 - 4 eps) > bound, so the exact test below would skip it too.
    const double bound = std::min(cone.max_range_m, certain_m);
    if (bound < 1e6) {
      const Point2 v = c - cone.origin;
      const double reach = bound + 1e-6;
      if (std::abs(v.x()) > reach || std::abs(v.y()) > reach) continue;
    }
    const double dist = (c - cone.origin).norm();
    if (dist <= kMinT || dist > cone.max_range_m || dist > certain_m) continue;
    const Point2 dir = (c - cone.origin) / dist;
    if (!f.may_be_inside(dir)) continue;  // outside the fan: skip the atan2
    const double offset = f.offset_of(dir);
    if (std::abs(offset) > f.fan_rad) continue;
    if (!in_sight(dir, dist)) continue;
    const double strength = f.gain * options.corner_strength * beam_pattern(offset, f.sigma_rad);
    out.push_back({dist, strength, false});
    if (strength >= kCertainStrength) certain_m = std::min(certain_m, dist);
  }
  return certain_m;
}

// True when the mirrored part of `ray` goes on, so bounce_candidates may add something.
bool bounces(const SonarScene& scene, const SonarModelOptions& options, const Ray& ray,
             double certain_m) {
  return ray.hit && ray.hit->t_m < certain_m && options.multipath &&
         scene.material_of(ray.hit->surface).mirror_reflectivity > 0.0;
}

// The one-bounce candidates of a ray for which bounces() holds, appended to `out`: the scattered
// echo of the second surface, then the retro-reflection of a concave corner. Neither is ever
// nearer than the ray's first hit (t1 + t2 >= t1; (t1 + t2 + t3) / 2 >= t1 as t2 + t3 >= t1).
void bounce_candidates(const SonarScene& scene, const Cone& cone, const SceneIndex* index,
                       const Fan& f, const Ray& ray, double certain_m,
                       std::vector<EchoCandidate>& out) {
  const std::optional<RayHit>& h1 = ray.hit;
  const Point2& d = ray.d;
  const SonarMaterial& m1 = scene.material_of(h1->surface);
  // The mirrored part goes on. No echo later than max range, nor later than a certain one,
  // can be heard first. The scattered echo reads t1 + t2 >= t2 and the retro-reflection
  // (t1 + t2 + t3) / 2 >= t2 (triangle inequality: t1 + t3 >= t2), so a second surface
  // further than `latest` gives no candidate: the second leg is cast no further than that,
  // plus a margin far above the rounding of the points (~1e-16 of their coordinates), and
  // never further than 2 * latest - t1 (the bound before this one, so nothing new is cast).
  const double mirrored = ray.beam * m1.mirror_reflectivity;
  const Point2 d2 = reflect(d, h1->normal);
  const double latest_m = std::min(cone.max_range_m, certain_m);
  const double margin_m =
      1e-6 + 1e-9 * (std::abs(cone.origin.x()) + std::abs(cone.origin.y()) +
                     std::abs(h1->point.x()) + std::abs(h1->point.y()) + latest_m);
  const double leg_m = std::min(2.0 * latest_m - h1->t_m, latest_m + margin_m);
  const auto h2 = first_hit(scene, h1->point, d2, leg_m, h1->surface, index);
  if (!h2) return;
  const SonarMaterial& m2 = scene.material_of(h2->surface);
  // The second surface scatters back along the bounce path: range = t1 + t2.
  const double back_range = h1->t_m + h2->t_m;
  if (back_range <= latest_m) {
    out.push_back(
        {back_range,
         mirrored * surface_strength(m2, std::abs(d2.dot(h2->normal)), back_range, f.g_exp, f.dphi),
         true});
  }
  // Or it mirrors again straight back at the transducer: a concave corner is a
  // retro-reflector, heard at about its own distance though both walls are oblique.
  const Point2 d3 = reflect(d2, h2->normal);
  const Point2 back = cone.origin - h2->point;
  const double t3 = back.norm();
  if (t3 <= kMinT) return;
  const Point2 back_dir = back / t3;
  const double retro_range = 0.5 * (h1->t_m + h2->t_m + t3);
  if (retro_range > latest_m) return;
  if (!f.may_be_inside(-back_dir)) return;  // arriving from outside the fan: skip the atan2
  const double arrival_offset = f.offset_of(-back_dir);
  if (std::abs(arrival_offset) > f.fan_rad) return;
  const double mismatch = std::acos(std::clamp(d3.dot(back_dir), -1.0, 1.0));
  const double lobe_rad = m2.specular_lobe_deg * std::numbers::pi / 180.0;
  if (mismatch > 4.0 * lobe_rad) return;  // beyond 4 sd the lobe adds nothing measurable
  if (!clear_line(scene, h2->point, back_dir, t3, kSightSlackM, h2->surface, index)) return;
  // Leaving along the ray and arriving from arrival_offset: the geometric mean of the two
  // one-way patterns stands in for the two-way pattern.
  const double two_way =
      std::sqrt(beam_pattern(ray.offset, f.sigma_rad) * beam_pattern(arrival_offset, f.sigma_rad));
  const double z = mismatch / lobe_rad;
  const double strength = f.gain * two_way * m1.mirror_reflectivity * m2.mirror_reflectivity *
                          m2.specular_strength * std::exp(-0.5 * z * z) /
                          (std::sqrt(2.0 * std::numbers::pi) * lobe_rad) * f.dphi;
  out.push_back({retro_range, strength, true});
}

bool by_range(const EchoCandidate& a, const EchoCandidate& b) { return a.range_m < b.range_m; }

bool any_nan_range(const std::vector<EchoCandidate>& v) {
  return std::any_of(v.begin(), v.end(),
                     [](const EchoCandidate& c) { return std::isnan(c.range_m); });
}

// Stable insertion sort by range: the same order as std::stable_sort, without its temporary
// buffer per ping (a ping has a few dozen candidates). Only a NaN range (a non-finite pose)
// breaks the strict weak order, and then the two could differ: such a ping, or one with very
// many candidates (a huge rays_per_cone), keeps std::stable_sort.
void stable_sort_by_range(std::vector<EchoCandidate>& out) {
  constexpr std::size_t kInsertionSortMax = 128;
  if (out.size() > kInsertionSortMax || any_nan_range(out)) {
    std::stable_sort(out.begin(), out.end(), by_range);
    return;
  }
  for (std::size_t i = 1; i < out.size(); ++i) {
    const EchoCandidate x = out[i];
    std::size_t j = i;
    for (; j > 0 && by_range(x, out[j - 1]); --j) out[j] = out[j - 1];
    out[j] = x;
  }
}

}  // namespace

std::vector<EchoCandidate> echo_candidates(const SonarScene& scene, const Cone& cone,
                                           const SonarModelOptions& options,
                                           const SceneIndex* index) {
  std::vector<EchoCandidate> out;
  echo_candidates(scene, cone, options, index, out);
  return out;
}

void echo_candidates(const SonarScene& scene, const Cone& cone, const SonarModelOptions& options,
                     const SceneIndex* index, std::vector<EchoCandidate>& out) {
  out.clear();
  const Fan f = fan_of(cone, options);
  // Direct hits of every ray first: a candidate heard for certain ends the listening, so nothing
  // beyond it is traced. Bounce paths are never shorter than their first leg, so the cut is exact.
  thread_local std::vector<Ray> rays;
  rays.clear();
  const double certain_m = direct_candidates(scene, cone, options, index, f, rays, out);
  for (const Ray& ray : rays) {
    if (bounces(scene, options, ray, certain_m)) {
      bounce_candidates(scene, cone, index, f, ray, certain_m, out);
    }
  }
  std::erase_if(out, [&](const EchoCandidate& c) { return c.range_m > certain_m; });
  stable_sort_by_range(out);
}

std::optional<EchoCandidate> first_heard(const SonarScene& scene, const Cone& cone,
                                         const SonarModelOptions& options, const SceneIndex* index,
                                         EchoListener& listener) {
  const auto offer_all =
      [&](const std::vector<EchoCandidate>& all) -> std::optional<EchoCandidate> {
    for (const EchoCandidate& c : all) {
      if (listener.hears(c)) return c;
    }
    return std::nullopt;
  };
  thread_local std::vector<EchoCandidate> direct;
  direct.clear();
  // A non-finite cone can give NaN ranges, whose order only the full list defines.
  if (!(std::isfinite(cone.origin.x()) && std::isfinite(cone.origin.y()) &&
        std::isfinite(cone.axis_rad))) {
    echo_candidates(scene, cone, options, index, direct);
    return offer_all(direct);
  }
  const Fan f = fan_of(cone, options);
  thread_local std::vector<Ray> rays;
  rays.clear();
  const double certain_m = direct_candidates(scene, cone, options, index, f, rays, direct);
  std::erase_if(direct, [&](const EchoCandidate& c) { return c.range_m > certain_m; });
  stable_sort_by_range(direct);

  // The full list is ordered by range, ties in the order the candidates were made: every direct
  // hit and corner before every bounce, bounces by ray and the scattered echo before the
  // retro-reflection. A ray's bounces are traced only once the listener is offered a candidate
  // at or beyond its first hit's range: they can be no nearer, so the order is the same.
  thread_local std::vector<int> pending;  // rays whose mirrored part goes on, by first-hit range
  pending.clear();
  for (int i = 0; i < static_cast<int>(rays.size()); ++i) {
    if (bounces(scene, options, rays[static_cast<std::size_t>(i)], certain_m)) pending.push_back(i);
  }
  const auto t1_of = [&](int i) { return rays[static_cast<std::size_t>(i)].hit->t_m; };
  // Unstable (no buffer to allocate): the order of equal ranges does not matter, as every ray
  // at or before a candidate's range is traced before that candidate is offered.
  std::sort(pending.begin(), pending.end(), [&](int a, int b) { return t1_of(a) < t1_of(b); });
  struct Bounce {
    EchoCandidate c;
    int order;  // 2 * ray + (0 scattered, 1 retro-reflected): the full list's order of making
  };
  thread_local std::vector<Bounce> bounced;  // traced, not yet offered, by (range, order)
  thread_local std::vector<EchoCandidate> scratch;
  bounced.clear();
  std::size_t next_direct = 0, next_bounce = 0, next_pending = 0;
  for (;;) {
    const bool have_direct = next_direct < direct.size();
    const bool have_bounce = next_bounce < bounced.size();
    // The next candidate in the full list's order among those traced: a direct one wins a tie.
    const bool take_direct = have_direct && (!have_bounce || direct[next_direct].range_m <=
                                                                 bounced[next_bounce].c.range_m);
    const double range_m = take_direct   ? direct[next_direct].range_m
                           : have_bounce ? bounced[next_bounce].c.range_m
                                         : std::numeric_limits<double>::infinity();
    if (next_pending < pending.size() && t1_of(pending[next_pending]) <= range_m) {
      const int ray = pending[next_pending++];
      scratch.clear();
      bounce_candidates(scene, cone, index, f, rays[static_cast<std::size_t>(ray)], certain_m,
                        scratch);
      for (std::size_t k = 0; k < scratch.size(); ++k) {
        if (scratch[k].range_m > certain_m) continue;
        // A ray's scattered echo (if any) comes first: k orders the two within the ray.
        const Bounce b{scratch[k], 2 * ray + static_cast<int>(k)};
        auto at = std::upper_bound(bounced.begin() + static_cast<std::ptrdiff_t>(next_bounce),
                                   bounced.end(), b, [](const Bounce& x, const Bounce& y) {
                                     return x.c.range_m < y.c.range_m ||
                                            (x.c.range_m == y.c.range_m && x.order < y.order);
                                   });
        bounced.insert(at, b);
      }
      continue;
    }
    if (!have_direct && !have_bounce) return std::nullopt;
    const EchoCandidate c = take_direct ? direct[next_direct++] : bounced[next_bounce++].c;
    if (listener.hears(c)) return c;
  }
}

}  // namespace cogmap::sim::sonar_detail
