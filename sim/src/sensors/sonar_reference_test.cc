// The sonar's echo candidates must never change when its code is made faster (issue 13: every
// run bit-identical). This file keeps the implementation of 2026-12-01 before that work, verbatim
// (sonar_raycast.cc as it was: full-scan ray casts, a bounce's second leg cast 2 * latest - t1
// far, std::stable_sort) as a reference, and compares the current echo_candidates (with the
// scene index, as SonarModel uses it) with it bit for bit over random cones in every shipped
// world, with default and non-default options and a random mix of materials.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <limits>
#include <numbers>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "cogmap/sim/world_geometry.h"
#include "cogmap/sim/world_spec.h"
#include "shipped_worlds_test_support.h"
#include "sonar_raycast.h"
#include "sonar_scene_index.h"

// ---- The reference: sonar_raycast.cc before issue 13's speed work (do not optimise) ----

namespace cogmap::sim::sonar_reference {

using sonar_detail::Cone;
using sonar_detail::RayHit;
using sonar_detail::SceneIndex;

std::optional<RayHit> ref_first_hit(const SonarScene& scene, const mapper::Point2& origin,
                                    const mapper::Point2& dir, double max_t_m,
                                    int skip_surface = -1, const SceneIndex* index = nullptr);

namespace {

using mapper::Point2;

// Rays start this far beyond their origin so a bounce never re-hits the surface it leaves.
constexpr double kMinT = 1e-9;
// Line-of-sight slack: a target counts as visible if nothing blocks it this much nearer.
constexpr double kSightSlackM = 1e-6;

double cross(const Point2& a, const Point2& b) { return a.x() * b.y() - a.y() * b.x(); }

// True when nothing in the scene (but `skip_surface`) is hit before `dist_m - slack` on the way
// from `from` in unit direction `dir`.
bool clear_line(const SonarScene& scene, const Point2& from, const Point2& dir, double dist_m,
                double slack_m, int skip_surface, const SceneIndex* index) {
  const double reach = dist_m - slack_m;
  if (reach <= kMinT) return true;
  return !ref_first_hit(scene, from, dir, reach, skip_surface, index).has_value();
}

}  // namespace

namespace {

// One surface's test, shared by every scan so all run the very same floating-point operations.
// Equally distant surfaces: the higher index wins, whatever order they are tested in.
void test_surface(const SonarScene& scene, int i, const Point2& origin, const Point2& dir,
                  double& best_t, std::optional<RayHit>& best) {
  const mapper::Segment& s = scene.surfaces[static_cast<std::size_t>(i)];
  const Point2 e = s.b - s.a;
  const double denom = cross(dir, e);
  if (std::abs(denom) < 1e-15) return;  // parallel: a grazing ray never echoes anyway
  const Point2 ao = s.a - origin;
  const double t = cross(ao, e) / denom;
  const double u = cross(ao, dir) / denom;
  if (t <= kMinT || t > best_t || u < 0.0 || u > 1.0) return;
  if (best && t == best_t && i < best->surface) return;
  const double len = e.norm();
  best_t = t;
  best = RayHit{t, i, origin + t * dir, Point2(-e.y() / len, e.x() / len)};
}

}  // namespace

std::optional<RayHit> ref_first_hit(const SonarScene& scene, const Point2& origin,
                                    const Point2& dir, double max_t_m, int skip_surface,
                                    const SceneIndex* index) {
  std::optional<RayHit> best;
  double best_t = max_t_m;
  if (index == nullptr) {
    for (int i = 0; i < static_cast<int>(scene.surfaces.size()); ++i) {
      if (i != skip_surface) test_surface(scene, i, origin, dir, best_t, best);
    }
    return best;
  }
  // Cell by cell outwards from the origin, stopping once the nearest hit lies before the next
  // cell: test_surface keeps the nearest hit (ties to the higher index) whatever the order.
  index->walk_ray(origin, dir, max_t_m, [&](int i) {
    if (i != skip_surface) test_surface(scene, i, origin, dir, best_t, best);
    return best_t;
  });
  return best;
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
  // Beyond 8 lobe widths exp(-32) adds nothing: skip the acos and exp.
  if (cos_incidence > std::cos(std::min(8.0 * lobe_rad, std::numbers::pi / 2))) {
    const double z = std::acos(std::min(1.0, cos_incidence)) / lobe_rad;
    mirror = m.specular_strength * std::exp(-0.5 * z * z) /
             (std::sqrt(2.0 * std::numbers::pi) * lobe_rad);
  }
  const double diffuse = m.diffuse_strength * power(cos_incidence, m.diffuse_incidence_exponent) *
                         power(std::max(range_m, 0.1), range_gain_exponent);
  return (mirror + diffuse) * dphi_rad;
}

}  // namespace

