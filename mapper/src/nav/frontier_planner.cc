#include "nav/frontier_planner.h"
#include "nav/nav_constants.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <deque>
#include <functional>
#include <limits>
#include <queue>
#include <utility>

namespace cogmap::mapper::nav {
namespace {

using Cell = ExploreMap::Cell;
constexpr int kDx[8] = {1, -1, 0, 0, 1, 1, -1, -1};
constexpr int kDy[8] = {0, 0, 1, -1, 1, -1, 1, -1};

/// Per cell the distance (metres, centre to centre) to the nearest obstacle cell, capped at
/// `cap_m`: a brushfire from every obstacle cell that keeps each cell's nearest source.
std::vector<double> clearance(const ExploreMap& map, double cap_m) {
  const int w = map.width(), h = map.height();
  std::vector<double> dist(static_cast<std::size_t>(w) * h, cap_m);
  std::vector<Cell> source(dist.size());
  std::deque<Cell> queue;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      if (!map.occupied({x, y})) continue;
      const std::size_t i = map.index({x, y});
      dist[i] = 0.0;
      source[i] = {x, y};
      queue.push_back({x, y});
    }
  }
  const double cell = map.cell_m();
  while (!queue.empty()) {
    const Cell c = queue.front();
    queue.pop_front();
    const Cell s = source[map.index(c)];
    for (int k = 0; k < 8; ++k) {
      const Cell n{c.x + kDx[k], c.y + kDy[k]};
      if (!map.inside(n)) continue;
      const double d = cell * std::hypot(n.x - s.x, n.y - s.y);
      const std::size_t j = map.index(n);
      if (d >= dist[j]) continue;
      dist[j] = d;
      source[j] = s;
      queue.push_back(n);
    }
  }
  return dist;
}

/// True when `c` lies in a gap between obstacle cells narrower than 2·reach_m along x or y
/// (a doorway): the nearest obstacle cells either side, centre to centre, less one cell.
/// Diagonals are not looked along: from a cell near a room's inside corner they meet the two
/// walls of the corner.
bool pinched(const ExploreMap& map, Cell c, double reach_m) {
  constexpr int kAxes[2][2] = {{1, 0}, {0, 1}};
  const double cell = map.cell_m();
  const int steps = static_cast<int>(std::ceil((2.0 * reach_m + cell) / cell));
  for (const auto& a : kAxes) {
    int nearest[2] = {0, 0};
    for (int side = 0; side < 2; ++side) {
      const int sign = side == 0 ? 1 : -1;
      for (int i = 1; i <= steps && nearest[side] == 0; ++i) {
        if (map.occupied({c.x + sign * i * a[0], c.y + sign * i * a[1]})) nearest[side] = i;
      }
    }
    if (nearest[0] > 0 && nearest[1] > 0 &&
        (nearest[0] + nearest[1] - 1) * cell <= 2.0 * reach_m + 1e-9) {
      return true;
    }
  }
  return false;
}

}  // namespace

bool frontier_banned(const ExploreMap& map, Cell c, std::span<const BannedFrontier> banned,
                     double banned_radius_m) {
  const Point2 p = map.center_of(c);
  return std::any_of(banned.begin(), banned.end(), [&](const BannedFrontier& b) {
    if ((b.at - p).norm() > banned_radius_m) return false;
    return !b.seen_from ||
           (p - *b.seen_from).norm() <= (b.at - *b.seen_from).norm() + 0.5 * map.cell_m();
  });
}

ExploreMapImage explore_map_image(const ExploreMap& map, std::span<const BannedFrontier> banned,
                                  double banned_radius_m) {
  ExploreMapImage image;
  image.width = map.width();
  image.height = map.height();
  image.cell_m = map.cell_m();
  image.origin_m = map.center_of({0, 0}) - Point2(0.5 * image.cell_m, 0.5 * image.cell_m);
  image.cells.resize(static_cast<std::size_t>(image.width) * image.height);
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const Cell c{x, y};
      std::uint8_t& out = image.cells[map.index(c)];
      if (!map.seen(c)) {
        out = ExploreMapImage::kUnseen;
      } else if (map.occupied(c)) {
        out = ExploreMapImage::kObstacle;
      } else if (!map.frontier(c)) {
        out = ExploreMapImage::kFree;
      } else {
        out = frontier_banned(map, c, banned, banned_radius_m) ? ExploreMapImage::kBannedFrontier
                                                               : ExploreMapImage::kFrontier;
      }
    }
  }
  return image;
}

