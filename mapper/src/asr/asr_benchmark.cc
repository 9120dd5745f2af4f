// Speed of the room pipeline on a 100 x 100 cell room (goal: build_room_polylines <= 2 ms).

#include <benchmark/benchmark.h>

#include "cogmap/mapper/asr/asr_builder.h"
#include "cogmap/mapper/asr/stages.h"
#include "test_rooms.h"

namespace cogmap::mapper {
namespace {

// A 9.5 m square room on 100 x 100 cells, path along the middle. `realistic` adds what a HIMM
// grid shows: walls thickened to 3 cells on the far side, jittered faces and 200 stray cells.
test::RasterRoom bench_room(bool realistic) {
  test::RasterRoom room =
      test::rasterise_room(100, 100, {{2, 2}, {97, 2}, {97, 97}, {2, 97}}, {{10, 50}, {90, 50}});
  if (!realistic) return room;
  test::add_noise(room, 7, 200);
  HistogramGrid thick = room.grid;
  for (int y = 0; y < 100; ++y) {
    for (int x = 0; x < 100; ++x) {
      if (room.grid.get({x, y}) != kHistogramMax) continue;
      for (int dy = -2; dy <= 2; ++dy) {
        for (int dx = -2; dx <= 2; ++dx) {
          if (thick.get({x + dx, y + dy}) == 0.0f) thick.set({x + dx, y + dy}, 12.0f);
        }
      }
    }
  }
  room.grid = thick;
  return room;
}

void BM_BuildRoomPolylines(benchmark::State& state) {
  const test::RasterRoom room = bench_room(state.range(0) != 0);
  std::size_t vertices = 0;
  for (auto _ : state) {
    const AsrTrace trace = build_room_polylines(room.grid, room.path, AsrBuilderOptions{});
    vertices = 0;
    for (const Polyline& line : trace.fitted) vertices += line.size();
    benchmark::DoNotOptimize(trace);
  }
  state.counters["fitted_vertices"] = static_cast<double>(vertices);
}
BENCHMARK(BM_BuildRoomPolylines)
    ->Arg(0)
    ->Arg(1)
    ->ArgName("realistic")
    ->Unit(benchmark::kMicrosecond);

void BM_CleanMap(benchmark::State& state) {
  const test::RasterRoom room = bench_room(state.range(0) != 0);
  for (auto _ : state) benchmark::DoNotOptimize(clean_map(room.grid, 7.0, 50.0));
}
BENCHMARK(BM_CleanMap)->Arg(0)->Arg(1)->ArgName("realistic")->Unit(benchmark::kMicrosecond);

void BM_ExtractPoints(benchmark::State& state) {
  const test::RasterRoom room = bench_room(state.range(0) != 0);
  const HistogramGrid cleaned = clean_map(room.grid, 7.0, 50.0);
  for (auto _ : state) benchmark::DoNotOptimize(extract_points(cleaned, 7.0, 4.0));
}
BENCHMARK(BM_ExtractPoints)->Arg(0)->Arg(1)->ArgName("realistic")->Unit(benchmark::kMicrosecond);

std::vector<Polyline> extracted_lines(bool realistic) {
  const test::RasterRoom room = bench_room(realistic);
  std::vector<Polyline> lines;
  for (const auto& chain : extract_points(clean_map(room.grid, 7.0, 50.0), 7.0, 4.0)) {
    Polyline line;
    for (const CellIndex& c : chain) line.push_back(room.grid.geometry().center_of(c));
    lines.push_back(line);
  }
  return lines;
}

void BM_SimplifyAndFit(benchmark::State& state) {
  const std::vector<Polyline> lines = extracted_lines(state.range(0) != 0);
  for (auto _ : state) {
    for (const Polyline& line : lines) {
      const auto kept = vertex_simplify_indices(line, 0.2);
      Polyline simplified;
      for (const std::size_t i : kept) simplified.push_back(line[i]);
      const auto dp = douglas_peucker_indices(simplified, 0.1);
      const auto vertices = refine_vertices(line, kept, dp, 0.1);
      benchmark::DoNotOptimize(fit_polyline(line, vertices, 0.9, 0.3));
    }
  }
}
BENCHMARK(BM_SimplifyAndFit)->Arg(0)->Arg(1)->ArgName("realistic")->Unit(benchmark::kMicrosecond);

void BM_VertexSimplify(benchmark::State& state) {
  const std::vector<Polyline> lines = extracted_lines(state.range(0) != 0);
  for (auto _ : state) {
    for (const Polyline& line : lines) benchmark::DoNotOptimize(vertex_simplify(line, 0.2));
  }
}
BENCHMARK(BM_VertexSimplify)->Arg(0)->Arg(1)->ArgName("realistic")->Unit(benchmark::kMicrosecond);

void BM_DouglasPeucker(benchmark::State& state) {
  std::vector<Polyline> lines;
  for (const Polyline& line : extracted_lines(state.range(0) != 0)) {
    lines.push_back(vertex_simplify(line, 0.2));
  }
  for (auto _ : state) {
    for (const Polyline& line : lines) benchmark::DoNotOptimize(douglas_peucker(line, 0.1));
  }
}
BENCHMARK(BM_DouglasPeucker)->Arg(0)->Arg(1)->ArgName("realistic")->Unit(benchmark::kMicrosecond);

void BM_FitLine(benchmark::State& state) {
  const std::vector<Polyline> lines = extracted_lines(false);
  for (auto _ : state) {
    for (const Polyline& line : lines) benchmark::DoNotOptimize(fit_line(line));
  }
}
BENCHMARK(BM_FitLine)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace cogmap::mapper
