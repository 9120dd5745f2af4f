// Simulator speed: simulated seconds per wall-clock second of SimRobot alone (physics, slip,
// encoders, sonar) in nine_rooms, and the one-off cost of extracting a world's true surfaces.
// docs/performance.md records the figures.
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <filesystem>
#include <random>
#include <vector>

#include "cogmap/sim/sim_robot.h"
#include "cogmap/sim/world_geometry.h"

namespace {

std::filesystem::path world_path(const char* name) {
  const char* env = std::getenv("COGMAP_SOURCE_DIR");
  return std::filesystem::path(env ? env : COGMAP_SOURCE_DIR_FALLBACK) / "worlds" / name;
}

// Drives a gentle arc at 0.4 m/s in nine_rooms for 60 simulated seconds per iteration; the arc
// meets walls, so contact solving is part of the cost.
void BM_SimRobotNineRooms(benchmark::State& state) {
  const cogmap::sim::WorldSpec world = cogmap::sim::load_world(world_path("nine_rooms.yaml"));
  cogmap::sim::SimRobotOptions options;
  options.physics_substeps = static_cast<int>(state.range(0));
  constexpr int kCycles = 600;
  double sim_s = 0.0;
  for (auto _ : state) {
    cogmap::sim::SimRobot robot(world, options, 42);
    robot.command({0.4, 0.15});
    for (int i = 0; i < kCycles; ++i) benchmark::DoNotOptimize(robot.next_frame());
    sim_s += robot.sim_time_s();
  }
  state.counters["sim_s_per_wall_s"] = benchmark::Counter(sim_s, benchmark::Counter::kIsRate);
}
BENCHMARK(BM_SimRobotNineRooms)->Arg(10)->Arg(5)->Unit(benchmark::kMillisecond);

// Sonar pings per second: every transducer of the P2-AT from 1000 random poses in a world
// (docs/sonar-model.md "Speed"); the random poses include some inside furniture, as a fair mix.
void BM_SonarPing(benchmark::State& state, const char* world_file) {
  const cogmap::sim::WorldSpec world = cogmap::sim::load_world(world_path(world_file));
  const cogmap::sim::SonarScene scene = cogmap::sim::surface_segments(world);
  const auto [lo, hi] = cogmap::sim::world_bounds(world);
  const cogmap::mapper::RobotGeometry geometry = cogmap::mapper::p2at_geometry();
  cogmap::sim::SonarModel model(cogmap::sim::SonarModelOptions{}, geometry, 1);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> ux(lo.x(), hi.x()), uy(lo.y(), hi.y()), ut(-3.14, 3.14);
  std::vector<cogmap::mapper::Pose2> poses;
  for (int i = 0; i < 1000; ++i) poses.push_back({ux(rng), uy(rng), ut(rng)});
  std::int64_t pings = 0;
  for (auto _ : state) {
    for (const auto& pose : poses) {
      for (int s = 0; s < static_cast<int>(geometry.sonars.size()); ++s) {
        benchmark::DoNotOptimize(model.ping(scene, pose, s, 0.0));
        ++pings;
      }
    }
  }
  state.counters["pings_per_s"] =
      benchmark::Counter(static_cast<double>(pings), benchmark::Counter::kIsRate);
}
BENCHMARK_CAPTURE(BM_SonarPing, nine_rooms, "nine_rooms.yaml")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_SonarPing, hallway_loop, "hallway_loop.yaml")->Unit(benchmark::kMillisecond);

void BM_WorldSurfaces(benchmark::State& state) {
  const cogmap::sim::WorldSpec world = cogmap::sim::load_world(world_path("hallway_loop.yaml"));
  for (auto _ : state) benchmark::DoNotOptimize(cogmap::sim::world_surfaces(world));
}
BENCHMARK(BM_WorldSurfaces)->Unit(benchmark::kMillisecond);

}  // namespace
