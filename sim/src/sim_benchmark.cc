// Simulator speed: simulated seconds per wall-clock second of SimRobot alone (physics, slip,
// encoders, sonar) in nine_rooms, and the one-off cost of extracting a world's true surfaces.
// docs/performance.md records the figures.
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <filesystem>

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

void BM_WorldSurfaces(benchmark::State& state) {
  const cogmap::sim::WorldSpec world = cogmap::sim::load_world(world_path("hallway_loop.yaml"));
  for (auto _ : state) benchmark::DoNotOptimize(cogmap::sim::world_surfaces(world));
}
BENCHMARK(BM_WorldSurfaces)->Unit(benchmark::kMillisecond);

}  // namespace
