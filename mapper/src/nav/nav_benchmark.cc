// ObstacleField::build per control cycle (docs/performance.md). A P2-AT drives a 2 m circle
// in an 8 m room split by a wall with a 1.5 m doorway; every frame its 16 sonars, ranges cast
// exactly against the walls (no echo beyond 5 m), go into the room grid and the short-term
// obstacle memory, as NavCore::sense feeds them. The benchmark then builds the field around the
// last 64 poses in turn with the filled grid and memory: the 5 m window (2,601 cells of 10 cm)
// read from the grid, the remembered echoes merged, the obstacle points listed.
// /mhimm: the default grid (read by rows); /himm: a grid read cell by cell (histogram_at).

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "cogmap/mapper/grid/grid_updater.h"
#include "nav/obstacle_field.h"
#include "nav/obstacle_memory.h"

namespace cogmap::mapper::nav {
namespace {

struct Wall {
  Point2 a, b;
};

const std::vector<Wall>& walls() {
  static const std::vector<Wall> w = {
      {{-4.0, -4.0}, {4.0, -4.0}}, {{4.0, -4.0}, {4.0, 4.0}},  {{4.0, 4.0}, {-4.0, 4.0}},
      {{-4.0, 4.0}, {-4.0, -4.0}}, {{1.0, -4.0}, {1.0, 0.25}}, {{1.0, 1.75}, {1.0, 4.0}},
  };
  return w;
}

/// Distance along the unit ray (o, d) to the nearest wall, or infinity.
double cast(const Point2& o, const Point2& d) {
  double best = std::numeric_limits<double>::infinity();
  for (const Wall& w : walls()) {
    const Point2 e = w.b - w.a;
    const double den = d.x() * e.y() - d.y() * e.x();
    if (std::abs(den) < 1e-12) continue;
    const Point2 q = w.a - o;
    const double t = (q.x() * e.y() - q.y() * e.x()) / den;
    const double s = (q.x() * d.y() - q.y() * d.x()) / den;
    if (t > 0.0 && s >= 0.0 && s <= 1.0) best = std::min(best, t);
  }
  return best;
}

struct Scene {
  std::unique_ptr<GridUpdater> grid;
  ObstacleMemory memory{MemoryOptions{}};
  std::vector<Point2> centers;
};

Scene make_scene(GridKind kind) {
  const RobotGeometry robot = p2at_geometry();
  Scene scene{make_grid_updater(kind, GridOptions{}, robot), ObstacleMemory{MemoryOptions{}}, {}};
  scene.grid->reset({0.0, 0.0});
  constexpr int kFrames = 600;  // 60 s at 10 Hz: three laps
  for (int f = 0; f < kFrames; ++f) {
    const double a = 2.0 * M_PI * f / 200.0;
    const Pose2 pose{-1.5 + 2.0 * std::cos(a), 2.0 * std::sin(a), a + M_PI / 2};
    SensorFrame frame;
    frame.time_s = 0.1 * f;
    for (int i = 0; i < static_cast<int>(robot.sonars.size()); ++i) {
      const SonarMount& m = robot.sonars[static_cast<std::size_t>(i)];
      const Point2 o = pose.transform(Point2(m.x_m, m.y_m));
      const double h = pose.theta_rad + m.heading_rad;
      const double r = cast(o, Point2(std::cos(h), std::sin(h)));
      const bool echo = r <= robot.sonar_max_range_m;
      frame.sonar.push_back({i, echo ? r : robot.sonar_max_range_m, echo, frame.time_s});
    }
    scene.grid->mark_robot(pose);
    for (const SonarReading& r : frame.sonar) scene.grid->integrate(pose, r);
    scene.memory.add_frame(frame, pose, robot);
    if (f >= kFrames - 64) scene.centers.push_back(pose.translation());
  }
  return scene;
}

/// Built once per grid kind (Google Benchmark calls the function several times).
const Scene& scene_for(GridKind kind) {
  if (kind == GridKind::kMhimm) {
    static const Scene mhimm = make_scene(GridKind::kMhimm);
    return mhimm;
  }
  static const Scene himm = make_scene(GridKind::kHimm);
  return himm;
}

void BM_ObstacleFieldBuild(benchmark::State& state, GridKind kind) {
  const Scene& scene = scene_for(kind);
  ObstacleField field(VfhOptions{}, MemoryOptions{});
  std::size_t i = 0, points = 0;
  for (auto _ : state) {
    field.build(scene.centers[i], scene.grid.get(), scene.memory);
    points += field.points().size();
    benchmark::DoNotOptimize(field.points().data());
    i = i + 1 == scene.centers.size() ? 0 : i + 1;
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
  state.counters["points"] = static_cast<double>(points) /
                             static_cast<double>(std::max<std::int64_t>(1, state.iterations()));
  state.counters["echoes"] = static_cast<double>(scene.memory.hits().size());
}

BENCHMARK_CAPTURE(BM_ObstacleFieldBuild, mhimm, GridKind::kMhimm);
BENCHMARK_CAPTURE(BM_ObstacleFieldBuild, himm, GridKind::kHimm);

}  // namespace
}  // namespace cogmap::mapper::nav
