#pragma once
/// Navigation on the live map (thesis §1.1.4, §2.2.3): VFH obstacle avoidance, a route
/// follower through waypoints and an explorer. Works the same on the simulator and the real
/// robot because it sees only the seam and the mapper's grid.

#include <memory>
#include <vector>

#include "cogmap/mapper/grid/grid_updater.h"
#include "cogmap/mapper/seam/robot_geometry.h"
#include "cogmap/mapper/seam/sensor_frame.h"
#include "cogmap/mapper/seam/velocity_command.h"

namespace cogmap::mapper::nav {

/// Everything a controller may look at in one cycle.
struct NavInput {
  const SensorFrame* frame = nullptr;  ///< this cycle's data (odometry, sonar, stalls)
  Pose2 pose;                          ///< the mapper's pose estimate, world frame
  const GridUpdater* grid = nullptr;   ///< the current room's grid, same frame as `pose`
  const RobotGeometry* robot = nullptr;
};

class Controller {
 public:
  virtual ~Controller() = default;
  virtual VelocityCommand step(const NavInput& input) = 0;
  /// True once the controller has nothing left to do (route finished).
  virtual bool done() const = 0;
};

struct VfhOptions {
  double sector_deg = 5.0;        ///< polar sweep increment, thesis §2.2.3
  double window_m = 2.5;          ///< active window around the robot
  double kappa = 1.0;             ///< κ of Eq. 2.16 (scaled by closeness, see docs)
  double threshold = 0.0;         ///< sectors with density above this are blocked (0 = auto)
  double safety_radius_m = 0.45;  ///< robot half-diagonal plus margin, for enlarging obstacles
};

struct RouteOptions {
  double speed_mps = 0.5;  ///< thesis §4: 0.5 m/s
  double waypoint_tolerance_m = 0.4;
  double max_turn_rate_radps = 1.0;
  VfhOptions vfh;
  double stuck_time_s = 4.0;  ///< no progress for this long triggers recovery
};

struct ExploreOptions {
  double speed_mps = 0.5;
  double max_turn_rate_radps = 1.0;
  VfhOptions vfh;
  double stuck_time_s = 4.0;
};

std::unique_ptr<Controller> make_route_follower(const RouteOptions& options,
                                                std::vector<Point2> waypoints_world);
std::unique_ptr<Controller> make_explorer(const ExploreOptions& options);
/// Sends zero velocity forever (teleop / none).
std::unique_ptr<Controller> make_idle_controller();

}  // namespace cogmap::mapper::nav
