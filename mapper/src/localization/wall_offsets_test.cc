// The translation from wall offsets on exact synthetic rooms: the shift that puts a room's
// walls back onto the same walls mapped before, only along the directions its walls measure,
// and nothing when the walls seen do not agree.
#include "cogmap/mapper/localization/wall_offsets.h"

#include <gtest/gtest.h>

#include <vector>

namespace cogmap::mapper {
namespace {

/// The closed outline of the box [x0, x1] x [y0, y1], moved by `shift`.
Polyline box(double x0, double y0, double x1, double y1, const Point2& shift = {0.0, 0.0}) {
  Polyline p{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}, {x0, y0}};
  for (Point2& q : p) q += shift;
  return p;
}

/// A path through the middle of the box (where the robot was).
std::vector<Point2> inside(double x0, double y0, double x1, double y1) {
  return {{0.5 * (x0 + x1) - 0.5, 0.5 * (y0 + y1)}, {0.5 * (x0 + x1) + 0.5, 0.5 * (y0 + y1)}};
}

TEST(FacingSegments, FaceThePathAndDropShortPieces) {
  const std::vector<Polyline> walls{box(0.0, 0.0, 5.0, 4.0), {{6.0, 0.0}, {6.3, 0.0}}};
  const std::vector<FacingSegment> s = facing_segments(walls, inside(0.0, 0.0, 5.0, 4.0), 0.5);
  ASSERT_EQ(s.size(), 4u);  // the 0.3 m piece is too short
  // Bottom, right, top, left: each normal points into the box.
  EXPECT_EQ(s[0].normal, Point2(0.0, 1.0));
  EXPECT_EQ(s[1].normal, Point2(-1.0, 0.0));
  EXPECT_EQ(s[2].normal, Point2(0.0, -1.0));
  EXPECT_EQ(s[3].normal, Point2(1.0, 0.0));
  EXPECT_TRUE(facing_segments(walls, {}, 0.5).empty());  // no path: no side to tell
}

TEST(WallOffsets, ShiftsARevisitedRoomBackOntoItsFirstVisit) {
  const auto path = inside(0.0, 0.0, 5.0, 4.0);
  const std::vector<Polyline> first{box(0.0, 0.0, 5.0, 4.0)};
  const std::vector<Polyline> again{box(0.0, 0.0, 5.0, 4.0, {0.3, -0.2})};
  const auto reference = facing_segments(first, path, 0.5);
  const auto current = facing_segments(again, path, 0.5);
  const TranslationFix fix = estimate_translation(reference, current, TranslationOptions{});
  ASSERT_TRUE(fix.applied);
  EXPECT_EQ(fix.pairs, 4);
  EXPECT_NEAR(fix.shift.x(), -0.3, 1e-12);
  EXPECT_NEAR(fix.shift.y(), 0.2, 1e-12);
  EXPECT_NEAR(fix.residual_m, 0.0, 1e-12);
  // Overlap along each normal: two 4 m walls measure x, two 5 m walls measure y.
  EXPECT_NEAR(fix.support_m[0], 10.0, 1e-9);
  EXPECT_NEAR(fix.support_m[1], 8.0, 1e-9);
}

// Two corridor walls along x fix the lateral position only: the shift along the corridor is
// left alone (nothing measures it), whatever the drift along it.
TEST(WallOffsets, CorrectsOnlyTheDirectionTheWallsMeasure) {
  const std::vector<Point2> path{{0.0, 1.2}, {8.0, 1.2}};
  const std::vector<Polyline> first{{{0.0, 0.0}, {8.0, 0.0}}, {{0.0, 2.4}, {8.0, 2.4}}};
  const std::vector<Polyline> again{{{0.5, 0.25}, {8.5, 0.25}}, {{0.5, 2.65}, {8.5, 2.65}}};
  const TranslationFix fix = estimate_translation(
      facing_segments(first, path, 0.5),
      facing_segments(again, std::vector<Point2>{{0.5, 1.45}, {8.5, 1.45}}, 0.5),
      TranslationOptions{});
  ASSERT_TRUE(fix.applied);
  EXPECT_NEAR(fix.shift.y(), -0.25, 1e-12);
  EXPECT_NEAR(fix.shift.x(), 0.0, 1e-12);
  EXPECT_NEAR(fix.support_m[1], 0.0, 1e-12);
}

// A wall seen from the next room is the same line's other face (0.12 m thick): never a pair.
TEST(WallOffsets, NeverPairsTheOtherFaceOfAWall) {
  const std::vector<Polyline> south_face{{{0.0, 0.0}, {5.0, 0.0}}};
  const std::vector<Polyline> north_face{{{0.0, 0.12}, {5.0, 0.12}}};
  const TranslationFix fix = estimate_translation(
      facing_segments(south_face, std::vector<Point2>{{2.5, -2.0}}, 0.5),
      facing_segments(north_face, std::vector<Point2>{{2.5, 2.0}}, 0.5), TranslationOptions{});
  EXPECT_EQ(fix.pairs, 0);
  EXPECT_FALSE(fix.applied);
  EXPECT_EQ(fix.shift, Point2(0.0, 0.0));
}

TEST(WallOffsets, LeavesAShiftBeyondTheGateAlone) {
  const auto path = inside(0.0, 0.0, 5.0, 4.0);
  const std::vector<Polyline> first{box(0.0, 0.0, 5.0, 4.0)};
  const std::vector<Polyline> again{box(0.0, 0.0, 5.0, 4.0, {1.2, 0.0})};
  const TranslationFix fix = estimate_translation(facing_segments(first, path, 0.5),
                                                  facing_segments(again, path, 0.5), {});
  // The walls along y are 1.2 m off (beyond max_offset_m 1.0) and make no pair; the walls
  // along x measure y (no shift needed) and nothing measures x: the 1.2 m is not corrected.
  EXPECT_EQ(fix.pairs, 2);
  EXPECT_TRUE(fix.applied);
  EXPECT_EQ(fix.shift.x(), 0.0);
  EXPECT_NEAR(fix.shift.y(), 0.0, 1e-12);
  EXPECT_NEAR(fix.support_m[1], 0.0, 1e-12);
}

// Walls that disagree (one piece 0.3 m one way, its neighbour 0.3 m the other) leave a 0.3 m
// residual: the room is not moved.
TEST(WallOffsets, RefusesWallsThatDisagree) {
  const std::vector<Point2> path{{5.0, 2.0}};
  const std::vector<Polyline> first{{{0.0, 0.0}, {4.0, 0.0}}, {{6.0, 0.0}, {10.0, 0.0}}};
  const std::vector<Polyline> again{{{0.0, 0.3}, {4.0, 0.3}}, {{6.0, -0.3}, {10.0, -0.3}}};
  const TranslationFix fix = estimate_translation(facing_segments(first, path, 0.5),
                                                  facing_segments(again, path, 0.5), {});
  EXPECT_EQ(fix.pairs, 2);
  EXPECT_NEAR(fix.residual_m, 0.3, 1e-12);
  EXPECT_FALSE(fix.applied);
  EXPECT_EQ(fix.shift, Point2(0.0, 0.0));
}

// Pieces turned further than max_angle_deg are not the same wall.
TEST(WallOffsets, PairsOnlyParallelWalls) {
  const std::vector<Point2> path{{2.5, 2.0}};
  const std::vector<Polyline> first{{{0.0, 0.0}, {5.0, 0.0}}};
  const std::vector<Polyline> turned{{{0.0, 0.1}, {5.0, 0.1 + 5.0 * 0.1051}}};  // 6°
  const std::vector<Polyline> slight{{{0.0, 0.1}, {5.0, 0.1 + 5.0 * 0.0699}}};  // 4°
  TranslationOptions o;
  o.min_support_m = 0.0;
  EXPECT_EQ(
      estimate_translation(facing_segments(first, path, 0.5), facing_segments(turned, path, 0.5), o)
          .pairs,
      0);
  EXPECT_EQ(
      estimate_translation(facing_segments(first, path, 0.5), facing_segments(slight, path, 0.5), o)
          .pairs,
      1);
}

}  // namespace
}  // namespace cogmap::mapper
