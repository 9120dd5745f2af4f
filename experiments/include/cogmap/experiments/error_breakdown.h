#pragma once
/// Where the map error comes from (metrics.json `error_breakdown`, docs/metrics.md): the
/// distance to the nearest true surface of every stage of the room pipeline (raw grid, cleaned
/// grid, extracted points, fitted lines), all placed in the corrected world frame, and the
/// heading error split into what a room starts with and what drifts in while it is mapped.

#include <cstddef>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "cogmap/experiments/metrics.h"
#include "cogmap/experiments/segment_index.h"
#include "cogmap/mapper/asr/asr_builder.h"
#include "cogmap/mapper/grid/grid.h"
#include "cogmap/mapper/seam/geometry.h"
#include "cogmap/mapper/seam/pose2.h"

namespace cogmap::experiments {

/// Distance statistics of one stage's points to the nearest true surface.
struct StageError {
  std::optional<double> median_m;  ///< empty when the stage has no point
  std::optional<double> p90_m;
  std::size_t count = 0;  ///< points (cells, vertices or line samples) measured
};

/// Median and p90 (metrics.h `quantile`) of `distances_m`; `distances_m` is reordered.
StageError stage_error(std::vector<double>& distances_m);

/// Centres of the cells of `grid` that the ASR builder counts as occupied (H > ε, as
/// clean_map and extract_points test it), mapped by `room_to_world`.
std::vector<mapper::Point2> occupied_cells_world(const mapper::HistogramGrid& grid,
                                                 double occupied_threshold,
                                                 const mapper::Pose2& room_to_world);

/// The distance of every point to the nearest segment of `truth`.
std::vector<double> nearest_distances_m(const SegmentIndex& truth,
                                        std::span<const mapper::Point2> points);

/// One piece of a map segment, as the map metrics sample it (sample_segments), and the distance
/// of its midpoint (the sample) to the nearest true surface: what figures/map_error.png colours.
struct ErrorPiece {
  mapper::Segment piece;
  double error_m = 0.0;
};
std::vector<ErrorPiece> error_pieces(std::span<const mapper::Segment> map,
                                     const SegmentIndex& truth, double sample_step_m);

/// One room's part in the heading breakdown. The room's map was drawn in the estimate frame as
/// it stood while the robot was in the room (its local frame; in-room corrections included), and
/// asr.pose turns that frame into the corrected world.
struct RoomSpan {
  double start_time_s = 0.0;
  double end_time_s = 0.0;
  double room_to_world_rad = 0.0;  ///< asr.pose.θ: the room's correction on leaving it
  /// True when the room ended at a boundary inside a frame: that frame's row was recorded after
  /// the mapper applied the room's correction, so its estimate is already in the corrected world.
  /// False for the room the end of the run closed (mapper.finish(), after the last row).
  bool last_row_corrected = true;
};

/// The heading errors of one room, degrees, wrapped to (−180, 180]: the heading the room's
/// corrected map was drawn with (estimate turned by asr.pose) minus the true heading, at the
/// room's first and last frame with truth.
struct RoomHeadingError {
  double entry_deg = 0.0;
  double exit_deg = 0.0;
};

/// Empty when no row in [start, end] has ground truth. `rows` are in time order.
std::optional<RoomHeadingError> room_heading_error(TrajectoryView rows, const RoomSpan& room);

/// The heading block: means over rooms with truth; empty optionals when there is none.
struct HeadingBreakdown {
  std::size_t rooms = 0;
  std::optional<double> entry_error_deg_mean_abs;
  std::optional<double> exit_error_deg_mean_abs;
  /// The worst room as the estimate left it (max over rooms of |error| at the last frame): the
  /// run's tail, which a mean hides (one room turned 15° by a wrong correction draws the rest
  /// of the map turned with it).
  std::optional<double> exit_error_deg_max_abs;
  std::optional<double> within_room_drift_deg_mean_abs;  ///< mean |wrap(exit − entry)|
  std::optional<double> within_room_drift_deg_max_abs;
};
/// Each room's errors as room_heading_error gives them, from one pass over `rows` (in time
/// order) for all rooms.
HeadingBreakdown heading_breakdown(TrajectoryView rows, std::span<const RoomSpan> rooms);

/// The `lines` samples laid onto the truth by one rigid transform of the whole map
/// (rigid_fit.h): the error left when only the map's placement as a whole is taken away.
struct AlignedMap {
  StageError error;
  std::optional<double> rotation_deg;           ///< the transform's turn; empty when no fit
  std::optional<mapper::Point2> start_shift_m;  ///< where it moves the run's start position
};

/// The `lines` samples with every room laid onto the truth by its own rigid transform: the
/// error left when the rooms' placements are taken away, the walls' own shape and smear.
struct AlignedRooms {
  StageError error;
  std::size_t rooms_fitted = 0;  ///< rooms with enough samples near the truth to fit
};

/// metrics.json `error_breakdown`.
struct ErrorBreakdown {
  StageError grid;     ///< occupied cells of the raw room grids
  StageError cleaned;  ///< occupied cells of the cleaned grids
  StageError points;   ///< vertices of the extracted polylines
  StageError lines;    ///< samples of the fitted polylines (the map metric's sampling)
  AlignedMap aligned_map;
  AlignedRooms aligned_rooms;
  HeadingBreakdown heading;
};

/// aligned_map and aligned_rooms of `rooms_lines` (each room's `lines` samples, world frame):
/// `start_m` is the run's start position, for AlignedMap::start_shift_m.
std::pair<AlignedMap, AlignedRooms> aligned_errors(
    std::span<const std::vector<mapper::Point2>> rooms_lines, const SegmentIndex& truth,
    const mapper::Point2& start_m);

/// Collects the stages' points room by room, from inside the mapper's room listener: the trace
/// (whole grids) is dropped after that call, so only one point per occupied cell, vertex and
/// line sample is kept, never a grid. Points, not distances: the end-of-run relaxation may
/// still move a room (move_room), and the breakdown measures the map as it is written.
class ErrorBreakdownBuilder {
 public:
  ErrorBreakdownBuilder(std::span<const mapper::Segment> truth, double occupied_threshold,
                        const MapMetricsOptions& options = {});

  /// `room_to_world` is the finished room's asr.pose (local -> corrected world).
  void add_room(int id, const mapper::Pose2& room_to_world, const mapper::AsrTrace& trace);
  /// Rooms re-placed (Mapper::room_moves): each move (world -> world) applies to all the
  /// points of its room.
  void move_rooms(std::span<const std::pair<int, mapper::Pose2>> moves);
  void add_room_span(const RoomSpan& span) { spans_.push_back(span); }

  const SegmentIndex& truth_index() const { return truth_; }

  /// The block, with the heading part from the run's trajectory. Releases the rooms' samples:
  /// call it once, after the last add_room.
  ErrorBreakdown finish(TrajectoryView rows);

 private:
  SegmentIndex truth_;
  double occupied_threshold_;
  double sample_step_m_;
  struct RoomPoints {
    int id = -1;
    std::vector<mapper::Point2> grid, cleaned, points, lines;
  };
  std::vector<RoomPoints> rooms_;
  std::vector<RoomSpan> spans_;
};

}  // namespace cogmap::experiments
