#pragma once
/// The options of the explorers (controller.h, make_explorer): the explore map, the frontier
/// planner, the edge follower and the explorer itself. Every default and where it comes from:
/// docs/algorithms.md, "Exploration".

#include <cstddef>
#include <cstdint>

#include "cogmap/mapper/nav/nav_options.h"

namespace cogmap::mapper::nav {

/// The explorer's long-term map (estimate frame, never reset at doorways): which cells a beam
/// has swept from close enough for the mapper to see them, and which hold echoes.
struct ExploreMapOptions {
  double cell_m = 0.2;              ///< coarse cells: a 0.9 m door is 4-5 of them, a 36-room
                                    ///< block (30 x 30 m) 22,500
  double free_sense_m = 2.5;        ///< floor swept by a beam this near counts as seen (half a
                                    ///< 5 m room: its middle is seen from a ring along the walls)
  double wall_sense_m = 1.3;        ///< an echo counts as seeing its wall only from this near:
                                    ///< the ±15° beam then spans ±0.35 m, so a doorway (0.9 m
                                    ///< and wider) shows as a gap, and the calibrated sonar hears
                                    ///< the wall at 40-60° incidence (Kuipers and Byun's robot
                                    ///< walked along the edge of a space for the same reason)
  double half_angle_deg = 12.0;     ///< the part of the 30° cone swept free (the beam's two-way
                                    ///< weight there is still ~0.35)
  double hit_half_angle_deg = 6.0;  ///< an echo marks the arc this near the axis (HIMM marks the
                                    ///< axis alone; a cell either side keeps thin walls closed)
  double occupancy_max_range_m = 3.0;  ///< farther echoes are too vague (30° beam: 1.6 m arc)
  double occupied_min_weight = 0.5;    ///< a cell is an obstacle after this much echo weight
  double occupied_ratio = 0.5;         ///< ...while its echo weight is at least this times the
                                       ///< weight of the beams that swept it free
  double weight_range_m = 1.0;         ///< evidence weighs (weight_range_m / distance)², at most
  double max_weight = 4.0;             ///< this: a 30° beam's arc at 2.5 m spans 1.3 m, as wide
                                       ///< as a door, so a doorway painted shut from afar is
                                       ///< opened by a few beams through it from 1 m
  double weight_cap = 16.0;            ///< both weights are halved when one reaches this, so
                                       ///< recent beams decide (drift moves old evidence)
  double free_margin_m = 0.2;          ///< the last stretch before an echo is not swept free
  double no_echo_free_m = 1.5;         ///< a pulse that never came back sweeps free only this
                                       ///< far: through a doorway nothing answers from a 5 m room
                                       ///< beyond, but a wall met at a shallow angle (over 40-60°
                                       ///< incidence) reflects the pulse away too, so a wall sensed
                                       ///< only obliquely loses little
  double max_span_m = 200.0;           ///< the map never grows beyond this in x or y: 1001²
                                       ///< cells (9 MB), ~56 MB while a plan runs (the room grid's
                                       ///< own bound is 200 m too, MapperOptions)
};

/// Choosing the next frontier (the edge of what has been seen) and the way to it.
struct FrontierOptions {
  double hard_clearance_m = 0.15;      ///< cells nearer an obstacle cell's centre are impassable
                                       ///< (with 0.2 m cells: the obstacle cells alone; the sonar
                                       ///< paints jambs into doorways, VFH keeps the real margin)
  double soft_clearance_m = 0.6;       ///< nearer than this a step costs more...
  double soft_weight = 3.0;            ///< ...up to (1 + this) times: paths keep to the middle
  double pinch_m = 0.7;                ///< a gap between obstacle cells along x or y narrower
                                       ///< than twice this is a doorway (doors are 0.9-1.2 m; a
                                       ///< 1.8 m corridor is none)
  double doorway_cost_m = 8.0;         ///< entering a doorway costs this much travel: a room's
                                       ///< own frontiers first, so it is finished before it is left
  int min_frontier_cells = 1;          ///< smaller frontier pieces are ignored. 1: a doorway the
                                       ///< side beams smear from both jambs often shows one open
                                       ///< cell; on generated buildings 13/18 runs entered every
                                       ///< room against 5/18 with 3 (docs/algorithms.md)
  double view_m = 0.9;                 ///< the robot drives to where a frontier cell is this near
                                       ///< (in sight), within ExploreMapOptions::wall_sense_m
  double goal_clearance_m = 0.5;       ///< ...preferring places this clear of obstacles (the body's
                                       ///< half-diagonal 0.4 m + a cell's half); nearer ones only
                                       ///< when no such place views the frontier, and never
  double min_goal_clearance_m = 0.35;  ///< nearer than this (half the body's width + 0.1 m)
  /// The last resort, when no place min_goal_clearance_m clear views any frontier: places in a
  /// doorway this clear (next to the obstacle cells of a door the jambs' echoes painted down to
  /// 0.4 m; the door behaviour then finds the real opening). Negative: no last resort.
  double doorway_goal_clearance_m = 0.15;
  /// Cells the robot's centre has passed through are passable for this plan, whatever echoes
  /// painted there since (ExploreOptions::plan_over_trail sets it for its second plan).
  bool trail_passable = false;
  /// The last look before stopping, when no frontier is reachable: the explore map's obstacle
  /// cells that the current room's grid holds as swept by a beam's axis (a cell below 0) and
  /// not echoed (no cell at this HIMM value or above: one axis echo adds 3, a jamb's neighbour
  /// 0.5 a reading) count as free for one more plan. The explore map paints every echo over
  /// ±6° from up to 3 m, so a doorway passed by at 2-3 m is painted shut there while the room
  /// grid, which paints the axis alone, keeps it open. Negative: off.
  double reopen_echo_himm = 1.0;
  int reopen_plans = 1;  ///< ...at most this many such plans in an exploration: the first
                         ///< found the rooms (3 found no more and cost up to give_up_s each)
  double los_clearance_m = 0.4;  ///< a straight leg skips path cells while it keeps this
                                 ///< far from obstacles (or as far as the path did)
  double max_leg_m = 4.0;        ///< ...and is at most this long
  double turn_cost_m = 0.6;      ///< turning onto the path costs this much travel per
                                 ///< radian: a skid-steer base loses 1-2 % of every turn in
                                 ///< heading, so a frontier behind must be ~2 m nearer
  double departure_m = 0.3;      ///< ...the path's direction taken this far out
};

/// The explorer (thesis §1.1.4 and §2.1.1, after Kuipers and Byun): drive to the nearest
/// frontier of what has been seen, a room's own frontiers before its doorways, back through
/// known doorways when a branch is finished, and stop when no reachable frontier is left.
/// `strategy: heading` keeps the thesis's Fig. 1.2 explorer (the most unexplored free
/// direction, never finishing).
enum class ExploreStrategy : std::uint8_t { kFrontier, kHeading, kEdge };

/// The edge explorer (Kuipers and Byun: walk along the edge of a space): keep the edge on the
/// right at follow_m, turn left where something is ahead, turn right around the edge's end
/// (through a doorway with the door behaviour when one is sensed there), and stop when back
/// where the edge was first taken. Right-hand rule: every wall joined to the first one is
/// walked, on both sides, so every room off it is entered and left again.
struct EdgeOptions {
  double follow_m = 0.9;  ///< edge distance from the robot's centre: the side sonar's
                          ///< ±15° beam spans ±0.24 m there, so a 0.9 m door shows, and
                          ///< walls are heard square-on (ExploreMapOptions::wall_sense_m)
  double lost_m = 1.6;    ///< nothing on the right nearer than this: the edge ended
  double corner_clearance_m = 0.6;    ///< less than this ahead of the bumper: inner corner
  double corner_margin_m = 0.5;       ///< ...and the left turn goes on until this much more is
  double corner_min_turn_rad = 0.5;   ///< clear, and at least this far (~30°)
  double corner_creep_mps = 0.1;      ///< ...creeping forward at this speed while more than
  double corner_creep_from_m = 0.35;  ///< this is clear ahead of the bumper
  double lateral_gain = 1.2;          ///< turn rate per metre off follow_m, rad/s
  double angle_gain = 1.0;            ///< turn rate per radian between heading and edge
  double pivot_radius_m = 0.6;        ///< the end of an edge is rounded at this radius (a 1 m
                                      ///< door's jamb: the centre passes 0.5-0.6 m from it)
  double pivot_speed_mps = 0.3;
  double end_advance_m = 0.3;       ///< where the edge ends, go on this far (the side beam loses
                                    ///< a jamb ~0.25 m behind the transducer; a door's middle is
                                    ///< 0.45-0.6 m past the jamb), turn to face the gap...
  double door_search_s = 1.5;       ///< ...and look this long for a doorway in it (the front
                                    ///< transducers fire every ~0.4 s; the door behaviour wants
                                    ///< 0.3 s of steady detection)
  double gap_clear_m = 1.2;         ///< facing the gap, the body's lane clear this far from the
                                    ///< bumper: a passage (past a 0.12 m wall, with margin)
  double cross_m = 1.3;             ///< ...crossed this far (the body's length past the jambs)
  double cross_timeout_s = 8.0;     ///< a crossing not done in this long ends (1.3 m at the
                                    ///< door speed takes 4.3 s)
  double cross_lean_rad = 0.12;     ///< ...leaning this far away from a jamb one forward
                                    ///< transducer hears (0.1 m off-centre over the 0.9 m run)
  double close_m = 1.0;             ///< the tour is closed within this of where it began...
  double close_heading_deg = 45.0;  ///< ...heading within this of the start heading...
  double min_loop_m = 10.0;         ///< ...after at least this much travel
};

/// The explorer's DoorOptions: the door search off; pockets refused, a goal in one given up;
/// no wider probe after a give-up.
inline DoorOptions explorer_door_options() {
  DoorOptions o;
  o.search_per_waypoint = 0;
  o.beyond_clear_m = 1.1;
  o.give_up_goal_in_pocket = true;
  // A goal given up is planned anew (and banned), never followed by the plan's next waypoint.
  o.probe_max_goal_after_skip_m = o.probe_max_goal_m;
  return o;
}

/// The explorer's VfhOptions: turn-backs are not held (turn_back_limit 0). On 304
/// explorations the hold entered 1 659 rooms against 1 673 with the same contacts: the
/// explorer re-plans its goal, and so the direction VFH aims at, every few seconds
/// (docs/algorithms.md, "Turn-backs held").
inline VfhOptions explorer_vfh_options() {
  VfhOptions o;
  o.turn_back_limit = 0;
  return o;
}

/// The explorer's SafetyOptions: the arc guard on for 0.5 s (0.25 m at 0.5 m/s). On 344
/// generated explorations it took the contact episodes from 46 to 17 (runs with one: 32 to
/// 11) with 14 more rooms entered; 1.0 s cost 24 rooms (docs/algorithms.md, "Turning on the
/// spot").
inline SafetyOptions explorer_safety_options() {
  SafetyOptions o;
  o.arc_guard_s = 0.5;
  return o;
}

struct ExploreOptions {
  ExploreStrategy strategy = ExploreStrategy::kFrontier;
  EdgeOptions edge;
  ExploreMapOptions map;
  FrontierOptions frontier;
  /// The route follower's door behaviour, used on the way, with one default of its own: no
  /// sweep along a wall for its door (`search_per_waypoint` 0). Measured on the 4 shipped and
  /// 12 generated explorations, seeds 1-3 (docs/algorithms.md, "Door search"): with sweeps,
  /// explorations completed 30 -> 29 of 51, rooms 253 -> 251 of 345, median wall error 0.226 ->
  /// 0.238 m; a frontier behind a wall is replaced by another one sooner than a sweep finds it.
  DoorOptions door = explorer_door_options();
  double waypoint_tolerance_m = 0.4;  ///< as RouteOptions
  double give_up_s = 45.0;            ///< no new cells seen and no progress_m nearer the goal for
                                      ///< this long: the goal is given up (a 7 m leg takes 14 s,
                                      ///< a door passage ~10 s, a recovery ~5 s, with margin)
  double progress_m = 0.3;            ///< what counts as nearer
  int progress_cells = 10;            ///< ...or this many cells newly seen (0.4 m²)
  double ban_radius_m = 0.6;          ///< frontier cells this near a given-up goal are ignored
  double blocked_path_s = 10.0;       ///< frontier explorer: the rest of the planned path has
                                      ///< crossed a cell the map shows an obstacle for this
                                      ///< long (a wall the beams had swept through, heard
                                      ///< since): plan again, the goal not given up (0 = follow
                                      ///< the path to the goal or to give_up_s). 10 s: measured
                                      ///< on generated buildings (docs/algorithms.md, "A path
                                      ///< run into a wall")
  double look_hold_s = 1.0;           ///< arrived: hold still this long (two cycles of the
                                      ///< sonar ring, fired every ~0.4 s) before the frontier,
                                      ///< if still there, is given up
  double start_room_edge_s = 150.0;   ///< frontier explorer: when no frontier is left and no
                                      ///< door has been passed yet (still in the start room,
                                      ///< its doorways painted shut), walk the room's edge as
                                      ///< the edge explorer does, at most this long (or once
                                      ///< round), then plan the frontiers once more before
                                      ///< stopping; a door passed on the way resumes the
                                      ///< frontiers (0 = stop at once). 150 s: one lap of a
                                      ///< 10 x 8 m room at the edge walk's ~0.21 m/s
                                      ///< (docs/algorithms.md, "The start room's edge walk")
  /// The give-up clock's progress_m nearer along what is left of the planned path (on) instead
  /// of as the crow flies (off): a goal whose way first leads away from it, round a wall or
  /// back through the rooms between, is then not given up while the robot is on its way. Off
  /// by default: on 304 generated and 60 shipped explorations it entered 6 more rooms of 2 423
  /// and changed the contacts by +2, within the spread of any drive change (docs/algorithms.md,
  /// "The give-up clock along the path").
  bool progress_along_path = false;
  /// When no frontier is reachable, plan once more with the cells the robot's centre passed
  /// through passable (FrontierOptions::trail_passable) before the other last resorts: a
  /// doorway walked through is a way back even after its jambs, heard obliquely from the rooms
  /// either side, have painted it shut again (explorations stopped with frontiers left in
  /// rooms they could no longer plan back to; docs/algorithms.md, "The way back").
  bool plan_over_trail = true;
  double time_budget_s = 0.0;      ///< stop after this long (0 = no budget); not complete
  double distance_budget_m = 0.0;  ///< stop after this much travel by the odometry (0 = no
                                   ///< budget); both budgets apply to every strategy
  // Every strategy:
  double speed_mps = 0.5;  ///< thesis §4: 0.5 m/s
  double max_turn_rate_radps = 1.0;
  VfhOptions vfh = explorer_vfh_options();
  double stuck_time_s = 4.0;  ///< no progress for this long triggers recovery
  MemoryOptions memory;
  SafetyOptions safety = explorer_safety_options();
  RecoveryOptions recovery;
  // strategy: heading (thesis Fig. 1.2):
  double horizon_m = 4.0;         ///< unexplored cells are counted this far along a sector
  double hysteresis_deg = 30.0;   ///< sectors this close to the current exploring heading...
  double hysteresis_bonus = 2.0;  ///< ...score this many extra (distance-weighted) cells
  double path_penalty = 1.0;      ///< score lost per recently visited point in a sector
  double path_spacing_m = 0.25;   ///< the recent path is sampled every this far
  std::size_t path_points = 400;  ///< recent path length kept (~100 m at 0.25 m)
  double commit_m = 1.0;          ///< the goal direction is re-chosen after this travel...
  double commit_s = 5.0;          ///< ...or this time, or as soon as its sector is blocked
  double path_ignore_m = 1.0;     ///< path points this close are the trail just left behind
};

}  // namespace cogmap::mapper::nav
