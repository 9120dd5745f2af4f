#include "cogmap/experiments/controller_factory.h"

namespace cogmap::experiments {

std::unique_ptr<mapper::nav::Controller> make_controller(const ControllerConfig& c) {
  switch (c.type) {
    case ControllerKind::kRoute: {
      mapper::nav::RouteOptions o;
      o.speed_mps = c.speed_mps;
      o.waypoint_tolerance_m = c.waypoint_tolerance_m;
      if (c.door_search && !*c.door_search) o.door.search_per_waypoint = 0;
      o.door.cross_side_walls.enabled = c.grazing_walls;
      if (c.arc_guard_s) o.safety.arc_guard_s = *c.arc_guard_s;
      return mapper::nav::make_route_follower(o, c.waypoints);
    }
    case ControllerKind::kExplore: {
      mapper::nav::ExploreOptions o;
      o.speed_mps = c.speed_mps;
      o.waypoint_tolerance_m = c.waypoint_tolerance_m;
      o.strategy = c.explore_strategy;
      o.time_budget_s = c.explore_time_budget_s;
      o.distance_budget_m = c.explore_distance_budget_m;
      if (c.door_search) {
        o.door.search_per_waypoint =
            *c.door_search ? mapper::nav::DoorOptions{}.search_per_waypoint : 0;
      }
      o.door.cross_side_walls.enabled = c.grazing_walls;
      o.plan_over_trail = c.plan_over_trail;
      o.progress_along_path = c.progress_along_path;
      o.blocked_path_s = c.blocked_path_s;
      if (c.arc_guard_s) o.safety.arc_guard_s = *c.arc_guard_s;
      return mapper::nav::make_explorer(o);
    }
    case ControllerKind::kNone:
      break;
  }
  return mapper::nav::make_idle_controller();
}

}  // namespace cogmap::experiments
