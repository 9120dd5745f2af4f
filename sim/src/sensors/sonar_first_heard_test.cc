// first_heard() traces a ray's bounces only when the listening reaches the range of the ray's
// first hit. That must change the work, never the answer: whatever candidate the receiver hears,
// it must have been offered exactly the prefix of the full, sorted candidate list before it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <limits>
#include <new>
#include <numbers>
#include <optional>
#include <random>
#include <vector>

#include "cogmap/sim/sonar_material.h"
#include "cogmap/sim/world_geometry.h"
#include "cogmap/sim/world_spec.h"
#include "shipped_worlds_test_support.h"
#include "sonar_raycast.h"

namespace cogmap::sim {
namespace {

using mapper::Point2;
using sonar_detail::Cone;
using sonar_detail::echo_candidates;
using sonar_detail::first_heard;
using sonar_detail::SceneIndex;
using test_support::same_bits;
using test_support::shipped_worlds;

// Hears the `hear_at`-th candidate offered (0-based; never if it is past the end) and remembers
// every candidate it was offered.
struct ScriptedListener final : sonar_detail::EchoListener {
  std::size_t hear_at;
  std::vector<EchoCandidate> offered;
  explicit ScriptedListener(std::size_t k) : hear_at(k) {}
  bool hears(const EchoCandidate& c) override {
    offered.push_back(c);
    return offered.size() == hear_at + 1;
  }
};

bool same(const EchoCandidate& a, const EchoCandidate& b) {
  return same_bits(a.range_m, b.range_m) && same_bits(a.strength, b.strength) &&
         a.multipath == b.multipath;
}

// For one cone: hearing at every position of the full list (and at none) offers that list's
// prefix, candidate for candidate, and returns the candidate heard.
void expect_prefixes(const SonarScene& scene, const SceneIndex* index, const Cone& cone,
                     const SonarModelOptions& options, int& bounce_before_direct) {
  const std::vector<EchoCandidate> full = echo_candidates(scene, cone, options, index);
  for (std::size_t k = 0; k <= full.size(); ++k) {
    ScriptedListener listener(k);
    const std::optional<EchoCandidate> heard = first_heard(scene, cone, options, index, listener);
    const std::size_t expected = std::min(k + 1, full.size());
    ASSERT_EQ(listener.offered.size(), expected) << "hearing #" << k;
    for (std::size_t i = 0; i < expected; ++i) {
      ASSERT_TRUE(same(listener.offered[i], full[i])) << "hearing #" << k << ", offer #" << i;
    }
    if (k < full.size()) {
      ASSERT_TRUE(heard.has_value());
      EXPECT_TRUE(same(*heard, full[k]));
    } else {
      EXPECT_FALSE(heard.has_value());
    }
  }
  // A bounce ranked before a direct echo: the interleaving the lazy order must get right.
  bool bounce_seen = false;
  for (const EchoCandidate& c : full) {
    if (c.multipath) bounce_seen = true;
    if (!c.multipath && bounce_seen) {
      ++bounce_before_direct;
      break;
    }
  }
}

TEST(SonarFirstHeard, OffersThePrefixOfTheFullListInEveryShippedWorld) {
  int interleaved = 0;  // cones whose list ranks a bounce before a direct echo
  for (const auto& path : shipped_worlds()) {
    SCOPED_TRACE(path.filename().string());
    SonarScene scene = surface_segments(load_world(path));
    // Half the cones with the world's own materials, half with a random mix of the built-in
    // ones (glass mirrors far more, so bounces are heard often).
    for (int mix = 0; mix < 2; ++mix) {
      if (mix == 1) {
        std::mt19937_64 pick_rng(21);
        std::uniform_int_distribution<int> pick(
            0, static_cast<int>(builtin_sonar_materials().size()) - 1);
        scene.surface_material.assign(scene.surfaces.size(), 0);
        for (int& m : scene.surface_material) m = pick(pick_rng);
      }
      const SceneIndex index(scene);
      double xmin = 1e9, ymin = 1e9, xmax = -1e9, ymax = -1e9;
      for (const mapper::Segment& s : scene.surfaces) {
        for (const Point2& p : {s.a, s.b}) {
          xmin = std::min(xmin, p.x()), xmax = std::max(xmax, p.x());
          ymin = std::min(ymin, p.y()), ymax = std::max(ymax, p.y());
        }
      }
      std::mt19937_64 rng(30 + mix);
      std::uniform_real_distribution<double> ux(xmin, xmax), uy(ymin, ymax);
      std::uniform_real_distribution<double> angle(-std::numbers::pi, std::numbers::pi);
      const SonarModelOptions options;
      int bounce_before_direct = 0;
      for (int k = 0; k < 300; ++k) {
        Cone cone;
        cone.origin = Point2(ux(rng), uy(rng));
        cone.axis_rad = angle(rng);
        cone.max_range_m = 5.0;
        // With and without the index: both must follow the same order.
        expect_prefixes(scene, &index, cone, options, bounce_before_direct);
        if (k % 10 == 0) expect_prefixes(scene, nullptr, cone, options, bounce_before_direct);
        if (HasFatalFailure()) return;
      }
      interleaved += bounce_before_direct;
    }
  }
  // 722 of the 3 300 cone evaluations over the five shipped worlds (2026-12-02).
  EXPECT_GT(interleaved, 360);
}

// A glass pane at 45 degrees 1 m ahead covers the upper half of the fan and mirrors it up onto a
// painted wall 0.8 m to the left; the lower half meets a painted wall 2 m ahead. So the bounces
// of the upper rays (~1.7 m) rank before the direct echoes of the lower ones (>= 2 m), and the
// lazy order has to trace them in the middle of the list.
TEST(SonarFirstHeard, TracesABounceThatComesBeforeADirectEcho) {
  SonarScene scene;
  scene.surfaces = {{Point2(0.9, 0.0), Point2(1.3, 0.4)},    // glass, along (1, 1)
                    {Point2(2.0, -2.0), Point2(2.0, 0.0)},   // painted, ahead
                    {Point2(-1.0, 0.8), Point2(3.0, 0.8)}};  // painted, to the left
  const int glass = 2;
  ASSERT_EQ(builtin_sonar_materials()[glass].name, "glass");
  scene.surface_material = {glass, 0, 0};
  const SceneIndex index(scene);
  const SonarModelOptions options;
  ASSERT_EQ(options.rays_per_cone, 17);
  ASSERT_EQ(options.fan_half_width_deg, 20.0);
  Cone cone;  // at the origin, facing +x
  const std::vector<EchoCandidate> full = echo_candidates(scene, cone, options, &index);
  // The ray 5 degrees up meets the pane at x = 0.9 / (1 - tan 5deg), leaves it along
  // (sin 5deg, cos 5deg) (a 45-degree mirror swaps the components) and scatters off the left
  // wall: range t1 + t2.
  const double a = 5.0 * std::numbers::pi / 180.0;
  const double x = 0.9 / (1.0 - std::tan(a));
  const double t1 = std::hypot(x, x - 0.9), t2 = (0.8 - (x - 0.9)) / std::cos(a);
  bool found = false;
  for (const EchoCandidate& c : full) {
    found |= c.multipath && std::abs(c.range_m - (t1 + t2)) < 1e-9;
  }
  EXPECT_TRUE(found) << "no scattered bounce at " << t1 + t2 << " m";
  EXPECT_NEAR(t1 + t2, 1.7065, 1e-4);
  int bounce_before_direct = 0;
  expect_prefixes(scene, &index, cone, options, bounce_before_direct);
  expect_prefixes(scene, nullptr, cone, options, bounce_before_direct);
  EXPECT_EQ(bounce_before_direct, 2);  // once per call above
}

// The test above relies on a default cone sitting at the origin, whatever the memory it is made
// in held before (an Eigen vector left uninitialised took the stack garbage of earlier tests).
TEST(SonarFirstHeard, DefaultConeSitsAtTheOriginWhateverTheMemoryHeld) {
  alignas(Cone) unsigned char bytes[sizeof(Cone)];
  volatile unsigned char* garbage = bytes;  // volatile: the compiler may not drop these stores
  for (std::size_t i = 0; i < sizeof(bytes); ++i) garbage[i] = 0xA5;
  const Cone* cone = new (bytes) Cone;
  EXPECT_TRUE(same_bits(cone->origin.x(), 0.0));
  EXPECT_TRUE(same_bits(cone->origin.y(), 0.0));
  EXPECT_EQ(cone->axis_rad, 0.0);
  EXPECT_EQ(cone->max_range_m, 5.0);
}

TEST(SonarFirstHeard, NonFiniteConeFallsBackToTheFullList) {
  const SonarScene scene = surface_segments(load_world(test_support::world_path("two_rooms.yaml")));
  const SceneIndex index(scene);
  const SonarModelOptions options;
  for (const double bad :
       {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    Cone cone;
    cone.origin = Point2(bad, 1.0);
    cone.axis_rad = 0.3;
    const std::vector<EchoCandidate> full = echo_candidates(scene, cone, options, &index);
    ScriptedListener never(full.size());
    EXPECT_FALSE(first_heard(scene, cone, options, &index, never).has_value());
    ASSERT_EQ(never.offered.size(), full.size());
    for (std::size_t i = 0; i < full.size(); ++i) EXPECT_TRUE(same(never.offered[i], full[i]));
  }
}

}  // namespace
}  // namespace cogmap::sim
