#include "cogmap/experiments/segment_index.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace cogmap::experiments {
namespace {

using mapper::Point2;

// Caps the bucket array so a stray far-away segment cannot make the index huge.
constexpr double kMaxCells = 4.0e6;
// Segments per cell the cell size aims at, on average over the segments' bounding box: a world
// crowded with small obstacles (each circle is 48 facets) gets smaller cells, so a sight line
// tests tens of segments per cell, not thousands. Ordinary buildings have far fewer segments
// than their area in cells of the given size, and keep it.
constexpr double kSegmentsPerCell = 8.0;

using mapper::cross;

// Sign of the orientation of (a, b, c) with a tolerance relative to the lengths involved.
int orientation(const Point2& a, const Point2& b, const Point2& c) {
  const double v = cross(b - a, c - a);
  const double scale = (b - a).norm() * (c - a).norm();
  const double eps = 1e-12 * std::max(1.0, scale);
  return v > eps ? 1 : (v < -eps ? -1 : 0);
}

bool on_segment(const Point2& a, const Point2& b, const Point2& p) {
  return std::min(a.x(), b.x()) - 1e-12 <= p.x() && p.x() <= std::max(a.x(), b.x()) + 1e-12 &&
         std::min(a.y(), b.y()) - 1e-12 <= p.y() && p.y() <= std::max(a.y(), b.y()) + 1e-12;
}

}  // namespace

bool segments_intersect(const Point2& p1, const Point2& p2, const Point2& q1, const Point2& q2) {
  const int o1 = orientation(p1, p2, q1), o2 = orientation(p1, p2, q2);
  const int o3 = orientation(q1, q2, p1), o4 = orientation(q1, q2, p2);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;  // a proper crossing
  // Touching: an endpoint lies on the other segment.
  if (o1 == 0 && on_segment(p1, p2, q1)) return true;
  if (o2 == 0 && on_segment(p1, p2, q2)) return true;
  if (o3 == 0 && on_segment(q1, q2, p1)) return true;
  if (o4 == 0 && on_segment(q1, q2, p2)) return true;
  return false;
}

SegmentIndex::SegmentIndex(std::span<const mapper::Segment> segments, double cell_m)
    : segments_(segments.begin(), segments.end()), cell_m_(cell_m) {
  if (segments_.empty()) return;
  double min_x = std::numeric_limits<double>::infinity(), min_y = min_x;
  double max_x = -min_x, max_y = -min_x;
  for (const auto& s : segments_) {
    min_x = std::min({min_x, s.a.x(), s.b.x()});
    min_y = std::min({min_y, s.a.y(), s.b.y()});
    max_x = std::max({max_x, s.a.x(), s.b.x()});
    max_y = std::max({max_y, s.a.y(), s.b.y()});
  }
  const double span_x = max_x - min_x, span_y = max_y - min_y;
  const double crowded_cell_m =
      std::sqrt(kSegmentsPerCell * (span_x + cell_m_) * (span_y + cell_m_) /
                static_cast<double>(segments_.size()));
  cell_m_ = std::min(cell_m_, crowded_cell_m);
  if ((span_x / cell_m_ + 2.0) * (span_y / cell_m_ + 2.0) > kMaxCells) {
    cell_m_ = std::sqrt((span_x + 2.0) * (span_y + 2.0) / kMaxCells) + cell_m_;
  }
  origin_x_m_ = min_x - cell_m_;
  origin_y_m_ = min_y - cell_m_;
  width_ = static_cast<int>(std::floor(span_x / cell_m_)) + 3;
  height_ = static_cast<int>(std::floor(span_y / cell_m_)) + 3;
  // A segment goes into every cell it touches: a cell is touched when the segment passes
  // within half a diagonal of its centre (a tiny superset, which keeps queries exact). The
  // (cell, segment) pairs are listed segment by segment, then counted into one flat array by
  // cell (a stable counting sort: each cell lists its segments in increasing order).
  const double reach = cell_m_ * std::sqrt(0.5) * (1.0 + 1e-9) + 1e-12;
  const std::size_t cells = static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_);
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;  // (cell, segment)
  for (std::size_t i = 0; i < segments_.size(); ++i) {
    const auto& s = segments_[i];
    const Cell lo = cell_of({std::min(s.a.x(), s.b.x()), std::min(s.a.y(), s.b.y())});
    const Cell hi = cell_of({std::max(s.a.x(), s.b.x()), std::max(s.a.y(), s.b.y())});
    for (int y = std::max(0, lo.y - 1); y <= std::min(height_ - 1, hi.y + 1); ++y) {
      for (int x = std::max(0, lo.x - 1); x <= std::min(width_ - 1, hi.x + 1); ++x) {
        const Point2 center(origin_x_m_ + (x + 0.5) * cell_m_, origin_y_m_ + (y + 0.5) * cell_m_);
        if (mapper::distance_to_segment_m(center, s) <= reach) {
          pairs.emplace_back(static_cast<std::uint32_t>(static_cast<std::size_t>(y) * width_ + x),
                             static_cast<std::uint32_t>(i));
        }
      }
    }
  }
  bucket_start_.assign(cells + 1, 0);
  for (const auto& [cell, i] : pairs) ++bucket_start_[cell + 1];
  for (std::size_t c = 0; c < cells; ++c) bucket_start_[c + 1] += bucket_start_[c];
  bucket_items_.resize(pairs.size());
  std::vector<std::uint32_t> next(bucket_start_.begin(), bucket_start_.end() - 1);
  for (const auto& [cell, i] : pairs) bucket_items_[next[cell]++] = i;
}

