// Readings per second of each updater (docs/performance.md). A robot wanders a 10 m
// room: each frame a pose uniform in the room's inner 8 m square with a random heading, then
// all 16 P2-AT sonars with ranges uniform in 0.3-5 m, one in ten without an echo. The script
// is generated once from a fixed seed, so every run integrates the same readings.

#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "cogmap/mapper/grid/grid_updater.h"

namespace cogmap::mapper {
namespace {

struct ScriptedReading {
  Pose2 pose;
  SonarReading reading;
};

const std::vector<ScriptedReading>& script() {
  static const std::vector<ScriptedReading> readings = [] {
    std::vector<ScriptedReading> out;
    std::mt19937_64 rng(20261122);
    std::uniform_real_distribution<double> pos(-4.0, 4.0), heading(-3.14159, 3.14159);
    std::uniform_real_distribution<double> range(0.3, 5.0), u01(0.0, 1.0);
    constexpr int kFrames = 4096;
    for (int f = 0; f < kFrames; ++f) {
      const Pose2 pose{pos(rng), pos(rng), heading(rng)};
      for (int i = 0; i < 16; ++i) {
        const bool echo = u01(rng) >= 0.1;
        out.push_back({pose, {i, echo ? range(rng) : 5.0, echo, 0.0}});
      }
    }
    return out;
  }();
  return readings;
}

void integrate_readings(benchmark::State& state, GridKind kind) {
  auto updater = make_grid_updater(kind, GridOptions{}, p2at_geometry());
  updater->reset({0.0, 0.0});
  const std::vector<ScriptedReading>& readings = script();
  for (const ScriptedReading& r : readings) updater->integrate(r.pose, r.reading);  // grow once
  std::size_t i = 0;
  for (auto _ : state) {
    const ScriptedReading& r = readings[i];
    benchmark::DoNotOptimize(updater->integrate(r.pose, r.reading));
    i = i + 1 == readings.size() ? 0 : i + 1;
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
  state.counters["grid_bytes"] = static_cast<double>(updater->grid_bytes());
}

void BM_Mhimm(benchmark::State& state) { integrate_readings(state, GridKind::kMhimm); }
void BM_Himm(benchmark::State& state) { integrate_readings(state, GridKind::kHimm); }
void BM_Bayes(benchmark::State& state) { integrate_readings(state, GridKind::kBayes); }
void BM_DempsterShafer(benchmark::State& state) {
  integrate_readings(state, GridKind::kDempsterShafer);
}

BENCHMARK(BM_Mhimm);
BENCHMARK(BM_Himm);
BENCHMARK(BM_Bayes);
BENCHMARK(BM_DempsterShafer);

}  // namespace
}  // namespace cogmap::mapper
