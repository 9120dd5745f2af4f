#include "nav/explore_map.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

namespace cogmap::mapper::nav {
namespace {

constexpr double kGrowMarginM = 8.0;  // grow in big steps: each growth copies the map

}  // namespace

ExploreMap::ExploreMap(const ExploreMapOptions& options) : options_(options) {
  // Every walk over cells steps by a fraction of a cell: a zero or negative size would never end.
  if (!(options_.cell_m >= 0.01)) options_.cell_m = 0.01;
}

ExploreMap::Cell ExploreMap::cell_of(const Point2& p) const {
  // Far-off or non-finite points map to a cell far outside any map (never inside()), without
  // an out-of-range float-to-int conversion.
  const auto index = [&](double v, double origin) {
    const double c = std::floor((v - origin) / options_.cell_m);
    return std::isfinite(c) ? static_cast<int>(std::clamp(c, -1e9, 1e9)) : -1000000000;
  };
  return {index(p.x(), origin_x_m_), index(p.y(), origin_y_m_)};
}

Point2 ExploreMap::center_of(Cell c) const {
  return {origin_x_m_ + (c.x + 0.5) * options_.cell_m, origin_y_m_ + (c.y + 0.5) * options_.cell_m};
}

bool ExploreMap::cover(const Point2& lo, const Point2& hi) {
  if (!lo.allFinite() || !hi.allFinite()) return false;
  if (width_ > 0) {
    const Cell a = cell_of(lo), b = cell_of(hi);
    if (inside(a) && inside(b)) return true;
  }
  const double cell = options_.cell_m;
  double new_lo_x = lo.x() - kGrowMarginM, new_lo_y = lo.y() - kGrowMarginM;
  double new_hi_x = hi.x() + kGrowMarginM, new_hi_y = hi.y() + kGrowMarginM;
  if (width_ > 0) {
    new_lo_x = std::min(new_lo_x, origin_x_m_);
    new_lo_y = std::min(new_lo_y, origin_y_m_);
    new_hi_x = std::max(new_hi_x, origin_x_m_ + width_ * cell);
    new_hi_y = std::max(new_hi_y, origin_y_m_ + height_ * cell);
  }
  if (new_hi_x - new_lo_x > options_.max_span_m || new_hi_y - new_lo_y > options_.max_span_m) {
    return false;
  }
  // Keep the lattice: the new origin lies a whole number of cells from the old one.
  int shift_x = 0, shift_y = 0;
  if (width_ > 0) {
    shift_x = static_cast<int>(std::ceil((origin_x_m_ - new_lo_x) / cell));
    shift_y = static_cast<int>(std::ceil((origin_y_m_ - new_lo_y) / cell));
    new_lo_x = origin_x_m_ - shift_x * cell;
    new_lo_y = origin_y_m_ - shift_y * cell;
  }
  const int w = static_cast<int>(std::ceil((new_hi_x - new_lo_x) / cell)) + 1;
  const int h = static_cast<int>(std::ceil((new_hi_y - new_lo_y) / cell)) + 1;
  std::vector<float> hits(static_cast<std::size_t>(w) * h, 0.0f), misses(hits.size(), 0.0f);
  std::vector<std::uint8_t> seen(hits.size(), 0), traversed(hits.size(), 0);
  for (int y = 0; y < height_; ++y) {
    for (int x = 0; x < width_; ++x) {
      const std::size_t from = static_cast<std::size_t>(y) * width_ + x;
      const std::size_t to = static_cast<std::size_t>(y + shift_y) * w + (x + shift_x);
      hits[to] = hits_[from];
      misses[to] = misses_[from];
      seen[to] = seen_[from];
      traversed[to] = traversed_[from];
    }
  }
  origin_x_m_ = new_lo_x;
  origin_y_m_ = new_lo_y;
  width_ = w;
  height_ = h;
  hits_ = std::move(hits);
  misses_ = std::move(misses);
  seen_ = std::move(seen);
  traversed_ = std::move(traversed);
  return true;
}

void ExploreMap::add(std::vector<float>& weights, std::size_t i, double distance_m) {
  const double ratio = options_.weight_range_m / std::max(distance_m, 1e-3);
  weights[i] += static_cast<float>(std::min(options_.max_weight, ratio * ratio));
  if (weights[i] >= options_.weight_cap) {
    hits_[i] *= 0.5f;
    misses_[i] *= 0.5f;
  }
}

void ExploreMap::mark_body(const Point2& center, double radius_m) {
  const Point2 r(radius_m, radius_m);
  if (!cover(center - r, center + r)) return;
  const Cell lo = cell_of(center - r), hi = cell_of(center + r);
  for (int y = lo.y; y <= hi.y; ++y) {
    for (int x = lo.x; x <= hi.x; ++x) {
      if ((center_of({x, y}) - center).norm() > radius_m) continue;
      const std::size_t i = index({x, y});
      mark_seen(i);
      hits_[i] = 0.0f;  // the robot stands there: nothing is
      misses_[i] = static_cast<float>(options_.weight_cap) * 0.5f;
    }
  }
}

void ExploreMap::mark_traversed(const Point2& center) {
  if (!cover(center, center)) return;
  traversed_[index(cell_of(center))] = 1;
}

void ExploreMap::add_frame(const SensorFrame& frame, const Pose2& pose,
                           const RobotGeometry& robot) {
  for (const SonarReading& r : frame.sonar) {
    if (r.index < 0 || static_cast<std::size_t>(r.index) >= robot.sonars.size()) continue;
    if (!std::isfinite(r.range_m) || r.range_m < robot.sonar_min_range_m) continue;
    // A reading beyond the sonar's range is no echo: it proves only that nothing answered.
    const bool echo = r.echo && r.range_m <= robot.sonar_max_range_m;
    const SonarMount& m = robot.sonars[static_cast<std::size_t>(r.index)];
    ++readings_;
    sweep(pose.transform(Point2(m.x_m, m.y_m)), pose.theta_rad + m.heading_rad,
          echo ? std::optional<double>(r.range_m) : std::nullopt, robot);
  }
  mark_body(pose.translation(), 0.5 * robot.width_m);
  mark_traversed(pose.translation());
}

bool ExploreMap::occluded(const Point2& origin, Cell target) const {
  const Point2 to = center_of(target);
  const double len = (to - origin).norm();
  const double step = 0.5 * options_.cell_m;
  for (double t = step; t < len; t += step) {
    const Cell c = cell_of(origin + (t / len) * (to - origin));
    if (c.x == target.x && c.y == target.y) return false;
    if (occupied(c)) return true;
  }
  return false;
}

void ExploreMap::sweep(const Point2& origin, double axis_rad, std::optional<double> echo_m,
                       const RobotGeometry& robot) {
  const ExploreMapOptions& o = options_;
  const double cell = o.cell_m;
  const double range_m = echo_m.value_or(0.0);
  const double hits_to = echo_m && range_m <= o.occupancy_max_range_m ? range_m + cell : 0.0;
  const double free_to =
      echo_m ? std::min(range_m - o.free_margin_m, std::max(o.free_sense_m, hits_to))
             : o.no_echo_free_m;
  const double reach = std::max(hits_to, free_to);
  if (reach <= 0.0) return;
  const Point2 r(reach, reach);
  if (!cover(origin - r, origin + r)) return;
  const Point2 axis(std::cos(axis_rad), std::sin(axis_rad));
  const double deg = std::numbers::pi / 180.0;
  const double cos_half =
      std::cos(std::min(o.half_angle_deg * deg, 0.5 * robot.sonar_beam_width_rad));
  const double tan_hit = std::tan(o.hit_half_angle_deg * deg);
  const double hit_half_width = std::max(0.5 * cell, range_m * tan_hit);
  const Cell lo = cell_of(origin - r), hi = cell_of(origin + r);
  // The score before this beam decides occlusion, so collect first and apply after.
  swept_.clear();
  hit_.clear();
  for (int y = lo.y; y <= hi.y; ++y) {
    for (int x = lo.x; x <= hi.x; ++x) {
      const Point2 d = center_of({x, y}) - origin;
      const double dist = d.norm();
      const double along = d.dot(axis);
      if (along <= 0.0 || dist > reach) continue;
      const double lateral = std::abs(axis.x() * d.y() - axis.y() * d.x());
      if (hits_to > 0.0 && std::abs(along - range_m) <= 0.5 * cell && lateral <= hit_half_width) {
        hit_.push_back({x, y});  // the echo's arc, near the axis
        continue;
      }
      if (dist < free_to && along >= cos_half * dist && !occluded(origin, {x, y})) {
        swept_.push_back({x, y});
      }
    }
  }
  for (const Cell c : swept_) {
    const std::size_t i = index(c);
    add(misses_, i, (center_of(c) - origin).norm());
    if ((center_of(c) - origin).norm() <= o.free_sense_m) mark_seen(i);
  }
  for (const Cell c : hit_) {
    const std::size_t i = index(c);
    add(hits_, i, range_m);
    if (range_m <= o.wall_sense_m) mark_seen(i);
  }
}

}  // namespace cogmap::mapper::nav
