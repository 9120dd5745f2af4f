#pragma once
/// The route follower with a route that can be replaced while it drives (the explorer's
/// legs to its frontier): the obstacle memory, the door behaviour and the trace carry over.

#include <memory>
#include <vector>

#include "cogmap/mapper/nav/controller.h"

namespace cogmap::mapper::nav {

class ReroutableFollower : public Controller {
 public:
  /// Replaces the remaining route by `waypoints_world`; the give-up clock and the recovery
  /// count start again, as for a new leg.
  virtual void set_waypoints(std::vector<Point2> waypoints_world) = 0;
};

/// A route follower with an empty route (done() until set_waypoints gives it one).
std::unique_ptr<ReroutableFollower> make_reroutable_route_follower(const RouteOptions& options);

}  // namespace cogmap::mapper::nav
