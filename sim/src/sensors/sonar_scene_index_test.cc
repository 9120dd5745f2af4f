// The spatial index must change only the speed of the sonar model, never a reading: every query
// below is answered with and without the index and compared bit for bit.
#include "sonar_scene_index.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "cogmap/sim/world_geometry.h"
#include "cogmap/sim/world_spec.h"
#include "shipped_worlds_test_support.h"
#include "sonar_raycast.h"

namespace cogmap::sim {
namespace {

using mapper::Point2;
using sonar_detail::echo_candidates;
using sonar_detail::first_hit;
using sonar_detail::SceneIndex;

using test_support::same_bits;
using test_support::same_hit;
using test_support::shipped_worlds;
using test_support::world_path;

// Random rays from random points, including rays exactly along the axes (parallel to most walls)
// and rays aimed exactly at surface endpoints, the cases where rounding decides.
void expect_same_hits(const SonarScene& scene, std::uint64_t seed, int rays) {
  const SceneIndex index(scene);
  std::mt19937_64 rng(seed);
  double xmin = 1e9, ymin = 1e9, xmax = -1e9, ymax = -1e9;
  for (const mapper::Segment& s : scene.surfaces) {
    for (const Point2& p : {s.a, s.b}) {
      xmin = std::min(xmin, p.x()), xmax = std::max(xmax, p.x());
      ymin = std::min(ymin, p.y()), ymax = std::max(ymax, p.y());
    }
  }
  std::uniform_real_distribution<double> ux(xmin - 2.0, xmax + 2.0), uy(ymin - 2.0, ymax + 2.0);
  std::uniform_real_distribution<double> angle(-std::numbers::pi, std::numbers::pi);
  std::uniform_real_distribution<double> reach(0.0, 12.0);
  std::uniform_int_distribution<int> pick(0, static_cast<int>(scene.surfaces.size()) - 1);
  int hits = 0;
  for (int k = 0; k < rays; ++k) {
    const Point2 o(ux(rng), uy(rng));
    Point2 d;
    switch (k % 4) {
      case 0:
        d = Point2(std::cos(angle(rng)), std::sin(angle(rng)));
        d.normalize();
        break;
      case 1: {  // along an axis
        const double a = (k / 4 % 4) * 0.5 * std::numbers::pi;
        d = Point2(std::cos(a), std::sin(a));
        break;
      }
      default: {  // exactly at an endpoint
        const mapper::Segment& s = scene.surfaces[static_cast<std::size_t>(pick(rng))];
        const Point2 target = k % 4 == 2 ? s.a : s.b;
        if ((target - o).norm() == 0.0) continue;
        d = (target - o).normalized();
      }
    }
    const double max_t = reach(rng);
    const int skip = k % 7 == 0 ? pick(rng) : -1;
    const auto full = first_hit(scene, o, d, max_t, skip);
    const auto fast = first_hit(scene, o, d, max_t, skip, &index);
    ASSERT_EQ(full.has_value(), fast.has_value()) << "ray " << k;
    if (!full) continue;
    ++hits;
    EXPECT_TRUE(same_hit(*full, *fast)) << "ray " << k;
  }
  EXPECT_GT(hits, rays / 10);  // the comparison exercised real hits, not only misses
}

TEST(SonarSceneIndex, RayHitsMatchFullScanInEveryShippedWorld) {
  const auto worlds = shipped_worlds();
  ASSERT_GE(worlds.size(), 5u);
  for (const auto& path : worlds) {
    SCOPED_TRACE(path.filename().string());
    expect_same_hits(surface_segments(load_world(path)), 11, 20000);
  }
}

// Random cones over the world's bounds: the candidate lists with and without the index must be
// identical bit for bit (ranges, strengths, kinds, order).
void expect_same_candidates(const SonarScene& scene, std::uint64_t seed, int cones,
                            int& multipath) {
  const SceneIndex index(scene);
  ASSERT_TRUE(index.matches(scene));
  double xmin = 1e9, ymin = 1e9, xmax = -1e9, ymax = -1e9;
  for (const mapper::Segment& s : scene.surfaces) {
    for (const Point2& p : {s.a, s.b}) {
      xmin = std::min(xmin, p.x()), xmax = std::max(xmax, p.x());
      ymin = std::min(ymin, p.y()), ymax = std::max(ymax, p.y());
    }
  }
  const SonarModelOptions options;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> ux(xmin - 0.5, xmax + 0.5), uy(ymin - 0.5, ymax + 0.5);
  std::uniform_real_distribution<double> angle(-std::numbers::pi, std::numbers::pi);
  std::size_t total = 0;
  for (int k = 0; k < cones; ++k) {
    sonar_detail::Cone cone;
    cone.origin = Point2(ux(rng), uy(rng));
    cone.axis_rad = angle(rng);
    cone.max_range_m = 5.0;
    const auto full = echo_candidates(scene, cone, options);
    const auto fast = echo_candidates(scene, cone, options, &index);
    ASSERT_EQ(full.size(), fast.size()) << "cone " << k;
    for (std::size_t i = 0; i < full.size(); ++i) {
      ASSERT_TRUE(same_bits(full[i].range_m, fast[i].range_m)) << "cone " << k << " #" << i;
      ASSERT_TRUE(same_bits(full[i].strength, fast[i].strength)) << "cone " << k << " #" << i;
      ASSERT_EQ(full[i].multipath, fast[i].multipath) << "cone " << k << " #" << i;
      multipath += full[i].multipath;
    }
    total += full.size();
  }
  EXPECT_GT(total, static_cast<std::size_t>(cones) * 2);  // real candidates were compared
}

TEST(SonarSceneIndex, EchoCandidatesMatchFullScanInEveryShippedWorld) {
  for (const auto& path : shipped_worlds()) {
    SCOPED_TRACE(path.filename().string());
    SonarScene scene = surface_segments(load_world(path));
    int multipath = 0;
    expect_same_candidates(scene, 5, 2000, multipath);
    EXPECT_GT(multipath, 100);  // the bounce and retro paths were compared too
    // The same geometry with a random mix of built-in materials (glass mirrors far more).
    std::mt19937_64 rng(8);
    std::uniform_int_distribution<int> pick(0,
                                            static_cast<int>(builtin_sonar_materials().size()) - 1);
    scene.surface_material.assign(scene.surfaces.size(), 0);
    for (int& m : scene.surface_material) m = pick(rng);
    expect_same_candidates(scene, 6, 1000, multipath);
  }
}

TEST(SonarSceneIndex, ModelCandidatesMatchTheUnindexedScan) {
  // SonarModel caches an index of the last scene: its answers equal a plain scan, also after it
  // switched between two scenes.
  const SonarScene a = surface_segments(load_world(world_path("nine_rooms.yaml")));
  const SonarScene b = surface_segments(load_world(world_path("two_rooms.yaml")));
  const auto g = mapper::p2at_geometry();
  const SonarModelOptions options;
  const SonarModel model(options, g, 1);
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> u(1.0, 9.0), angle(-3.14, 3.14);
  for (int k = 0; k < 400; ++k) {
    const SonarScene& scene = k % 3 == 0 ? b : a;
    const mapper::Pose2 pose{u(rng), u(rng), angle(rng)};
    const int i = k % 16;
    const auto& m = g.sonars[static_cast<std::size_t>(i)];
    sonar_detail::Cone cone;
    cone.origin = pose.transform(Point2(m.x_m, m.y_m));
    cone.axis_rad = pose.theta_rad + m.heading_rad;
    cone.max_range_m = g.sonar_max_range_m;
    const auto plain = echo_candidates(scene, cone, options);
    const auto cached = model.echo_candidates(scene, pose, i);
    ASSERT_EQ(plain.size(), cached.size()) << k;
    for (std::size_t j = 0; j < plain.size(); ++j) {
      ASSERT_TRUE(same_bits(plain[j].range_m, cached[j].range_m)) << k;
      ASSERT_TRUE(same_bits(plain[j].strength, cached[j].strength)) << k;
      ASSERT_EQ(plain[j].multipath, cached[j].multipath) << k;
    }
  }
}

TEST(SonarSceneIndex, CornerQueryMatchesFullScan) {
  const SonarScene scene = surface_segments(load_world(world_path("nine_rooms.yaml")));
  ASSERT_FALSE(scene.corners.empty());
  const SceneIndex index(scene);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> jitter(-0.08, 0.08);
  for (int k = 0; k < 20000; ++k) {
    const Point2& c = scene.corners[static_cast<std::size_t>(k) % scene.corners.size()];
    const Point2 p = c + Point2(jitter(rng), jitter(rng));
    bool full = false;
    for (const Point2& q : scene.corners) full = full || (q - p).norm() <= 0.05;
    EXPECT_EQ(full, index.corner_within(p, 0.05)) << "query " << k;
  }
}

TEST(SonarSceneIndex, MatchesOnlyTheSameBits) {
  SonarScene scene;
  scene.surfaces.push_back({Point2(0.0, 0.0), Point2(1.0, 0.0)});
  const SceneIndex index(scene);
  EXPECT_TRUE(index.matches(scene));
  SonarScene moved = scene;
  moved.surfaces[0].b.x() = std::nextafter(1.0, 2.0);
  EXPECT_FALSE(index.matches(moved));
  SonarScene signed_zero = scene;
  signed_zero.surfaces[0].a.y() = -0.0;  // == 0.0, but not the same bits
  EXPECT_FALSE(index.matches(signed_zero));
  SonarScene more = scene;
  more.corners.push_back(Point2(0.0, 0.0));
  EXPECT_FALSE(index.matches(more));
}

TEST(SonarSceneIndex, EmptySceneHasNoHits) {
  const SonarScene scene{};
  const SceneIndex index(scene);
  EXPECT_FALSE(first_hit(scene, Point2(0, 0), Point2(1, 0), 5.0, -1, &index).has_value());
  EXPECT_FALSE(index.corner_within(Point2(0, 0), 1.0));
}

}  // namespace
}  // namespace cogmap::sim