std::optional<FrontierPlan> plan_to_frontier(const ExploreMap& map, const Pose2& from,
                                             std::span<const BannedFrontier> banned,
                                             double banned_radius_m, const FrontierOptions& o) {
  const int w = map.width(), h = map.height();
  auto cell_at = [w](std::size_t i) {
    return Cell{static_cast<int>(i % w), static_cast<int>(i / w)};
  };
  const Cell start = map.cell_of(from.translation());
  if (w == 0 || !map.inside(start)) return std::nullopt;
  const std::size_t n = static_cast<std::size_t>(w) * h;
  const double cap_m = std::max({o.soft_clearance_m, o.pinch_m, o.los_clearance_m}) + map.cell_m();
  const std::vector<double> clear = clearance(map, cap_m);
  // A cell the robot's centre has passed through is passable whatever was painted there since
  // (ExploreMap::traversed): the way through a doorway it took stays a way back.
  auto passable = [&](Cell c) {
    return (o.trail_passable && map.traversed(c)) ||
           (map.seen(c) && !map.occupied(c) && clear[map.index(c)] >= o.hard_clearance_m);
  };
  // Frontier cells: passable, next to an unseen cell.
  std::vector<std::uint8_t> frontier(n, 0);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const Cell c{x, y};
      if (!passable(c)) continue;
      bool edge = false;
      for (int k = 0; k < 4 && !edge; ++k) edge = !map.seen({x + kDx[k], y + kDy[k]});
      if (edge && !frontier_banned(map, c, banned, banned_radius_m)) frontier[map.index(c)] = 1;
    }
  }
  // Clusters (8-connected); pieces too small to be more than a gap between beams are dropped.
  std::vector<int> cluster(n, -1);
  std::vector<std::size_t> cluster_size;
  for (std::size_t i = 0; i < n; ++i) {
    if (!frontier[i] || cluster[i] >= 0) continue;
    const int id = static_cast<int>(cluster_size.size());
    std::size_t size = 0;
    std::vector<std::size_t> stack{i};
    cluster[i] = id;
    while (!stack.empty()) {
      const std::size_t j = stack.back();
      stack.pop_back();
      ++size;
      const Cell c = cell_at(j);
      for (int k = 0; k < 8; ++k) {
        const Cell m{c.x + kDx[k], c.y + kDy[k]};
        if (!map.inside(m)) continue;
        const std::size_t mi = map.index(m);
        if (!frontier[mi] || cluster[mi] >= 0) continue;
        cluster[mi] = id;
        stack.push_back(mi);
      }
    }
    cluster_size.push_back(size);
  }
  // Goals: passable cells with a frontier cell of a large enough cluster within view_m and in
  // sight (no obstacle cell between), remembering which one.
  std::vector<std::int64_t> views(n, -1);
  const int view_cells = static_cast<int>(o.view_m / map.cell_m());
  auto in_sight = [&](Cell a, Cell b) {
    const int steps = 2 * std::max(std::abs(b.x - a.x), std::abs(b.y - a.y));
    for (int k = 1; k < steps; ++k) {
      const double t = static_cast<double>(k) / steps;
      const Cell c{static_cast<int>(std::lround(a.x + t * (b.x - a.x))),
                   static_cast<int>(std::lround(a.y + t * (b.y - a.y)))};
      if (map.occupied(c)) return false;
    }
    return true;
  };
  for (std::size_t i = 0; i < n; ++i) {
    if (!frontier[i] || cluster_size[static_cast<std::size_t>(cluster[i])] <
                            static_cast<std::size_t>(o.min_frontier_cells)) {
      continue;
    }
    const Cell f = cell_at(i);
    for (int dy = -view_cells; dy <= view_cells; ++dy) {
      for (int dx = -view_cells; dx <= view_cells; ++dx) {
        const Cell c{f.x + dx, f.y + dy};
        if (!map.inside(c) || map.cell_m() * std::hypot(dx, dy) > o.view_m) continue;
        const std::size_t j = map.index(c);
        if (views[j] >= 0 || !passable(c) || !in_sight(c, f)) continue;
        views[j] = static_cast<std::int64_t>(i);
      }
    }
  }
  // Dijkstra from the robot's cell over passable cells (the start always counts as passable:
  // the robot stands there).
  std::vector<double> cost(n, kInf);
  std::vector<std::int64_t> parent(n, -1);
  std::vector<double> departure(n, from.theta_rad);  // the path's direction on leaving
  std::vector<std::int8_t> pinch(n, -1);             // -1 unknown, computed on demand
  auto is_pinch = [&](Cell c) {
    std::int8_t& p = pinch[map.index(c)];
    if (p < 0) {
      p = clear[map.index(c)] <= o.pinch_m + map.cell_m() && pinched(map, c, o.pinch_m) ? 1 : 0;
    }
    return p == 1;
  };
  const Point2 start_m = map.center_of(start);
  using Entry = std::pair<double, std::size_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open;
  cost[map.index(start)] = 0.0;
  open.push({0.0, map.index(start)});
  while (!open.empty()) {
    const auto [c_cost, i] = open.top();
    open.pop();
    if (c_cost > cost[i]) continue;
    const Cell c = cell_at(i);
    const bool here_pinch = is_pinch(c);
    for (int k = 0; k < 8; ++k) {
      const Cell m{c.x + kDx[k], c.y + kDy[k]};
      if (!map.inside(m) || !passable(m)) continue;
      const std::size_t j = map.index(m);
      const double near = std::max(0.0, 1.0 - clear[j] / o.soft_clearance_m);
      double step = map.cell_m() * (k < 4 ? 1.0 : std::sqrt(2.0)) * (1.0 + o.soft_weight * near);
      if (!here_pinch && is_pinch(m)) step += o.doorway_cost_m;
      if (cost[i] + step >= cost[j]) continue;
      cost[j] = cost[i] + step;
      parent[j] = static_cast<std::int64_t>(i);
      // The direction the path leaves in: toward where it first gets departure_m away.
      const Point2 d = map.center_of(m) - start_m;
      departure[j] = d.norm() <= o.departure_m ? std::atan2(d.y(), d.x()) : departure[i];
      open.push({cost[j], j});
    }
  }
  // The goal: the cheapest place in view of a frontier, counting the turn onto the path (a
  // skid-steer base loses heading in every turn), among the clear ones first; as a last resort
  // (nothing else is left to explore) a place in a doorway the jambs' echoes painted narrower
  // than the body: the door behaviour finds the real opening there by the live sonar.
  std::size_t goal = n;
  const double tiers[3] = {o.goal_clearance_m, o.min_goal_clearance_m, o.doorway_goal_clearance_m};
  for (int tier = 0; tier < 3; ++tier) {
    const double need = tiers[tier];
    const bool doorways_only = tier == 2;
    if (doorways_only && !(need >= 0.0)) break;  // negative or NaN: no last resort
    double best = kInf;
    for (std::size_t i = 0; i < n; ++i) {
      if (views[i] < 0 || cost[i] == kInf || clear[i] < need) continue;
      if (doorways_only && !is_pinch(cell_at(i))) continue;
      const double total =
          cost[i] + o.turn_cost_m * std::abs(wrap_angle_rad(departure[i] - from.theta_rad));
      if (total < best) {
        best = total;
        goal = i;
      }
    }
    if (goal != n) break;
  }
  if (goal == n) return std::nullopt;

  // The path, start to goal, then straight legs over it.
  std::vector<Cell> path;
  for (std::int64_t i = static_cast<std::int64_t>(goal); i >= 0; i = parent[i]) {
    path.push_back(cell_at(static_cast<std::size_t>(i)));
  }
  std::reverse(path.begin(), path.end());
  auto leg_clear = [&](std::size_t a, std::size_t b) {
    double need = o.los_clearance_m;
    for (std::size_t k = a; k <= b; ++k) need = std::min(need, clear[map.index(path[k])]);
    const Point2 pa = map.center_of(path[a]), pb = map.center_of(path[b]);
    const double len = (pb - pa).norm();
    if (len > o.max_leg_m) return false;
    for (double t = 0.0; t <= len; t += 0.5 * map.cell_m()) {
      const Cell c = map.cell_of(pa + (len > 0 ? t / len : 0.0) * (pb - pa));
      if (o.trail_passable && map.traversed(c)) continue;
      if (!map.seen(c) || map.occupied(c) || clear[map.index(c)] + 1e-9 < need) {
        return false;
      }
    }
    return true;
  };
  FrontierPlan plan;
  const auto viewed = static_cast<std::size_t>(views[goal]);
  plan.goal = map.center_of(path.back());
  plan.frontier = map.center_of(cell_at(viewed));
  plan.cost_m = cost[goal];
  plan.frontier_cells = cluster_size[static_cast<std::size_t>(cluster[viewed])];
  plan.frontier_in_doorway = is_pinch(cell_at(viewed));
  std::size_t anchor = 0;
  while (anchor + 1 < path.size()) {
    std::size_t next = anchor + 1;
    while (next + 1 < path.size() && leg_clear(anchor, next + 1)) ++next;
    plan.waypoints.push_back(map.center_of(path[next]));
    anchor = next;
  }
  if (plan.waypoints.empty()) plan.waypoints.push_back(plan.goal);
  return plan;
}

