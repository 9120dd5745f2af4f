#pragma once
// Synthetic rooms for the localisation tests and benchmark: noisy wall chains plus clutter.

#include <cmath>
#include <numbers>
#include <random>
#include <utility>
#include <vector>

#include "cogmap/mapper/seam/geometry.h"

namespace cogmap::mapper::testing {

/// Turns the corner list of a closed room into wall chains: each side is cut into pieces of
/// 0.3-1.0 m, each piece's direction gets N(0, noise) added, then everything is rotated by
/// `rotation_rad` about the origin. `clutter_fraction` of extra segments (0.1-0.3 m, uniform
/// random direction) are scattered inside the room's bounding box as separate polylines.
inline std::vector<Polyline> noisy_room(const std::vector<Point2>& corners, double rotation_rad,
                                        double noise_rad, double clutter_fraction,
                                        std::mt19937_64& rng) {
  std::normal_distribution<double> noise(0.0, noise_rad);
  std::uniform_real_distribution<double> piece(0.3, 1.0), unit(0.0, 1.0);
  const double c = std::cos(rotation_rad), s = std::sin(rotation_rad);
  auto rotate = [&](const Point2& p) {
    return Point2{c * p.x() - s * p.y(), s * p.x() + c * p.y()};
  };
  std::vector<Polyline> out;
  Polyline chain{rotate(corners[0])};
  Point2 cursor = corners[0];
  int segments = 0;
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const Point2 a = corners[i], b = corners[(i + 1) % corners.size()];
    const double side_m = (b - a).norm();
    const double dir = std::atan2(b.y() - a.y(), b.x() - a.x());
    double done_m = 0.0;
    while (done_m < side_m - 1e-9) {
      const double len = std::min(piece(rng), side_m - done_m);
      const double d = dir + noise(rng);
      cursor += len * Point2{std::cos(d), std::sin(d)};
      chain.push_back(rotate(cursor));
      done_m += len;
      ++segments;
    }
    cursor = b;  // restart each side at the true corner so noise does not accumulate
    chain.push_back(rotate(cursor));
  }
  out.push_back(chain);
  double min_x = 1e9, min_y = 1e9, max_x = -1e9, max_y = -1e9;
  for (const Point2& p : corners) {
    min_x = std::min(min_x, p.x());
    max_x = std::max(max_x, p.x());
    min_y = std::min(min_y, p.y());
    max_y = std::max(max_y, p.y());
  }
  const int clutter = static_cast<int>(std::lround(clutter_fraction * segments));
  std::uniform_real_distribution<double> angle(-std::numbers::pi, std::numbers::pi),
      length(0.1, 0.3);
  for (int k = 0; k < clutter; ++k) {
    const Point2 p{min_x + unit(rng) * (max_x - min_x), min_y + unit(rng) * (max_y - min_y)};
    const double a = angle(rng), len = length(rng);
    out.push_back({rotate(p), rotate(p + len * Point2{std::cos(a), std::sin(a)})});
  }
  return out;
}

/// A 5 x 4 m rectangular room.
inline std::vector<Point2> rectangle_room() { return {{0, 0}, {5, 0}, {5, 4}, {0, 4}}; }

/// A 6 x 5 m L-shaped room (a 2 x 2 m corner cut out).
inline std::vector<Point2> l_shaped_room() {
  return {{0, 0}, {6, 0}, {6, 3}, {4, 3}, {4, 5}, {0, 5}};
}

/// The test scene: the rectangular room and, beside it, the L-shaped room, as one ASR's walls
/// (about 40 m of wall in ~60 pieces, plus clutter), rotated by `rotation_rad` about the origin.
inline std::vector<Polyline> noisy_scene(double rotation_rad, double noise_rad,
                                         double clutter_fraction, std::mt19937_64& rng) {
  std::vector<Polyline> out =
      noisy_room(rectangle_room(), rotation_rad, noise_rad, clutter_fraction, rng);
  std::vector<Point2> l_room = l_shaped_room();
  for (Point2& p : l_room) p.x() += 6.0;
  for (Polyline& line : noisy_room(l_room, rotation_rad, noise_rad, clutter_fraction, rng)) {
    out.push_back(std::move(line));
  }
  return out;
}

}  // namespace cogmap::mapper::testing
