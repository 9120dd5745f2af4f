#pragma once
/// Test support for the frontier planner: explore maps built cell by cell (Scene) and checks of
/// a plan's legs, shared by frontier_planner_test.cc and frontier_doorway_test.cc.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "nav/explore_map.h"
#include "nav/frontier_planner.h"

namespace cogmap::mapper::nav::testing {

inline constexpr double kCellM = 0.2;
inline constexpr double kPi = std::numbers::pi;

// Cells by index on a lattice whose centres are the multiples of 0.2 m: (i, j) is (0.2 i, 0.2 j).
using Key = std::pair<int, int>;
inline Point2 at(Key k) { return {kCellM * k.first, kCellM * k.second}; }

/// Builds an explore map cell by cell: `free` cells seen and free (a 5 cm body on each),
/// every other cell next to one (4-neighbours) a seen obstacle unless listed in `open`
/// (left unseen), everything else unseen. An obstacle is one echo at 0.6 m from a transducer
/// 3 cells back over two free cells, so its beam sweeps only free cells.
class Scene {
 public:
  void add_free(int x0, int y0, int x1, int y1) {
    for (int y = y0; y <= y1; ++y) {
      for (int x = x0; x <= x1; ++x) free_.insert({x, y});
    }
  }
  void add_open(int x0, int y0, int x1, int y1) {
    for (int y = y0; y <= y1; ++y) {
      for (int x = x0; x <= x1; ++x) open_.insert({x, y});
    }
  }
  /// A free disc of `radius_m` around `center`, as the robot's body would leave it.
  void add_disc(const Point2& center, double radius_m) { discs_.push_back({center, radius_m}); }

  ExploreMap build() const {
    ExploreMap map;
    std::set<Key> walls;
    map.mark_body(Point2(0.1, 0.1), 0.0);  // pins the lattice (corner 8 m before the box)
    EXPECT_EQ(map.seen_count(), 0u);
    for (const auto& [c, r] : discs_) map.mark_body(c, r);
    for (const Key& k : free_) map.mark_body(at(k), 0.05);
    RobotGeometry robot;
    robot.sonars = {{0.0, 0.0, 0.0}};
    robot.width_m = 0.0;  // the transducers below stand off cell centres: no body cell
    constexpr int kDirs[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
    for (const Key& f : free_) {
      for (const auto& d : kDirs) {
        const Key w{f.first + d[0], f.second + d[1]};
        if (free_.count(w) || open_.count(w) || walls.count(w)) continue;
        walls.insert(w);
        bool drawn = false;
        for (const auto& e : kDirs) {  // e: from the transducer towards the wall
          const Key b1{w.first - e[0], w.second - e[1]},
              b2{w.first - 2 * e[0], w.second - 2 * e[1]};
          if (!free_.count(b1) || !free_.count(b2)) continue;
          const Point2 from = at(w) - 0.6 * Point2(e[0], e[1]) + Point2(0.03, 0.03);
          SensorFrame frame;
          frame.sonar = {{0, 0.6, true, 0.0}};
          map.add_frame(frame, {from.x(), from.y(), std::atan2(e[1], e[0])}, robot);
          drawn = true;
          break;
        }
        EXPECT_TRUE(drawn) << "no free run to draw wall cell " << w.first << "," << w.second;
      }
    }
    // The map must be what was asked for.
    for (const Key& k : free_) {
      const ExploreMap::Cell c = map.cell_of(at(k));
      EXPECT_TRUE(map.seen(c) && !map.occupied(c)) << k.first << "," << k.second;
    }
    for (const Key& k : walls) {
      const ExploreMap::Cell c = map.cell_of(at(k));
      EXPECT_TRUE(map.seen(c) && map.occupied(c)) << k.first << "," << k.second;
    }
    for (const Key& k : open_) EXPECT_FALSE(map.seen(map.cell_of(at(k))));
    return map;
  }

 private:
  std::set<Key> free_, open_;
  std::vector<std::pair<Point2, double>> discs_;
};

inline bool walkable(const ExploreMap& map, const Point2& p) {
  const ExploreMap::Cell c = map.cell_of(p);
  return map.seen(c) && !map.occupied(c);
}

/// Every waypoint, and every point of the straight legs between them (from the start cell's
/// centre), lies on seen, free cells; no leg is longer than `max_leg_m`.
inline void expect_walkable_legs(const ExploreMap& map, const Pose2& from, const FrontierPlan& plan,
                                 double max_leg_m) {
  ASSERT_FALSE(plan.waypoints.empty());
  EXPECT_NEAR((plan.waypoints.back() - plan.goal).norm(), 0.0, 1e-9);
  Point2 a = map.center_of(map.cell_of(from.translation()));
  for (const Point2& b : plan.waypoints) {
    EXPECT_TRUE(walkable(map, b)) << b.transpose();
    const double len = (b - a).norm();
    EXPECT_LE(len, max_leg_m + 1e-9) << a.transpose() << " -> " << b.transpose();
    for (double t = 0.0; t <= len; t += 0.02) {
      const Point2 p = a + (t / len) * (b - a);
      EXPECT_TRUE(walkable(map, p))
          << "leg " << a.transpose() << " -> " << b.transpose() << " crosses " << p.transpose();
    }
    a = b;
  }
}

inline std::string describe(const FrontierPlan& plan) {
  std::ostringstream out;
  out << "cost " << plan.cost_m << " goal " << plan.goal.transpose() << " frontier "
      << plan.frontier.transpose() << " waypoints";
  for (const Point2& w : plan.waypoints) out << " (" << w.x() << ", " << w.y() << ")";
  return out.str();
}

inline std::size_t count_frontier_cells(const ExploreMap& map) {
  std::size_t n = 0;
  for (int y = 0; y < map.height(); ++y) {
    for (int x = 0; x < map.width(); ++x) n += map.frontier({x, y}) ? 1 : 0;
  }
  return n;
}

}  // namespace cogmap::mapper::nav::testing
