#pragma once
/// Navigation on the live map (thesis §1.1.4, §2.2.3): VFH obstacle avoidance, a route
/// follower through waypoints and an explorer. Works the same on the simulator and the real
/// robot because it sees only the seam and the mapper's grid. The algorithms, every option and
/// the deviations from the thesis are explained in docs/algorithms.md.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "cogmap/mapper/grid/grid_updater.h"
#include "cogmap/mapper/seam/robot_geometry.h"
#include "cogmap/mapper/seam/sensor_frame.h"
#include "cogmap/mapper/seam/velocity_command.h"

namespace cogmap::mapper::nav {

/// Everything a controller may look at in one cycle.
struct NavInput {
  const SensorFrame* frame = nullptr;  ///< this cycle's data (time, sonar, stalls); null = stop
  Pose2 pose;                          ///< the mapper's pose estimate, world frame
  const GridUpdater* grid =
      nullptr;  ///< the current room's grid, same frame as `pose`; may be null
  const RobotGeometry* robot = nullptr;  ///< sonar mounts and limits; null = RobotGeometry{}
};

/// What the controller is doing this cycle (for traces, figures and tests).
enum class NavMode : std::uint8_t {
  kIdle,         ///< no frame, idle controller, or nothing to do
  kDrive,        ///< steering along the VFH direction
  kBlocked,      ///< every sector blocked: turning in place toward the freest sector
  kBackOff,      ///< recovery: reversing away from where it got stuck
  kTurn,         ///< recovery: turning in place toward the freest sector
  kDone,         ///< route finished
  kDoorAlign,    ///< door behaviour: driving to the point in front of a sensed opening
  kDoorCross,    ///< door behaviour: crossing the opening along its axis
  kExploreDone,  ///< explorer: no unexplored exit left (or a budget ran out)
  kDoorProbe,    ///< door behaviour: closing in slowly on a waypoint behind a sensed wall
                 ///< until the sonar sees through the opening (or the way proves shut)
  kDirect,       ///< route follower: straight at the waypoint, its lane sensed clear
  kLook,         ///< explorer: arrived, holding still while the sonar looks at the frontier
  kEdgeFollow,   ///< edge explorer: keeping the edge of the space on the right
  kEdgeCorner,   ///< edge explorer: turning left at an inner corner (something ahead)
  kEdgePivot,    ///< edge explorer: turning right around the end of the edge
  kDoorSearch,   ///< route follower: sweeping along a wall that hides the door, listening
                 ///< with the side transducers for the gap
};

/// The mode's name for logs and traces ("drive", "door_cross", ...).
const char* to_string(NavMode mode);

/// The last cycle's decisions, kept so the renderer and the experiments can show them.
struct NavTrace {
  NavMode mode = NavMode::kIdle;
  double target_rad = 0.0;         ///< goal direction fed to VFH, world frame, CCW
  double direction_rad = 0.0;      ///< direction VFH chose (valid when has_direction)
  bool has_direction = false;      ///< false when every sector was blocked
  double front_clearance_m = 0.0;  ///< nearest obstacle ahead (±front half-angle) from the bumper
  std::size_t waypoint_index = 0;  ///< route follower: the waypoint being approached
  std::size_t skipped_waypoints = 0;  ///< route follower: waypoints given up after recoveries
  std::size_t recoveries = 0;         ///< stuck recoveries started so far
  std::size_t door_passages = 0;      ///< doorways crossed under the door behaviour
  bool door_active = false;           ///< the door behaviour holds an opening (align/cross)
  Point2 door_center_m{0.0, 0.0};     ///< ...its centre, estimate frame (valid when active)
  double door_normal_rad = 0.0;       ///< ...the direction through it
  double door_width_m = 0.0;          ///< ...and its sensed width
  std::size_t rooms_visited = 0;      ///< explorer: rooms entered (the start room counts)
  bool exploration_complete = false;  ///< explorer: stopped with no reachable frontier left
  std::vector<double> density;        ///< enlarged polar density per sector (Eq. 2.17)
  std::vector<std::uint8_t> blocked;  ///< 1 for a blocked sector after thresholding
};

/// A navigation behaviour: one velocity command per sensor frame.
class Controller {
 public:
  virtual ~Controller() = default;
  /// The command for this cycle. Never throws; a null frame yields a zero command.
  virtual VelocityCommand step(const NavInput& input) = 0;
  /// True once the controller has nothing left to do (route finished).
  virtual bool done() const = 0;
  /// The last cycle's decisions (an empty trace for controllers without any).
  virtual const NavTrace& trace() const;
  /// Waypoints skipped because the robot stayed stuck on them (route follower; else 0).
  std::size_t skipped_waypoints() const { return trace().skipped_waypoints; }
};

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
  double goal_in_door_m = 0.8;       ///< a goal within approach_m of an opening's line must lie
                                     ///< this near its centre (0.5 m drift + half a 0.6 m door)
  double wall_fit_m = 1.0;           ///< the opening's axis is fitted to the wall this far beyond
                                     ///< each jamb (0 = the jamb line alone)
  /// Probing: the P2-AT has no 0° transducer, and from farther than ~1 m its ±10° beams
  /// reach a 1 m door's jambs (10-20° off their axes) and paint them inside the opening. So
  /// a waypoint within probe_range_m behind a sensed wall is approached head-on at the door
  /// speed, which brings the ±10° beams through the gap (at 0.8 m the jambs lie 22° off
  /// their axes) and lets the clearing open it, instead of VFH swinging along the wall.
  double probe_range_m = 2.5;         ///< a sensed wall across the line to the waypoint nearer
                                      ///< than this is probed (VFH's window)
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
  double give_up_s = 40.0;        ///< a waypoint not approached by progress_m within this long is
                                  ///< given up: the longest leg in a 5 x 5 m room (7 m) takes 14 s,
                                  ///< plus a door passage (~10 s) and a recovery, with margin
  double progress_m = 0.3;        ///< what counts as approaching
  double direct_range_m = 2.5;    ///< a waypoint this near (VFH's window) with a clear lane
                                  ///< to it is driven straight at, without VFH. 0 = always
                                  ///< VFH (the thesis's behaviour)
  double direct_margin_m = 0.08;  ///< beyond the body's half-width each side: VFH's margin
                                  ///< (safety_radius_m 0.33 = 0.2525 + 0.08)
  double blocked_reach_m = 0.9;   ///< a waypoint this close behind a sensed obstacle (a door
                                  ///< centre the drifted estimate puts in the jamb) is reached
};

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
                                       ///< cells (8 MB), ~55 MB while a plan runs (the room grid's
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
  double min_goal_clearance_m = 0.35;  ///< nearer than this (half the body's width + 0.1 m),
                                       ///< except as a last resort, when no place that clear
                                       ///< views any frontier: then places in a doorway this
  double doorway_goal_clearance_m = 0.15;  ///< clear (a door the jambs' echoes painted down to
                                           ///< 0.4 m: next to its obstacle cells; negative: off)
  double los_clearance_m = 0.4;            ///< a straight leg skips path cells while it keeps this
                                           ///< far from obstacles (or as far as the path did)
  double max_leg_m = 4.0;                  ///< ...and is at most this long
  double turn_cost_m = 0.6;                ///< turning onto the path costs this much travel per
                             ///< radian: a skid-steer base loses 1-2 % of every turn in
                             ///< heading, so a frontier behind must be ~2 m nearer
  double departure_m = 0.3;  ///< ...the path's direction taken this far out
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

