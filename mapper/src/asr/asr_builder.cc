// build_room_polylines: the room pipeline of thesis §3.1.5-3.1.8 (Fig. 3.3 b-g) on one grid.

#include <algorithm>
#include <vector>

#include "cogmap/mapper/asr/asr_builder.h"
#include "cogmap/mapper/asr/stages.h"

namespace cogmap::mapper {

AsrTrace build_room_polylines(const HistogramGrid& grid, const std::vector<Point2>& robot_path,
                              const AsrBuilderOptions& options) {
  AsrTrace trace;
  trace.raw = grid;
  trace.robot_path = robot_path;
  const GridGeometry& geometry = grid.geometry();
  const double cell_m = geometry.cell_size_m();

  trace.cleaned = clean_map(grid, options.occupied_threshold, options.max_sonar_range_m / cell_m);
  const std::vector<std::vector<CellIndex>> chains =
      extract_points(trace.cleaned, options.occupied_threshold, options.polyline_gap_cells);

  for (const std::vector<CellIndex>& chain : chains) {
    Polyline points;
    points.reserve(chain.size());
    for (const CellIndex& c : chain) points.push_back(geometry.center_of(c));
    trace.extracted.push_back(points);
    // A lone cell (or a chain shorter than the minimum) is a speck, not a wall.
    if (static_cast<int>(points.size()) < options.min_polyline_cells || points.size() < 2) {
      continue;
    }

    const std::vector<std::size_t> kept =
        vertex_simplify_indices(points, options.vertex_tolerance_cells * cell_m);
    Polyline simplified;
    simplified.reserve(kept.size());
    for (const std::size_t i : kept) simplified.push_back(points[i]);

    // DP positions refer to `simplified`; refinement maps them back to the extracted points.
    const double eta_m = options.douglas_peucker_cells * cell_m;
    const std::vector<std::size_t> dp_positions = douglas_peucker_indices(simplified, eta_m);
    Polyline dp;
    for (const std::size_t i : dp_positions) dp.push_back(simplified[i]);
    const std::vector<std::size_t> vertices = refine_vertices(points, kept, dp_positions, eta_m);

    PolylineFit fit = fit_polyline(points, vertices, options.min_abs_correlation,
                                   options.join_max_distance_cells * cell_m);
    trace.vertex_simplified.push_back(std::move(simplified));
    trace.douglas_peucker.push_back(std::move(dp));
    trace.fitted.push_back(std::move(fit.wall));
    trace.rejected.insert(trace.rejected.end(), fit.rejected.begin(), fit.rejected.end());
  }
  return trace;
}

std::vector<Polyline> accepted_walls(const AsrTrace& trace) {
  std::vector<Polyline> out;
  for (const Polyline& line : trace.fitted) {
    for (std::size_t i = 1; i < line.size(); ++i) {
      const Point2& a = line[i - 1];
      const Point2& b = line[i];
      const bool rejected = std::any_of(
          trace.rejected.begin(), trace.rejected.end(),
          [&](const Segment& s) { return (s.a == a && s.b == b) || (s.a == b && s.b == a); });
      if (!rejected) out.push_back({a, b});
    }
  }
  return out;
}

}  // namespace cogmap::mapper