std::vector<EchoCandidate> ref_echo_candidates(const SonarScene& scene, const Cone& cone,
                                               const SonarModelOptions& options,
                                               const SceneIndex* index) {
  std::vector<EchoCandidate> out;
  const double sigma_rad = options.beam_sigma_deg * std::numbers::pi / 180.0;
  const double fan_rad = options.fan_half_width_deg * std::numbers::pi / 180.0;
  const double gain = std::pow(10.0, options.detection_gain_db / 10.0);
  const double g_exp = options.diffuse_range_gain_exponent;
  const Point2 axis(std::cos(cone.axis_rad), std::sin(cone.axis_rad));
  auto offset_of = [&](const Point2& dir) { return std::atan2(cross(axis, dir), axis.dot(dir)); };

  // Direct hits of every ray first: a candidate heard for certain (probability exactly 1 in
  // double precision) ends the listening, so nothing beyond it is traced. Bounce paths are never
  // shorter than their first leg, so the cut is exact.
  const int n = options.rays_per_cone;
  const double dphi = n == 1 ? 2.0 * fan_rad : 2.0 * fan_rad / (n - 1);
  struct Ray {
    Point2 d;
    double offset, beam;
    std::optional<RayHit> hit;
  };
  thread_local std::vector<Ray> rays;
  rays.clear();
  double certain_m = std::numeric_limits<double>::infinity();
  for (int i = 0; i < n; ++i) {
    const double offset = n == 1 ? 0.0 : -fan_rad + 2.0 * fan_rad * i / (n - 1);
    const double angle = cone.axis_rad + offset;
    Ray ray{Point2(std::cos(angle), std::sin(angle)), offset,
            gain * beam_pattern(offset, sigma_rad), std::nullopt};
    ray.hit = ref_first_hit(scene, cone.origin, ray.d, cone.max_range_m, -1, index);
    if (ray.hit) {
      const SonarMaterial& m1 = scene.material_of(ray.hit->surface);
      const double strength = ray.beam * surface_strength(m1, std::abs(ray.d.dot(ray.hit->normal)),
                                                          ray.hit->t_m, g_exp, dphi);
      out.push_back({ray.hit->t_m, strength, false});
      if (strength >= kCertainStrength) certain_m = std::min(certain_m, ray.hit->t_m);
    }
    rays.push_back(ray);
  }
  // Convex corners and edges diffract the pulse in every direction (none beyond a certain
  // echo can be heard first, so their line of sight is not tested).
  const double cos_fan = std::cos(fan_rad);
  for (const Point2& c : scene.corners) {
    const double dist = (c - cone.origin).norm();
    if (dist <= kMinT || dist > cone.max_range_m || dist > certain_m) continue;
    const Point2 dir = (c - cone.origin) / dist;
    if (axis.dot(dir) < cos_fan - 1e-12) continue;  // outside the fan: skip the atan2
    const double offset = offset_of(dir);
    if (std::abs(offset) > fan_rad) continue;
    if (!clear_line(scene, cone.origin, dir, dist, options.corner_radius_m, -1, index)) continue;
    const double strength = gain * options.corner_strength * beam_pattern(offset, sigma_rad);
    out.push_back({dist, strength, false});
    if (strength >= kCertainStrength) certain_m = std::min(certain_m, dist);
  }

  for (const Ray& ray : rays) {
    if (!ray.hit || ray.hit->t_m >= certain_m) continue;
    const std::optional<RayHit>& h1 = ray.hit;
    const Point2& d = ray.d;
    const double offset = ray.offset;
    const double beam = ray.beam;
    const SonarMaterial& m1 = scene.material_of(h1->surface);
    if (!options.multipath || m1.mirror_reflectivity <= 0.0) continue;

    // The mirrored part goes on. No echo later than max range, nor later than a certain one,
    // can be heard first, and both bounce ranges are at least (t1 + t2) / 2: the second leg is
    // cast at most 2 * latest - t1 far.
    const double mirrored = beam * m1.mirror_reflectivity;
    const Point2 d2 = reflect(d, h1->normal);
    const double latest_m = std::min(cone.max_range_m, certain_m);
    const auto h2 =
        ref_first_hit(scene, h1->point, d2, 2.0 * latest_m - h1->t_m, h1->surface, index);
    if (!h2) continue;
    const SonarMaterial& m2 = scene.material_of(h2->surface);
    // The second surface scatters back along the bounce path: range = t1 + t2.
    const double back_range = h1->t_m + h2->t_m;
    if (back_range <= latest_m) {
      out.push_back(
          {back_range,
           mirrored * surface_strength(m2, std::abs(d2.dot(h2->normal)), back_range, g_exp, dphi),
           true});
    }
    // Or it mirrors again straight back at the transducer: a concave corner is a
    // retro-reflector, heard at about its own distance though both walls are oblique.
    const Point2 d3 = reflect(d2, h2->normal);
    const Point2 back = cone.origin - h2->point;
    const double t3 = back.norm();
    if (t3 <= kMinT) continue;
    const Point2 back_dir = back / t3;
    const double retro_range = 0.5 * (h1->t_m + h2->t_m + t3);
    if (retro_range > latest_m) continue;
    const double arrival_offset = offset_of(-back_dir);
    if (std::abs(arrival_offset) > fan_rad) continue;
    const double mismatch = std::acos(std::clamp(d3.dot(back_dir), -1.0, 1.0));
    const double lobe_rad = m2.specular_lobe_deg * std::numbers::pi / 180.0;
    if (mismatch > 4.0 * lobe_rad) continue;  // beyond 4 sd the lobe adds nothing measurable
    if (!clear_line(scene, h2->point, back_dir, t3, kSightSlackM, h2->surface, index)) continue;
    // Leaving along the ray and arriving from arrival_offset: the geometric mean of the two
    // one-way patterns stands in for the two-way pattern.
    const double two_way =
        std::sqrt(beam_pattern(offset, sigma_rad) * beam_pattern(arrival_offset, sigma_rad));
    const double z = mismatch / lobe_rad;
    const double strength = gain * two_way * m1.mirror_reflectivity * m2.mirror_reflectivity *
                            m2.specular_strength * std::exp(-0.5 * z * z) /
                            (std::sqrt(2.0 * std::numbers::pi) * lobe_rad) * dphi;
    out.push_back({retro_range, strength, true});
  }
  std::erase_if(out, [&](const EchoCandidate& c) { return c.range_m > certain_m; });
  std::stable_sort(out.begin(), out.end(), [](const EchoCandidate& a, const EchoCandidate& b) {
    return a.range_m < b.range_m;
  });
  return out;
}

}  // namespace cogmap::sim::sonar_reference

