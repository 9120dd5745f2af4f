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

/// Sum of segment lengths of a polyline, metres.
double polyline_length_m(const Polyline& line);

/// Shortest distance from `p` to the finite segment `s`, metres.
double distance_to_segment_m(const Point2& p, const Segment& s);

}  // namespace cogmap::mapper