SegmentIndex::Cell SegmentIndex::cell_of(const Point2& p) const {
  return {static_cast<int>(std::floor((p.x() - origin_x_m_) / cell_m_)),
          static_cast<int>(std::floor((p.y() - origin_y_m_) / cell_m_))};
}

std::span<const std::uint32_t> SegmentIndex::bucket(int x, int y) const {
  if (x < 0 || y < 0 || x >= width_ || y >= height_) return {};
  const std::size_t c = static_cast<std::size_t>(y) * width_ + x;
  return {bucket_items_.data() + bucket_start_[c], bucket_items_.data() + bucket_start_[c + 1]};
}

double SegmentIndex::nearest_distance_m(const Point2& p) const {
  double best = std::numeric_limits<double>::infinity();
  if (segments_.empty()) return best;
  const Cell c = cell_of(p);
  const int max_ring = std::max(
      {std::abs(c.x), std::abs(c.x - (width_ - 1)), std::abs(c.y), std::abs(c.y - (height_ - 1))});
  auto visit = [&](int x, int y) {
    for (const std::uint32_t i : bucket(x, y)) {
      best = std::min(best, mapper::distance_to_segment_m(p, segments_[i]));
    }
  };
  for (int r = 0; r <= max_ring; ++r) {
    for (int dy = -r; dy <= r; ++dy) {
      if (dy == -r || dy == r) {
        for (int dx = -r; dx <= r; ++dx) visit(c.x + dx, c.y + dy);
      } else {
        visit(c.x - r, c.y + dy);
        if (r > 0) visit(c.x + r, c.y + dy);
      }
    }
    // Every cell of ring r+1 or beyond lies at least r cells away from p's own cell.
    if (best <= r * cell_m_) break;
  }
  return best;
}

