#pragma once
/// Our extension beyond §3.1.9-3.1.10: at the end of a run, every room's position is adjusted
/// at once so that the walls the rooms share agree. EM corrects each room's heading against the
/// rooms just before it, and the online translation ("Translation from revisited walls") shifts
/// a room onto walls it saw again; neither moves a room that shares nothing with its
/// reference, so the position drift of a branch stays in every room mapped after it. Here all
/// rooms are unknowns together: consecutive rooms keep the offset the estimate gave them, within
/// the drift of the path between them, and every pair of rooms that saw the same wall (from the
/// same side, or the next run of its line past a door) or the two faces of one wall (from the
/// rooms either side of it) pulls them into agreement. A least-squares problem over the rooms'
/// shifts, re-paired a few times. docs/algorithms.md, "Relaxing the rooms' positions at the end
/// of a run".

#include <span>
#include <vector>

#include "cogmap/mapper/localization/wall_offsets.h"
#include "cogmap/mapper/seam/geometry.h"

namespace cogmap::mapper {

/// Defaults from physics and from measurement on generated buildings (docs/algorithms.md);
/// the thesis has no such step.
struct RelaxationOptions {
  /// On: the rooms are re-placed when the run ends. Off: each room stays where it was placed
  /// when the robot left it.
  bool enabled = true;
  /// How fast the estimate's position drifts, sd per axis per metre of path: the door fixes'
  /// figure (DoorFixOptions::drift_sd_per_m), fitted to re-passed doors.
  double drift_sd_per_m = 0.016;
  /// The least drift between two consecutive rooms, sd per axis (a room cut after a metre
  /// still differs from the last by a cell or so).
  double min_step_sd_m = 0.02;
  /// How well a pair of fitted walls gives their offset, sd for one metre of overlap (a wall
  /// fitted on 0.1 m cells lies within about one cell).
  double offset_sd_m = 0.1;
  /// A wall seen from both sides: its thickness as first assumed, and the sd of that guess
  /// (office partitions are 0.08-0.25 m). The run estimates it from its own pairs.
  double wall_thickness_m = 0.15;
  double wall_thickness_sd_m = 0.08;
  /// A pair of wall pieces: parallel within this (EM leaves 1-3° between rooms, and a 0.5 m
  /// piece's direction on 0.1 m cells is known to a few degrees).
  double max_angle_deg = 8.0;
  double min_overlap_m = 0.5;  ///< ...overlapping this much along their direction
  double min_segment_m = 0.5;  ///< shorter pieces are not matched (TranslationOptions)
  /// The first pairing: offsets up to this many sds of the drift between the two rooms (and at
  /// least min_gate_m, at most max_gate_m) can be the same wall.
  double gate_sigmas = 3.0;
  double min_gate_m = 0.25;
  double max_gate_m = 0.8;
  /// After the first solution the rooms stand near their place: re-pairing takes offsets up to
  /// this, and a pair still off by more than two sds weighs less (Huber).
  double later_gate_m = 0.3;
  /// The nearest partner wins only if the next one is at least this much further
  /// (ratio × nearest + margin): parallel walls a cell apart could be either.
  double ambiguity_ratio = 2.0;
  double ambiguity_margin_m = 0.1;
  int rounds = 5;  ///< pair, solve, re-pair with the rooms where the last solution put them
  /// Pieces on one line, seen from the same side, that do not overlap but end within this of
  /// each other pair too (0: never): a wall runs on past a door (0.8-1.2 m) on the same line,
  /// a corridor's consecutive cuts draw its walls end to end, and a corridor's wall runs
  /// straight for tens of metres past doors and junctions. Their offset is taken at the nearer
  /// end and weighed as continuation_weight_m of overlap (an extrapolation). 20 m with the
  /// angle sd below: measured against 1 (the default until 2026-12-08), 4 and 10 m on
  /// generated routes and explorations, and 40 m on the hallway (docs/algorithms.md, "Wall
  /// lines carried past their gaps").
  double continuation_gap_m = 20.0;
  double continuation_weight_m = 0.5;
  /// How well the two pieces' directions agree, the turn between their rooms included: an
  /// offset taken d metres past the earlier piece's end is uncertain by d × this more, so a
  /// wall line carried across a long gap pulls weakly (0: as near as at the end). 0.04 rad,
  /// 2.3°: EM leaves rooms 1-3° apart, and 0.02 rad pulled generated explorations' walls onto
  /// lines they were only nearly on where 0.04 did not (a desk's front along a wall).
  double continuation_angle_sd_rad = 0.04;
  /// A room is paired with at most this many earlier rooms, the nearest (as EM's reference
  /// rooms): bounds the work and the problem's fill however long a run stays in one place.
  int max_partners = 32;
};

/// One room as the end of the run sees it: its walls as pieces facing the side the robot saw
/// them from (facing_segments), in the world frame where the room was placed, and the length
/// of the path the robot drove in it.
struct RelaxationRoom {
  std::vector<FacingSegment> walls;
  double path_m = 0.0;
};

struct Relaxation {
  /// Per room (in input order), the shift to add to its placement; room 0 stays.
  std::vector<Point2> shifts;
  double wall_thickness_m = 0.0;  ///< as estimated (the prior when no wall was seen twice)
  int same_side_pairs = 0;        ///< pairs of the last round
  int two_face_pairs = 0;
};

/// The shifts that bring the rooms' shared walls into agreement, rooms kept in sequence within
/// their drift. Rooms are in the order they were mapped; consecutive ones are neighbours on the
/// robot's path. Rooms without a wall in common with any other follow their neighbours.
Relaxation relax_room_positions(std::span<const RelaxationRoom> rooms,
                                const RelaxationOptions& options);

}  // namespace cogmap::mapper
