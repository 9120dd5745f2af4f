#include "cogmap/experiments/error_breakdown.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <tuple>

#include "cogmap/experiments/rigid_fit.h"

namespace cogmap::experiments {

using mapper::Point2;
using mapper::Pose2;
using mapper::Segment;

namespace {

constexpr double kDegPerRad = 180.0 / std::numbers::pi;

std::vector<Point2> vertices_world(const std::vector<mapper::Polyline>& lines, const Pose2& pose) {
  std::vector<Point2> out;
  for (const mapper::Polyline& line : lines) {
    for (const Point2& p : line) out.push_back(pose.transform(p));
  }
  return out;
}

std::vector<Segment> segments_world(const std::vector<mapper::Polyline>& lines, const Pose2& pose) {
  std::vector<Segment> out;
  for (const mapper::Polyline& line : lines) {
    for (std::size_t i = 1; i < line.size(); ++i) {
      out.push_back({pose.transform(line[i - 1]), pose.transform(line[i])});
    }
  }
  return out;
}

void append(std::vector<double>& to, const std::vector<double>& from) {
  to.insert(to.end(), from.begin(), from.end());
}

double mean(const std::vector<double>& v) {
  double sum = 0.0;
  for (const double x : v) sum += x;
  return sum / static_cast<double>(v.size());
}

double heading_error_deg(const TrajectoryRow& row, double correction_rad) {
  // Rotations compose by adding angles, whatever the pivot of the correction.
  const double drawn_rad = row.estimate.theta_rad + correction_rad;
  return mapper::wrap_angle_rad(drawn_rad - row.truth->theta_rad) * kDegPerRad;
}

}  // namespace

StageError stage_error(std::vector<double>& distances_m) {
  StageError e;
  e.count = distances_m.size();
  if (distances_m.empty()) return e;
  e.median_m = quantile(distances_m, 0.5);
  e.p90_m = quantile(distances_m, 0.9);
  return e;
}

std::vector<Point2> occupied_cells_world(const mapper::HistogramGrid& grid,
                                         double occupied_threshold, const Pose2& room_to_world) {
  std::vector<Point2> out;
  const mapper::GridGeometry& g = grid.geometry();
  for (int y = 0; y < grid.height(); ++y) {
    for (int x = 0; x < grid.width(); ++x) {
      // Strictly greater, as the builder's stages test it (asr_builder.h: "H > ε is occupied").
      if (static_cast<double>(grid.get({x, y})) > occupied_threshold) {
        out.push_back(room_to_world.transform(g.center_of({x, y})));
      }
    }
  }
  return out;
}

std::vector<double> nearest_distances_m(const SegmentIndex& truth, std::span<const Point2> points) {
  std::vector<double> out;
  out.reserve(points.size());
  for (const Point2& p : points) out.push_back(truth.nearest_distance_m(p));
  return out;
}

std::vector<ErrorPiece> error_pieces(std::span<const Segment> map, const SegmentIndex& truth,
                                     double sample_step_m) {
  std::vector<ErrorPiece> out;
  for (const SurfaceSample& s : sample_segments(map, sample_step_m)) {
    // The sample is its piece's midpoint and stands for weight_m of the segment.
    const Segment& seg = map[s.segment];
    const Point2 half = (seg.b - seg.a) * (0.5 * s.weight_m / seg.length_m());
    out.push_back({{s.point - half, s.point + half}, truth.nearest_distance_m(s.point)});
  }
  return out;
}

namespace {

// The room's errors from the first and the last row with a true pose within its span.
std::optional<RoomHeadingError> heading_error_of(const std::optional<TrajectoryRow>& first,
                                                 const std::optional<TrajectoryRow>& last,
                                                 const RoomSpan& room) {
  if (!first) return std::nullopt;
  // The first row is the boundary frame the room shares with its parent: its estimate is already
  // in this room's frame (the parent's correction applied). So is every row up to the last,
  // which carries this room's correction too when the room ended inside that frame.
  const bool last_corrected = room.last_row_corrected && last->t_s == room.end_time_s;
  return RoomHeadingError{heading_error_deg(*first, room.room_to_world_rad),
                          heading_error_deg(*last, last_corrected ? 0.0 : room.room_to_world_rad)};
}

}  // namespace

std::optional<RoomHeadingError> room_heading_error(TrajectoryView rows, const RoomSpan& room) {
  // Copies: a row is valid only until the next one is read.
  std::optional<TrajectoryRow> first;
  std::optional<TrajectoryRow> last;
  for (const TrajectoryRow& row : rows) {
    if (row.t_s < room.start_time_s) continue;
    if (row.t_s > room.end_time_s) break;
    if (!row.truth) continue;
    if (!first) first = row;
    last = row;
  }
  return heading_error_of(first, last, room);
}

HeadingBreakdown heading_breakdown(TrajectoryView rows, std::span<const RoomSpan> rooms) {
  // One pass over the rows for all rooms (a long run's rows are read back from disk): the rows
  // are in time order, so each room's first and last row with a true pose within its span are
  // those room_heading_error finds.
  std::vector<std::optional<TrajectoryRow>> first(rooms.size()), last(rooms.size());
  for (const TrajectoryRow& row : rows) {
    if (!row.truth) continue;
    for (std::size_t k = 0; k < rooms.size(); ++k) {
      if (row.t_s < rooms[k].start_time_s || row.t_s > rooms[k].end_time_s) continue;
      if (!first[k]) first[k] = row;
      last[k] = row;
    }
  }
  std::vector<double> entry, exit, drift;
  for (std::size_t k = 0; k < rooms.size(); ++k) {
    const std::optional<RoomHeadingError> e = heading_error_of(first[k], last[k], rooms[k]);
    if (!e) continue;
    entry.push_back(std::abs(e->entry_deg));
    exit.push_back(std::abs(e->exit_deg));
    const double drift_rad = mapper::wrap_angle_rad((e->exit_deg - e->entry_deg) / kDegPerRad);
    drift.push_back(std::abs(drift_rad * kDegPerRad));
  }
  HeadingBreakdown h;
  h.rooms = entry.size();
  if (entry.empty()) return h;
  h.entry_error_deg_mean_abs = mean(entry);
  h.exit_error_deg_mean_abs = mean(exit);
  h.exit_error_deg_max_abs = *std::max_element(exit.begin(), exit.end());
  h.within_room_drift_deg_mean_abs = mean(drift);
  h.within_room_drift_deg_max_abs = *std::max_element(drift.begin(), drift.end());
  return h;
}

std::pair<AlignedMap, AlignedRooms> aligned_errors(std::span<const std::vector<Point2>> rooms_lines,
                                                   const SegmentIndex& truth,
                                                   const Point2& start_m) {
  std::vector<Point2> all;
  for (const std::vector<Point2>& room : rooms_lines) {
    all.insert(all.end(), room.begin(), room.end());
  }
  AlignedMap whole;
  const RigidFit map_fit = fit_rigid(all, truth);
  if (map_fit.fitted) {
    whole.rotation_deg = map_fit.transform.theta_rad * kDegPerRad;
    whole.start_shift_m = map_fit.transform.transform(start_m) - start_m;
  }

  // Each room from where the whole map's fit put it, by its own fit with the near gates only:
  // a room of one or two short walls pulled from a metre away could snap onto its neighbour's.
  RigidFitOptions room_options;
  room_options.gates_m = {0.4, 0.25};
  room_options.min_pairs = 20;  // 1 m of wall at the 5 cm sampling
  AlignedRooms rooms;
  std::vector<double> whole_m, rooms_m;
  for (const std::vector<Point2>& room : rooms_lines) {
    std::vector<Point2> moved = room;
    for (Point2& p : moved) p = map_fit.transform.transform(p);
    append(whole_m, nearest_distances_m(truth, moved));
    // A room too small to fit (or with nothing near the truth) stays where the map's fit put it.
    const RigidFit room_fit = fit_rigid(moved, truth, room_options);
    if (room_fit.fitted) ++rooms.rooms_fitted;
    for (Point2& p : moved) p = room_fit.transform.transform(p);
    append(rooms_m, nearest_distances_m(truth, moved));
  }
  whole.error = stage_error(whole_m);
  rooms.error = stage_error(rooms_m);
  return {whole, rooms};
}

ErrorBreakdownBuilder::ErrorBreakdownBuilder(std::span<const Segment> truth,
                                             double occupied_threshold,
                                             const MapMetricsOptions& options)
    : truth_(truth, options.index_cell_m),
      occupied_threshold_(occupied_threshold),
      sample_step_m_(options.sample_step_m) {}

void ErrorBreakdownBuilder::add_room(int id, const Pose2& room_to_world,
                                     const mapper::AsrTrace& trace) {
  RoomPoints room;
  room.id = id;
  room.grid = occupied_cells_world(trace.raw, occupied_threshold_, room_to_world);
  room.cleaned = occupied_cells_world(trace.cleaned, occupied_threshold_, room_to_world);
  room.points = vertices_world(trace.extracted, room_to_world);
  // The fitted polylines are the ASR's walls (rejected fits kept as their DP segments), so
  // this stage samples exactly what the `map` block measures.
  const std::vector<Segment> lines = segments_world(trace.fitted, room_to_world);
  for (const SurfaceSample& s : sample_segments(lines, sample_step_m_)) {
    room.lines.push_back(s.point);
  }
  rooms_.push_back(std::move(room));
}

void ErrorBreakdownBuilder::move_rooms(std::span<const std::pair<int, Pose2>> moves) {
  for (const auto& [id, move] : moves) {
    for (RoomPoints& room : rooms_) {
      if (room.id != id) continue;
      for (std::vector<Point2>* stage : {&room.grid, &room.cleaned, &room.points, &room.lines}) {
        for (Point2& p : *stage) p = move.transform(p);
      }
    }
  }
}

ErrorBreakdown ErrorBreakdownBuilder::finish(TrajectoryView rows) {
  std::vector<double> grid_m, cleaned_m, points_m, lines_m;
  for (const RoomPoints& room : rooms_) {
    append(grid_m, nearest_distances_m(truth_, room.grid));
    append(cleaned_m, nearest_distances_m(truth_, room.cleaned));
    append(points_m, nearest_distances_m(truth_, room.points));
    append(lines_m, nearest_distances_m(truth_, room.lines));
  }
  ErrorBreakdown b;
  b.grid = stage_error(grid_m);
  b.cleaned = stage_error(cleaned_m);
  b.points = stage_error(points_m);
  b.lines = stage_error(lines_m);
  std::vector<std::vector<Point2>> rooms_lines;
  for (RoomPoints& room : rooms_) rooms_lines.push_back(std::move(room.lines));
  const Point2 start_m =
      rows.begin() == rows.end() ? Point2::Zero() : rows.begin()->estimate.translation();
  std::tie(b.aligned_map, b.aligned_rooms) = aligned_errors(rooms_lines, truth_, start_m);
  b.heading = heading_breakdown(rows, spans_);
  // The points are done with: give their memory back before the map metrics run.
  std::vector<RoomPoints>().swap(rooms_);
  return b;
}

}  // namespace cogmap::experiments
