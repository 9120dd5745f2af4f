// The end-of-run relaxation of the rooms' positions on exact synthetic walls: a wall seen
// again pulls the later room back by the weights of the pair against the chain, a wall seen
// from both sides does the same less the thickness (which the pairs estimate), a room with no
// wall in common follows its neighbours, and nothing moves for walls too far apart, ambiguous,
// crossing, or not finite.
#include "cogmap/mapper/localization/map_relaxation.h"

#include <gtest/gtest.h>

#include <limits>

namespace cogmap::mapper {
namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

/// A wall piece from a to b seen from the side `normal` points to.
FacingSegment wall(Point2 a, Point2 b, Point2 normal) { return {a, b, normal}; }

RelaxationOptions relaxation_options() {
  RelaxationOptions o;
  o.drift_sd_per_m = 0.016;
  o.min_step_sd_m = 0.02;
  o.offset_sd_m = 0.1;
  o.wall_thickness_m = 0.15;
  o.wall_thickness_sd_m = 0.08;
  o.continuation_gap_m = 1.0;
  o.continuation_weight_m = 0.5;
  o.continuation_angle_sd_rad = 0.0;
  o.max_partners = 32;
  return o;
}

// Room 1 (after 50 m of path: chain sd 0.8 m, weight 1/0.64) draws room 0's north wall, seen
// from the south, 0.3 m too far north over 3.5 m of overlap (weight 3.5 / 0.01 = 350).
TEST(MapRelaxation, AWallSeenAgainPullsTheLaterRoomBackByTheWeights) {
  const std::vector<RelaxationRoom> rooms = {{{wall({0.0, 2.0}, {4.0, 2.0}, {0.0, -1.0})}, 5.0},
                                             {{wall({0.5, 2.3}, {4.5, 2.3}, {0.0, -1.0})}, 50.0}};
  const Relaxation r = relax_room_positions(rooms, relaxation_options());
  ASSERT_EQ(r.shifts.size(), 2u);
  EXPECT_NEAR(r.shifts[0].norm(), 0.0, 1e-6);  // room 0 is where the start pose put it
  const double w_pair = 350.0, w_chain = 1.0 / 0.64;
  EXPECT_NEAR(r.shifts[1].y(), -0.3 * w_pair / (w_pair + w_chain), 1e-6);
  EXPECT_NEAR(r.shifts[1].x(), 0.0, 1e-9);  // along the wall nothing is known
  EXPECT_EQ(r.same_side_pairs, 1);
  EXPECT_EQ(r.two_face_pairs, 0);
  EXPECT_NEAR(r.wall_thickness_m, 0.15, 1e-9);  // no wall seen from both sides: the prior
}

// Pieces of one wall split by a gap (a door) are the same line, not two candidates.
TEST(MapRelaxation, PiecesOfOneWallAreNoAmbiguity) {
  const std::vector<RelaxationRoom> rooms = {
      {{wall({0.0, 2.0}, {2.0, 2.0}, {0.0, -1.0}), wall({3.0, 2.0}, {5.0, 2.0}, {0.0, -1.0})}, 5.0},
      {{wall({0.5, 2.2}, {4.5, 2.2}, {0.0, -1.0})}, 50.0}};
  const Relaxation r = relax_room_positions(rooms, relaxation_options());
  EXPECT_LT(r.shifts[1].y(), -0.19);
  EXPECT_EQ(r.same_side_pairs, 1);
}

// Two parallel walls 0.15 m apart, both seen from the south: the piece between them at 0.1 m
// from one and 0.05 m from the other could be either; it pairs with neither.
TEST(MapRelaxation, AnAmbiguousPieceMovesNothing) {
  const std::vector<RelaxationRoom> rooms = {
      {{wall({0.0, 2.0}, {4.0, 2.0}, {0.0, -1.0}), wall({0.0, 2.15}, {4.0, 2.15}, {0.0, -1.0})},
       5.0},
      {{wall({0.0, 2.1}, {4.0, 2.1}, {0.0, -1.0})}, 50.0}};
  const Relaxation r = relax_room_positions(rooms, relaxation_options());
  EXPECT_EQ(r.same_side_pairs, 0);
  EXPECT_NEAR(r.shifts[1].norm(), 0.0, 1e-9);
}

// Too far apart for the drift between the rooms (0.9 m > the 0.8 m gate), crossing at 20°, or
// on one line but 1.2 m beyond its end (more than the 1 m continuation gap): not the same wall.
TEST(MapRelaxation, WallsBeyondTheGatesAreNotPaired) {
  const RelaxationRoom first = {{wall({0.0, 2.0}, {4.0, 2.0}, {0.0, -1.0})}, 5.0};
  for (const FacingSegment& other :
       {wall({0.0, 2.9}, {4.0, 2.9}, {0.0, -1.0}), wall({0.0, 1.6}, {4.0, 3.06}, {0.0, -1.0}),
        wall({5.2, 2.1}, {8.0, 2.1}, {0.0, -1.0})}) {
    const std::vector<RelaxationRoom> rooms = {first, {{other}, 500.0}};
    const Relaxation r = relax_room_positions(rooms, relaxation_options());
    EXPECT_EQ(r.same_side_pairs + r.two_face_pairs, 0);
    EXPECT_NEAR(r.shifts[1].norm(), 0.0, 1e-9);
  }
  // Two consecutive rooms after 1 m of path (chain sd 0.02 m): 0.3 m is beyond their 0.25 m
  // gate, in the first round and every later one.
  const std::vector<RelaxationRoom> near = {first,
                                            {{wall({0.0, 2.3}, {4.0, 2.3}, {0.0, -1.0})}, 1.0}};
  EXPECT_EQ(relax_room_positions(near, relaxation_options()).same_side_pairs, 0);
}

// Room 1 draws the wall's next run, 0.6 m past the end of room 0's piece (a door between them),
// 0.2 m too far north: the offset at its near end pairs them with 0.5 m of overlap's weight
// (50 against the chain's 1/0.64). Seen from the other side, or 1.2 m on, it would not.
TEST(MapRelaxation, TheNextRunOfAWallLineIsPairedAcrossAGap) {
  const std::vector<RelaxationRoom> rooms = {{{wall({0.0, 2.0}, {4.0, 2.0}, {0.0, -1.0})}, 5.0},
                                             {{wall({4.6, 2.2}, {8.6, 2.2}, {0.0, -1.0})}, 50.0}};
  const Relaxation r = relax_room_positions(rooms, relaxation_options());
  EXPECT_EQ(r.same_side_pairs, 1);
  EXPECT_NEAR(r.shifts[1].y(), -0.2 * 50.0 / (50.0 + 1.0 / 0.64), 1e-9);
  RelaxationOptions off = relaxation_options();
  off.continuation_gap_m = 0.0;
  EXPECT_EQ(relax_room_positions(rooms, off).same_side_pairs, 0);
  const std::vector<RelaxationRoom> other_side = {
      rooms[0], {{wall({4.6, 2.2}, {8.6, 2.2}, {0.0, 1.0})}, 50.0}};
  EXPECT_EQ(relax_room_positions(other_side, relaxation_options()).two_face_pairs, 0);
}

// A corridor's wall carried 10 m past the end of room 0's piece, 0.2 m too far north: paired
// within a 20 m continuation gap, its offset (taken at the near end, 10 m out) weighed as 0.5 m
// of overlap against 0.1² + (10 × 0.04)² m², 2.94 against the chain's 1/0.64; without the
// angle's spread it would weigh 50, and within the old 1 m gap it is no pair at all.
TEST(MapRelaxation, AWallLineCarriedFarPullsByWhatItsDirectionLeavesKnown) {
  const std::vector<RelaxationRoom> rooms = {{{wall({0.0, 2.0}, {4.0, 2.0}, {0.0, -1.0})}, 5.0},
                                             {{wall({14.0, 2.2}, {18.0, 2.2}, {0.0, -1.0})}, 50.0}};
  RelaxationOptions o = relaxation_options();
  o.continuation_gap_m = 20.0;
  o.continuation_angle_sd_rad = 0.04;
  const Relaxation r = relax_room_positions(rooms, o);
  EXPECT_EQ(r.same_side_pairs, 1);
  const double w_pair = 0.5 / (0.01 + 0.4 * 0.4), w_chain = 1.0 / 0.64;
  EXPECT_NEAR(r.shifts[1].y(), -0.2 * w_pair / (w_pair + w_chain), 1e-9);
  EXPECT_NEAR(r.shifts[1].x(), 0.0, 1e-9);
  o.continuation_angle_sd_rad = 0.0;
  EXPECT_NEAR(relax_room_positions(rooms, o).shifts[1].y(), -0.2 * 50.0 / (50.0 + w_chain), 1e-9);
  EXPECT_EQ(relax_room_positions(rooms, relaxation_options()).same_side_pairs, 0);
}

// A robot that stays in one office cuts room after room on the same walls: each is paired
// with its max_partners nearest earlier rooms only (5 here: rooms 1-4 have fewer before them),
// so the work and the problem grow with the rooms, not with their square.
TEST(MapRelaxation, RoomsInOnePlaceArePairedWithTheirNearestFew) {
  std::vector<RelaxationRoom> rooms(100, {{wall({0.0, 2.0}, {4.0, 2.0}, {0.0, -1.0})}, 4.5});
  RelaxationOptions o = relaxation_options();
  o.max_partners = 5;
  const Relaxation r = relax_room_positions(rooms, o);
  EXPECT_EQ(r.same_side_pairs, 1 + 2 + 3 + 4 + 95 * 5);
  for (const Point2& s : r.shifts) EXPECT_NEAR(s.norm(), 0.0, 1e-9);
}

// A wall's south face from room 0, its north face from room 1, drawn 0.2 m too far north; the
// thickness held at 0.12 m (sd 1 mm): room 1 moves back by the pair's weight against the chain.
TEST(MapRelaxation, TheTwoFacesOfAWallPullTheRoomsTogether) {
  RelaxationOptions o = relaxation_options();
  o.wall_thickness_m = 0.12;
  o.wall_thickness_sd_m = 0.001;
  const std::vector<RelaxationRoom> rooms = {{{wall({0.0, 2.0}, {4.0, 2.0}, {0.0, -1.0})}, 5.0},
                                             {{wall({0.0, 2.32}, {4.0, 2.32}, {0.0, 1.0})}, 50.0}};
  const Relaxation r = relax_room_positions(rooms, o);
  EXPECT_EQ(r.two_face_pairs, 1);
  // Rows: y = 0 (w_c), t = 0.12 (w_t), −y + t = 0.32 (w_p); by hand:
  //   (w_c + w_p) y − w_p t = −0.32 w_p,   −w_p y + (w_p + w_t) t = 0.32 w_p + 0.12 w_t.
  const double w_p = 4.0 / (0.01 + 1e-6), w_c = 1.0 / 0.64, w_t = 1e6;
  const double a11 = w_c + w_p, a12 = -w_p, a22 = w_p + w_t;
  const double b1 = -0.32 * w_p, b2 = 0.32 * w_p + 0.12 * w_t;
  const double det = a11 * a22 - a12 * a12;
  EXPECT_NEAR(r.shifts[1].y(), (b1 * a22 - a12 * b2) / det, 1e-9);
  EXPECT_NEAR(r.shifts[1].y(), -0.2, 0.002);
  EXPECT_NEAR(r.wall_thickness_m, (a11 * b2 - a12 * b1) / det, 1e-9);
}

// Room 1 sees the room's south wall (same side as room 0) d = 0.1 m too far north, and the
// north wall's other face: the same-side pair fixes the shift, the two-face pair then measures
// the thickness (0.12 m) against its prior (0.15 ± 0.08 m). Solved by hand (y = room 1's
// shift, t = the thickness; long path: the chain weighs 1/(0.016 · 1000)²):
//   (w_B + w_A + w_c) y − w_A t = −w_B d − w_A (0.12 + d)
//   −w_A y + (w_A + w_t) t      =  w_A (0.12 + d) + w_t · 0.15
TEST(MapRelaxation, TheThicknessIsEstimatedFromTheRunsOwnWalls) {
  const double d = 0.1;
  const std::vector<RelaxationRoom> rooms = {
      {{wall({0.0, -1.0}, {4.0, -1.0}, {0.0, 1.0}), wall({0.0, 2.0}, {4.0, 2.0}, {0.0, -1.0})},
       5.0},
      {{wall({0.0, -1.0 + d}, {4.0, -1.0 + d}, {0.0, 1.0}),
        wall({0.0, 2.12 + d}, {4.0, 2.12 + d}, {0.0, 1.0})},
       1000.0}};
  const Relaxation r = relax_room_positions(rooms, relaxation_options());
  EXPECT_EQ(r.same_side_pairs, 1);
  EXPECT_EQ(r.two_face_pairs, 1);
  const double w_b = 4.0 / 0.01, w_a = 4.0 / (0.01 + 0.0064), w_c = 1.0 / (16.0 * 16.0),
               w_t = 1.0 / 0.0064;
  const double a11 = w_b + w_a + w_c, a12 = -w_a, a22 = w_a + w_t;
  const double b1 = -w_b * d - w_a * (0.12 + d), b2 = w_a * (0.12 + d) + w_t * 0.15;
  const double det = a11 * a22 - a12 * a12;
  EXPECT_NEAR(r.shifts[1].y(), (b1 * a22 - a12 * b2) / det, 1e-6);
  EXPECT_NEAR(r.wall_thickness_m, (a11 * b2 - a12 * b1) / det, 1e-6);
  // Each two-face pair also carries the spread of walls' thicknesses (0.08 m), so one wall
  // moves the estimate from the prior most of the way to what it measured.
  EXPECT_LT(r.wall_thickness_m, 0.14);
}

// Room 2 sees room 0's wall 0.4 m off; room 1 between them saw nothing in common. Equal paths
// make equal chain weights: room 1 takes half of room 2's shift.
TEST(MapRelaxation, ARoomWithoutCommonWallsFollowsItsNeighbours) {
  const std::vector<RelaxationRoom> rooms = {{{wall({0.0, 2.0}, {4.0, 2.0}, {0.0, -1.0})}, 5.0},
                                             {{wall({10.0, 0.0}, {10.0, 4.0}, {-1.0, 0.0})}, 20.0},
                                             {{wall({0.0, 2.4}, {4.0, 2.4}, {0.0, -1.0})}, 20.0}};
  const Relaxation r = relax_room_positions(rooms, relaxation_options());
  EXPECT_EQ(r.same_side_pairs, 1);
  EXPECT_LT(r.shifts[2].y(), -0.35);
  EXPECT_NEAR(r.shifts[1].y(), 0.5 * r.shifts[2].y(), 1e-6);
}

TEST(MapRelaxation, NothingToRelaxAndBadGeometryAreHarmless) {
  EXPECT_TRUE(relax_room_positions({}, relaxation_options()).shifts.empty());
  const std::vector<RelaxationRoom> one = {{{wall({0.0, 2.0}, {4.0, 2.0}, {0.0, -1.0})}, 5.0}};
  EXPECT_EQ(relax_room_positions(one, relaxation_options()).shifts.size(), 1u);
  const std::vector<RelaxationRoom> bad = {
      {{wall({0.0, 2.0}, {4.0, 2.0}, {0.0, -1.0}), wall({kNan, 2.0}, {4.0, 2.0}, {0.0, -1.0}),
        wall({1.0, 1.0}, {1.0, 1.0}, {0.0, -1.0})},
       kNan},
      {{wall({0.0, 2.2}, {4.0, 2.2}, {0.0, -1.0}), wall({0.0, 2.2}, {4.0, kNan}, {0.0, -1.0})},
       -3.0}};
  const Relaxation r = relax_room_positions(bad, relaxation_options());
  ASSERT_EQ(r.shifts.size(), 2u);
  EXPECT_TRUE(r.shifts[1].allFinite());
  EXPECT_EQ(r.same_side_pairs, 1);
  // The good pieces still pair: 0.2 m over 4 m (weight 400) against the chain's least sd
  // (0.02 m, weight 2500: no path is no drift).
  EXPECT_NEAR(r.shifts[1].y(), -0.2 * 400.0 / 2900.0, 1e-9);
}

}  // namespace
}  // namespace cogmap::mapper
