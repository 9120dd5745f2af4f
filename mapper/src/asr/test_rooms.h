#pragma once
// Test and benchmark support (not part of the library): rasterised rooms with known walls.

#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "cogmap/mapper/grid/bresenham.h"
#include "cogmap/mapper/grid/grid.h"
#include "cogmap/mapper/seam/geometry.h"

namespace cogmap::mapper::test {

/// A HIMM-scale grid of one room and the truth it was drawn from.
struct RasterRoom {
  HistogramGrid grid;
  std::vector<Segment> true_walls;  ///< through the wall cells' centres, metres
  std::vector<Point2> path;         ///< robot path vertices, metres
};

inline bool inside_polygon(const std::vector<CellIndex>& polygon, double x, double y) {
  bool inside = false;
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const double xi = polygon[i].x, yi = polygon[i].y, xj = polygon[j].x, yj = polygon[j].y;
    if ((yi > y) != (yj > y) && x < (xj - xi) * (y - yi) / (yj - yi) + xi) inside = !inside;
  }
  return inside;
}

/// Draws a closed polygon room (vertices in cells) with walls one cell thick at 15, free cells
/// inside at -3, the robot path (vertices in cells) at kRobotPathValue, everything else 0.
inline RasterRoom rasterise_room(int width, int height, const std::vector<CellIndex>& polygon,
                                 const std::vector<CellIndex>& path, double cell_scale_mm = 100) {
  RasterRoom room;
  room.grid = HistogramGrid(GridGeometry(0.0, 0.0, cell_scale_mm, width, height), 0.0f);
  const GridGeometry& g = room.grid.geometry();
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      if (inside_polygon(polygon, x, y)) room.grid.set({x, y}, kHistogramFloor);
    }
  }
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const CellIndex a = polygon[i], b = polygon[(i + 1) % polygon.size()];
    for_each_line_cell(a, b, [&](CellIndex c) {
      room.grid.set(c, kHistogramMax);
      return true;
    });
    room.true_walls.push_back({g.center_of(a), g.center_of(b)});
  }
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    for_each_line_cell(path[i], path[i + 1], [&](CellIndex c) {
      room.grid.set(c, kRobotPathValue);
      return true;
    });
  }
  for (const CellIndex& c : path) room.path.push_back(g.center_of(c));
  return room;
}

/// Moves every wall cell by -1, 0 or +1 cell across its wall (seeded), and adds `spurious`
/// isolated occupied cells anywhere (seeded). Walls must be axis-aligned.
inline void add_noise(RasterRoom& room, std::uint32_t seed, int spurious) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> shift(-1, 1);
  HistogramGrid noisy = room.grid;
  const GridGeometry& g = room.grid.geometry();
  for (int y = 0; y < g.height(); ++y) {
    for (int x = 0; x < g.width(); ++x) {
      if (room.grid.get({x, y}) != kHistogramMax) continue;
      // Across the wall: the axis along which the neighbours are not wall cells.
      const bool horizontal =
          room.grid.get({x - 1, y}) == kHistogramMax || room.grid.get({x + 1, y}) == kHistogramMax;
      const int s = shift(rng);
      if (s == 0) continue;
      const CellIndex to = horizontal ? CellIndex{x, y + s} : CellIndex{x + s, y};
      if (noisy.get(to) == kRobotPathValue || !g.contains(to)) continue;
      noisy.set({x, y}, 0.0f);
      noisy.set(to, kHistogramMax);
    }
  }
  std::uniform_int_distribution<int> px(0, g.width() - 1), py(0, g.height() - 1);
  for (int i = 0; i < spurious; ++i) {
    const CellIndex c{px(rng), py(rng)};
    if (noisy.get(c) != kRobotPathValue) noisy.set(c, 10.0f);
  }
  room.grid = noisy;
}

/// Points every `step_m` along the polyline, both ends included.
inline std::vector<Point2> sample_polyline(const Polyline& line, double step_m) {
  std::vector<Point2> out;
  if (line.size() == 1) out.push_back(line[0]);
  for (std::size_t i = 1; i < line.size(); ++i) {
    const Point2 d = line[i] - line[i - 1];
    const int n = std::max(1, static_cast<int>(std::ceil(d.norm() / step_m)));
    for (int k = 0; k <= n; ++k) out.push_back(line[i - 1] + (static_cast<double>(k) / n) * d);
  }
  return out;
}

inline double distance_to_segments(const Point2& p, const std::vector<Segment>& segments) {
  double best = std::numeric_limits<double>::infinity();
  for (const Segment& s : segments) best = std::min(best, distance_to_segment_m(p, s));
  return best;
}

inline std::vector<Segment> to_segments(const std::vector<Polyline>& lines) {
  std::vector<Segment> out;
  for (const Polyline& line : lines) {
    if (line.size() == 1) out.push_back({line[0], line[0]});
    for (std::size_t i = 1; i < line.size(); ++i) out.push_back({line[i - 1], line[i]});
  }
  return out;
}

}  // namespace cogmap::mapper::test