/// The explorer's DoorOptions: the door search off; pockets refused, a goal in one given up.
inline DoorOptions explorer_door_options() {
  DoorOptions o;
  o.search_per_waypoint = 0;
  o.beyond_clear_m = 1.1;
  o.give_up_goal_in_pocket = true;
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
  double look_hold_s = 1.0;           ///< arrived: hold still this long (two cycles of the
                                      ///< sonar ring, fired every ~0.4 s) before the frontier,
                                      ///< if still there, is given up
  double time_budget_s = 0.0;         ///< stop after this long (0 = no budget); not complete
  double distance_budget_m = 0.0;     ///< stop after this much travel by the odometry (0 = no
                                      ///< budget); both budgets apply to every strategy
  // Every strategy:
  double speed_mps = 0.5;  ///< thesis §4: 0.5 m/s
  double max_turn_rate_radps = 1.0;
  VfhOptions vfh;
  double stuck_time_s = 4.0;  ///< no progress for this long triggers recovery
  MemoryOptions memory;
  SafetyOptions safety;
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

/// Follows `waypoints_world` (world frame) in order; done() after the last one.
std::unique_ptr<Controller> make_route_follower(const RouteOptions& options,
                                                std::vector<Point2> waypoints_world);
/// Explores (ExploreOptions::strategy); the frontier explorer is done() when no reachable
/// frontier is left or a budget ran out, the heading explorer never.
std::unique_ptr<Controller> make_explorer(const ExploreOptions& options);
/// Sends zero velocity forever (teleop / none).
std::unique_ptr<Controller> make_idle_controller();

}  // namespace cogmap::mapper::nav
