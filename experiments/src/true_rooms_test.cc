#include "cogmap/experiments/true_rooms.h"

#include <gtest/gtest.h>

#include <cmath>
#include <initializer_list>
#include <limits>
#include <numbers>
#include <vector>

namespace cogmap::experiments {
namespace {

using mapper::Point2;
using mapper::Pose2;
using mapper::Segment;

constexpr double kThickness = 0.12;  // the shipped worlds' walls

// The true surfaces of a wall of thickness kThickness along the polyline, as sim::true_surfaces
// gives them: both faces, kThickness / 2 off the centre line, and a cap at each end of every
// piece (so a door between two pieces is exactly as wide as the gap between their ends).
void add_wall(std::vector<Segment>& out, std::initializer_list<Point2> polyline) {
  const std::vector<Point2> v(polyline);
  for (std::size_t k = 0; k + 1 < v.size(); ++k) {
    const Point2 d = (v[k + 1] - v[k]).normalized();
    const Point2 n = 0.5 * kThickness * Point2(-d.y(), d.x());
    const Point2 la = v[k] + n, lb = v[k + 1] + n, ra = v[k] - n, rb = v[k + 1] - n;
    out.push_back({la, lb});
    out.push_back({rb, ra});
    out.push_back({ra, la});
    out.push_back({lb, rb});
  }
}

TrajectoryRow row_at_xy(double x, double y) {
  TrajectoryRow row;
  row.truth = Pose2{x, y, 0.0};
  row.odometry = row.estimate = Pose2{x, y, 0.0};
  return row;
}

// Rows every 5 cm along the straight path a -> b.
void add_path(std::vector<TrajectoryRow>& rows, Point2 a, Point2 b) {
  const int n = static_cast<int>(std::ceil((b - a).norm() / 0.05));
  for (int k = 0; k <= n; ++k) {
    const Point2 p = a + (b - a) * (static_cast<double>(k) / std::max(n, 1));
    rows.push_back(row_at_xy(p.x(), p.y()));
  }
}

// Two 5 x 5 m rooms side by side (A: x 0-5, B: x 5-10), joined by a door `door_m` wide
// centred at y = 2.5 in the dividing wall x = 5.
std::vector<Segment> two_rooms(double door_m) {
  std::vector<Segment> s;
  add_wall(s, {{0, 0}, {10, 0}, {10, 5}, {0, 5}, {0, 0}});
  add_wall(s, {{5, 0}, {5, 2.5 - door_m / 2}});
  add_wall(s, {{5, 2.5 + door_m / 2}, {5, 5}});
  return s;
}

// worlds/nine_rooms.yaml without its furniture: 3 x 3 rooms of 5 x 5 m, 1 m doors (a snake).
std::vector<Segment> nine_rooms() {
  std::vector<Segment> s;
  add_wall(s, {{0, 0}, {15, 0}, {15, 15}, {0, 15}, {0, 0}});
  for (const double x : {5.0, 10.0}) {
    add_wall(s, {{x, 0}, {x, 2}});
    add_wall(s, {{x, 3}, {x, 7}});
    add_wall(s, {{x, 8}, {x, 12}});
    add_wall(s, {{x, 13}, {x, 15}});
  }
  add_wall(s, {{0, 10}, {12, 10}});
  add_wall(s, {{13, 10}, {15, 10}});
  add_wall(s, {{0, 5}, {2, 5}});
  add_wall(s, {{3, 5}, {15, 5}});
  return s;
}

// A corridor 2 m wide between its wall faces (y 0.06-2.06) and 15 m long, with three 5 x 5 m
// rooms north of it, each entered through a 1 m door in the corridor's north wall.
std::vector<Segment> corridor_with_rooms() {
  std::vector<Segment> s;
  add_wall(s, {{0, 0}, {15, 0}, {15, 7.12}, {0, 7.12}, {0, 0}});
  add_wall(s, {{0, 2.12}, {2, 2.12}});
  add_wall(s, {{3, 2.12}, {7, 2.12}});
  add_wall(s, {{8, 2.12}, {12, 2.12}});
  add_wall(s, {{13, 2.12}, {15, 2.12}});
  add_wall(s, {{5, 2.12}, {5, 7.12}});
  add_wall(s, {{10, 2.12}, {10, 7.12}});
  return s;
}

// Two 5 x 5 m rooms side by side (A: x 0-5, B: x 5-10) with no door between them.
std::vector<Segment> two_rooms_no_door() {
  std::vector<Segment> s;
  add_wall(s, {{0, 0}, {10, 0}, {10, 5}, {0, 5}, {0, 0}});
  add_wall(s, {{5, 0}, {5, 5}});
  return s;
}

// The outline of a solid box obstacle (as sim::true_surfaces gives an obstacle: its four sides,
// no thickness).
void add_box(std::vector<Segment>& out, Point2 lo, Point2 hi) {
  out.push_back({{lo.x(), lo.y()}, {hi.x(), lo.y()}});
  out.push_back({{hi.x(), lo.y()}, {hi.x(), hi.y()}});
  out.push_back({{hi.x(), hi.y()}, {lo.x(), hi.y()}});
  out.push_back({{lo.x(), hi.y()}, {lo.x(), lo.y()}});
}

TEST(TrueRooms, TwoRoomsWithAOneMetreDoorAreTwoRooms) {
  const auto walls = two_rooms(1.0);
  std::vector<TrajectoryRow> in_a;
  add_path(in_a, {1.0, 1.0}, {3.5, 4.0});
  const TrueRooms a = count_true_rooms(walls, in_a);
  EXPECT_EQ(a.total, 2u);
  EXPECT_EQ(a.visited, 1u);

  std::vector<TrajectoryRow> both = in_a;
  add_path(both, {3.5, 4.0}, {2.5, 2.5});
  add_path(both, {2.5, 2.5}, {8.0, 2.5});  // through the door
  const TrueRooms b = count_true_rooms(walls, both);
  EXPECT_EQ(b.total, 2u);
  EXPECT_EQ(b.visited, 2u);
}

TEST(TrueRooms, NoRowsVisitNothing) {
  const TrueRooms r = count_true_rooms(two_rooms(1.0), {});
  EXPECT_EQ(r.total, 2u);
  EXPECT_EQ(r.visited, 0u);
}

TEST(TrueRooms, StandingInTheDoorwayEntersNeitherRoom) {
  // The doorway (and every cell within 0.65 m of a wall) is not room core.
  const std::vector<TrajectoryRow> rows{row_at_xy(5.0, 2.5), row_at_xy(5.5, 2.5)};
  EXPECT_EQ(count_true_rooms(two_rooms(1.0), rows).visited, 0u);
}

TEST(TrueRooms, A1point2MetreDoorStillSeparates) {
  EXPECT_EQ(count_true_rooms(two_rooms(1.2), {}).total, 2u);
}

TEST(TrueRooms, A1point6MetreOpeningMergesTheRooms) {
  // The documented limit: an opening wider than 2 × door_close_radius_m between wall cells
  // (about 1.42 m between the wall faces) stays open, so the two rooms are one.
  std::vector<TrajectoryRow> rows{row_at_xy(2.5, 2.5), row_at_xy(7.5, 2.5)};
  const TrueRooms r = count_true_rooms(two_rooms(1.6), rows);
  EXPECT_EQ(r.total, 1u);
  EXPECT_EQ(r.visited, 1u);
}

TEST(TrueRooms, NineRoomBlockHasNineRooms) {
  std::vector<TrajectoryRow> rows;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) rows.push_back(row_at_xy(2.5 + 5.0 * i, 2.5 + 5.0 * j));
  }
  const TrueRooms all = count_true_rooms(nine_rooms(), rows);
  EXPECT_EQ(all.total, 9u);
  EXPECT_EQ(all.visited, 9u);
  rows.resize(4);
  EXPECT_EQ(count_true_rooms(nine_rooms(), rows).visited, 4u);
}

