#pragma once
// Mapper's state (Mapper::Impl), shared by the facade's two files: mapper.cc feeds it frames,
// mapper_rooms.cc ends rooms (the ASR pipeline, EM, the translation, door fixes, glimpses and
// scan matches).

#include <algorithm>
#include <chrono>
#include <cmath>
#include <deque>

#include "cogmap/mapper/localization/glimpse_heading.h"
#include "cogmap/mapper/mapper.h"
#include "facade/room_recorder.h"
#include "facade/room_relaxation.h"

namespace cogmap::mapper {
namespace facade_detail {

inline double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

inline AsrBuilderOptions builder_with_range(AsrBuilderOptions builder, const RobotGeometry& robot) {
  builder.max_sonar_range_m = robot.sonar_max_range_m;
  return builder;
}

/// Linear interpolation of two poses (heading along the shorter arc).
inline Pose2 interpolate(const Pose2& a, const Pose2& b, double t) {
  return {a.x_m + t * (b.x_m - a.x_m), a.y_m + t * (b.y_m - a.y_m),
          wrap_angle_rad(a.theta_rad + t * wrap_angle_rad(b.theta_rad - a.theta_rad))};
}

inline RejectedReadings sum(const RejectedReadings& a, const RejectedReadings& b) {
  return {a.not_finite + b.not_finite, a.non_positive + b.non_positive, a.beyond_max + b.beyond_max,
          a.unknown_sonar + b.unknown_sonar};
}

}  // namespace facade_detail

struct Mapper::Impl {
  MapperOptions options;
  RobotGeometry robot;
  AsrStore& store;
  Pose2 start_pose;
  Pose2 correction;  ///< world estimate = correction ∘ (start_pose ∘ odometry)
  internal::RoomRecorder room;
  std::unique_ptr<AsrBoundaryDetector> boundary;
  Localizer localizer;
  GlimpseHeading glimpse;
  DoorMemory doors;  ///< doorways passed so far (options.door_fix)
  /// Per finished room (options.relaxation), what the end-of-run relaxation starts from.
  internal::RoomRelaxation relaxation;
  std::vector<std::pair<int, Pose2>> room_moves;  ///< what finish() re-placed
  /// This room's earlier glimpses' walls (world, corrected): EM reference besides `resident`.
  std::deque<std::vector<Polyline>> glimpse_walls;
  /// Variance of the heading error left after the last glimpse or room correction, rad².
  double glimpse_variance_rad2 = 0.0;
  ScanMatcher scan_match;  ///< options.scan_match
  /// Variances of the estimate's heading (rad²) and position (m² per axis) against the scan
  /// matcher's memory after its last match.
  double scan_rotation_var_rad2 = 0.0;
  double scan_shift_var_m2 = 0.0;
  OdometryRecalibrator recalibrator;
  HeldTurnFilter held_turn;  ///< options.held_turn
  std::optional<Pose2> previous_odometry;
  AsrGraph graph;
  MapperStats stats;
  RejectedReadings rejected_in_finished_rooms;
  std::deque<Asr> resident;  ///< most recent finished rooms, newest last
  /// The accepted (|ρ| ≥ threshold) walls of the rooms in `resident`, world frame (corrected).
  std::deque<std::vector<Polyline>> resident_accepted;
  /// The same walls as pieces facing the side they were seen from (the translation's reference).
  std::deque<std::vector<FacingSegment>> resident_facing;
  /// The correction the last finished room applied to the estimate (its placement, asr.pose,
  /// but for a shift the map alone takes).
  Pose2 last_room_fix;
  /// Variance of the heading error left after the last localised room, rad² (the start pose
  /// is known: 0). Grows by each room's drift, shrinks by (1 - gain) when EM corrects.
  double heading_variance_rad2 = 0.0;
  RoomListener listener;
  std::optional<Pose2> last_estimate;
  double last_time_s = 0.0;
  bool started = false;
  Point2 room_lo{0.0, 0.0}, room_hi{0.0, 0.0};  // bounding box of the path in the current room
  double room_travel_m = 0.0;                   // path length of the estimate in the current room
  double travel_m = 0.0;  // path length of the estimate since the start (door fixes' clock)
  Point2 room_last_point{0.0, 0.0};

  /// The current room's path starts over at `p` (room 0, and every room after a boundary).
  void restart_room_path(const Point2& p) {
    room_lo = room_hi = room_last_point = p;
    room_travel_m = 0.0;
  }
  int next_id = 0;

