#pragma once
/// Navigation on the live map (thesis §1.1.4, §2.2.3): VFH obstacle avoidance, a route
/// follower through waypoints and an explorer. Works the same on the simulator and the real
/// robot because it sees only the seam and the mapper's grid. The algorithms, every option and
/// the deviations from the thesis are explained in docs/algorithms.md.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "cogmap/mapper/grid/grid_updater.h"
#include "cogmap/mapper/nav/explore_options.h"
#include "cogmap/mapper/nav/nav_options.h"
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

/// The frontier explorer's own map (estimate frame), one byte a cell: what it believed it had
/// seen (`output.explore_map`, docs/formats.md). For finding out why an exploration stopped.
struct ExploreMapImage {
  enum Cell : std::uint8_t {
    kUnseen = 0,
    kFree = 1,            ///< seen and not an obstacle
    kObstacle = 2,        ///< echoes outweigh the beams that swept it
    kFrontier = 3,        ///< free, next to an unseen cell
    kBannedFrontier = 4,  ///< a frontier cell given up (a failed goal, a look in vain)
  };
  int width = 0;
  int height = 0;
  double cell_m = 0.0;
  Point2 origin_m{0.0, 0.0};        ///< estimate-frame position of cell (0, 0)'s outer corner
  std::vector<std::uint8_t> cells;  ///< row-major from cell (0, 0), x east, y north
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
  /// The explorer's map as it stands (frontier explorer; else none).
  virtual std::optional<ExploreMapImage> explore_map() const { return std::nullopt; }
  /// Waypoints skipped because the robot stayed stuck on them (route follower; else 0).
  std::size_t skipped_waypoints() const { return trace().skipped_waypoints; }
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