TEST(TrueRooms, CorridorCountsAsARoom) {
  const auto walls = corridor_with_rooms();
  std::vector<TrajectoryRow> corridor_only;
  add_path(corridor_only, {0.8, 1.06}, {14.2, 1.06});
  const TrueRooms r = count_true_rooms(walls, corridor_only);
  EXPECT_EQ(r.total, 4u);  // the corridor and three rooms
  EXPECT_EQ(r.visited, 1u);

  std::vector<TrajectoryRow> into_middle = corridor_only;
  add_path(into_middle, {7.5, 1.06}, {7.5, 4.6});
  EXPECT_EQ(count_true_rooms(walls, into_middle).visited, 2u);
}

TEST(TrueRooms, SliversSmallerThanTheAreaLimitAreNotRooms) {
  // A closed 2.2 x 2.2 m closet in room A: its core is about 0.66 m square, under 1 m².
  auto walls = two_rooms(1.0);
  add_wall(walls, {{1, 1}, {3.2, 1}, {3.2, 3.2}, {1, 3.2}, {1, 1}});
  EXPECT_EQ(count_true_rooms(walls, {}).total, 2u);
  TrueRoomsOptions small;
  small.min_room_area_m2 = 0.1;
  EXPECT_EQ(count_true_rooms(walls, {}, small).total, 3u);
}

