#pragma once
/// The true geometry of a world: the solid pieces physics collides with, and the surfaces the
/// sonar can hit and the metrics compare maps against (docs/formats.md "Definitions": a wall of
/// thickness t is a surface on both sides of its polyline, t/2 away; an obstacle's surface is
/// its outline).

#include <vector>

#include "cogmap/mapper/seam/geometry.h"
#include "cogmap/sim/sonar_model.h"
#include "cogmap/sim/world_spec.h"

namespace cogmap::sim {

/// Sides of the regular polygon that stands in for a circle's surface.
inline constexpr int kCircleSides = 48;

/// One solid piece: a closed polygon (last vertex not repeated), clockwise (solid on the right
/// of every edge), world frame. Walls give one convex quad per polyline segment, mitred at
/// joints so neighbouring quads share an edge; obstacles give their outline.
struct SolidPiece {
  mapper::Polyline outline;
  bool convex = true;   ///< false only for non-convex polygon obstacles
  bool circle = false;  ///< the outline approximates a circle (physics uses a true circle)
  mapper::Point2 circle_center{0.0, 0.0};  ///< valid when circle
  double circle_radius_m = 0.0;            ///< valid when circle
};

/// Every solid piece of the world, walls first, in file order.
std::vector<SolidPiece> solid_pieces(const WorldSpec& world);

/// The visible surfaces and the convex corners of a world.
struct WorldSurfaces {
  /// Every surface segment that bounds free space, oriented with the solid on its right;
  /// parts buried inside another piece (a wall's end inside the wall it meets) are removed.
  std::vector<mapper::Segment> surfaces;
  /// Convex vertices of those surfaces (wall ends, door jambs, box corners, circle facets):
  /// the edges that echo sonar from any angle.
  std::vector<mapper::Point2> corners;
  /// Material of each surface (index into WorldSpec::materials), parallel to `surfaces`.
  std::vector<int> surface_material;
};

/// Computes the surfaces and corners of a world (O(surfaces x pieces); done once per run).
WorldSurfaces world_surfaces(const WorldSpec& world);

/// What the sonar model can hit: world_surfaces() as a SonarScene.
SonarScene surface_segments(const WorldSpec& world);

/// The true surfaces alone, for metrics and figures.
std::vector<mapper::Segment> true_surfaces(const WorldSpec& world);

}  // namespace cogmap::sim
