#pragma once
/// The individual stages of the room pipeline, exposed for tests and tools.

#include <span>
#include <vector>

#include "cogmap/mapper/grid/grid.h"
#include "cogmap/mapper/seam/geometry.h"

namespace cogmap::mapper {

/// Fig. 3.8: keeps an occupied cell only if a Bresenham ray reaches a robot-path cell within
/// `max_range_cells` without crossing another occupied cell; others become unexplored (0).
HistogramGrid clean_map(const HistogramGrid& grid, double occupied_threshold,
                        double max_range_cells);

/// Fig. 3.9: follow-and-remove nearest-neighbour extraction of cells with H > ε into ordered
/// polylines of cell indices, broken where the next cell is farther than γ cells.
std::vector<std::vector<CellIndex>> extract_points(const HistogramGrid& grid,
                                                   double occupied_threshold, double gap_cells);

/// Fig. A.4: drops every vertex closer than `tolerance` to the last kept vertex.
Polyline vertex_simplify(const Polyline& line, double tolerance);

/// Fig. A.5: Douglas-Peucker with perpendicular-distance tolerance `tolerance` (same units).
Polyline douglas_peucker(const Polyline& line, double tolerance);

/// Least-squares line through points (Eqs. 3.8-3.9) with its correlation (Eq. 3.10).
struct LineFit {
  Point2 point{0.0, 0.0};      ///< a point on the line (the centroid)
  Point2 direction{1.0, 0.0};  ///< unit direction
  double correlation = 0.0;    ///< |ρ| in the line's own frame (rotation invariant; see docs)
  bool valid = false;          ///< false for fewer than 2 distinct points
};
LineFit fit_line(std::span<const Point2> points);

}  // namespace cogmap::mapper
