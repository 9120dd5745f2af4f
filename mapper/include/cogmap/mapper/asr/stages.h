#pragma once
/// The individual stages of the room pipeline (thesis §3.1.5-3.1.8), exposed for tests and
/// tools. docs/algorithms.md maps every function to its thesis figure.

#include <cstddef>
#include <span>
#include <vector>

#include "cogmap/mapper/grid/grid.h"
#include "cogmap/mapper/seam/geometry.h"

namespace cogmap::mapper {

/// Fig. 3.7/3.8: keeps an occupied cell (H > ε) only if a Bresenham ray from it reaches a
/// robot-path cell (kRobotPathValue) no farther than `max_range_cells` without crossing another
/// occupied cell of the input; other occupied cells become unexplored (0). All other cells,
/// path cells included, are copied unchanged.
HistogramGrid clean_map(const HistogramGrid& grid, double occupied_threshold,
                        double max_range_cells);

/// Fig. 3.9: follow-and-remove nearest-neighbour extraction of cells with H > ε into ordered
/// polylines of cell indices, broken where the next cell is farther than γ (`gap_cells`) cells.
std::vector<std::vector<CellIndex>> extract_points(const HistogramGrid& grid,
                                                   double occupied_threshold, double gap_cells);

/// Fig. A.4: indices of the vertices kept when every vertex closer than `tolerance` to the last
/// kept vertex is dropped. The first and the last vertex are always kept.
std::vector<std::size_t> vertex_simplify_indices(const Polyline& line, double tolerance);

/// Fig. A.4: the polyline of vertex_simplify_indices().
Polyline vertex_simplify(const Polyline& line, double tolerance);

/// Fig. A.5: indices (ascending) kept by Douglas-Peucker with distance tolerance `tolerance`
/// (same units as the line) to the finite segment; both endpoints are kept.
std::vector<std::size_t> douglas_peucker_indices(const Polyline& line, double tolerance);

/// Fig. A.5: the polyline of douglas_peucker_indices().
Polyline douglas_peucker(const Polyline& line, double tolerance);

/// Corner refinement (not in the thesis; see docs): `simplified_indices` are the VertexSimplify
/// survivors as indices into the extracted `points`, `dp_positions` the DP survivors as positions
/// in `simplified_indices`. Each interior DP vertex moves to the point, among those VertexSimplify
/// dropped next to it, farthest from the chord of its neighbouring vertices, and is dropped if
/// that distance is not above `tolerance` (η). Returns ascending indices into `points`.
std::vector<std::size_t> refine_vertices(const Polyline& points,
                                         std::span<const std::size_t> simplified_indices,
                                         std::span<const std::size_t> dp_positions,
                                         double tolerance);

/// Rotation-invariant least-squares line (orthogonal regression; see docs for why this and not
/// Eqs. 3.8-3.9 literally).
struct LineFit {
  Point2 point{0.0, 0.0};      ///< a point on the line (the centroid), input units
  Point2 direction{1.0, 0.0};  ///< unit direction
  double correlation = 0.0;    ///< |ρ| of Eq. 3.10 in the frame where the line runs at 45°
  bool valid = false;          ///< false for fewer than 2 distinct points

  /// Orthogonal projection of `p` onto the fitted line.
  Point2 project(const Point2& p) const { return point + (p - point).dot(direction) * direction; }
};

/// Orthogonal least-squares line through `points` with |ρ| = (λ1 − λ2)/(λ1 + λ2) of the
/// covariance eigenvalues (equals Eq. 3.10 evaluated with the line rotated to 45°).
LineFit fit_line(std::span<const Point2> points);

/// Eqs. 3.8-3.10 exactly as printed: y = b0 + b1 x by ordinary least squares, Pearson's ρ.
struct RegressionFit {
  double b0 = 0.0;           ///< intercept, Eq. 3.9
  double b1 = 0.0;           ///< slope, Eq. 3.8
  double correlation = 0.0;  ///< signed ρ, Eq. 3.10
  bool valid = false;        ///< false when the x or the y values have no spread
};

/// The thesis's y-on-x regression; degenerate for vertical and for exactly horizontal lines,
/// kept as the reference that fit_line() is checked against.
RegressionFit regress_y_on_x(std::span<const Point2> points);

/// One polyline after the §3.1.8 fitting stage.
struct PolylineFit {
  Polyline wall;                  ///< fitted lines joined; rejected DP segments kept as they are
  std::vector<Segment> rejected;  ///< the DP segments whose fit had |ρ| below the threshold
};

/// §3.1.8 for one polyline: `points` are the extracted points in order, `vertex_indices` the
/// ascending indices of the Douglas-Peucker vertices among them (first and last included). Each
/// DP segment is replaced by the line fitted to the points between its two vertices when
/// |ρ| >= `min_abs_correlation`; consecutive fitted lines are joined at their intersection when
/// it lies within `join_max_distance` of the shared DP vertex, else at the two projections.
PolylineFit fit_polyline(const Polyline& points, std::span<const std::size_t> vertex_indices,
                         double min_abs_correlation, double join_max_distance);

}  // namespace cogmap::mapper
