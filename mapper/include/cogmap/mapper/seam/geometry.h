#pragma once
/// The geometry vocabulary shared by every module: points, segments and polylines in metres.

#include <Eigen/Core>
#include <vector>

namespace cogmap::mapper {

/// A point in metres (x forward/east, y left/north; REP-103).
using Point2 = Eigen::Vector2d;

/// A straight wall piece from `a` to `b`, metres.
struct Segment {
  Point2 a{0.0, 0.0};
  Point2 b{0.0, 0.0};
  double length_m() const { return (b - a).norm(); }
};

/// An ordered chain of vertices, metres; consecutive vertices form the wall.
using Polyline = std::vector<Point2>;

/// The z component of a × b: positive when b lies anticlockwise of a; |a × b| / |a| is b's
/// distance from the line along a.
inline double cross(const Point2& a, const Point2& b) { return a.x() * b.y() - a.y() * b.x(); }

/// Sum of segment lengths of a polyline, metres.
double polyline_length_m(const Polyline& line);

/// The point of the finite segment `s` nearest to `p` (the foot of the perpendicular, or the
/// nearer end).
Point2 closest_point_on_segment(const Point2& p, const Segment& s);

/// Shortest distance from `p` to the finite segment `s`, metres.
double distance_to_segment_m(const Point2& p, const Segment& s);

}  // namespace cogmap::mapper
