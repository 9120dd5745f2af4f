// Localisation over a run of 43 ASRs (the thesis's longest experiment): each new room is
// estimated against the previous, already corrected one. Goal: <= 38 ms for all 43.

#include <benchmark/benchmark.h>

#include <numbers>
#include <random>
#include <vector>

#include "cogmap/mapper/localization/localizer.h"
#include "synthetic_rooms.h"

namespace cogmap::mapper {
namespace {

constexpr int kAsrCount = 43;
constexpr double kDeg = std::numbers::pi / 180.0;

/// 43 rooms of 2-5 m sides (10-40 segments each with clutter), drifting by up to ±3° a room.
std::vector<std::vector<Polyline>> make_run(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> side(2.0, 5.0), drift(-3.0 * kDeg, 3.0 * kDeg);
  std::bernoulli_distribution l_shape(0.3);
  std::vector<std::vector<Polyline>> rooms;
  double heading = 0.0;
  for (int i = 0; i < kAsrCount; ++i) {
    const double w = side(rng), h = side(rng);
    std::vector<Point2> corners{{0, 0}, {w, 0}, {w, h}, {0, h}};
    if (l_shape(rng)) corners = {{0, 0}, {w, 0}, {w, h / 2}, {w / 2, h / 2}, {w / 2, h}, {0, h}};
    rooms.push_back(testing::noisy_room(corners, heading, 1.0 * kDeg, 0.2, rng));
    heading += drift(rng);
  }
  return rooms;
}

void BM_Localize43Asrs(benchmark::State& state) {
  const auto rooms = make_run(43);
  std::size_t segments = 0;
  for (const auto& room : rooms) {
    for (const Polyline& line : room) segments += line.size() - 1;
  }
  const Localizer localizer{LocalizerOptions{}};
  for (auto _ : state) {
    double total = 0.0;
    for (int i = 1; i < kAsrCount; ++i) {
      total += localizer.estimate(rooms[i - 1], rooms[i]).rotation_rad;
    }
    benchmark::DoNotOptimize(total);
  }
  state.counters["asrs"] = kAsrCount;
  state.counters["segments_per_asr"] = static_cast<double>(segments) / kAsrCount;
}
BENCHMARK(BM_Localize43Asrs)->Unit(benchmark::kMillisecond);

void BM_EmOneAsr(benchmark::State& state) {
  const auto rooms = make_run(7);
  const Localizer localizer{LocalizerOptions{}};
  int iterations = 0;
  for (auto _ : state) {
    const Localization r = localizer.estimate(rooms[0], rooms[1]);
    iterations = r.em.iterations;
    benchmark::DoNotOptimize(r.rotation_rad);
  }
  state.counters["em_iterations"] = iterations;
}
BENCHMARK(BM_EmOneAsr)->Unit(benchmark::kMicrosecond);

/// One room against a reference of the N rooms before it (the mapper's default is 32), with the
/// reference's directions one by one (bin 0) or pooled in 0.25° bins
/// (`mapper.em_reference_bin_deg`): args are N and the bin width in hundredths of a degree.
void BM_LocalizeAgainstLongReference(benchmark::State& state) {
  const auto rooms = make_run(11);
  const int reference_rooms = static_cast<int>(state.range(0));
  std::vector<Polyline> reference;
  for (int i = 0; i < reference_rooms; ++i) {
    const auto& room = rooms[static_cast<std::size_t>(i % (kAsrCount - 1))];
    reference.insert(reference.end(), room.begin(), room.end());
  }
  LocalizerOptions options;
  options.reference_bin_rad = static_cast<double>(state.range(1)) / 100.0 * kDeg;
  const Localizer localizer{options};
  int iterations = 0;
  for (auto _ : state) {
    const Localization r = localizer.estimate(reference, rooms[kAsrCount - 1]);
    iterations = r.em.iterations;
    benchmark::DoNotOptimize(r.rotation_rad);
  }
  state.counters["em_iterations"] = iterations;
}
BENCHMARK(BM_LocalizeAgainstLongReference)
    ->Args({2, 0})
    ->Args({32, 0})
    ->Args({32, 25})
    ->Args({256, 0})
    ->Args({256, 25})
    ->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace cogmap::mapper
