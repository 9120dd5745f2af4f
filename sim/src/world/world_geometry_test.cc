#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
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

// A pile of pieces on one spot, each kind of overlap the clipping meets: walls laid 13 mm
// apart along one line (their long faces collinear), walls crossing at one point, boxes and
// circles strewn over them and a concave polygon. What is kept must be exactly the parts of the
// pieces' edges that lie inside no other piece: held point by point against the pieces
// themselves, so it fails for a clip that buries too much or too little (the convex pieces are
// cut by intervals, the concave one point by point; docs/reliability.md, "Worlds").
TEST(WorldGeometry, APileKeepsExactlyTheEdgesInsideNoOtherPiece) {
  std::string yaml =
      "name: pile\n"
      "walls:\n"
      "  thickness_m: 0.1\n"
      "  polylines:\n";
  for (int i = 0; i < 60; ++i) {  // collinear: y 5 ± 0.05, x from 0.013 i
    yaml += "    - [[" + std::to_string(0.013 * i) + ", 5], [" + std::to_string(3 + 0.013 * i) +
            ", 5]]\n";
  }
  for (int i = 0; i < 12; ++i) {  // a star through (6, 5)
    const double a = 3.14159265358979 * i / 12.0;
    yaml += "    - [[" + std::to_string(6 + 1.5 * std::cos(a)) + ", " +
            std::to_string(5 + 1.5 * std::sin(a)) + "], [" + std::to_string(6 - 1.5 * std::cos(a)) +
            ", " + std::to_string(5 - 1.5 * std::sin(a)) + "]]\n";
  }
  yaml += "obstacles:\n";
  unsigned state = 12345u;  // a fixed sequence of positions
  const auto next = [&state] {
    state = state * 1664525u + 1013904223u;
    return (state >> 8) / 16777216.0;
  };
  for (int i = 0; i < 16; ++i) {
    const double x = 0.5 + 6.5 * next(), y = 4.0 + 2.0 * next();
    if (i % 2 == 0) {
      yaml += "  - {box: {center: [" + std::to_string(x) + ", " + std::to_string(y) +
              "], size: [0.6, 0.3], angle_deg: " + std::to_string(90.0 * next()) + "}}\n";
    } else {
      yaml += "  - {circle: {center: [" + std::to_string(x) + ", " + std::to_string(y) +
              "], radius_m: 0.25}}\n";
    }
  }
  yaml += "  - {polygon: [[1, 4.6], [2.5, 4.6], [2.5, 5.4], [2.0, 5.4], [2.0, 4.9], [1, 4.9]]}\n";
  yaml += "start: {x_m: 9, y_m: 9}\n";
  const WorldSpec w = parse(yaml);
  const std::vector<SolidPiece> pieces = solid_pieces(w);
  const std::vector<Segment> surfaces = world_surfaces(w).surfaces;
  ASSERT_EQ(pieces.size(), 60u + 12u + 17u);
  // Inside a piece by more than `margin` (outside the reach of rounding), or outside it by more.
  const auto inside_by = [](const Point2& p, const mapper::Polyline& outline, double margin) {
    return geom::point_in_polygon(p, outline) && geom::distance_to_boundary_m(p, outline) > margin;
  };
  const auto outside_by = [](const Point2& p, const mapper::Polyline& outline, double margin) {
    return !geom::point_in_polygon(p, outline) && geom::distance_to_boundary_m(p, outline) > margin;
  };
  // Nothing kept lies inside a piece.
  for (const Segment& s : surfaces) {
    for (const double t : {0.25, 0.5, 0.75}) {
      const Point2 p = s.a + t * (s.b - s.a);
      for (const SolidPiece& piece : pieces) {
        ASSERT_FALSE(inside_by(p, piece.outline, 1e-7)) << p.transpose();
      }
    }
  }
  // Every edge point clear of every other piece is kept (straight walls: every quad edge is a
  // candidate; a circle's or polygon's edges too).
  int checked = 0;
  for (std::size_t owner = 0; owner < pieces.size(); ++owner) {
    const mapper::Polyline& o = pieces[owner].outline;
    for (std::size_t e = 0; e < o.size(); ++e) {
      const Point2 a = o[e], b = o[(e + 1) % o.size()];
      for (int k = 0; k < 9; ++k) {
        const Point2 p = a + ((k + 0.5) / 9.0) * (b - a);
        bool clear = true;
        for (std::size_t i = 0; i < pieces.size() && clear; ++i) {
          if (i != owner && !outside_by(p, pieces[i].outline, 1e-7)) clear = false;
        }
        if (!clear) continue;
        ++checked;
        const bool kept = std::any_of(surfaces.begin(), surfaces.end(), [&](const Segment& s) {
          return mapper::distance_to_segment_m(p, s) < 1e-9;
        });
        ASSERT_TRUE(kept) << "piece " << owner << " edge " << e << " at " << p.transpose();
      }
    }
  }
  EXPECT_GT(checked, 1000);  // the clear points are most of the star's and the clutter's edges

  // A face lying on another piece's boundary is not inside it: three walls laid along one line
  // keep their six long faces whole (the points checked above are clear of every boundary).
  const WorldSpec line = parse(
      "name: line\n"
      "walls: {thickness_m: 0.1, polylines: [[[0, 5], [3, 5]], [[0.013, 5], [3.013, 5]],"
      " [[0.026, 5], [3.026, 5]]]}\n"
      "start: {x_m: 9, y_m: 9}\n");
  const std::vector<Segment> faces = world_surfaces(line).surfaces;
  for (const double x0 : {0.0, 0.013, 0.026}) {
    EXPECT_TRUE(has_segment(faces, {x0, 5.05}, {x0 + 3, 5.05})) << x0;
    EXPECT_TRUE(has_segment(faces, {x0 + 3, 4.95}, {x0, 4.95})) << x0;
  }
}

}  // namespace
}  // namespace cogmap::sim
