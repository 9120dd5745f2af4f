// ObstacleField::build against the plain per-cell scan it replaced (kept here as the
// reference): the same points, bit for bit and in the same order, and the same occupied
// cells, for grids read by rows (MHIMM) and cell by cell (HIMM, Bayes, a hand-filled grid),
// with windows at and beyond the grid's edges, with and without remembered echoes.

#include "nav/obstacle_field.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "nav/fake_grid_updater.h"
#include "nav/nav_test_util.h"

namespace cogmap::mapper::nav {
namespace {

struct Reference {
  GridGeometry geometry;
  std::vector<ObstaclePoint> points;
  std::vector<std::pair<CellIndex, float>> cells;  // every cell of the box with a value >= 0
};

/// The scan as it was before rows and offset tables (commit 8aaeff8).
Reference reference_build(const VfhOptions& vfh, const MemoryOptions& memory_options,
                          const Point2& center, const GridUpdater* grid,
                          const ObstacleMemory& memory) {
  Reference out;
  const GridGeometry geometry = grid ? grid->geometry() : GridGeometry(0.0, 0.0, 100.0, 0, 0);
  out.geometry = geometry;
  const double window = vfh.window_m;
  const double window_sq = window * window;
  const auto inside = [&](CellIndex c) {
    return (geometry.center_of(c) - center).squaredNorm() <= window_sq;
  };
  const CellIndex lo = geometry.cell_of(center - Point2(window, window));
  const CellIndex hi = geometry.cell_of(center + Point2(window, window));
  const int nx = hi.x - lo.x + 1, ny = hi.y - lo.y + 1;
  const auto slot = [&](CellIndex c) {
    const int x = c.x - lo.x, y = c.y - lo.y;
    if (x < 0 || y < 0 || x >= nx || y >= ny) return -1;
    return x * ny + y;
  };
  const std::size_t n = static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny);
  std::vector<float> cells(n, -1.0f), near_grid(n, -1.0f), echoes(n, -1.0f);
  const double near_sq =
      memory.has_echoes() ? vfh.grid_min_range_m * std::abs(vfh.grid_min_range_m) : 0.0;
  if (grid) {
    for (int y = std::max(lo.y, 0); y <= std::min(hi.y, geometry.height() - 1); ++y) {
      for (int x = std::max(lo.x, 0); x <= std::min(hi.x, geometry.width() - 1); ++x) {
        const CellIndex c{x, y};
        const float value = grid->histogram_at(c);
        if (value <= vfh.occupied_above || !inside(c)) continue;
        const auto k = static_cast<std::size_t>(slot(c));
        if ((geometry.center_of(c) - center).squaredNorm() < near_sq) {
          near_grid[k] = value;
        } else {
          cells[k] = value;
        }
      }
    }
  }
  for (const ObstacleMemory::Hit& h : memory.hits()) {
    const CellIndex c = geometry.cell_of(h.world_m);
    if (!inside(c)) continue;
    const int k = slot(c);
    if (k < 0) continue;
    float& v = echoes[static_cast<std::size_t>(k)];
    v = std::min(kHistogramMax, std::max(v, 0.0f) + memory_options.hit_value);
  }
  for (std::size_t k = 0; k < n; ++k) {
    if (echoes[k] < 0.0f) continue;
    if (near_grid[k] >= 0.0f) cells[k] = near_grid[k];
    cells[k] = std::max(std::max(cells[k], 0.0f), echoes[k]);
  }
  for (int x = 0; x < nx; ++x) {
    for (int y = 0; y < ny; ++y) {
      const float value = cells[static_cast<std::size_t>(x * ny + y)];
      if (value < 0.0f) continue;
      out.points.push_back({geometry.center_of({lo.x + x, lo.y + y}) - center, value});
      out.cells.push_back({{lo.x + x, lo.y + y}, value});
    }
  }
  return out;
}

using testing::same_bits;
bool same_bits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

/// Builds the field and the reference and compares them exactly.
void expect_same(const VfhOptions& vfh, const MemoryOptions& memory_options, const Point2& center,
                 const GridUpdater* grid, const ObstacleMemory& memory, const std::string& what) {
  SCOPED_TRACE(what);
  ObstacleField field(vfh, memory_options);
  // Twice, so the second build reuses the first one's buffers.
  field.build(center + Point2(0.37, -0.21), grid, memory);
  field.build(center, grid, memory);
  const Reference ref = reference_build(vfh, memory_options, center, grid, memory);
  ASSERT_EQ(field.points().size(), ref.points.size());
  for (std::size_t i = 0; i < ref.points.size(); ++i) {
    const ObstaclePoint& p = field.points()[i];
    const ObstaclePoint& q = ref.points[i];
    ASSERT_TRUE(same_bits(p.offset_m.x(), q.offset_m.x())) << i;
    ASSERT_TRUE(same_bits(p.offset_m.y(), q.offset_m.y())) << i;
    ASSERT_TRUE(same_bits(p.certainty, q.certainty)) << i;
  }
  // occupied(): exactly the listed cells, over the box and a margin around it.
  std::size_t occupied = 0;
  const CellIndex c0 = ref.geometry.cell_of(center);
  const int reach = static_cast<int>(vfh.window_m / ref.geometry.cell_size_m()) + 4;
  for (int y = c0.y - reach; y <= c0.y + reach; ++y) {
    for (int x = c0.x - reach; x <= c0.x + reach; ++x) occupied += field.occupied({x, y});
  }
  EXPECT_EQ(occupied, ref.cells.size());
  for (const auto& [cell, value] : ref.cells) EXPECT_TRUE(field.occupied(cell));
}

SensorFrame random_frame(std::mt19937_64& rng, double time_s) {
  std::uniform_real_distribution<double> range(0.2, 5.0), u01(0.0, 1.0);
  SensorFrame f;
  f.time_s = time_s;
  for (int i = 0; i < 16; ++i) {
    const bool echo = u01(rng) >= 0.1;
    f.sonar.push_back({i, echo ? range(rng) : 5.0, echo, time_s});
  }
  return f;
}

TEST(ObstacleFieldBuild, MatchesThePerCellScanOnEveryGridKind) {
  const RobotGeometry robot = p2at_geometry();
  for (const GridKind kind : {GridKind::kMhimm, GridKind::kHimm, GridKind::kBayes}) {
    std::mt19937_64 rng(20261201);
    std::uniform_real_distribution<double> pos(-4.0, 4.0), heading(-3.14159, 3.14159);
    auto grid = make_grid_updater(kind, GridOptions{}, robot);
    grid->reset({0.0, 0.0});
    ObstacleMemory memory{MemoryOptions{}};
    const int frames = kind == GridKind::kBayes ? 60 : 400;
    for (int f = 0; f < frames; ++f) {
      const Pose2 pose{pos(rng), pos(rng), heading(rng)};
      const SensorFrame frame = random_frame(rng, 0.1 * f);
      grid->mark_robot(pose);
      for (const SonarReading& r : frame.sonar) grid->integrate(pose, r);
      memory.add_frame(frame, pose, robot);
    }
    memory.add_contact({1.0, 1.0, 0.3}, robot, 0.1 * frames, true);
    ObstacleMemory none{MemoryOptions{}};
    ObstacleMemory contacts_only{MemoryOptions{}};
    contacts_only.add_contact({0.5, -0.5, 1.0}, robot, 0.0, false);
    const GridGeometry& g = grid->geometry();
    const Point2 low_corner(g.origin_x_m(), g.origin_y_m());
    const Point2 high_corner = g.center_of({g.width() - 1, g.height() - 1});
    std::vector<Point2> centers = {{0.0, 0.0},
                                   {0.05, 0.05},
                                   {3.33, -2.71},
                                   low_corner,
                                   high_corner,
                                   low_corner - Point2(1.0, 0.5),
                                   high_corner + Point2(2.4, 0.0),
                                   {-40.0, 3.0}};
    for (int i = 0; i < 24; ++i) centers.emplace_back(pos(rng), pos(rng));
    for (const double window : {2.5, 1.0, 3.03}) {
      for (const double near : {1.5, 0.0, -0.5, 4.0}) {
        VfhOptions vfh;
        vfh.window_m = window;
        vfh.grid_min_range_m = near;
        for (const float occupied_above : {7.0f, -2.0f}) {
          vfh.occupied_above = occupied_above;
          for (std::size_t c = 0; c < centers.size(); ++c) {
            const std::string what = std::string(to_string(kind)) + " center " + std::to_string(c) +
                                     " window " + std::to_string(window) + " near " +
                                     std::to_string(near) + " above " +
                                     std::to_string(occupied_above);
            expect_same(vfh, MemoryOptions{}, centers[c], grid.get(), memory, what);
            expect_same(vfh, MemoryOptions{}, centers[c], grid.get(), none, what + " no memory");
            expect_same(vfh, MemoryOptions{}, centers[c], grid.get(), contacts_only,
                        what + " contacts only");
            expect_same(vfh, MemoryOptions{}, centers[c], nullptr, memory, what + " no grid");
          }
        }
      }
    }
  }
}

TEST(ObstacleFieldBuild, MatchesThePerCellScanOnAHandFilledGrid) {
  // Values on both sides of ε, path cells, a wall through the window and a box at its edge.
  testing::FakeGridUpdater grid{-3.0, -3.0, 6.0, -1.0f};
  grid.fill_box(-2.0, 1.0, 2.0, 1.05, 15.0f);
  grid.fill_box(2.3, -2.9, 2.9, -2.3, 7.5f);
  grid.fill_box(-0.5, -0.5, 0.5, -0.45, 7.0f);
  grid.set(0.0, 0.0, kRobotPathValue);
  ObstacleMemory memory{MemoryOptions{}};
  SensorFrame f;
  f.sonar = {{3, 0.8, true, 0.0}, {4, 1.2, true, 0.0}, {0, 2.0, true, 0.0}};
  memory.add_frame(f, {}, p2at_geometry());
  for (const Point2& center : {Point2(0.0, 0.0), Point2(1.95, -1.2), Point2(-2.99, 2.99)}) {
    expect_same(VfhOptions{}, MemoryOptions{}, center, &grid, memory, "fake");
  }
}

TEST(GridUpdater, HistogramRowIsTheRowOfHistogramAt) {
  const RobotGeometry robot = p2at_geometry();
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> pos(-4.0, 4.0), heading(-3.14159, 3.14159);
  auto grid = make_grid_updater(GridKind::kMhimm, GridOptions{}, robot);
  grid->reset({0.0, 0.0});
  for (int f = 0; f < 100; ++f) {
    const Pose2 pose{pos(rng), pos(rng), heading(rng)};
    grid->mark_robot(pose);
    for (const SonarReading& r : random_frame(rng, 0.1 * f).sonar) grid->integrate(pose, r);
  }
  const GridGeometry& g = grid->geometry();
  for (int y = 0; y < g.height(); ++y) {
    const std::span<const float> row = grid->histogram_row(y);
    ASSERT_EQ(row.size(), static_cast<std::size_t>(g.width()));
    for (int x = 0; x < g.width(); ++x) {
      ASSERT_TRUE(same_bits(row[static_cast<std::size_t>(x)], grid->histogram_at({x, y})));
    }
  }
  // Grids that keep other values do not offer rows.
  EXPECT_TRUE(make_grid_updater(GridKind::kHimm, GridOptions{}, robot)->histogram_row(0).empty());
}

}  // namespace
}  // namespace cogmap::mapper::nav
