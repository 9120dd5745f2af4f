// Mapper's room ends: the finished room through the ASR pipeline, EM and the translation,
// the door fixes, the next room begun; and the in-room glimpses and scan matches
// (docs/algorithms.md).
#include <algorithm>
#include <chrono>
#include <cmath>

#include "facade/mapper_impl.h"

namespace cogmap::mapper {
namespace {

/// Rooms kept in RAM as localisation reference: the previous room and the one before it.
constexpr std::size_t kResidentRooms = 2;

}  // namespace

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
  stats.localization_time_s += facade_detail::seconds_since(em_start);
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
  stats.localization_time_s += facade_detail::seconds_since(start);
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
  // The new room's local frame is the current estimate frame, so its walls (and its echoes) are
  // already in world-estimate coordinates.
  const EchoRefitOptions& refit = options.localizer.echo_refit;
  const Localization fix =
      refit.band_m > 0.0
          ? localizer.estimate(reference,
                               refit_wall_directions(accepted_walls(trace), room.echoes(), refit),
                               prior)
          : localizer.estimate(reference, accepted_walls(trace), prior);
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
  stats.build_time_s += facade_detail::seconds_since(build_start);

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
    stats.localization_time_s += facade_detail::seconds_since(em_start);
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
    stats.localization_time_s +=
        facade_detail::seconds_since(shift_start);  // localisation, as EM's
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
  rejected_in_finished_rooms =
      facade_detail::sum(rejected_in_finished_rooms, room.grid().rejected());
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

}  // namespace cogmap::mapper
