#pragma once
/// Small planar geometry on closed polygons (last vertex not repeated), shared by world
/// validation, surface extraction and the Box2D body builder.

#include <vector>

#include "cogmap/mapper/seam/geometry.h"

namespace cogmap::sim::geom {

/// z of the 2D cross product a x b (the mapper's own).
using mapper::cross;

/// Signed area of a closed polygon, m²: positive when counter-clockwise.
double signed_area(const mapper::Polyline& polygon);

/// True when the closed segments [a, b] and [c, d] share at least one point.
bool segments_touch(const mapper::Point2& a, const mapper::Point2& b, const mapper::Point2& c,
                    const mapper::Point2& d);

/// True when no two edges of the closed polygon meet except neighbours at their shared vertex.
bool is_simple_polygon(const mapper::Polyline& polygon);

/// True when `p` lies inside the closed polygon (even-odd rule; boundary points are ambiguous).
bool point_in_polygon(const mapper::Point2& p, const mapper::Polyline& polygon);

/// Distance from `p` to the polygon's boundary, metres.
double distance_to_boundary_m(const mapper::Point2& p, const mapper::Polyline& polygon);

/// Parameters t in (0, 1) where the segment a + t (b - a) crosses an edge of the polygon,
/// sorted ascending (duplicates possible).
std::vector<double> crossings(const mapper::Point2& a, const mapper::Point2& b,
                              const mapper::Polyline& polygon);

/// Splits a simple polygon into triangles (ear clipping); each triangle counter-clockwise.
std::vector<mapper::Polyline> triangulate(const mapper::Polyline& polygon);

}  // namespace cogmap::sim::geom
