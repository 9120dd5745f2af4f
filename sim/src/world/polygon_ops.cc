#include "world/polygon_ops.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cogmap::sim::geom {

using mapper::Point2;
using mapper::Polyline;

namespace {

// Orientation tolerance, m²: world coordinates are metres with millimetre detail at best,
// so products below this are collinear for every practical purpose.
constexpr double kCollinearEps = 1e-12;

int orientation(const Point2& a, const Point2& b, const Point2& c) {
  const double v = cross(b - a, c - a);
  if (v > kCollinearEps) return 1;
  if (v < -kCollinearEps) return -1;
  return 0;
}

bool on_segment(const Point2& a, const Point2& b, const Point2& p) {
  return std::min(a.x(), b.x()) - 1e-12 <= p.x() && p.x() <= std::max(a.x(), b.x()) + 1e-12 &&
         std::min(a.y(), b.y()) - 1e-12 <= p.y() && p.y() <= std::max(a.y(), b.y()) + 1e-12;
}

}  // namespace

double signed_area(const Polyline& polygon) {
  double twice = 0.0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    twice += cross(polygon[i], polygon[(i + 1) % polygon.size()]);
  }
  return 0.5 * twice;
}

bool segments_touch(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  const int o1 = orientation(a, b, c), o2 = orientation(a, b, d);
  const int o3 = orientation(c, d, a), o4 = orientation(c, d, b);
  if (o1 != o2 && o3 != o4) return true;
  return (o1 == 0 && on_segment(a, b, c)) || (o2 == 0 && on_segment(a, b, d)) ||
         (o3 == 0 && on_segment(c, d, a)) || (o4 == 0 && on_segment(c, d, b));
}

bool is_simple_polygon(const Polyline& polygon) {
  const std::size_t n = polygon.size();
  if (n < 3) return false;
  for (std::size_t i = 0; i < n; ++i) {
    const Point2& a = polygon[i];
    const Point2& b = polygon[(i + 1) % n];
    for (std::size_t j = i + 1; j < n; ++j) {
      const Point2& c = polygon[j];
      const Point2& d = polygon[(j + 1) % n];
      const bool adjacent = j == i + 1 || (i == 0 && j == n - 1);
      if (!adjacent) {
        if (segments_touch(a, b, c, d)) return false;
        continue;
      }
      // Neighbours share one vertex; they must not fold back over each other.
      const Point2 shared = (j == i + 1) ? b : a;
      const Point2 u = ((j == i + 1) ? a : b) - shared;
      const Point2 v = ((j == i + 1) ? d : c) - shared;
      if (std::abs(cross(u, v)) <= kCollinearEps && u.dot(v) > 0.0) return false;
    }
  }
  return true;
}

bool point_in_polygon(const Point2& p, const Polyline& polygon) {
  bool inside = false;
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const Point2& a = polygon[i];
    const Point2& b = polygon[j];
    if ((a.y() > p.y()) != (b.y() > p.y())) {
      const double x = a.x() + (p.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
      if (p.x() < x) inside = !inside;
    }
  }
  return inside;
}

double distance_to_boundary_m(const Point2& p, const Polyline& polygon) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const mapper::Segment s{polygon[i], polygon[(i + 1) % polygon.size()]};
    best = std::min(best, mapper::distance_to_segment_m(p, s));
  }
  return best;
}

std::vector<double> crossings(const Point2& a, const Point2& b, const Polyline& polygon) {
  std::vector<double> out;
  const Point2 r = b - a;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Point2& c = polygon[i];
    const Point2 s = polygon[(i + 1) % polygon.size()] - c;
    const double denom = cross(r, s);
    if (std::abs(denom) <= kCollinearEps) continue;  // parallel: touching edges never split
    const double t = cross(c - a, s) / denom;
    const double u = cross(c - a, r) / denom;
    if (t > 0.0 && t < 1.0 && u >= 0.0 && u <= 1.0) out.push_back(t);
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<Polyline> triangulate(const Polyline& polygon) {
  std::vector<Point2> ring = polygon;
  if (signed_area(ring) < 0.0) std::reverse(ring.begin(), ring.end());
  std::vector<Polyline> out;
  // Ear clipping is O(n³) in the worst case; world polygons have a handful of vertices.
  while (ring.size() > 3) {
    bool clipped = false;
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const Point2& prev = ring[(i + ring.size() - 1) % ring.size()];
      const Point2& cur = ring[i];
      const Point2& next = ring[(i + 1) % ring.size()];
      if (cross(cur - prev, next - cur) <= 0.0) continue;  // reflex or flat: not an ear
      bool empty = true;
      for (std::size_t k = 0; k < ring.size() && empty; ++k) {
        const Point2& q = ring[k];
        if (q == prev || q == cur || q == next) continue;
        empty = !(cross(cur - prev, q - prev) >= 0.0 && cross(next - cur, q - cur) >= 0.0 &&
                  cross(prev - next, q - next) >= 0.0);
      }
      if (!empty) continue;
      out.push_back({prev, cur, next});
      ring.erase(ring.begin() + static_cast<std::ptrdiff_t>(i));
      clipped = true;
      break;
    }
    if (!clipped) break;  // numerically degenerate remainder: drop it rather than loop forever
  }
  if (ring.size() == 3 && std::abs(signed_area(ring)) > 0.0) out.push_back(ring);
  return out;
}

}  // namespace cogmap::sim::geom