TEST(TrueRooms, RowsWithoutTruthAreIgnored) {
  std::vector<TrajectoryRow> rows{row_at_xy(2.5, 2.5)};
  TrajectoryRow no_truth;  // estimate and odometry in room B, but no true pose
  no_truth.estimate = no_truth.odometry = Pose2{7.5, 2.5, 0.0};
  rows.push_back(no_truth);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  rows.push_back(row_at_xy(nan, 2.5));
  rows.push_back(row_at_xy(1e300, -1e300));  // far outside the raster
  const TrueRooms r = count_true_rooms(two_rooms(1.0), rows);
  EXPECT_EQ(r.total, 2u);
  EXPECT_EQ(r.visited, 1u);
}

TEST(TrueRooms, NoSurfacesIsNoRooms) {
  const std::vector<TrajectoryRow> rows{row_at_xy(1.0, 1.0)};
  const TrueRooms none = count_true_rooms({}, rows);
  EXPECT_EQ(none.total, 0u);
  EXPECT_EQ(none.visited, 0u);

  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<Segment> not_finite{{{nan, 0.0}, {1.0, 1.0}}};
  EXPECT_EQ(count_true_rooms(not_finite, rows).total, 0u);
  const std::vector<Segment> one_wall{{{0.0, 0.0}, {5.0, 0.0}}};
  EXPECT_EQ(count_true_rooms(one_wall, rows).total, 0u);
}

TEST(TrueRooms, RotatedBuildingGivesTheSameCounts) {
  const double a = 37.0 * std::numbers::pi / 180.0;
  const auto turn = [&](const Point2& p) {
    return Point2(3.0 + std::cos(a) * p.x() - std::sin(a) * p.y(),
                  -2.0 + std::sin(a) * p.x() + std::cos(a) * p.y());
  };
  const auto rotated = [&](const std::vector<Segment>& walls) {
    std::vector<Segment> out;
    for (const Segment& s : walls) out.push_back({turn(s.a), turn(s.b)});
    return out;
  };
  const auto rows_at = [&](std::initializer_list<Point2> points) {
    std::vector<TrajectoryRow> rows;
    for (const Point2& p : points) rows.push_back(row_at_xy(turn(p).x(), turn(p).y()));
    return rows;
  };

  const TrueRooms two = count_true_rooms(rotated(two_rooms(1.0)), rows_at({{2.5, 2.5}}));
  EXPECT_EQ(two.total, 2u);
  EXPECT_EQ(two.visited, 1u);
  const TrueRooms nine =
      count_true_rooms(rotated(nine_rooms()), rows_at({{2.5, 2.5}, {7.5, 7.5}, {12.5, 12.5}}));
  EXPECT_EQ(nine.total, 9u);
  EXPECT_EQ(nine.visited, 3u);
  const TrueRooms corridor =
      count_true_rooms(rotated(corridor_with_rooms()), rows_at({{7.5, 1.06}, {2.5, 4.6}}));
  EXPECT_EQ(corridor.total, 4u);
  EXPECT_EQ(corridor.visited, 2u);
  EXPECT_EQ(count_true_rooms(rotated(two_rooms(1.6)), {}).total, 1u);
}

TEST(TrueRooms, AClosedBoxInsideARoomIsNoRoom) {
  // An 8 x 8 m room with a solid 2.5 x 2.5 m box in its middle: the box's inside has a core of
  // about 1.08 x 1.08 m (over 1 m²) but no door, so the robot can never enter it.
  std::vector<Segment> walls;
  add_wall(walls, {{0, 0}, {8, 0}, {8, 8}, {0, 8}, {0, 0}});
  add_box(walls, {2.75, 2.75}, {5.25, 5.25});
  std::vector<TrajectoryRow> rows;
  add_path(rows, {1.0, 1.0}, {7.0, 1.0});
  const TrueRooms r = count_true_rooms(walls, rows);
  EXPECT_EQ(r.total, 1u);
  EXPECT_EQ(r.visited, 1u);
  // Without a true pose there is no start, and every enclosed component counts.
  EXPECT_EQ(count_true_rooms(walls, {}).total, 2u);
}