std::optional<Point2> SegmentIndex::nearest_point_within(const Point2& p, double radius_m) const {
  if (segments_.empty() || !(radius_m >= 0.0)) return std::nullopt;
  // As any_within_m: a segment point within radius_m lies in the box p ± radius_m, in a cell
  // that lists its segment.
  const Cell lo = cell_of({p.x() - radius_m, p.y() - radius_m});
  const Cell hi = cell_of({p.x() + radius_m, p.y() + radius_m});
  std::optional<Point2> best;
  double best_m = radius_m;
  for (int y = std::max(0, lo.y); y <= std::min(height_ - 1, hi.y); ++y) {
    for (int x = std::max(0, lo.x); x <= std::min(width_ - 1, hi.x); ++x) {
      for (const std::uint32_t i : bucket(x, y)) {
        const Point2 q = mapper::closest_point_on_segment(p, segments_[i]);
        const double dist_m = (p - q).norm();
        if (dist_m <= best_m) {
          best_m = dist_m;
          best = q;
        }
      }
    }
  }
  return best;
}

bool SegmentIndex::any_within_m(const Point2& p, double radius_m) const {
  if (segments_.empty() || !(radius_m >= 0.0)) return false;
  // A segment point within radius_m of p lies in the box p ± radius_m, and the segment is
  // listed in the cell holding that point; every segment lies inside the grid, so the box is
  // clamped to it.
  const Cell lo = cell_of({p.x() - radius_m, p.y() - radius_m});
  const Cell hi = cell_of({p.x() + radius_m, p.y() + radius_m});
  for (int y = std::max(0, lo.y); y <= std::min(height_ - 1, hi.y); ++y) {
    for (int x = std::max(0, lo.x); x <= std::min(width_ - 1, hi.x); ++x) {
      for (const std::uint32_t i : bucket(x, y)) {
        if (mapper::distance_to_segment_m(p, segments_[i]) <= radius_m) return true;
      }
    }
  }
  return false;
}

bool SegmentIndex::crosses(const Point2& a, const Point2& b, std::size_t i) const {
  return segments_intersect(a, b, segments_[i].a, segments_[i].b);
}

std::size_t SegmentIndex::first_blocker(const Point2& a, const Point2& b,
                                        std::size_t exclude) const {
  if (segments_.empty()) return kNone;
  // Amanatides-Woo traversal of the cells the segment crosses, starting at `a`, so the
  // occluder nearest to `a` (usually in the first cells) ends the walk early.
  const double sx = (a.x() - origin_x_m_) / cell_m_, sy = (a.y() - origin_y_m_) / cell_m_;
  const double ex = (b.x() - origin_x_m_) / cell_m_, ey = (b.y() - origin_y_m_) / cell_m_;
  int ix = static_cast<int>(std::floor(sx)), iy = static_cast<int>(std::floor(sy));
  const int end_x = static_cast<int>(std::floor(ex)), end_y = static_cast<int>(std::floor(ey));
  const double dx = ex - sx, dy = ey - sy;
  const int step_x = dx > 0 ? 1 : -1, step_y = dy > 0 ? 1 : -1;
  const double inf = std::numeric_limits<double>::infinity();
  double t_max_x = dx != 0 ? (step_x > 0 ? ix + 1 - sx : sx - ix) / std::abs(dx) : inf;
  double t_max_y = dy != 0 ? (step_y > 0 ? iy + 1 - sy : sy - iy) / std::abs(dy) : inf;
  const double t_delta_x = dx != 0 ? 1.0 / std::abs(dx) : inf;
  const double t_delta_y = dy != 0 ? 1.0 / std::abs(dy) : inf;
  const int max_steps = std::abs(end_x - ix) + std::abs(end_y - iy) + 2;
  for (int step = 0; step <= max_steps; ++step) {
    for (const std::uint32_t i : bucket(ix, iy)) {
      if (i == exclude) continue;
      if (segments_intersect(a, b, segments_[i].a, segments_[i].b)) return i;
    }
    if (ix == end_x && iy == end_y) break;
    if (t_max_x < t_max_y) {
      ix += step_x;
      t_max_x += t_delta_x;
    } else {
      iy += step_y;
      t_max_y += t_delta_y;
    }
  }
  return kNone;
}

}  // namespace cogmap::experiments