// ---- The comparison ----
namespace cogmap::sim {
namespace {

using mapper::Point2;

using test_support::same_bits;
using test_support::shipped_worlds;

// Random cones over the world's bounds; `total` counts the candidates compared.
void expect_same_as_reference(const SonarScene& scene, const SonarModelOptions& options,
                              std::uint64_t seed, int cones, int& multipath, std::size_t& total) {
  const sonar_detail::SceneIndex index(scene);
  double xmin = 1e9, ymin = 1e9, xmax = -1e9, ymax = -1e9;
  for (const mapper::Segment& s : scene.surfaces) {
    for (const Point2& p : {s.a, s.b}) {
      xmin = std::min(xmin, p.x()), xmax = std::max(xmax, p.x());
      ymin = std::min(ymin, p.y()), ymax = std::max(ymax, p.y());
    }
  }
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> ux(xmin - 0.5, xmax + 0.5), uy(ymin - 0.5, ymax + 0.5);
  std::uniform_real_distribution<double> angle(-std::numbers::pi, std::numbers::pi);
  std::vector<EchoCandidate> reused;
  for (int k = 0; k < cones; ++k) {
    sonar_detail::Cone cone;
    cone.origin = Point2(ux(rng), uy(rng));
    cone.axis_rad = angle(rng);
    cone.max_range_m = 5.0;
    const auto want = sonar_reference::ref_echo_candidates(scene, cone, options, nullptr);
    const auto got = sonar_detail::echo_candidates(scene, cone, options, &index);
    sonar_detail::echo_candidates(scene, cone, options, &index, reused);
    EXPECT_EQ(want.size(), got.size()) << "cone " << k;
    EXPECT_EQ(want.size(), reused.size()) << "cone " << k;
    if (want.size() != got.size() || want.size() != reused.size()) return;
    for (std::size_t i = 0; i < want.size(); ++i) {
      for (const EchoCandidate* c : {&got[i], static_cast<const EchoCandidate*>(&reused[i])}) {
        ASSERT_TRUE(same_bits(want[i].range_m, c->range_m)) << "cone " << k << " #" << i;
        ASSERT_TRUE(same_bits(want[i].strength, c->strength)) << "cone " << k << " #" << i;
        ASSERT_EQ(want[i].multipath, c->multipath) << "cone " << k << " #" << i;
      }
      multipath += want[i].multipath;
    }
    total += want.size();
  }
}

TEST(SonarReference, EchoCandidatesMatchThePreSpeedUpCodeInEveryShippedWorld) {
  SonarModelOptions louder;  // more certain echoes: the early cuts are exercised more
  louder.detection_gain_db = 12.0;
  SonarModelOptions other;  // a different fan: the per-options ray table is rebuilt
  other.rays_per_cone = 13;
  other.fan_half_width_deg = 25.0;
  other.beam_sigma_deg = 7.5;
  other.corner_radius_m = 0.1;
  for (const auto& path : shipped_worlds()) {
    SCOPED_TRACE(path.filename().string());
    SonarScene scene = surface_segments(load_world(path));
    int multipath = 0;
    std::size_t total = 0;
    expect_same_as_reference(scene, SonarModelOptions{}, 21, 1500, multipath, total);
    EXPECT_GT(total, 3000u);    // real candidates were compared
    EXPECT_GT(multipath, 100);  // the bounce and retro paths too
    expect_same_as_reference(scene, louder, 22, 500, multipath, total);
    expect_same_as_reference(scene, other, 23, 500, multipath, total);
    // The same geometry with a random mix of built-in materials (glass and metal mirror more).
    std::mt19937_64 rng(24);
    std::uniform_int_distribution<int> pick(0,
                                            static_cast<int>(builtin_sonar_materials().size()) - 1);
    scene.surface_material.assign(scene.surfaces.size(), 0);
    for (int& m : scene.surface_material) m = pick(rng);
    expect_same_as_reference(scene, SonarModelOptions{}, 25, 1000, multipath, total);
    expect_same_as_reference(scene, other, 26, 300, multipath, total);
  }
}

}  // namespace
}  // namespace cogmap::sim
