#pragma once
/// The explorer's choice of where to go next: the cheapest frontier cluster of the explore
/// map (seen, passable cells next to unseen ones), reached by Dijkstra over seen cells whose
/// step cost grows near obstacles and jumps on entering a doorway, so a room's own frontiers
/// come before the ones behind its doors.

#include <optional>
#include <span>
#include <vector>

#include "cogmap/mapper/nav/controller.h"
#include "nav/explore_map.h"

namespace cogmap::mapper::nav {

struct FrontierPlan {
  Point2 goal{0.0, 0.0};             ///< where to drive: the cheapest place in view of a frontier
  Point2 frontier{0.0, 0.0};         ///< the frontier cell it views (its centre), estimate frame
  std::vector<Point2> waypoints;     ///< from the first leg's end to the goal
  double cost_m = 0.0;               ///< weighted path cost to the goal
  std::size_t frontier_cells = 0;    ///< size of the goal's cluster
  bool frontier_in_doorway = false;  ///< the frontier cell lies in a gap narrower than 2·pinch_m
};

/// A frontier given up. A goal that failed bans every frontier cell within the radius; a look
/// that left its frontier (from `seen_from`) bans only the cells no farther from there than
/// the frontier itself: free cells beyond it that the look has just begun to reveal (the far
/// side of a doorway) are new frontier, not the same one.
struct BannedFrontier {
  Point2 at{0.0, 0.0};
  std::optional<Point2> seen_from;
};

/// Whether frontier cell `c` is given up: within `banned_radius_m` of a ban, and for a look's ban
/// no farther from where it looked than the banned cell (+ half a cell).
bool frontier_banned(const ExploreMap& map, ExploreMap::Cell c,
                     std::span<const BannedFrontier> banned, double banned_radius_m);

/// The map cell by cell as the planner sees it (output.explore_map): unseen, free, obstacle,
/// frontier, or a frontier given up.
ExploreMapImage explore_map_image(const ExploreMap& map, std::span<const BannedFrontier> banned,
                                  double banned_radius_m);

/// The plan to the cheapest reachable frontier cluster from `from` (its heading prices the
/// first step's turn: turn_cost_m per radian), or nullopt when no
/// frontier of min_frontier_cells is reachable. Frontier cells within `banned_radius_m` of a
/// point in `banned` (goals given up) are ignored.
std::optional<FrontierPlan> plan_to_frontier(const ExploreMap& map, const Pose2& from,
                                             std::span<const BannedFrontier> banned,
                                             double banned_radius_m,
                                             const FrontierOptions& options);

/// Whether the rest of a planned path crosses a cell `map` now shows an obstacle: `legs` is
/// the plan's start followed by its waypoints, `next` the waypoint being approached (its leg
/// begins at legs[next]). Cells the robot's centre has passed through are not obstacles (the
/// planner's own rule for the way back), nor are cells within `skip_m` of `robot`, which are
/// the body's surroundings that VFH and the door behaviour steer around.
bool path_blocked(const ExploreMap& map, std::span<const Point2> legs, std::size_t next,
                  const Point2& robot, double skip_m);

/// What is left of a planned path, metres: from `robot` to the waypoint being approached
/// (`legs` and `next` as for path_blocked: legs[next + 1]), then leg by leg to the last point.
/// A `next` past the last waypoint leaves the distance to the last point; no legs, 0.
double remaining_path_m(std::span<const Point2> legs, std::size_t next, const Point2& robot);

}  // namespace cogmap::mapper::nav