double remaining_path_m(std::span<const Point2> legs, std::size_t next, const Point2& robot) {
  if (legs.empty()) return 0.0;
  const std::size_t ahead = std::min(next + 1, legs.size() - 1);
  double left_m = (legs[ahead] - robot).norm();
  for (std::size_t k = ahead; k + 1 < legs.size(); ++k) left_m += (legs[k + 1] - legs[k]).norm();
  return left_m;
}

bool path_blocked(const ExploreMap& map, std::span<const Point2> legs, std::size_t next,
                  const Point2& robot, double skip_m) {
  // Half-cell steps along each leg: the cells its line runs through (one it clips by less than
  // a quarter cell at a corner may be passed over).
  const double step_m = 0.5 * map.cell_m();
  for (std::size_t k = next; k + 1 < legs.size(); ++k) {
    const Point2 from = legs[k], to = legs[k + 1];
    const double length_m = (to - from).norm();
    if (!std::isfinite(length_m)) return false;
    const int steps = static_cast<int>(std::ceil(length_m / step_m));
    for (int i = 0; i <= steps; ++i) {
      const Point2 p = steps == 0 ? from : from + (static_cast<double>(i) / steps) * (to - from);
      if ((p - robot).norm() < skip_m) continue;
      const Cell c = map.cell_of(p);
      if (map.occupied(c) && !map.traversed(c)) return true;
    }
  }
  return false;
}

}  // namespace cogmap::mapper::nav
