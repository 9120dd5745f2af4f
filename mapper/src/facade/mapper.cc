#include "cogmap/mapper/mapper.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <deque>

#include "cogmap/mapper/localization/glimpse_heading.h"
#include "facade/room_recorder.h"
#include "facade/room_relaxation.h"

namespace cogmap::mapper {
namespace {

/// Rooms kept in RAM as localisation reference: the previous room and the one before it.
constexpr std::size_t kResidentRooms = 2;

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

AsrBuilderOptions builder_with_range(AsrBuilderOptions builder, const RobotGeometry& robot) {
  builder.max_sonar_range_m = robot.sonar_max_range_m;
  return builder;
}

/// Linear interpolation of two poses (heading along the shorter arc).
Pose2 interpolate(const Pose2& a, const Pose2& b, double t) {
  return {a.x_m + t * (b.x_m - a.x_m), a.y_m + t * (b.y_m - a.y_m),
          wrap_angle_rad(a.theta_rad + t * wrap_angle_rad(b.theta_rad - a.theta_rad))};
}

RejectedReadings operator+(const RejectedReadings& a, const RejectedReadings& b) {
  return {a.not_finite + b.not_finite, a.non_positive + b.non_positive, a.beyond_max + b.beyond_max,
          a.unknown_sonar + b.unknown_sonar};
}

}  // namespace

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
                builder_with_range(opts.builder, geometry), opts.localizer,
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

