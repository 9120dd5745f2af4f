// The fan's nearest-first surface list must change only the speed of the sonar model: every ray
// and line of sight below is answered by the list and by the full scan and compared bit for bit,
// and the box queries it is built from must list everything in their box.
#include "sonar_fan_surfaces.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "../world/world_test_support.h"
#include "cogmap/sim/world_geometry.h"
#include "cogmap/sim/world_spec.h"
#include "shipped_worlds_test_support.h"
#include "sonar_raycast.h"
#include "sonar_scene_index.h"

namespace cogmap::sim {
namespace {

using mapper::Point2;
using sonar_detail::FanSurfaces;
using sonar_detail::first_hit;
using sonar_detail::SceneIndex;
using test_support::same_hit;
using test_support::shipped_worlds;
using test_support::world_path;

struct Bounds {
  double xmin = 1e9, ymin = 1e9, xmax = -1e9, ymax = -1e9;
};

Bounds bounds_of(const SonarScene& scene) {
  Bounds b;
  for (const mapper::Segment& s : scene.surfaces) {
    for (const Point2& p : {s.a, s.b}) {
      b.xmin = std::min(b.xmin, p.x()), b.xmax = std::max(b.xmax, p.x());
      b.ymin = std::min(b.ymin, p.y()), b.ymax = std::max(b.ymax, p.y());
    }
  }
  return b;
}

Point2 unit(double angle_rad) { return Point2(std::cos(angle_rad), std::sin(angle_rad)); }

// Random fans of several widths and reaches; for each, the directions a ping uses (its edges
// exactly, evenly spaced rays) and the ones where rounding decides (exactly at surface ends in the
// fan, along the axes), at random lengths.
void expect_fan_matches_full_scan(const SonarScene& scene, std::uint64_t seed, int fans, int& hits,
                                  int& blocked, int* cut_fans = nullptr) {
  const SceneIndex index(scene);
  const Bounds b = bounds_of(scene);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> ux(b.xmin - 1.0, b.xmax + 1.0);
  std::uniform_real_distribution<double> uy(b.ymin - 1.0, b.ymax + 1.0);
  std::uniform_real_distribution<double> angle(-std::numbers::pi, std::numbers::pi);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  const double widths_deg[] = {20.0, 2.5, 45.0, 89.0};
  const double reaches_m[] = {5.0, 0.4, 12.0};
  FanSurfaces fan;
  for (int k = 0; k < fans; ++k) {
    const Point2 origin(ux(rng), uy(rng));
    // Every fourth fan points exactly along an axis, where walls are parallel to the edges.
    const double axis = k % 4 == 0 ? (k / 4 % 4) * 0.5 * std::numbers::pi : angle(rng);
    const double half = widths_deg[k % 4] * std::numbers::pi / 180.0;
    const double reach = reaches_m[k % 3];
    fan.gather(index, origin, unit(axis), std::cos(half), std::sin(half), reach);
    if (cut_fans != nullptr && fan.sector_count() > 0) ++*cut_fans;
    std::vector<Point2> dirs = {unit(axis - half), unit(axis + half), unit(axis)};
    for (int i = 0; i < 17; ++i) dirs.push_back(unit(axis - half + 2.0 * half * i / 16));
    const Point2 ax = unit(axis);
    for (const mapper::Segment& s : scene.surfaces) {
      for (const Point2& end : {s.a, s.b}) {
        const Point2 v = end - origin;
        const double d = v.norm();
        if (d == 0.0 || d > reach) continue;
        const Point2 dir = v / d;
        if (std::abs(std::atan2(ax.x() * dir.y() - ax.y() * dir.x(), ax.dot(dir))) <= half) {
          dirs.push_back(dir);
        }
      }
    }
    for (const Point2& dir : dirs) {
      const double max_t = reach * (k % 2 == 0 ? 1.0 : u01(rng));
      const auto full = first_hit(scene, origin, dir, max_t);
      const auto by_fan = fan.first_hit(dir, max_t);
      ASSERT_EQ(full.has_value(), by_fan.has_value()) << "fan " << k;
      ASSERT_EQ(full.has_value(), fan.blocked(dir, max_t)) << "fan " << k;
      if (!full) continue;
      ++hits;
      ASSERT_TRUE(same_hit(*full, *by_fan)) << "fan " << k;
      // Just short of the hit nothing blocks; the hit itself does.
      const double short_t = std::nextafter(full->t_m, 0.0);
      ASSERT_EQ(first_hit(scene, origin, dir, short_t).has_value(), fan.blocked(dir, short_t))
          << "fan " << k;
      blocked += fan.blocked(dir, full->t_m);
    }
    // Every corner in the fan and within reach is listed, in the scene's order.
    const auto corners = fan.corners();
    ASSERT_TRUE(std::is_sorted(corners.begin(), corners.end()));
    ASSERT_TRUE(std::adjacent_find(corners.begin(), corners.end()) == corners.end());
    for (std::size_t c = 0; c < scene.corners.size(); ++c) {
      const Point2 v = scene.corners[c] - origin;
      const double d = v.norm();
      if (d == 0.0 || d > reach) continue;
      const Point2 dir = v / d;
      if (std::abs(std::atan2(ax.x() * dir.y() - ax.y() * dir.x(), ax.dot(dir))) > half) continue;
      ASSERT_TRUE(std::binary_search(corners.begin(), corners.end(), static_cast<int>(c)))
          << "fan " << k << " corner " << c;
    }
  }
}

TEST(SonarFanSurfaces, RaysAndSightLinesMatchTheFullScanInEveryShippedWorld) {
  const auto worlds = shipped_worlds();
  ASSERT_GE(worlds.size(), 5u);
  for (const auto& path : worlds) {
    SCOPED_TRACE(path.filename().string());
    int hits = 0, blocked = 0;
    expect_fan_matches_full_scan(surface_segments(load_world(path)), 21, 600, hits, blocked);
    EXPECT_GT(hits, 1500) << hits;  // real hits were compared, not only misses
    EXPECT_EQ(blocked, hits);
  }
}

TEST(SonarFanSurfaces, ACrowdedFanCutIntoSectorsMatchesTheFullScan) {
  // A 6 x 6 m room holding 60 chair legs and 20 small boxes at random: fans over a few hundred
  // surfaces are cut into sectors, and every ray and sight line must still answer as the full
  // scan does (rays between the legs, exactly at facet ends, and along the axes).
  std::mt19937_64 rng(57);
  std::uniform_real_distribution<double> place(0.3, 5.7), angle(0.0, 180.0);
  std::string text =
      "name: crowded\nwalls:\n  polylines:\n    - [[0, 0], [6, 0], [6, 6], [0, 6], [0, 0]]\n"
      "obstacles:\n";
  // Everything at least 1.2 m from the start corner, where the robot stands.
  const auto center = [&] {
    double x = 0.0, y = 0.0;
    do {
      x = place(rng), y = place(rng);
    } while (x < 1.2 && y < 1.2);
    return "[" + std::to_string(x) + ", " + std::to_string(y) + "]";
  };
  for (int i = 0; i < 60; ++i) {
    text += "  - {circle: {center: " + center() + ", radius_m: 0.02}}\n";
  }
  for (int i = 0; i < 20; ++i) {
    text += "  - {box: {center: " + center() +
            ", size: [0.3, 0.2], angle_deg: " + std::to_string(angle(rng)) + "}}\n";
  }
  text += "start: {x_m: 0.5, y_m: 0.5, theta_deg: 0}\n";
  const WorldSpec world = sim::testing::parse(text);
  int hits = 0, blocked = 0, cut = 0;
  expect_fan_matches_full_scan(surface_segments(world), 58, 48, hits, blocked, &cut);
  EXPECT_GE(cut, 20) << cut;       // 25 of the 32 fans reaching 5 or 12 m took the sector path
  EXPECT_GT(hits, 15000) << hits;  // 23 244
  EXPECT_EQ(blocked, hits);
}

TEST(SonarFanSurfaces, OnlySurfacesAheadWithinTheFanAreTested) {
  // A wall ahead and one behind, one beside the fan, and a pillar face seen edge-on.
  SonarScene scene;
  scene.surfaces = {{Point2(2.0, -1.0), Point2(2.0, 1.0)},    // 0: ahead, 2 m
                    {Point2(-1.0, -1.0), Point2(-1.0, 1.0)},  // 1: behind
                    {Point2(1.0, 1.5), Point2(3.0, 1.5)},     // 2: beside (37-56° off the axis)
                    {Point2(1.0, 0.0), Point2(1.5, 0.0)}};    // 3: on the axis, edge-on
  const SceneIndex index(scene, 0.5);
  FanSurfaces fan;
  const double half = 20.0 * std::numbers::pi / 180.0;
  fan.gather(index, Point2(0.0, 0.0), unit(0.0), std::cos(half), std::sin(half), 5.0);
  const auto hit = fan.first_hit(unit(0.1), 5.0);
  ASSERT_TRUE(hit.has_value());
  EXPECT_EQ(hit->surface, 0);
  EXPECT_DOUBLE_EQ(hit->t_m, 2.0 / std::cos(0.1));
  EXPECT_FALSE(fan.blocked(unit(0.1), 1.9));
  EXPECT_TRUE(fan.blocked(unit(-0.3), 2.2));
  // Along the axis the edge-on face is parallel (no echo) and the wall at 2 m answers.
  ASSERT_TRUE(fan.first_hit(unit(0.0), 5.0).has_value());
  EXPECT_EQ(fan.first_hit(unit(0.0), 5.0)->surface, 0);
}

TEST(SceneIndexBoxes, ListEverySurfaceAndCornerInTheBox) {
  const SonarScene scene = surface_segments(load_world(world_path("nine_rooms.yaml")));
  const SceneIndex index(scene);
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> u(-1.0, 16.0), size(0.0, 6.0);
  std::vector<int> surfaces, corners;
  std::size_t listed = 0;
  for (int k = 0; k < 500; ++k) {
    const Point2 lo(u(rng), u(rng));
    const Point2 hi = lo + Point2(size(rng), size(rng));
    index.surfaces_in_box(lo, hi, surfaces);
    index.corners_in_box(lo, hi, corners);
    std::vector<int> sorted = surfaces;
    std::sort(sorted.begin(), sorted.end());
    ASSERT_TRUE(std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end());
    ASSERT_TRUE(std::is_sorted(corners.begin(), corners.end()));
    ASSERT_TRUE(std::adjacent_find(corners.begin(), corners.end()) == corners.end());
    const auto inside = [&](const Point2& p) {
      return p.x() >= lo.x() && p.x() <= hi.x() && p.y() >= lo.y() && p.y() <= hi.y();
    };
    for (std::size_t i = 0; i < scene.surfaces.size(); ++i) {
      // A surface with a point in the box (the segment clipped to it, Liang-Barsky) is listed.
      const mapper::Segment& s = scene.surfaces[i];
      const Point2 d = s.b - s.a;
      double t0 = 0.0, t1 = 1.0;
      const auto clip = [&](double p, double q) {  // keeps the part where p * t <= q
        if (p == 0.0) {
          if (q < 0.0) t1 = -1.0;
        } else if (p < 0.0) {
          t0 = std::max(t0, q / p);
        } else {
          t1 = std::min(t1, q / p);
        }
      };
      clip(-d.x(), s.a.x() - lo.x());
      clip(d.x(), hi.x() - s.a.x());
      clip(-d.y(), s.a.y() - lo.y());
      clip(d.y(), hi.y() - s.a.y());
      if (t0 <= t1) {
        ASSERT_TRUE(std::binary_search(sorted.begin(), sorted.end(), static_cast<int>(i)))
            << "box " << k << " surface " << i;
      }
    }
    for (std::size_t c = 0; c < scene.corners.size(); ++c) {
      if (!inside(scene.corners[c])) continue;
      ASSERT_TRUE(std::binary_search(corners.begin(), corners.end(), static_cast<int>(c)))
          << "box " << k << " corner " << c;
    }
    listed += surfaces.size();
  }
  EXPECT_GT(listed, 500u);
}

}  // namespace
}  // namespace cogmap::sim