  Impl(const MapperOptions& opts, const RobotGeometry& geometry, AsrStore& asr_store,
       const Pose2& start)
      : options(opts),
        robot(geometry),
        store(asr_store),
        start_pose(start),
        room(make_grid_updater(opts.grid, opts.grid_options, geometry),
             opts.grid_options.cell_scale_mm / 2000.0),
        boundary(opts.boundary == BoundaryKind::kDoorway
                     ? make_doorway_detector(opts.doorway, geometry)
                     : make_distance_detector(opts.distance)),
        localizer(opts.localizer),
        // The glimpse grid exists only when glimpses are on (a second grid costs memory).
        glimpse(opts.glimpse,
                opts.glimpse.enabled ? make_grid_updater(opts.grid, opts.grid_options, geometry)
                                     : nullptr,
                facade_detail::builder_with_range(opts.builder, geometry), opts.localizer,
                opts.grid_options.cell_scale_mm / 2000.0),
        doors(opts.door_fix),
        relaxation(opts.relaxation),
        scan_match(opts.scan_match, geometry),
        recalibrator(applied_curvature_gain(opts.odometry_calibration, geometry),
                     geometry.odometry_track_m),
        held_turn(opts.held_turn) {
    options.builder.max_sonar_range_m = geometry.sonar_max_range_m;
  }

  Pose2 odometry_world(const Pose2& odometry) const { return start_pose.compose(odometry); }
  Pose2 estimate(const Pose2& odometry) const {
    return correction.compose(odometry_world(odometry));
  }

  /// The end point of `reading`, placed at `at` on its transducer's axis, into the room's echoes
  /// (a reading without an echo, at or past the range limit, or of no known transducer: none).
  void keep_echo(const Pose2& at, const SonarReading& reading) {
    if (!reading.echo || !(reading.range_m > 0.0) || !(reading.range_m < robot.sonar_max_range_m) ||
        reading.index < 0 || static_cast<std::size_t>(reading.index) >= robot.sonars.size()) {
      return;
    }
    const SonarMount& mount = robot.sonars[static_cast<std::size_t>(reading.index)];
    const Point2 transducer = at.transform(Point2(mount.x_m, mount.y_m));
    const double axis_rad = at.theta_rad + mount.heading_rad;
    room.add_echo(transducer + reading.range_m * Point2(std::cos(axis_rad), std::sin(axis_rad)));
  }

  void integrate(const SensorFrame& frame, const Pose2& pose) {
    const Pose2 previous = last_estimate.value_or(pose);
    const double span_s = frame.time_s - last_time_s;
    for (const SonarReading& reading : frame.sonar) {
      // A transducer fired somewhere within the last cycle; place it on the interpolated pose.
      double t = 1.0;
      if (last_estimate && span_s > 0.0) {
        t = std::clamp((reading.time_s - last_time_s) / span_s, 0.0, 1.0);
      }
      const Pose2 at = facade_detail::interpolate(previous, pose, t);
      if (room.grid().integrate(at, reading)) ++stats.readings_used;
      if (options.localizer.echo_refit.band_m > 0.0) keep_echo(at, reading);
      if (options.glimpse.enabled) glimpse.integrate(at, reading);
      if (options.scan_match.enabled) scan_match.add(at, reading, room.id());
    }
    stats.rejected = facade_detail::sum(rejected_in_finished_rooms, room.grid().rejected());
    stats.peak_grid_bytes = std::max(stats.peak_grid_bytes, room.grid().grid_bytes());
  }

  /// A glimpse is due: measure its rotation against the mapped walls and turn the estimate.
  void finish_glimpse(const Pose2& pose);
  /// A scan match is due: match the newest echoes against the memory and move the estimate.
  void finish_scan_match(const Pose2& pose);

  std::optional<int> finish_room(double time_s, const std::optional<BoundaryEvent>& leaving);
  /// Ends the current room at `event` (finish_room at `end_time_s`) and starts the next at
  /// `start_time_s` and the frame's estimate, which it updates in `pose` (the finished room's
  /// correction, a door fix).
  std::optional<int> next_room(double end_time_s, double start_time_s, const Pose2& odometry,
                               const BoundaryEvent& event, Pose2& pose);
  /// A doorway passed (the entry of the room just begun, corrected estimate frame): with
  /// options.door_fix, the shift that puts it back where the same door was first passed, applied
  /// to the estimate from now on (zero for a new door).
  Point2 fix_at_door(const Exit& entry);
  Localization localize(const Asr& asr, const AsrTrace& trace) const;
  /// The shift of a room (after EM's rotation `rotated`) from its walls' offsets against the
  /// reference rooms' (options.translation); records it in `localized`.
  Pose2 translate(const Asr& asr, const AsrTrace& trace, const Pose2& rotated,
                  std::optional<Localization>& localized);
};

}  // namespace cogmap::mapper
