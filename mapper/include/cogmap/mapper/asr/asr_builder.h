#pragma once
/// Room -> polylines (thesis §3.1.5-3.1.8): clean map, extract points, vertex simplify,
/// Douglas-Peucker, least-squares line fit. Every stage's output is kept in AsrTrace so the
/// renderer can draw Fig. 3.3 (a)-(g) for every room without running anything again.

#include <vector>

#include "cogmap/mapper/grid/grid.h"
#include "cogmap/mapper/seam/geometry.h"

namespace cogmap::mapper {

/// Thresholds of the room pipeline; τ, γ, η and the join distance are in cells (scaled by ℘).
struct AsrBuilderOptions {
  double occupied_threshold = 7.0;      ///< ε, thesis Table 4.1: H > ε is occupied
  double vertex_tolerance_cells = 2.0;  ///< τ, thesis Table 4.1 / Fig. A.4
  double polyline_gap_cells = 4.0;      ///< γ, thesis Table 4.1 / §3.1.6: break distance
  double douglas_peucker_cells = 1.0;   ///< η, thesis Fig. A.5 (no value given; see docs)
  double min_abs_correlation = 0.9;     ///< |ρ| acceptance, thesis §3.1.8
  double max_sonar_range_m = 5.0;       ///< max_dist of the clean-map rays, thesis Fig. 3.8
  /// Fitted lines meet at their intersection only if it lies this close to the shared DP vertex
  /// (not in the thesis; see docs/algorithms.md).
  double join_max_distance_cells = 3.0;
  /// Extracted polylines with fewer cells are dropped as noise (not in the thesis; see docs).
  int min_polyline_cells = 2;
};

/// Every intermediate product of one room, in the grid's (local) frame, metres.
struct AsrTrace {
  int asr_id = -1;
  HistogramGrid raw;                        ///< Fig. 3.3 (a): the room's grid on the HIMM scale
  HistogramGrid cleaned;                    ///< (b): after the clean-map rays
  std::vector<Polyline> extracted;          ///< (c): ordered cell centres, split at γ breaks
  std::vector<Polyline> vertex_simplified;  ///< (d): after VertexSimplify (τ)
  std::vector<Polyline> douglas_peucker;    ///< (e): after Douglas-Peucker (η)
  std::vector<Polyline> fitted;             ///< (f-g): least-squares lines, |ρ| accepted
  std::vector<Segment> rejected;            ///< DP segments whose fit had |ρ| < threshold
  std::vector<Point2> robot_path;           ///< the robot's centre path through the room
};

/// Runs the pipeline on one room's grid. `robot_path` is the robot centre path (grid frame);
/// the path cells of `grid` are expected to carry kRobotPathValue already.
AsrTrace build_room_polylines(const HistogramGrid& grid, const std::vector<Point2>& robot_path,
                              const AsrBuilderOptions& options);

/// The segments of a room's walls but the rejected fits (§3.1.8), each as a two-vertex polyline.
/// A rejected fit stays in the wall as its Douglas-Peucker segment (so the map keeps it) but is,
/// by the fit's own test, no straight line: it carries no direction. The short joins between a
/// fitted line and a rejected neighbour's vertex, or two fitted lines that do not meet, come
/// along (docs/algorithms.md, "Odometry prior on the rotation": leaving them out was measured).
std::vector<Polyline> accepted_walls(const AsrTrace& trace);

}  // namespace cogmap::mapper
