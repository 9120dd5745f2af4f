#pragma once
/// The options of the navigation behaviours on the live map (controller.h): VFH, the obstacle
/// memory, the safety check, the recovery, the door behaviour and the route follower. Every
/// default and where it comes from: docs/algorithms.md, "Navigation".

#include <cstddef>
#include <cstdint>

namespace cogmap::mapper::nav {

/// Vector Field Histogram (thesis §2.2.3, Eqs. 2.15-2.17; Borenstein & Koren 1991, with the
/// obstacle enlargement and hysteresis of VFH+, Ulrich & Borenstein 1998).
struct VfhOptions {
  double sector_deg = 5.0;     ///< polar sweep increment, thesis §2.2.3 ("5° increments")
  double window_m = 2.5;       ///< active window radius; also d_max of κ(d) = kappa·(1 - d/d_max)
  double kappa = 1.0;          ///< κ of Eq. 2.16, scaled by closeness (see docs)
  double threshold = 0.0;      ///< τ_high: sector blocked above it; 0 = auto from block_range_m
  double block_range_m = 1.5;  ///< auto τ_high: a cell of full certainty (15) blocks within this
  double hysteresis_ratio = 0.5;  ///< τ_low = ratio·τ_high; between the two a sector keeps
                                  ///< its previous state (VFH+ binary histogram)
  double safety_radius_m = 0.33;  ///< r: robot half-width 0.2525 m + 0.08 m margin; obstacles
                                  ///< enlarged by asin(r/d) (1 m doors stay passable)
  float occupied_above = 7.0f;    ///< HIMM cells above this are obstacles (thesis ε = 7)
  int smoothing_sectors = 1;      ///< l of Borenstein's smoothing (used for the freest sector)
  int wide_valley_sectors = 8;    ///< s_max: valleys at least this wide are "wide" (40°)
  int edge_offset_sectors = 4;    ///< wide valley: steer this far inside the nearer edge (20°)
  double previous_weight = 0.0;   ///< cost of leaving last cycle's direction (VFH+ μ3); 0 =
                                  ///< the thesis's memoryless choice. VFH+'s 0.4 (μ3/μ1 = 2/5)
                                  ///< was measured worse: it keeps driving along a wall past
                                  ///< the door (docs/algorithms.md, "Door passage")
  double heading_weight = 0.2;    ///< cost of turning relative to missing the target (VFH+
                                  ///< μ2/μ1, smaller so the target dominates)
  /// Detour side: when last cycle's choice went round an obstacle on one side of the target
  /// (more than detour_rad off it), a candidate on the other side costs this much more. A
  /// waypoint close behind a wall swings its bearing as the robot moves along the wall, and
  /// the cheaper side flipped every few seconds, each flip a ~180° turn on the spot (nine_rooms
  /// seed 5: 37 s of it, 30° of heading drift). 1 rad: a switch is worth ~57° of target error.
  double side_switch_rad = 1.0;
  double detour_rad = 0.5;        ///< ...a choice this far (29°) off the target is a detour
  double grid_min_range_m = 1.5;  ///< room-grid cells nearer than this are ignored; the recent
                                  ///< sonar (MemoryOptions) alone decides there, because the
                                  ///< grid's 30° angular smear closes 1 m doorways (docs);
                                  ///< used only while some echo is remembered
  /// Turn-backs held (nav/turn_backs.h): after turn_back_limit choices within
  /// turn_back_window_s that each leave last cycle's direction by more than 90° (a turn on
  /// the spot back the way the robot came), toward one target, a candidate more than 90° from
  /// last cycle's direction costs turn_back_cost_rad more for turn_back_hold_s: VFH follows
  /// the obstacle round instead of swinging between two valleys. 0 disables (the explorer's
  /// default, explorer_vfh_options). Measured on 1 680 generated routes (docs/algorithms.md,
  /// "Turn-backs held"): completed 1 518 -> 1 531, waypoints given up 416 -> 390, contact
  /// episodes 192 -> 164.
  int turn_back_limit = 2;             ///< one turn-back is a dead end left; two, a limit cycle
  double turn_back_window_s = 20.0;    ///< a turn-back takes 3-5 s of turning and ~1 m of driving
  double turn_back_hold_s = 20.0;      ///< walking round a desk or along a room's wall (40 s: the
                                       ///< same routes completed, docs)
  double turn_back_cost_rad = 3.2;     ///< > π: any valley ahead is taken first
  double turn_back_target_deg = 45.0;  ///< the target swinging more than this is a new one
};

/// Short-term obstacle memory: raw sonar echoes of the last seconds in the estimate frame,
/// so avoidance works right after the room grid is reset at a doorway.
struct MemoryOptions {
  double keep_s = 3.0;           ///< an echo is forgotten after this long
  double max_range_m = 3.0;      ///< farther echoes are too vague (30° beam) to steer by
  float hit_value = 8.0f;        ///< HIMM-scale certainty per echo in a cell (one echo > ε)
  double contact_keep_s = 10.0;  ///< a stuck contact (invisible obstacle) is kept this long
  std::size_t max_hits = 4096;   ///< bound on remembered echoes (oldest dropped first)
  /// Free-space clearing (HIMM's decrement along the axis, thesis §2.2.3): a later reading
  /// that runs past a remembered echo along its axis removes it. An echo off a door jamb
  /// seen at the beam's edge is painted on the axis, inside the opening; the next pulse of
  /// the same transducer through the opening erases it. 0 disables.
  double clear_half_angle_deg = 3.0;     ///< the core of the beam (two-way sd 6°: weight 0.88
                                         ///< at 3°, so a reflector there would have answered)
  double clear_min_half_width_m = 0.05;  ///< never narrower than this (half a 10 cm cell)
  double clear_margin_m = 0.2;           ///< an echo this close before the reading is kept (range
                                         ///< noise and the 0.15 m threshold walk of weak echoes)
  double clear_max_m = 3.0;  ///< a reading without echo clears this far (the memory's reach)
};

/// Heading control and the front safety check.
struct SafetyOptions {
  double heading_gain = 1.5;           ///< k of w = k·heading error, 1/s
  double turn_in_place_deg = 60.0;     ///< larger heading errors turn on the spot
  double front_half_angle_deg = 30.0;  ///< the cone ahead checked for the nearest obstacle
  double slow_clearance_m = 1.0;       ///< from the bumper: below it speed falls linearly
  double stop_clearance_m = 0.35;      ///< from the bumper: below it forward speed is zero
  /// Turning on the spot (|v| ≤ spin_max_speed_mps) is checked over the next spin_guard_deg of
  /// the turn: when a sensed point would come within spin_guard_margin_m of the body outline,
  /// the robot first moves away from it along its axis at spin_escape_mps (back from a point
  /// ahead of the centre, forward from one behind), if that lane is clear. 0° disables.
  /// Measured in docs/algorithms.md, "Turning on the spot".
  double spin_guard_deg = 20.0;  ///< two cycles of the 1 rad/s turn plus its ramp-down
  double spin_guard_margin_m =
      0.04;  ///< points are 0.1 m cell centres: a face may lie 0.05 m nearer
  double spin_max_speed_mps = 0.05;  ///< slower than this counts as turning on the spot
  double spin_escape_mps = 0.1;      ///< the move away, either way along the axis
  /// ...only into a lane clear by more than this from the bumper: a sensed point is a 0.1 m
  /// cell's centre (the face may be 0.05 m nearer), plus spin_guard_margin_m and a cycle's
  /// travel (0.01 m). 0.04 (the margin alone) drove the bumper into faces 0.06-0.09 m off.
  /// Refused, the turn goes the long way round if that strikes nothing (docs/algorithms.md,
  /// "Turning on the spot").
  double spin_escape_clearance_m = 0.1;
  /// Moving (|v| > spin_max_speed_mps) on an arc that brings a sensed point within
  /// spin_guard_margin_m of the body outline in the next arc_guard_s: the forward (or
  /// backward) speed is dropped and the turn alone goes on, under the spin guard. The ±30°
  /// cone ahead never sees a point beside a front corner that a turn swings that corner
  /// into. 0 disables. Off here (routes: no fewer contact episodes on 290 routes, more
  /// waypoints given up); the explorers' default is 0.5 s (explorer_safety_options(),
  /// docs/algorithms.md "Turning on the spot").
  double arc_guard_s = 0.0;
};

/// Stuck detection and the back-off-and-turn recovery.
struct RecoveryOptions {
  double stuck_distance_m = 0.1;       ///< less progress than this over stuck_time_s is stuck
  double stuck_rotation_deg = 30.0;    ///< ...unless it turned at least this much
  double stall_time_s = 0.5;           ///< wheel stall flags held this long mean stuck
  double backoff_distance_m = 0.4;     ///< reverse this far
  double backoff_speed_mps = 0.2;      ///< reversing speed (positive number)
  double rear_stop_clearance_m = 0.2;  ///< stop reversing when something is this close behind
  double turn_time_s = 1.5;            ///< longest in-place turn toward the freest sector
  double turn_done_deg = 10.0;         ///< the turn ends early once aligned this well
  int max_attempts = 3;                ///< per waypoint; one more stuck skips the waypoint
};

/// Walls met at a grazing angle while crossing a doorway (side_walls.h): the side transducers'
/// echoes beside the body, fitted with a line and carried on ahead, count for the crossing's
/// lane check. The calibrated sonar hears a painted wall only within 40-60° of its normal
/// (docs/sonar-model.md), so a wall the body closes in on at less than ~35° is silent to the
/// transducers that look ahead. Off by default: on 1 564 generated and shipped routes drawn
/// after it was chosen it cut contact episodes 116 -> 63 (runs with one 51 -> 35) and completed
/// 1 396 routes against 1 413, but on the shipped three-room route, seeds 1-5, EM's mean
/// corrected heading error came out 4.87° against odometry's 4.72° (seeds 1-20: 3.72 ->
/// 3.53°), which issue 10 forbids (docs/algorithms.md, "Walls met at a grazing angle").
/// `controller.grazing_walls: true` turns it on.
struct SideWallOptions {
  bool enabled = false;
  double reach_m = 0.5;         ///< echoes up to this far out from the body's side, and this far
                                ///< before and behind it, are fitted: the side and ±50°
                                ///< transducers' echoes of a wall the body is about to touch
  double ahead_m = 1.3;         ///< the line is carried on this far ahead of the centre (the
                                ///< bumper's 0.31 m plus the 1 m where the front check slows)
  double step_m = 0.05;         ///< ...as a point every this far (half a room-grid cell)
  int min_points = 3;           ///< a line needs this many echoes...
  double min_span_m = 0.3;      ///< ...spanning this much of it (one 10 cm cell is no line)...
  double max_rms_m = 0.08;      ///< ...lying this close to it (a wall painted two 10 cm cells
                                ///< thick by the beam's arc: rms ~0.06)...
  double max_angle_deg = 35.0;  ///< ...within this of the heading: a wall across the way (the
                                ///< doorway's own) is the front transducers' to hear
  double lane_margin_m = 0.05;  ///< the points stop the robot where they enter its half-width
                                ///< plus this
};

/// The door behaviour (docs/algorithms.md, "Door passage"): when the straight line to the goal
/// is blocked, look for an opening in the sensed obstacles between the robot and the goal, lock
/// onto it and cross it along its axis. It reads only the obstacle field (recent sonar and the
/// live grid) in the estimate frame, so an estimate off by 0.3-0.5 m still finds the real gap.
struct DoorOptions {
  bool enabled = true;
  double min_width_m = 0.7;     ///< narrower sensed gaps are refused: the P2-AT is 0.505 m wide
                                ///< and the sonar's beam smear narrows a 0.9 m door to ~0.75 m
  double max_width_m = 1.5;     ///< wider gaps are open space, left to VFH (a door of at
                                ///< most 1.2 m is sensed no wider; + 0.3 m for 10 cm cells)
  double search_range_m = 3.5;  ///< jambs are looked for this far (the sonar memory's reach)
  double max_offset_m = 1.6;    ///< an opening's centre may lie this far off the goal line
                                ///< (0.5 m estimate drift + door offsets along a 5 m wall)
  double depth_m = 0.3;         ///< a point this far beyond the jamb line still closes a gap
  /// A gap with something behind it is a pocket (furniture beside a wall), not a door: the
  /// crossing ends exit_m beyond the opening, where the body must be able to turn on the spot.
  /// 0 (routes) checks nothing: a route leads through real doors, where a single smeared echo
  /// beyond one would refuse it; the explorer's goals may lie in pockets (explorer_door_options).
  double beyond_clear_m = 0.0;  ///< explorer: 1.1, nothing sensed this near beyond the opening's
                                ///< line: exit_m 0.7 + the P2-AT's half-diagonal 0.40 m
  double beyond_lane_m = 0.35;  ///< ...within this of its axis: half the 0.505 m body + 0.1 m
  /// A waypoint inside a pocket closed across at least beyond_lane_m is given up at once (the
  /// explorer's goal is only a place to look from; it then chooses another).
  bool give_up_goal_in_pocket = false;
  double bin_deg = 3.0;      ///< the polar scan's bins (nearest point per bin)
  double approach_m = 0.8;   ///< align on the door axis this far before the opening
  double exit_m = 0.7;       ///< the crossing ends this far beyond it (half the body + margin)
  double lookahead_m = 0.6;  ///< pure pursuit along the axis while crossing
  double align_tolerance_m = 0.12;   ///< lateral error at which the crossing starts
  double speed_mps = 0.3;            ///< crossing speed: 2.3 s through a 0.7 m band, time for the
                                     ///< side sonars (fired every ~0.5 s) to see both jambs
  double track_m = 0.4;              ///< a re-detected opening within this is the same door
  double confirm_s = 0.3;            ///< detected this long without a break before it is trusted
                                     ///< (3 cycles): one-cycle gaps between sparse early echoes
                                     ///< are ignored; 1.0 s was measured worse (the detection
                                     ///< flickers while the robot turns and is never confirmed)
  double timeout_s = 25.0;           ///< a passage not done in this long is abandoned (bounded)
  double lost_s = 6.0;               ///< ...as is one not re-detected for this long before crossing
                                     ///< (twice the sonar memory's 3 s)
  double closed_after_s = 3.0;       ///< crossing: less than closed_progress_m along the axis in
  double closed_progress_m = 0.15;   ///< this long means the opening is closed (at the door
                                     ///< speed 0.15 m takes 0.5 s; recoveries start at 4 s)
  double jamb_support_m = 0.35;      ///< a jamb point needs a wall point this close beyond it
                                     ///< (10 cm cells, a 30° beam at 1-2 m leaves 0.1-0.3 m gaps)
  double rejected_keep_s = 30.0;     ///< a closed or abandoned opening is not retried this long
  double max_axis_angle_deg = 60.0;  ///< an opening's axis may lie this far off the direction
                                     ///< to the goal (a door 0.5 m aside from 1 m: 27°)
  /// An opening counts only when seen within this of its axis. Every echo is painted on its
  /// beam's axis at the range of the beam's nearest ray: a wall seen at incidence θ from d
  /// metres is painted d·(1/cos θ − 1/cos(θ − 12°)) in front of itself (12°: the two-way beam's
  /// 2σ), 0.29 m at 50° from 1 m, the opening's depth_m. Beyond that a wall seen obliquely
  /// shows gaps and "jambs" where there is no door (docs/algorithms.md, "Door passage", 7).
  /// 90 = no test.
  double max_view_incidence_deg = 50.0;
  double goal_in_door_m = 0.8;  ///< a goal within approach_m of an opening's line must lie
                                ///< this near its centre (0.5 m drift + half a 0.6 m door)
  double wall_fit_m = 1.0;      ///< the opening's axis is fitted to the wall this far beyond
                                ///< each jamb (0 = the jamb line alone)
  /// Probing: the P2-AT has no 0° transducer, and from farther than ~1 m its ±10° beams
  /// reach a 1 m door's jambs (10-20° off their axes) and paint them inside the opening. So
  /// a waypoint within probe_range_m behind a sensed wall is approached head-on at the door
  /// speed, which brings the ±10° beams through the gap (at 0.8 m the jambs lie 22° off
  /// their axes) and lets the clearing open it, instead of VFH swinging along the wall.
  double probe_range_m = 2.5;     ///< a sensed wall across the line to the waypoint nearer
                                  ///< than this is probed (VFH's window)
  double probe_max_goal_m = 5.0;  ///< ...while the waypoint lies within the sonar's range
                                  ///< (as search_max_goal_m): a corridor's next point
                                  ///< tens of metres on has no door in that wall
  /// ...or within this right after a waypoint was given up (a door not found: the next
  /// waypoint, a room's centre, lies behind that door's wall by the room's half-depth, which in
  /// rooms larger than 5 m puts it beyond probe_max_goal_m, and VFH alone never finds the way).
  /// 8 m: a 9 m room's half-depth plus the 1-2 m the robot may stand before the given-up door,
  /// with margin; a corridor's next point lies tens of metres on. Also for the search.
  /// Measured on rooms of 3-9 m (docs/algorithms.md, "Door passage": 6.5-11 m a plateau).
  double probe_max_goal_after_skip_m = 8.0;
  double probe_min_angle_deg = 45.0;  ///< ...meeting the line at least this steeply (a door's
                                      ///< wall is crossed, a corridor side is run along)
  double probe_rearm_m = 1.0;         ///< after a failed probe, probe again only this far away
  double probe_stall_s = 3.0;         ///< no progress_m nearer for this long (turning on the spot
                                      ///< excepted): the probe has failed and VFH takes over
                                      ///< until probe_rearm_m; 5 s (beyond the memory's keep_s) was
                                      ///< measured no better (docs/algorithms.md, "Door passage")
  /// Search: a probe that stalls has met the wall where the door is not. The side
  /// transducers meet a wall square-on when the robot runs along it, and there a door is a
  /// clean gap between two stretches of echoes, which the front transducers, seeing the wall
  /// obliquely, smear shut or open wrongly (docs/algorithms.md, "Door search"). So the robot
  /// sweeps along the wall, toward the waypoint's side first and then back past where it
  /// began, and crosses the first gap it hears. 0 searches per waypoint disables it.
  int search_per_waypoint = 2;               ///< sweeps tried for one waypoint
  double search_min_beyond_m = 1.0;          ///< the waypoint, or the one after it, must lie this
                                             ///< far beyond the wall (a room centre: ~2.5 m)...
  double search_max_goal_m = 5.0;            ///< ...and within the sonar's range: a corridor's
                                             ///< corner point that the estimate's drift puts
                                             ///< behind the end wall has no door to find, and its
                                             ///< next leg is tens of metres long
  double search_standoff_m = 0.65;           ///< robot centre to wall line: half the 0.505 m body
                                             ///< + 0.4 m, so the side echoes come from ~0.45 m
  double search_span_m = 2.0;                ///< swept either side of where the sweep began, and
  double search_beyond_goal_m = 1.0;         ///< ...this far past the waypoint's foot on the wall
  double search_max_span_m = 3.5;            ///< (a room's half-width + a door-offset margin)
  double search_lookahead_m = 0.6;           ///< aim this far ahead along the standoff line
  double search_band_m = 0.25;               ///< an echo this near the wall line is the wall
  double search_max_incidence_deg = 25.0;    ///< readings meeting the wall further off its
                                             ///< normal are not used (the beam's ±15° + 10°)
  double search_min_gap_m = 0.45;            ///< a 0.9 m door heard square-on at 0.45 m: the ±15°
                                             ///< beam smears each jamb ~0.12 m into it (0.66 m);
                                             ///< less than that is one or two lost echoes
  double search_max_unseen_m = 0.35;         ///< no stretch of a gap this long without a reading
                                             ///< through it (readings ~0.15 m apart at 0.3 m/s)
  double search_turn_clearance_m = 0.8;      ///< a corner ahead this near the bumper turns the
                                             ///< sweep: turning nearer puts the corner's wall
                                             ///< within the doorway detector's 0.8 m of one side
                                             ///< while the swept wall is at the other, which then
                                             ///< reads as a doorway passed (nine rooms seed 3
                                             ///< at 0.45 m: a room split in two, EM 12.7° off)
  double search_approach_tolerance_m = 0.1;  ///< the gap is handed over this near its
                                             ///< approach point (a 0.9 m door leaves the
                                             ///< 0.505 m body 0.2 m either side)
  double search_timeout_s = 45.0;            ///< a sweep (and its approach) lasts at most this long
  double search_max_rms_m = 0.1;  ///< the blocking echoes must lie on a line (10 cm cells)
  /// Crossing: the side transducers see the jambs square-on; the opening's centre follows
  /// the middle between the nearest sensed points either side within recenter_band_m of the
  /// door line (a 0.12 m wall plus a 10 cm cell either side), by this fraction per cycle
  /// (0.2 at 10 Hz: a time constant of ~0.5 s, longer than one sonar cycle). 0 disables.
  double recenter_gain = 0.2;
  double recenter_band_m = 0.3;
  /// Crossing: what the lane check finds within recenter_band_m of the door line is the
  /// jambs and the sonar's smear of them (a 0.9 m door is sensed 0.7-0.75 m wide), and with the
  /// route's stop/slow distances (0.35/1.0 m) it held the robot to a crawl in front of an open
  /// door until the door was called closed. Those points stop the robot only this near; what
  /// lies beyond the band keeps the route's distances. The crossing speed (0.3 m/s) stops in
  /// 0.075 m at the P2-AT's 0.6 m/s² plus 0.03 m in one 0.1 s cycle: 0.25 m is 2.4 times that.
  /// Measured on generated buildings (docs/algorithms.md, "Door passage").
  double cross_stop_clearance_m = 0.25;  ///< from the bumper, door-band points: no forward speed
  double cross_slow_clearance_m = 0.6;   ///< ...and below this the speed falls linearly
  /// Crossing: a wall closed in on at a grazing angle (the crossing steers straight along the
  /// opening's axis without VFH, and its lane check sees only echoes ahead) stops the robot
  /// where its line enters the lane, so the crossing is called closed rather than wedging a
  /// corner against the wall. Off by default (SideWallOptions::enabled).
  SideWallOptions cross_side_walls;
};

/// The route follower (experiments drive a robot through a list of world points).
struct RouteOptions {
  double speed_mps = 0.5;             ///< thesis §4: the robot drove at 0.5 m/s
  double waypoint_tolerance_m = 0.4;  ///< a waypoint counts as reached this close
  double pass_half_width_m = 1.0;     ///< ...or passed once the robot crosses the line through
                                      ///< it perpendicular to the route leg within this of it:
                                      ///< steering by a drifting estimate, a waypoint in a
                                      ///< doorway may lie 0.2-0.5 m off the opening actually
                                      ///< driven through; 0 disables
  double max_turn_rate_radps = 1.0;
  VfhOptions vfh;
  double stuck_time_s = 4.0;  ///< no progress for this long triggers recovery
  MemoryOptions memory;
  SafetyOptions safety;
  RecoveryOptions recovery;
  DoorOptions door;
  double give_up_s = 60.0;        ///< a waypoint not approached by progress_m within this long is
                                  ///< given up: a door found only at the second try (a probe that
                                  ///< stalls, the door search's sweep along the wall, a passage
                                  ///< lost to a phantom jamb, then the real one) takes 40-60 s;
                                  ///< measured 25 / 40 / 60 / 80 s (docs/algorithms.md, "A minute
                                  ///< per waypoint"), 60 is the knee
  double progress_m = 0.3;        ///< what counts as approaching
  double direct_range_m = 2.5;    ///< a waypoint this near (VFH's window) with a clear lane
                                  ///< to it is driven straight at, without VFH. 0 = always
                                  ///< VFH (the thesis's behaviour)
  double direct_margin_m = 0.08;  ///< beyond the body's half-width each side: VFH's margin
                                  ///< (safety_radius_m 0.33 = 0.2525 + 0.08)
  double blocked_reach_m = 0.9;   ///< a waypoint this close behind a sensed obstacle (a door
                                  ///< centre the drifted estimate puts in the jamb) is reached
};

}  // namespace cogmap::mapper::nav