  void integrate(const SensorFrame& frame, const Pose2& pose) {
    const Pose2 previous = last_estimate.value_or(pose);
    const double span_s = frame.time_s - last_time_s;
    for (const SonarReading& reading : frame.sonar) {
      // A transducer fired somewhere within the last cycle; place it on the interpolated pose.
      double t = 1.0;
      if (last_estimate && span_s > 0.0) {
        t = std::clamp((reading.time_s - last_time_s) / span_s, 0.0, 1.0);
      }
      const Pose2 at = interpolate(previous, pose, t);
      if (room.grid().integrate(at, reading)) ++stats.readings_used;
      if (options.glimpse.enabled) glimpse.integrate(at, reading);
      if (options.scan_match.enabled) scan_match.add(at, reading, room.id());
    }
    stats.rejected = rejected_in_finished_rooms + room.grid().rejected();
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

void Mapper::Impl::finish_glimpse(const Pose2& pose) {
  std::vector<Polyline> reference;
  for (const auto* source : {&resident_accepted, &glimpse_walls}) {
    for (const std::vector<Polyline>& walls : *source) {
      reference.insert(reference.end(), walls.begin(), walls.end());
    }
  }
  const double drift_sigma =
      heading_drift_sigma_rad(options.localizer.drift, glimpse.turned_rad(), glimpse.travelled_m());
  const double prior_var = glimpse_variance_rad2 + drift_sigma * drift_sigma;
  const auto em_start = std::chrono::steady_clock::now();
  GlimpseFix fix = glimpse.measure(reference, RotationPrior{std::sqrt(prior_var)});
  stats.localization_time_s += seconds_since(em_start);
  const Localization& l = fix.localization;
  glimpse_variance_rad2 = l.applied ? (1.0 - l.gain) * prior_var : prior_var;
  if (l.applied && l.rotation_rad != 0.0) {
    const Pose2 turn = rotation_about(pose.translation(), l.rotation_rad);
    correction = turn.compose(correction);
    for (Polyline& line : fix.walls) {
      for (Point2& p : line) p = turn.transform(p);
    }
    ++stats.glimpse_corrections;
    stats.glimpse_correction_abs_rad += std::abs(l.rotation_rad);
  }
  ++stats.glimpses;
  // A glimpse gated out as an outlier would teach the reference its error; the first one of a
  // run (nothing to compare with) is the reference.
  if (l.applied || reference.empty()) {
    glimpse_walls.push_back(std::move(fix.walls));
    if (glimpse_walls.size() > options.glimpse.reference_glimpses) glimpse_walls.pop_front();
  }
}

void Mapper::Impl::finish_scan_match(const Pose2& pose) {
  // Odometry's drift since the last match: the turns' share and the random walk of the
  // distance (the model's floor is a room's, not a metre's).
  const HeadingDriftModel& drift = options.localizer.drift;
  const double turned = scan_match.turned_rad(), travelled = scan_match.travelled_m();
  const double rotation_drift = drift.per_rad_turned * drift.per_rad_turned * turned * turned +
                                drift.rad_per_sqrt_m * drift.rad_per_sqrt_m * travelled;
  const double rotation_prior = scan_rotation_var_rad2 + rotation_drift;
  // Position: odometry's distance error, and the heading's error swept over the distance.
  const double per_m = options.scan_match.shift_drift_per_m;
  const double shift_prior =
      scan_shift_var_m2 + (per_m * per_m + rotation_prior) * travelled * travelled;
  const auto start = std::chrono::steady_clock::now();
  const ScanMatchFix fix = scan_match.match(pose, rotation_prior, shift_prior);
  stats.localization_time_s += seconds_since(start);
  ++stats.scan_matches;
  scan_rotation_var_rad2 = fix.rotation_var_rad2;
  scan_shift_var_m2 = fix.shift_var_m2;
  if (!fix.measured) return;
  ++stats.scan_matches_measured;
  correction = fix.transform().compose(correction);
  stats.scan_match_rotation_abs_rad += std::abs(fix.rotation_rad);
  stats.scan_match_shift_abs_m += fix.shift_m.norm();
}

Localization Mapper::Impl::localize(const Asr& asr, const AsrTrace& trace) const {
  // Only walls whose least-squares fit was accepted (§3.1.8) carry a direction: the rejected
  // DP segments kept in asr.walls for the map are, by the fit's own test, not straight lines.
  std::vector<Polyline> reference;
  for (const std::vector<Polyline>& room_walls : resident_accepted) {
    reference.insert(reference.end(), room_walls.begin(), room_walls.end());
  }
  // Odometry's prior on the rotation since the reference was corrected: the drift of the
  // turns and the distance driven in this room (its path, entry and exit headings).
  const std::optional<double> exit_heading =
      asr.exits.size() > 1 ? std::optional<double>(asr.exits[1].heading_rad) : std::nullopt;
  const HeadingDriftModel& drift = options.localizer.drift;
  const double turned =
      path_rotation_rad(asr.path, asr.exits.front().heading_rad, exit_heading, drift.chord_m);
  RotationPrior prior;  // none: EM's answer as it is
  if (options.localizer.odometry_prior) {
    // The heading error the reference rooms were left with (carried, Kalman-style) plus the
    // drift accumulated in this room: a correction refused earlier widens the next prior, so a
    // drift that builds up over many rooms is eventually admitted.
    const double room_sigma = heading_drift_sigma_rad(drift, turned, path_length_m(asr.path));
    prior.sigma_rad = std::sqrt(heading_variance_rad2 + room_sigma * room_sigma);
  }
  // The new room's local frame is the current estimate frame, so its walls are already in
  // world-estimate coordinates.
  const Localization fix = localizer.estimate(reference, accepted_walls(trace), prior);
  return fix;
}

Pose2 Mapper::Impl::translate(const Asr& asr, const AsrTrace& trace, const Pose2& rotated,
                              std::optional<Localization>& localized) {
  // The new room's accepted walls and path with EM's rotation applied, against the reference
  // rooms' walls (world frame, corrected).
  const std::vector<FacingSegment> current = placed_facing_segments(
      accepted_walls(trace), asr.path, rotated, options.translation.min_segment_m);
  std::vector<FacingSegment> reference;
  for (const std::vector<FacingSegment>& room_walls : resident_facing) {
    reference.insert(reference.end(), room_walls.begin(), room_walls.end());
  }
  const TranslationFix fix = estimate_translation(reference, current, options.translation);
  if (localized) {
    localized->translation_tried = true;
    localized->translation_pairs = fix.pairs;
    localized->translation_applied = fix.applied;
    localized->translation_m = fix.shift;
  }
  if (!fix.applied) return rotated;
  ++stats.translations;
  stats.translation_abs_m += fix.shift.norm();
  return Pose2{fix.shift.x(), fix.shift.y(), 0.0}.compose(rotated);
}

Point2 Mapper::Impl::fix_at_door(const Exit& entry) {
  const std::optional<Point2> shift =
      doors.pass({entry.center, entry.width_m, entry.heading_rad, travel_m});
  if (!shift) return Point2::Zero();
  correction = Pose2{shift->x(), shift->y(), 0.0}.compose(correction);
  if (options.scan_match.enabled) scan_match.shift_all(*shift);
  ++stats.door_fixes;
  stats.door_fix_abs_m += shift->norm();
  return *shift;
}

std::optional<int> Mapper::Impl::finish_room(double time_s,
                                             const std::optional<BoundaryEvent>& leaving) {
  const auto build_start = std::chrono::steady_clock::now();
  AsrTrace trace_in = build_room_polylines(room.grid().histogram(), room.path(), options.builder);
  stats.build_time_s += seconds_since(build_start);

  Asr asr;
  asr.id = room.id();
  asr.walls = trace_in.fitted;  // rejected fits stay in as their DP segments (§3.1.8 reading)
  asr.exits.push_back(room.entry());
  if (leaving) {
    asr.exits.push_back({leaving->exit_center, leaving->exit_width_m, leaving->heading_rad, {}});
  }
  asr.reference_point = room.entry().center;
  asr.parent = room.parent();
  asr.path = room.path();
  asr.cell_scale_mm = room.grid().geometry().cell_scale_mm();
  asr.grid_bytes = room.grid().grid_bytes();
  for (const Polyline& line : trace_in.extracted) asr.extracted_vertex_count += line.size();
  asr.start_time_s = room.start_time_s();
  asr.end_time_s = time_s;
  asr.odometry_pose = correction.inverse();  // local (estimate) -> odometry-only world

  Pose2 room_correction;  // identity
  std::optional<Localization> localized;
  if (options.localization == LocalizationKind::kEm && !resident.empty()) {
    const auto em_start = std::chrono::steady_clock::now();
    const Localization& fix = localized.emplace(localize(asr, trace_in));
    stats.localization_time_s += seconds_since(em_start);
    if (options.localizer.odometry_prior && std::isfinite(fix.prior_sigma_rad)) {
      const double prior_var = fix.prior_sigma_rad * fix.prior_sigma_rad;
      // A correction applied whole leaves the measurement's own uncertainty.
      const double after_var =
          options.localizer.prior_shrinks
              ? (1.0 - fix.gain) * prior_var
              : std::min(prior_var, fix.measurement_sigma_rad * fix.measurement_sigma_rad);
      heading_variance_rad2 = fix.applied ? after_var : prior_var;
    }
    if (fix.applied) {
      room_correction = rotation_about(asr.reference_point, fix.rotation_rad);
      asr.heading_correction_rad = fix.rotation_rad;
    }
  }
  // The room is placed by EM's rotation and, with options.translation, shifted onto the walls
  // it shares with rooms mapped before it; the estimate the robot steers by takes the shift
  // only with options.translation.moves_estimate (docs/algorithms.md, "Translation from
  // revisited walls").
  Pose2 placed = room_correction;
  if (options.localization == LocalizationKind::kEm && options.translation.enabled &&
      !resident_facing.empty()) {
    const auto shift_start = std::chrono::steady_clock::now();
    placed = translate(asr, trace_in, room_correction, localized);
    stats.localization_time_s += seconds_since(shift_start);  // localisation, as EM's
  }
  asr.pose = placed;
  // Everything mapped from here on is corrected too: the robot's estimate turns with the room.
  last_room_fix = options.translation.moves_estimate ? placed : room_correction;
  correction = last_room_fix.compose(correction);
  if (options.scan_match.enabled) scan_match.move_room(asr.id, last_room_fix);
  const std::vector<Polyline> accepted = accepted_walls(trace_in);
  if (options.localization == LocalizationKind::kEm && options.relaxation.enabled) {
    // Where the estimate's own continuity puts the room: the rooms after it were mapped from
    // there (a map-only shift is the relaxation's to decide again).
    relaxation.remember(asr, accepted, last_room_fix);
  }
  std::vector<Polyline> accepted_world = accepted;
  for (Polyline& line : accepted_world) {
    for (Point2& p : line) p = asr.pose.transform(p);
  }
  if (options.translation.enabled) {
    resident_facing.push_back(
        placed_facing_segments(accepted, asr.path, asr.pose, options.translation.min_segment_m));
  }
  resident_accepted.push_back(std::move(accepted_world));
  const std::size_t keep = std::max<std::size_t>(options.localizer.reference_rooms, 1);
  if (resident_accepted.size() > keep) resident_accepted.pop_front();
  if (resident_facing.size() > keep) resident_facing.pop_front();

  store.save(asr);
  graph.add_node({asr.id, asr.pose, asr.pose.transform(asr.reference_point)});
  if (asr.parent) {
    graph.add_edge({*asr.parent, asr.id, 1, asr.pose.transform(asr.reference_point)});
  }
  ++stats.rooms;
  if (listener) {
    trace_in.asr_id = asr.id;  // the trace is not needed after this: no copy of its grids
    listener(asr, trace_in, localized);
  }
  rejected_in_finished_rooms = rejected_in_finished_rooms + room.grid().rejected();
  resident.push_back(std::move(asr));
  if (resident.size() > kResidentRooms) resident.pop_front();
  return resident.back().id;
}

std::optional<int> Mapper::Impl::next_room(double end_time_s, double start_time_s,
                                           const Pose2& odometry, const BoundaryEvent& event,
                                           Pose2& pose) {
  const std::optional<int> finished = finish_room(end_time_s, event);
  // The finished room's correction applies from now on: re-express pose and exit.
  const Pose2 fix = last_room_fix;
  pose = estimate(odometry);
  Exit entry{fix.transform(event.exit_center),
             event.exit_width_m,
             wrap_angle_rad(event.heading_rad + fix.theta_rad),
             {}};
  // A doorway (a cut has no width) passed before fixes the estimate's position; with
  // localisation off the estimate stays odometry's, as the thesis's baseline.
  if (options.localization == LocalizationKind::kEm && options.door_fix.enabled &&
      event.exit_width_m > 0.0) {
    const Point2 shift = fix_at_door(entry);
    entry.center += shift;
    pose = estimate(odometry);
  }
  room.start(next_id++, start_time_s, pose, entry, finished);
  restart_room_path(pose.translation());
  if (options.glimpse.enabled) {
    // The finished room's walls are the reference now; its glimpses were part of it.
    glimpse_walls.clear();
    glimpse.begin(pose);
  }
  return finished;
}

Mapper::Mapper(const MapperOptions& options, const RobotGeometry& robot, AsrStore& store,
               const Pose2& start_pose)
    : impl_(std::make_unique<Impl>(options, robot, store, start_pose)) {}

Mapper::~Mapper() = default;

void Mapper::set_room_listener(RoomListener listener) { impl_->listener = std::move(listener); }

std::optional<int> Mapper::process(const SensorFrame& frame) {
  Impl& m = *impl_;
  ++m.stats.frames;
  // Everything below sees the odometry re-integrated for the base's arcs (as reported when
  // options.odometry_calibration.curvature_gain is 0).
  // ...and with the turns made while the body was held taken out.
  const Pose2 odometry = m.held_turn.update(m.recalibrator.update(frame.odometry), frame);
  m.stats.held_turns = m.held_turn.detections();
  m.stats.held_turn_removed_abs_rad = m.held_turn.removed_abs_rad();
  const double turned_rad =
      m.previous_odometry ? wrap_angle_rad(odometry.theta_rad - m.previous_odometry->theta_rad)
                          : 0.0;
  m.previous_odometry = odometry;
  Pose2 pose = m.estimate(odometry);
  if (!m.started) {
    // Room 0 is entered at the known start pose.
    m.room.start(m.next_id++, frame.time_s, pose, Exit{pose.translation(), 0.0, pose.theta_rad, {}},
                 std::nullopt);
    m.restart_room_path(pose.translation());
    m.started = true;
    if (m.options.glimpse.enabled) m.glimpse.begin(pose);
  }
  // The extent limit bounds every room grid whatever the input: a pose that would stretch the
  // room past it (a log's time gap admits an odometry jump of kilometres, which grew one grid
  // to gigabytes) starts the next room before anything of the frame is drawn, whatever
  // min_room_duration_s says, and the frame's readings are not spread along the jump.
  std::optional<int> finished;
  const Point2 here = pose.translation();
  if ((m.room_hi.cwiseMax(here) - m.room_lo.cwiseMin(here)).maxCoeff() >
      m.options.max_room_extent_m) {
    const double heading = m.last_estimate ? m.last_estimate->theta_rad : pose.theta_rad;
    finished = m.next_room(m.last_time_s, frame.time_s, odometry,
                           BoundaryEvent{m.last_time_s, m.room_last_point, 0.0, heading}, pose);
    m.last_estimate.reset();
  }
  m.room.visit(pose);
  m.integrate(frame, pose);
  if (m.options.scan_match.enabled && m.scan_match.visit(pose, turned_rad)) {
    m.finish_scan_match(pose);
    pose = m.estimate(odometry);
  }
  if (m.options.glimpse.enabled && m.glimpse.visit(pose, turned_rad)) {
    m.finish_glimpse(pose);
    pose = m.estimate(odometry);
    m.glimpse.begin(pose);
  }
  m.room_lo = m.room_lo.cwiseMin(pose.translation());
  m.room_hi = m.room_hi.cwiseMax(pose.translation());
  const double step_m = (pose.translation() - m.room_last_point).norm();
  m.room_travel_m += step_m;
  m.travel_m += step_m;
  m.room_last_point = pose.translation();

  std::optional<BoundaryEvent> event = m.boundary->update(frame, pose);
  const double travel_limit_m = applied_max_room_travel_m(m.options);
  const bool too_long = travel_limit_m > 0.0 && m.room_travel_m >= travel_limit_m;
  if (!event && (too_long || (m.room_hi - m.room_lo).maxCoeff() > m.options.max_room_extent_m)) {
    event = BoundaryEvent{frame.time_s, pose.translation(), 0.0, pose.theta_rad};
  }
  if (!finished && event && frame.time_s - m.room.start_time_s() >= m.options.min_room_duration_s) {
    finished = m.next_room(frame.time_s, frame.time_s, odometry, *event, pose);
  }
  m.last_estimate = pose;
  m.last_time_s = frame.time_s;
  return finished;
}

std::optional<int> Mapper::finish() {
  Impl& m = *impl_;
  if (!m.started) return std::nullopt;
  m.started = false;
  const std::optional<int> id = m.finish_room(m.last_time_s, std::nullopt);
  if (m.relaxation.rooms() > 1) {
    const auto relax_start = std::chrono::steady_clock::now();
    m.room_moves = m.relaxation.relax(m.store, m.graph, m.stats);
    m.stats.localization_time_s += seconds_since(relax_start);
  }
  // The last room's correction turns the robot's estimate too, as every room's does when the
  // robot leaves it: pose_estimate() is the end of the run as the whole map sees it.
  if (m.previous_odometry) m.last_estimate = m.estimate(*m.previous_odometry);
  return id;
}

Pose2 Mapper::odometry_pose() const {
  return impl_->correction.inverse().compose(impl_->last_estimate.value_or(impl_->start_pose));
}

Pose2 Mapper::pose_estimate() const { return impl_->last_estimate.value_or(impl_->start_pose); }

const GridUpdater& Mapper::grid() const { return impl_->room.grid(); }
const AsrGraph& Mapper::graph() const { return impl_->graph; }
const AsrStore& Mapper::store() const { return impl_->store; }
const MapperStats& Mapper::stats() const { return impl_->stats; }
const std::vector<std::pair<int, Pose2>>& Mapper::room_moves() const { return impl_->room_moves; }

void Mapper::append_room_segments(const Asr& asr, bool corrected, std::vector<MapSegment>& map) {
  for (const Segment& s : asr.world_segments(corrected)) map.push_back({asr.id, s});
}

std::vector<Mapper::MapSegment> Mapper::master_map(bool corrected) const {
  std::vector<MapSegment> out;
  for (int id : impl_->store.ids()) append_room_segments(impl_->store.load(id), corrected, out);
  return out;
}

}  // namespace cogmap::mapper
