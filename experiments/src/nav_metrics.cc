#include "cogmap/experiments/nav_metrics.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>

#include "cogmap/mapper/seam/geometry.h"

namespace cogmap::experiments {
namespace {

using mapper::Point2;

double point_segment_m(const Point2& p, const Point2& a, const Point2& b) {
  return mapper::distance_to_segment_m(p, mapper::Segment{a, b});
}

using mapper::cross;

bool segments_cross(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  const double d1 = cross(b - a, c - a), d2 = cross(b - a, d - a);
  const double d3 = cross(d - c, a - c), d4 = cross(d - c, b - c);
  return ((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0));
}

double segment_segment_m(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  if (segments_cross(a, b, c, d)) return 0.0;
  return std::min({point_segment_m(a, c, d), point_segment_m(b, c, d), point_segment_m(c, a, b),
                   point_segment_m(d, a, b)});
}

/// Distance from the footprint's outline to the nearest surface (0 when one crosses it).
/// A surface entirely inside the footprint is impossible in the simulator (Box2D keeps the
/// body out), so the outline suffices.
double footprint_clearance_m(const mapper::Pose2& pose, std::span<const mapper::Segment> surfaces,
                             const mapper::RobotGeometry& robot) {
  const double hl = 0.5 * robot.length_m, hw = 0.5 * robot.width_m;
  const std::array<Point2, 4> corners = {
      pose.transform(Point2(hl, hw)), pose.transform(Point2(-hl, hw)),
      pose.transform(Point2(-hl, -hw)), pose.transform(Point2(hl, -hw))};
  const Point2 c = pose.translation();
  const double reach = std::hypot(hl, hw) + kContactDistanceM;
  double best = std::numeric_limits<double>::infinity();
  for (const mapper::Segment& s : surfaces) {
    if (point_segment_m(c, s.a, s.b) > reach) continue;  // cheap rejection
    for (int i = 0; i < 4; ++i) {
      best = std::min(best, segment_segment_m(corners[i], corners[(i + 1) % 4], s.a, s.b));
    }
  }
  return best;
}

/// The point of segment ab nearest segment cd (the crossing point when they cross).
Point2 nearest_on_first(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  if (segments_cross(a, b, c, d)) {
    const double t = cross(c - a, d - c) / cross(b - a, d - c);
    return a + t * (b - a);
  }
  auto project = [](const Point2& p, const Point2& u, const Point2& v) {
    return mapper::closest_point_on_segment(p, {u, v});
  };
  // The nearest pair has an endpoint of one segment in it.
  Point2 best = a;
  double best_m = std::numeric_limits<double>::infinity();
  auto consider = [&](const Point2& on_first, const Point2& other) {
    const double m = (on_first - other).norm();
    if (m < best_m) {
      best_m = m;
      best = on_first;
    }
  };
  consider(a, project(a, c, d));
  consider(b, project(b, c, d));
  consider(project(c, a, b), c);
  consider(project(d, a, b), d);
  return best;
}

}  // namespace

std::optional<Point2> nearest_outline_point(const mapper::Pose2& pose,
                                            std::span<const mapper::Segment> surfaces,
                                            const mapper::RobotGeometry& robot) {
  const double hl = 0.5 * robot.length_m, hw = 0.5 * robot.width_m;
  const std::array<Point2, 4> corners = {
      pose.transform(Point2(hl, hw)), pose.transform(Point2(-hl, hw)),
      pose.transform(Point2(-hl, -hw)), pose.transform(Point2(hl, -hw))};
  std::optional<Point2> best;
  double best_m = std::numeric_limits<double>::infinity();
  for (const mapper::Segment& s : surfaces) {
    for (int i = 0; i < 4; ++i) {
      const Point2& a = corners[i];
      const Point2& b = corners[(i + 1) % 4];
      const double m = segment_segment_m(a, b, s.a, s.b);
      if (m < best_m) {
        best_m = m;
        best = nearest_on_first(a, b, s.a, s.b);
      }
    }
  }
  if (!best) return std::nullopt;
  return pose.inverse().transform(*best);
}

void add_contacts(NavMetrics& nav, TrajectoryView rows, std::span<const mapper::Segment> surfaces,
                  const mapper::RobotGeometry& robot, const SegmentIndex* index,
                  std::span<const ModeChange> modes) {
  // footprint_clearance_m tests a surface only when its centre is within `reach` of it; a pose
  // with no surface that near (a little beyond, against rounding) has clearance +infinity.
  const double reach =
      std::hypot(0.5 * robot.length_m, 0.5 * robot.width_m) + kContactDistanceM + 1e-9;
  std::size_t episodes = 0;
  double time_s = 0.0;
  nav.contact_start_s.clear();
  nav.contact_onsets.clear();
  bool touching = false;
  std::optional<double> last_t;
  std::size_t row_index = 0;
  for (const TrajectoryRow& r : rows) {
    const std::size_t i = row_index++;
    if (!r.truth) continue;
    const bool near = !index || index->any_within_m(r.truth->translation(), reach);
    const bool now = near && footprint_clearance_m(*r.truth, surfaces, robot) <= kContactDistanceM;
    if (now && !touching) {
      ++episodes;
      nav.contact_start_s.push_back(r.t_s);
      ContactOnset onset;
      onset.t_s = r.t_s;
      const auto after =
          std::upper_bound(modes.begin(), modes.end(), i,
                           [](std::size_t row, const ModeChange& c) { return row < c.first_row; });
      onset.mode = after == modes.begin() ? "unknown" : mapper::nav::to_string((after - 1)->mode);
      onset.body_m = nearest_outline_point(*r.truth, surfaces, robot).value_or(Point2(0.0, 0.0));
      nav.contact_onsets.push_back(std::move(onset));
    }
    if (now && last_t) time_s += r.t_s - *last_t;
    touching = now;
    last_t = r.t_s;
  }
  nav.contacts = episodes;
  nav.contact_s = time_s;
}

void add_mode_interval(NavMetrics& nav, const std::string& mode, double dtheta_rad, double dt_s) {
  const double wrapped = std::remainder(dtheta_rad, 2.0 * M_PI);
  const double deg = std::abs(wrapped) * 180.0 / M_PI;
  nav.turn_deg += deg;
  nav.turn_deg_by_mode[mode] += deg;
  nav.time_s_by_mode[mode] += dt_s;
}

void add_mode_drift(NavMetrics& nav, const std::string& mode, double odometry_dtheta_rad,
                    double true_dtheta_rad) {
  const double error =
      std::remainder(odometry_dtheta_rad, 2.0 * M_PI) - std::remainder(true_dtheta_rad, 2.0 * M_PI);
  nav.heading_drift_deg_by_mode[mode] += error * 180.0 / M_PI;
}

double odometry_distance_m(TrajectoryView rows) {
  double d = 0.0;
  std::optional<mapper::Point2> previous;  // a row is valid only until the next one is read
  for (const TrajectoryRow& row : rows) {
    if (previous) d += (row.odometry.translation() - *previous).norm();
    previous = row.odometry.translation();
  }
  return d;
}

}  // namespace cogmap::experiments
