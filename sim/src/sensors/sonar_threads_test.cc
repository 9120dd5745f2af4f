// The sonar traced on two threads (SonarModel::set_threads(2)) must give the very readings of
// one thread: the random draws are taken in firing order before any ping is traced, and the
// scene index keeps each thread's query scratch apart.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <thread>
#include <vector>

#include "cogmap/sim/sonar_model.h"
#include "cogmap/sim/world_geometry.h"
#include "cogmap/sim/world_spec.h"
#include "shipped_worlds_test_support.h"
#include "sonar_scene_index.h"

namespace cogmap::sim {
namespace {

using mapper::Point2;
using mapper::Pose2;
using test_support::same_bits;
using test_support::shipped_worlds;

// A path wandering about the start for `cycles` 0.1 s frames: turning and drifting, so that
// every frame's firings see new poses and most transducers hear something.
Pose2 wander(const Pose2& start, double t_s) {
  return {start.x_m + 1.5 * std::sin(0.11 * t_s), start.y_m + 1.0 * std::sin(0.07 * t_s + 1.0),
          start.theta_rad + 0.4 * t_s};
}

std::vector<mapper::SonarReading> run_frames(const SonarScene& scene, const Pose2& start,
                                             int threads, int cycles) {
  SonarModel model(SonarModelOptions{}, mapper::p2at_geometry(), 77);
  model.set_threads(threads);
  std::vector<mapper::SonarReading> out;
  for (int c = 0; c < cycles; ++c) {
    const auto got =
        model.cycle(scene, 0.1 * c, 0.1 * (c + 1), [&](double t) { return wander(start, t); });
    out.insert(out.end(), got.begin(), got.end());
  }
  return out;
}

TEST(SonarThreads, TwoThreadsReadExactlyAsOneInEveryShippedWorld) {
  for (const auto& path : shipped_worlds()) {
    const WorldSpec world = load_world(path);
    const SonarScene scene = surface_segments(world);
    const auto one = run_frames(scene, world.start, 1, 600);
    const auto two = run_frames(scene, world.start, 2, 600);
    ASSERT_EQ(one.size(), two.size()) << path;
    int echoes = 0;
    for (std::size_t k = 0; k < one.size(); ++k) {
      ASSERT_EQ(one[k].index, two[k].index) << path << " reading " << k;
      ASSERT_TRUE(same_bits(one[k].time_s, two[k].time_s)) << path << " reading " << k;
      ASSERT_EQ(one[k].echo, two[k].echo) << path << " reading " << k;
      ASSERT_TRUE(same_bits(one[k].range_m, two[k].range_m)) << path << " reading " << k;
      echoes += one[k].echo ? 1 : 0;
    }
    // 60 s at 25 firings of two transducers a second; most of them hear a wall.
    EXPECT_EQ(one.size(), 3000u) << path;
    EXPECT_GT(echoes, 1500) << path;
  }
}

TEST(SonarThreads, SwitchingThreadsMidRunChangesNoReading) {
  const WorldSpec world = load_world(test_support::world_path("nine_rooms.yaml"));
  const SonarScene scene = surface_segments(world);
  const auto one = run_frames(scene, world.start, 1, 200);
  SonarModel model(SonarModelOptions{}, mapper::p2at_geometry(), 77);
  std::vector<mapper::SonarReading> switched;
  for (int c = 0; c < 200; ++c) {
    model.set_threads(c / 50 % 2 == 0 ? 1 : 2);  // 1, 2, 1, 2 threads, 50 frames each
    EXPECT_EQ(model.threads(), c / 50 % 2 == 0 ? 1 : 2);
    const auto got = model.cycle(scene, 0.1 * c, 0.1 * (c + 1),
                                 [&](double t) { return wander(world.start, t); });
    switched.insert(switched.end(), got.begin(), got.end());
  }
  ASSERT_EQ(switched.size(), one.size());
  for (std::size_t k = 0; k < one.size(); ++k) {
    ASSERT_TRUE(same_bits(one[k].range_m, switched[k].range_m)) << k;
    ASSERT_EQ(one[k].echo, switched[k].echo) << k;
  }
}

TEST(SonarThreads, OnlyOneOrTwoThreads) {
  SonarModel model(SonarModelOptions{}, mapper::p2at_geometry(), 1);
  EXPECT_THROW(model.set_threads(0), std::invalid_argument);
  EXPECT_THROW(model.set_threads(3), std::invalid_argument);
  EXPECT_EQ(model.threads(), 1);
}

TEST(SonarThreads, OneIndexQueriedFromTwoThreadsAtOnceAnswersAsFromOne) {
  // Each thread's queries use its own stamps; shared stamps would drop or repeat surfaces.
  const SonarScene scene =
      surface_segments(load_world(test_support::world_path("nine_rooms.yaml")));
  const sonar_detail::SceneIndex index(scene);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> x(-2.0, 20.0), size(0.1, 6.0);
  std::vector<std::pair<Point2, Point2>> boxes;
  for (int i = 0; i < 4000; ++i) {
    const Point2 lo(x(rng), x(rng));
    boxes.emplace_back(lo, lo + Point2(size(rng), size(rng)));
  }
  auto answer = [&](std::size_t from, std::size_t step) {
    std::vector<std::vector<int>> out(boxes.size());
    for (std::size_t i = from; i < boxes.size(); i += step) {
      index.surfaces_in_box(boxes[i].first, boxes[i].second, out[i]);
      std::sort(out[i].begin(), out[i].end());
    }
    return out;
  };
  const auto alone = answer(0, 1);
  for (int round = 0; round < 5; ++round) {
    std::vector<std::vector<int>> a, b;
    std::thread other([&] { b = answer(0, 1); });
    a = answer(0, 1);
    other.join();
    ASSERT_EQ(a, alone) << round;
    ASSERT_EQ(b, alone) << round;
  }
}

}  // namespace
}  // namespace cogmap::sim
