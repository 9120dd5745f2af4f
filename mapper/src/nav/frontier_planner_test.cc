#include "nav/frontier_planner.h"

#include "nav/explore_reopen.h"
#include "nav/fake_grid_updater.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "nav/explore_map.h"

namespace cogmap::mapper::nav {
namespace {

constexpr double kCellM = 0.2;
constexpr double kPi = std::numbers::pi;

// Cells by index on a lattice whose centres are the multiples of 0.2 m: (i, j) is (0.2 i, 0.2 j).
using Key = std::pair<int, int>;
Point2 at(Key k) { return {kCellM * k.first, kCellM * k.second}; }

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

bool walkable(const ExploreMap& map, const Point2& p) {
  const ExploreMap::Cell c = map.cell_of(p);
  return map.seen(c) && !map.occupied(c);
}

/// Every waypoint, and every point of the straight legs between them (from the start cell's
/// centre), lies on seen, free cells; no leg is longer than `max_leg_m`.
void expect_walkable_legs(const ExploreMap& map, const Pose2& from, const FrontierPlan& plan,
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

std::string describe(const FrontierPlan& plan) {
  std::ostringstream out;
  out << "cost " << plan.cost_m << " goal " << plan.goal.transpose() << " frontier "
      << plan.frontier.transpose() << " waypoints";
  for (const Point2& w : plan.waypoints) out << " (" << w.x() << ", " << w.y() << ")";
  return out.str();
}

std::size_t count_frontier_cells(const ExploreMap& map) {
  std::size_t n = 0;
  for (int y = 0; y < map.height(); ++y) {
    for (int x = 0; x < map.width(); ++x) n += map.frontier({x, y}) ? 1 : 0;
  }
  return n;
}

// A seen free disc of 2.1 m around the origin (no cell centre lies on its rim), unseen
// space all round: the frontier is the rim, its cells 1.9-2.1 m out.
ExploreMap disc_map() {
  Scene scene;
  scene.add_disc({0.0, 0.0}, 2.1);
  return scene.build();
}

TEST(FrontierPlanner, GoesToTheRimOfASeenDisc) {
  const ExploreMap map = disc_map();
  const std::optional<FrontierPlan> plan =
      plan_to_frontier(map, {0.0, 0.0, 0.0}, {}, 0.0, FrontierOptions{});
  ASSERT_TRUE(plan.has_value());
  EXPECT_GE(plan->frontier.norm(), 1.8);
  EXPECT_LE(plan->frontier.norm(), 2.1);
  EXPECT_TRUE(map.frontier(map.cell_of(plan->frontier)));
  EXPECT_LE((plan->goal - plan->frontier).norm(), FrontierOptions{}.view_m + 1e-9);
  EXPECT_TRUE(walkable(map, plan->goal));
  // The goal is the nearest place in view: no farther out than the frontier less 0.9 m, plus
  // a cell's diagonal for the lattice.
  EXPECT_LE(plan->goal.norm(), 2.1 - FrontierOptions{}.view_m + kCellM * std::sqrt(2.0));
  EXPECT_GE(plan->cost_m, plan->goal.norm() - 1e-9);
  // The whole rim is one 8-connected cluster.
  EXPECT_EQ(plan->frontier_cells, count_frontier_cells(map));
  expect_walkable_legs(map, {0.0, 0.0, 0.0}, *plan, FrontierOptions{}.max_leg_m);
}

TEST(FrontierPlanner, PrefersTheFrontierAhead) {
  const ExploreMap map = disc_map();
  FrontierOptions options;
  options.turn_cost_m = 0.6;
  for (double heading : {0.0, kPi / 2, kPi, -kPi / 2}) {
    const Point2 ahead(std::cos(heading), std::sin(heading));
    const std::optional<FrontierPlan> plan =
        plan_to_frontier(map, {0.0, 0.0, heading}, {}, 0.0, options);
    ASSERT_TRUE(plan.has_value()) << heading;
    // Within 45° of the heading, for the frontier and for the goal.
    EXPECT_GT(plan->frontier.normalized().dot(ahead), std::cos(kPi / 4))
        << heading << ": " << plan->frontier.transpose();
    EXPECT_GT(plan->goal.normalized().dot(ahead), std::cos(kPi / 4))
        << heading << ": " << plan->goal.transpose();
  }
}

TEST(FrontierPlanner, AFrontierBehindMustBeMuchNearer) {
  // A corridor along x (walls 1.6 m apart), open at both ends, the robot facing +x: the
  // frontier ahead is 3.0 m away, the one behind 1.6 m (1.4 m nearer, less than the turn's
  // turn_cost_m × π = 1.9 m), so ahead wins.
  Scene scene;
  scene.add_free(-8, -3, 15, 3);
  scene.add_open(16, -3, 16, 3);
  scene.add_open(-9, -3, -9, 3);
  const ExploreMap map = scene.build();
  FrontierOptions options;
  options.turn_cost_m = 0.6;
  const std::optional<FrontierPlan> ahead =
      plan_to_frontier(map, {0.0, 0.0, 0.0}, {}, 0.0, options);
  ASSERT_TRUE(ahead.has_value());
  EXPECT_NEAR(ahead->frontier.x(), 3.0, 1e-9) << describe(*ahead);
  // Without the turn's price the nearer end behind is chosen.
  FrontierOptions no_turn;
  no_turn.turn_cost_m = 0.0;
  const std::optional<FrontierPlan> behind =
      plan_to_frontier(map, {0.0, 0.0, 0.0}, {}, 0.0, no_turn);
  ASSERT_TRUE(behind.has_value());
  EXPECT_NEAR(behind->frontier.x(), -1.6, 1e-9) << describe(*behind);
}

TEST(FrontierPlanner, NothingLeftInAnEnclosedRoom) {
  Scene closed;
  closed.add_free(-5, -5, 5, 5);  // 2.2 m square room, walled all round
  const ExploreMap map = closed.build();
  EXPECT_FALSE(plan_to_frontier(map, {0.0, 0.0, 0.0}, {}, 0.0, FrontierOptions{}).has_value());
  FrontierOptions one;
  one.min_frontier_cells = 1;
  EXPECT_FALSE(plan_to_frontier(map, {0.0, 0.0, 0.0}, {}, 0.0, one).has_value());
}

TEST(FrontierPlanner, FrontierPiecesSmallerThanMinFrontierCellsAreIgnored) {
  Scene closed;
  closed.add_free(-5, -5, 5, 5);
  FrontierOptions three;
  three.min_frontier_cells = 3;
  // A 3-cell (0.6 m) gap in the east wall leaves a frontier of min_frontier_cells.
  Scene gap = closed;
  gap.add_open(6, -1, 6, 1);
  const std::optional<FrontierPlan> plan =
      plan_to_frontier(gap.build(), {0.0, 0.0, 0.0}, {}, 0.0, three);
  ASSERT_TRUE(plan.has_value());
  EXPECT_NEAR(plan->frontier.x(), 1.0, 1e-9);
  EXPECT_EQ(plan->frontier_cells, 3u);
  // Two cells (0.4 m) are too few for 3, enough for 2; one cell is enough for 1.
  Scene narrow = closed;
  narrow.add_open(6, 0, 6, 1);
  const ExploreMap narrow_map = narrow.build();
  EXPECT_FALSE(plan_to_frontier(narrow_map, {0.0, 0.0, 0.0}, {}, 0.0, three).has_value());
  FrontierOptions two;
  two.min_frontier_cells = 2;
  const std::optional<FrontierPlan> two_plan =
      plan_to_frontier(narrow_map, {0.0, 0.0, 0.0}, {}, 0.0, two);
  ASSERT_TRUE(two_plan.has_value());
  EXPECT_EQ(two_plan->frontier_cells, 2u);
  Scene single = closed;
  single.add_open(6, 0, 6, 0);
  const ExploreMap single_map = single.build();
  EXPECT_FALSE(plan_to_frontier(single_map, {0.0, 0.0, 0.0}, {}, 0.0, two).has_value());
  FrontierOptions one;
  one.min_frontier_cells = 1;
  const std::optional<FrontierPlan> one_plan =
      plan_to_frontier(single_map, {0.0, 0.0, 0.0}, {}, 0.0, one);
  ASSERT_TRUE(one_plan.has_value());
  EXPECT_NEAR((one_plan->frontier - Point2(1.0, 0.0)).norm(), 0.0, 1e-9);
}

TEST(FrontierPlanner, BannedFrontiersAreSkipped) {
  const ExploreMap map = disc_map();
  const std::optional<FrontierPlan> first =
      plan_to_frontier(map, {0.0, 0.0, 0.0}, {}, 0.0, FrontierOptions{});
  ASSERT_TRUE(first.has_value());
  ASSERT_GT(first->frontier.x(), 0.0);
  const std::vector<BannedFrontier> banned = {{first->frontier, std::nullopt}};
  const std::optional<FrontierPlan> second =
      plan_to_frontier(map, {0.0, 0.0, 0.0}, banned, 2.0, FrontierOptions{});
  ASSERT_TRUE(second.has_value());
  EXPECT_GT((second->frontier - first->frontier).norm(), 2.0);
  EXPECT_GE(second->frontier.norm(), 1.8);
  // Banning the whole rim leaves nothing.
  const std::vector<BannedFrontier> all = {{{0.0, 0.0}, std::nullopt}};
  EXPECT_FALSE(plan_to_frontier(map, {0.0, 0.0, 0.0}, all, 2.2, FrontierOptions{}).has_value());
}

// A closed room x -2.0 .. 0.8 m, y -1.0 .. 1.0 m, whose east wall (x = 1.0) has a doorway of
// cells door_y0 .. door_y1, and beyond it the next room seen as far as cell far_x (its side
// walls one cell either side of the doorway), unseen past it: the map after a look through.
ExploreMap door_map(int door_y0, int door_y1, int far_x) {
  Scene scene;
  scene.add_free(-10, -5, 4, 5);
  scene.add_free(5, door_y0, far_x, door_y1);
  scene.add_open(far_x + 1, door_y0, far_x + 1, door_y1);
  return scene.build();
}

// A 1 m doorway (y -0.4 .. 0.4) with the first 0.4 m beyond it seen (frontier at x = 1.4).
ExploreMap looked_through_door_map() { return door_map(-2, 2, 7); }

TEST(FrontierPlanner, ALookBansTheDoorButNotWhatItRevealedBeyond) {
  const ExploreMap map = looked_through_door_map();
  const Pose2 from{-1.0, 0.0, 0.0};
  const Point2 door(1.0, 0.0);
  const std::optional<FrontierPlan> open = plan_to_frontier(map, from, {}, 0.0, FrontierOptions{});
  ASSERT_TRUE(open.has_value());
  EXPECT_NEAR(open->frontier.x(), 1.4, 1e-9) << describe(*open);
  EXPECT_TRUE(open->frontier_in_doorway) << describe(*open);
  // A goal given up bans everything within the radius, the far side's frontier included.
  const std::vector<BannedFrontier> failed = {{door, std::nullopt}};
  EXPECT_FALSE(plan_to_frontier(map, from, failed, 0.6, FrontierOptions{}).has_value());
  // A look from inside the room leaves the cells beyond the door (2.4 m from the viewer,
  // the door 2.0 m) open...
  const std::vector<BannedFrontier> looked = {{door, from.translation()}};
  const std::optional<FrontierPlan> beyond =
      plan_to_frontier(map, from, looked, 0.6, FrontierOptions{});
  ASSERT_TRUE(beyond.has_value());
  EXPECT_NEAR(beyond->frontier.x(), 1.4, 1e-9) << describe(*beyond);
  // ...but one from the far side bans them: they lie between that viewer and the door.
  const std::vector<BannedFrontier> from_far_side = {{door, Point2(2.4, 0.0)}};
  EXPECT_FALSE(plan_to_frontier(map, from, from_far_side, 0.6, FrontierOptions{}).has_value());
}

// The same room with its doorway painted down to two cells (y 0.0 .. 0.2 at x = 1.0, as the
// jambs' echoes paint a 1 m door), and 0.6 m of the far side seen (frontier at x = 1.6): no
// place 0.35 m clear views that frontier from within 0.9 m.
TEST(FrontierPlanner, ADoorwayPaintedNarrowIsTheLastResort) {
  const ExploreMap map = door_map(0, 1, 8);
  const Pose2 from{-1.0, 0.0, 0.0};
  const std::optional<FrontierPlan> plan = plan_to_frontier(map, from, {}, 0.0, FrontierOptions{});
  ASSERT_TRUE(plan.has_value());
  EXPECT_NEAR(plan->frontier.x(), 1.6, 1e-9) << describe(*plan);
  EXPECT_NEAR(plan->goal.x(), 1.0, 1e-9) << describe(*plan);  // in the doorway itself
  expect_walkable_legs(map, from, *plan, FrontierOptions{}.max_leg_m);
  FrontierOptions no_last_resort;
  no_last_resort.doorway_goal_clearance_m = -1.0;
  EXPECT_FALSE(plan_to_frontier(map, from, {}, 0.0, no_last_resort).has_value());
  // A frontier that a place 0.35 m clear views is taken the usual way, from that place.
  const std::optional<FrontierPlan> open =
      plan_to_frontier(looked_through_door_map(), from, {}, 0.0, FrontierOptions{});
  ASSERT_TRUE(open.has_value());
  EXPECT_LE(open->goal.x(), 0.6) << describe(*open);
}

// The doorway painted shut altogether (its five cells at x = 1.0 obstacles, the far side seen
// to x = 1.6 through it before the jambs' echoes closed it): nothing is reachable, until the
// room grid, which saw beams pass through the door's cells and no echo there, reopens them
// (FrontierOptions::reopen_echo_himm, the explorer's last look before it stops).
TEST(FrontierPlanner, ADoorwayPaintedShutIsReopenedByTheRoomGrid) {
  Scene scene;
  scene.add_free(-10, -5, 4, 5);
  scene.add_free(6, -2, 8, 2);
  scene.add_open(9, -2, 9, 2);
  ExploreMap map = scene.build();
  const Pose2 from{-1.0, 0.0, 0.0};
  ASSERT_FALSE(plan_to_frontier(map, from, {}, 0.0, FrontierOptions{}).has_value());
  // The room grid: 0.1 m cells, unexplored but for the doorway, swept by beams (-1).
  testing::FakeGridUpdater room(-3.0, -2.0, 6.0, 0.0f);
  room.fill_box(0.9, -0.5, 1.1, 0.5, -1.0f);
  const double echo_himm = FrontierOptions{}.reopen_echo_himm;
  ExploreMap same = map;
  EXPECT_EQ(reopen_swept_cells(same, room, echo_himm), 5u);  // the five door cells, no jamb
  const std::optional<FrontierPlan> plan = plan_to_frontier(same, from, {}, 0.0, FrontierOptions{});
  ASSERT_TRUE(plan.has_value());
  EXPECT_NEAR(plan->frontier.x(), 1.6, 1e-9) << describe(*plan);
  expect_walkable_legs(same, from, *plan, FrontierOptions{}.max_leg_m);
  // An echo on an axis in the doorway's middle cell (a post there) keeps that cell shut.
  room.set(1.05, 0.05, 3.0f);
  ExploreMap walled = map;
  EXPECT_EQ(reopen_swept_cells(walled, room, echo_himm), 4u);
  EXPECT_TRUE(walled.occupied(walled.cell_of(Point2(1.0, 0.0))));
  EXPECT_FALSE(walled.occupied(walled.cell_of(Point2(1.0, 0.2))));
}

// The same doorway painted shut after the robot walked through it and back (its centre's
// trail along y = 0 from x = -1.0 to 1.4): with the trail passable (the explorer's plan when
// nothing else is reachable, ExploreOptions::plan_over_trail) the plan goes through the
// doorway along the trail; a trail that stopped short of the door opens nothing.
TEST(FrontierPlanner, ADoorwayWalkedThroughStaysAWayBackOverTheTrail) {
  Scene scene;
  scene.add_free(-10, -5, 4, 5);
  scene.add_free(6, -2, 8, 2);
  scene.add_open(9, -2, 9, 2);
  const ExploreMap painted = scene.build();
  const Pose2 from{-1.0, 0.0, 0.0};
  FrontierOptions over_trail;
  over_trail.trail_passable = true;
  ASSERT_FALSE(plan_to_frontier(painted, from, {}, 0.0, over_trail).has_value());

  ExploreMap walked = painted;
  for (double x = -1.0; x <= 1.4 + 1e-9; x += 0.05) walked.mark_traversed({x, 0.01});
  ASSERT_TRUE(walked.occupied(walked.cell_of(Point2(1.0, 0.0))));  // still painted shut
  EXPECT_FALSE(plan_to_frontier(walked, from, {}, 0.0, FrontierOptions{}).has_value());
  const std::optional<FrontierPlan> plan = plan_to_frontier(walked, from, {}, 0.0, over_trail);
  ASSERT_TRUE(plan.has_value());
  EXPECT_NEAR(plan->frontier.x(), 1.6, 1e-9) << describe(*plan);
  // Every leg keeps to seen free cells or to the trail.
  Point2 a = walked.center_of(walked.cell_of(from.translation()));
  for (const Point2& b : plan->waypoints) {
    const double len = (b - a).norm();
    for (double t = 0.0; t <= len; t += 0.02) {
      const Point2 p = a + (t / len) * (b - a);
      EXPECT_TRUE(walkable(walked, p) || walked.traversed(walked.cell_of(p)))
          << "leg " << a.transpose() << " -> " << b.transpose() << " crosses " << p.transpose();
    }
    a = b;
  }
  EXPECT_GT(plan->waypoints.back().x(), 1.0) << describe(*plan);  // beyond the door

  ExploreMap short_of_door = painted;
  for (double x = -1.0; x <= 0.6 + 1e-9; x += 0.05) short_of_door.mark_traversed({x, 0.01});
  EXPECT_FALSE(plan_to_frontier(short_of_door, from, {}, 0.0, over_trail).has_value());
}

TEST(FrontierPlanner, AFrontierInTheOpenIsNoDoorway) {
  const std::optional<FrontierPlan> plan =
      plan_to_frontier(disc_map(), {0.0, 0.0, 0.0}, {}, 0.0, FrontierOptions{});
  ASSERT_TRUE(plan.has_value());
  EXPECT_FALSE(plan->frontier_in_doorway) << describe(*plan);
}

TEST(FrontierPlanner, LegsStayOnSeenFreeCellsAndAreBounded) {
  // An L: a corridor east from the start (1.4 m wide), then north, open at the far end.
  Scene scene;
  scene.add_free(-1, -3, 30, 3);
  scene.add_free(24, 4, 30, 20);
  scene.add_open(24, 21, 30, 21);
  const ExploreMap map = scene.build();
  const Pose2 from{0.0, 0.0, 0.0};
  for (double max_leg_m : {4.0, 1.5}) {
    FrontierOptions options;
    options.max_leg_m = max_leg_m;
    const std::optional<FrontierPlan> plan = plan_to_frontier(map, from, {}, 0.0, options);
    ASSERT_TRUE(plan.has_value()) << max_leg_m;
    EXPECT_NEAR(plan->frontier.y(), 4.0, 1e-9);
    EXPECT_GE(plan->goal.y(), 3.0);
    EXPECT_GT(plan->cost_m, (plan->goal - from.translation()).norm());
    // The corner forces a bend (two legs at least), and no leg is longer than max_leg_m.
    const double straight = (plan->goal - map.center_of(map.cell_of(from.translation()))).norm();
    EXPECT_GE(plan->waypoints.size(),
              std::max<std::size_t>(2, static_cast<std::size_t>(std::ceil(straight / max_leg_m))));
    expect_walkable_legs(map, from, *plan, max_leg_m);
  }
}

// A room x -2.0 .. 2.4, y -1.0 .. 1.0, open to the east (frontier at x = 2.4). Its west wall
// (x = -2.2) has a gap of `gap_cells` cells from y = -0.2 up into a strip x -3.0 .. -2.4 open
// to the west (frontier at x = -3.0). From x = -1.2 the strip's goal (about 1.4 m away,
// through the gap) is nearer than the room's (about 2.8 m); the doorway's cost (8 m) must
// reverse that. Both ways start with a quarter turn.
void expect_open_frontier_first(int gap_cells) {
  Scene scene;
  scene.add_free(-10, -5, 12, 5);
  scene.add_free(-11, -1, -11, -2 + gap_cells);
  scene.add_free(-15, -5, -12, 5);
  scene.add_open(13, -5, 13, 5);
  scene.add_open(-16, -5, -16, 5);
  const ExploreMap map = scene.build();
  const Pose2 from{-1.2, 0.0, kPi / 2};
  FrontierOptions doors;
  doors.pinch_m = 0.7;
  doors.doorway_cost_m = 8.0;
  const std::optional<FrontierPlan> plan = plan_to_frontier(map, from, {}, 0.0, doors);
  ASSERT_TRUE(plan.has_value());
  EXPECT_NEAR(plan->frontier.x(), 2.4, 1e-9) << describe(*plan);
  EXPECT_GT(plan->goal.x(), 1.4);
  // Without the doorway's cost the strip's frontier is the cheaper one.
  FrontierOptions free_doors = doors;
  free_doors.doorway_cost_m = 0.0;
  const std::optional<FrontierPlan> through = plan_to_frontier(map, from, {}, 0.0, free_doors);
  ASSERT_TRUE(through.has_value());
  EXPECT_NEAR(through->frontier.x(), -3.0, 1e-9) << describe(*through);
  EXPECT_LT(through->goal.x(), -2.2);        // beyond the gap
  EXPECT_LT(through->cost_m, plan->cost_m);  // the open route costs the same either way
}

TEST(FrontierPlanner, OpenFrontierBeforeOneThroughA06mDoorway) { expect_open_frontier_first(3); }

// pinch_m promises a doorway for gaps under 1.4 m; a 0.8 m door is the common case.
TEST(FrontierPlanner, OpenFrontierBeforeOneThroughA08mDoorway) { expect_open_frontier_first(4); }

TEST(ExploreMapImage, ClassifiesEveryCellAsThePlannerSeesIt) {
  // A 5 x 5 free room walled round, with one wall cell left unseen: its inner neighbour is the
  // only frontier.
  Scene scene;
  scene.add_free(0, 0, 4, 4);
  scene.add_open(5, 2, 5, 2);
  const ExploreMap map = scene.build();
  auto cell = [&](const ExploreMapImage& image, Key k) {
    return image.cells[map.index(map.cell_of(at(k)))];
  };
  const ExploreMapImage image = explore_map_image(map, {}, 0.6);
  ASSERT_EQ(image.width, map.width());
  ASSERT_EQ(image.height, map.height());
  ASSERT_EQ(image.cells.size(), static_cast<std::size_t>(map.width() * map.height()));
  EXPECT_DOUBLE_EQ(image.cell_m, kCellM);
  EXPECT_NEAR(image.origin_m.x(), map.center_of({0, 0}).x() - 0.5 * kCellM, 1e-12);
  EXPECT_NEAR(image.origin_m.y(), map.center_of({0, 0}).y() - 0.5 * kCellM, 1e-12);
  EXPECT_EQ(cell(image, {2, 2}), ExploreMapImage::kFree);
  EXPECT_EQ(cell(image, {4, 2}), ExploreMapImage::kFrontier);
  EXPECT_EQ(cell(image, {5, 2}), ExploreMapImage::kUnseen);
  EXPECT_EQ(cell(image, {5, 1}), ExploreMapImage::kObstacle);
  EXPECT_EQ(cell(image, {-1, 3}), ExploreMapImage::kObstacle);
  auto count = [](const ExploreMapImage& i, std::uint8_t v) {
    return std::count(i.cells.begin(), i.cells.end(), v);
  };
  EXPECT_EQ(count(image, ExploreMapImage::kFrontier), 1);
  EXPECT_EQ(count(image, ExploreMapImage::kObstacle), 19);  // 4 sides x 5, less the gap
  EXPECT_EQ(count(image, ExploreMapImage::kFree), 24);
  // A failed goal at the frontier gives it up; a ban 1 m away does not.
  const BannedFrontier here{at({4, 2}), std::nullopt}, far{at({4, 2}) + Point2(0.0, 1.0), {}};
  EXPECT_EQ(cell(explore_map_image(map, std::span(&here, 1), 0.6), {4, 2}),
            ExploreMapImage::kBannedFrontier);
  EXPECT_EQ(cell(explore_map_image(map, std::span(&far, 1), 0.6), {4, 2}),
            ExploreMapImage::kFrontier);
  // A look from inside the room bans the cells no farther than the frontier, not past it.
  const BannedFrontier look{at({4, 2}), at({0, 2})};
  EXPECT_EQ(cell(explore_map_image(map, std::span(&look, 1), 0.6), {4, 2}),
            ExploreMapImage::kBannedFrontier);
}

}  // namespace
}  // namespace cogmap::mapper::nav
