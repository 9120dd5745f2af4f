#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "cogmap/sim/world_geometry.h"
#include "world/polygon_ops.h"
#include "world/world_test_support.h"

namespace cogmap::sim {
namespace {

using mapper::Point2;
using mapper::Segment;

using testing::parse;

// True when `surfaces` holds a segment from a to b (in that direction, 1e-9 m).
bool has_segment(const std::vector<Segment>& surfaces, Point2 a, Point2 b) {
  return std::any_of(surfaces.begin(), surfaces.end(), [&](const Segment& s) {
    return (s.a - a).norm() < 1e-9 && (s.b - b).norm() < 1e-9;
  });
}

bool has_point(const std::vector<Point2>& points, Point2 p) {
  return std::any_of(points.begin(), points.end(),
                     [&](const Point2& q) { return (q - p).norm() < 1e-9; });
}

TEST(WorldGeometry, BoxRoomHasExactFaces) {
  const WorldSpec w = parse(
      "name: box\n"
      "walls: {thickness_m: 0.2, polylines: [[[0, 0], [4, 0], [4, 3], [0, 3], [0, 0]]]}\n"
      "obstacles: [{box: {center: [2, 1.5], size: [1, 0.5]}}]\n"
      "start: {x_m: 1, y_m: 1}\n");
  const SonarScene scene = surface_segments(w);
  ASSERT_EQ(scene.surfaces.size(), 12u);
  // Inner faces run counter-clockwise round the room (solid on the right of each).
  EXPECT_TRUE(has_segment(scene.surfaces, {0.1, 0.1}, {3.9, 0.1}));
  EXPECT_TRUE(has_segment(scene.surfaces, {3.9, 0.1}, {3.9, 2.9}));
  EXPECT_TRUE(has_segment(scene.surfaces, {3.9, 2.9}, {0.1, 2.9}));
  EXPECT_TRUE(has_segment(scene.surfaces, {0.1, 2.9}, {0.1, 0.1}));
  // Outer faces run clockwise.
  EXPECT_TRUE(has_segment(scene.surfaces, {4.1, -0.1}, {-0.1, -0.1}));
  EXPECT_TRUE(has_segment(scene.surfaces, {4.1, 3.1}, {4.1, -0.1}));
  EXPECT_TRUE(has_segment(scene.surfaces, {-0.1, 3.1}, {4.1, 3.1}));
  EXPECT_TRUE(has_segment(scene.surfaces, {-0.1, -0.1}, {-0.1, 3.1}));
  // The box outline, clockwise.
  EXPECT_TRUE(has_segment(scene.surfaces, {2.5, 1.75}, {2.5, 1.25}));
  EXPECT_TRUE(has_segment(scene.surfaces, {2.5, 1.25}, {1.5, 1.25}));
  EXPECT_TRUE(has_segment(scene.surfaces, {1.5, 1.25}, {1.5, 1.75}));
  EXPECT_TRUE(has_segment(scene.surfaces, {1.5, 1.75}, {2.5, 1.75}));
  // Convex corners: the building's outside corners and the box corners; the room's inside
  // corners are concave and do not count.
  ASSERT_EQ(scene.corners.size(), 8u);
  for (const Point2& p :
       {Point2{-0.1, -0.1}, Point2{4.1, -0.1}, Point2{4.1, 3.1}, Point2{-0.1, 3.1},
        Point2{1.5, 1.25}, Point2{2.5, 1.25}, Point2{2.5, 1.75}, Point2{1.5, 1.75}}) {
    EXPECT_TRUE(has_point(scene.corners, p)) << p.transpose();
  }
  EXPECT_FALSE(has_point(scene.corners, {0.1, 0.1}));
}

TEST(WorldGeometry, WallMeetingAnotherIsClippedAndItsEndIsTwoCorners) {
  const WorldSpec w = parse(
      "name: t\n"
      "walls: {thickness_m: 0.2, polylines: [[[0, 0], [4, 0]], [[2, 0], [2, 1]]]}\n"
      "start: {x_m: 1, y_m: 1}\n");
  const std::vector<Segment> s = true_surfaces(w);
  // The long wall's upper face is split by the stub; its lower face is whole.
  EXPECT_TRUE(has_segment(s, {0.0, 0.1}, {1.9, 0.1}));
  EXPECT_TRUE(has_segment(s, {2.1, 0.1}, {4.0, 0.1}));
  EXPECT_TRUE(has_segment(s, {4.0, -0.1}, {0.0, -0.1}));
  // The stub's faces start at the long wall's face; its buried end cap is gone.
  EXPECT_TRUE(has_segment(s, {1.9, 0.1}, {1.9, 1.0}));
  EXPECT_TRUE(has_segment(s, {2.1, 1.0}, {2.1, 0.1}));
  EXPECT_TRUE(has_segment(s, {1.9, 1.0}, {2.1, 1.0}));
  EXPECT_EQ(s.size(), 8u);  // long wall: 3 faces + 2 caps; stub: 2 faces + 1 cap
  EXPECT_TRUE(has_segment(s, {4.0, 0.1}, {4.0, -0.1}));
  EXPECT_TRUE(has_segment(s, {0.0, -0.1}, {0.0, 0.1}));
  const WorldSurfaces ws = world_surfaces(w);
  // Free wall ends: both corners of each cap (the stub's top and the long wall's two ends).
  EXPECT_EQ(ws.corners.size(), 6u);
  EXPECT_TRUE(has_point(ws.corners, {1.9, 1.0}));
  EXPECT_TRUE(has_point(ws.corners, {2.1, 1.0}));
  EXPECT_FALSE(has_point(ws.corners, {1.9, 0.1}));  // concave junction
}

TEST(WorldGeometry, SolidPiecesAreClockwiseMitredQuads) {
  const WorldSpec w = parse(
      "name: l\n"
      "walls: {thickness_m: 0.2, polylines: [[[0, 0], [2, 0], [2, 2]]]}\n"
      "obstacles: [{circle: {center: [0.5, 1.5], radius_m: 0.2}},\n"
      "            {polygon: [[1, 1], [1.5, 1], [1.5, 1.5], [1.25, 1.2], [1, 1.5]]}]\n"
      "start: {x_m: 0.6, y_m: 0.7}\n");
  const auto pieces = solid_pieces(w);
  ASSERT_EQ(pieces.size(), 4u);
  EXPECT_LT(geom::signed_area(pieces[0].outline), 0.0);
  // The mitre at (2, 0): outer corner (2.1, -0.1) and inner corner (1.9, 0.1) shared by both.
  EXPECT_TRUE(has_point(pieces[0].outline, {2.1, -0.1}));
  EXPECT_TRUE(has_point(pieces[1].outline, {2.1, -0.1}));
  EXPECT_TRUE(has_point(pieces[0].outline, {1.9, 0.1}));
  EXPECT_TRUE(has_point(pieces[1].outline, {1.9, 0.1}));
  EXPECT_TRUE(pieces[2].circle);
  EXPECT_EQ(pieces[2].outline.size(), static_cast<std::size_t>(kCircleSides));
  EXPECT_FALSE(pieces[3].convex);
  // The notch vertex (1.25, 1.2) of the polygon is reflex: not an echoing corner.
  const WorldSurfaces ws = world_surfaces(w);
  EXPECT_FALSE(has_point(ws.corners, {1.25, 1.2}));
  EXPECT_TRUE(has_point(ws.corners, {1.5, 1.5}));
  EXPECT_TRUE(has_point(ws.corners, {2.1, -0.1}));
}

TEST(PolygonOps, SimplicityAreaAndTriangulation) {
  const mapper::Polyline square{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  EXPECT_DOUBLE_EQ(geom::signed_area(square), 1.0);
  EXPECT_TRUE(geom::is_simple_polygon(square));
  EXPECT_FALSE(geom::is_simple_polygon({{0, 0}, {1, 1}, {1, 0}, {0, 1}}));
  EXPECT_TRUE(geom::point_in_polygon({0.5, 0.5}, square));
  EXPECT_FALSE(geom::point_in_polygon({1.5, 0.5}, square));
  EXPECT_DOUBLE_EQ(geom::distance_to_boundary_m({0.5, 0.25}, square), 0.25);
  const mapper::Polyline notch{{0, 0}, {2, 0}, {2, 2}, {1, 1}, {0, 2}};
  const auto tris = geom::triangulate(notch);
  ASSERT_EQ(tris.size(), 3u);
  double area = 0.0;
  for (const auto& t : tris) {
    EXPECT_GT(geom::signed_area(t), 0.0);
    area += geom::signed_area(t);
  }
  EXPECT_DOUBLE_EQ(area, geom::signed_area(notch));
  const auto t = geom::crossings({-1, 0.5}, {2, 0.5}, square);
  ASSERT_EQ(t.size(), 2u);
  EXPECT_DOUBLE_EQ(t[0], 1.0 / 3.0);
  EXPECT_DOUBLE_EQ(t[1], 2.0 / 3.0);
}

}  // namespace
}  // namespace cogmap::sim