TEST(TrueRooms, TheEnclosedBlockInsideACorridorLoopIsNoRoom) {
  // As worlds/hallway_loop.yaml: a corridor loop 2.88 m wide between wall faces around a 14 x
  // 14 m block with no door, and a 5 x 5 m office in the block's corner entered from the
  // corridor through a 1 m door (x 5-6 in the block's south wall).
  std::vector<Segment> walls;
  add_wall(walls, {{0, 0}, {20, 0}, {20, 20}, {0, 20}, {0, 0}});
  add_wall(walls, {{6, 3}, {17, 3}, {17, 17}, {3, 17}, {3, 3}, {5, 3}});
  add_wall(walls, {{3, 8}, {8, 8}, {8, 3}});
  std::vector<TrajectoryRow> rows;
  add_path(rows, {1.5, 1.5}, {18.5, 1.5});
  const TrueRooms r = count_true_rooms(walls, rows);
  EXPECT_EQ(r.total, 2u);  // the corridor and the office; not the block
  EXPECT_EQ(r.visited, 1u);
  EXPECT_EQ(count_true_rooms(walls, {}).total, 3u);  // no start: the block counts too
}

TEST(TrueRooms, StartInAWithTheDoorOpenReachesBothRooms) {
  const std::vector<TrajectoryRow> rows{row_at_xy(2.5, 2.5)};
  const TrueRooms r = count_true_rooms(two_rooms(1.0), rows);
  EXPECT_EQ(r.total, 2u);
  EXPECT_EQ(r.visited, 1u);
}

TEST(TrueRooms, WithoutADoorTheOtherRoomIsUnreachable) {
  const auto walls = two_rooms_no_door();
  const TrueRooms from_a = count_true_rooms(walls, std::vector<TrajectoryRow>{row_at_xy(2.5, 2.5)});
  EXPECT_EQ(from_a.total, 1u);
  EXPECT_EQ(from_a.visited, 1u);
  const TrueRooms from_b = count_true_rooms(walls, std::vector<TrajectoryRow>{row_at_xy(7.5, 2.5)});
  EXPECT_EQ(from_b.total, 1u);
  EXPECT_EQ(from_b.visited, 1u);
  EXPECT_EQ(count_true_rooms(walls, {}).total, 2u);  // no start: the fallback counts both
}

TEST(TrueRooms, TheStartIsTheFirstRowWithAFiniteTruePosition) {
  const auto walls = two_rooms_no_door();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  TrajectoryRow no_truth;
  no_truth.estimate = no_truth.odometry = Pose2{2.5, 2.5, 0.0};
  // Starts in B; a later row in A (a teleport) neither makes A reachable nor visits it.
  const std::vector<TrajectoryRow> rows{no_truth, row_at_xy(nan, 2.5), row_at_xy(7.5, 2.5),
                                        row_at_xy(2.5, 2.5)};
  const TrueRooms r = count_true_rooms(walls, rows);
  EXPECT_EQ(r.total, 1u);
  EXPECT_EQ(r.visited, 1u);
}

TEST(TrueRooms, AStartOnAWallCellUsesTheNearestFreeCell) {
  // x = 4.96 lies in the dividing wall (faces at 4.94 and 5.06), nearer room A's side.
  const auto walls = two_rooms_no_door();
  const std::vector<TrajectoryRow> rows{row_at_xy(4.96, 2.5), row_at_xy(2.5, 2.5)};
  const TrueRooms r = count_true_rooms(walls, rows);
  EXPECT_EQ(r.total, 1u);
  EXPECT_EQ(r.visited, 1u);
}

TEST(TrueRooms, AStartOutsideTheBuildingReachesNoRoom) {
  // Far off the raster: clamped to its border, which is the outside.
  const std::vector<TrajectoryRow> rows{row_at_xy(-50.0, 2.5)};
  EXPECT_EQ(count_true_rooms(two_rooms(1.0), rows).total, 0u);
}

TEST(TrueRooms, HugeWorldIsCoarsenedNotExhausted) {
  // A 2 km building at 5 cm would be 1.6e9 cells; it is coarsened to max_cells instead.
  std::vector<Segment> walls;
  add_wall(walls, {{0, 0}, {2000, 0}, {2000, 2000}, {0, 2000}, {0, 0}});
  TrueRoomsOptions small;
  small.max_cells = 100'000;
  const std::vector<TrajectoryRow> rows{row_at_xy(1000.0, 1000.0)};
  // Coarsened to ~6 m cells: far past the 0.1 m at which a door stays open, so flagged...
  const TrueRooms r = count_true_rooms(walls, rows, small);
  EXPECT_FALSE(r.measurable);
  EXPECT_EQ(r.total, 0u);
  // ...while the count itself still works at that scale when asked to.
  TrueRoomsOptions lenient = small;
  lenient.max_measurable_resolution_m = 10.0;
  const TrueRooms coarse = count_true_rooms(walls, rows, lenient);
  EXPECT_TRUE(coarse.measurable);
  EXPECT_EQ(coarse.total, 1u);
  EXPECT_EQ(coarse.visited, 1u);
}

}  // namespace
}  // namespace cogmap::experiments
