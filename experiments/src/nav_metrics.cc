#include "cogmap/experiments/nav_metrics.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>

namespace cogmap::experiments {
namespace {

using mapper::Point2;

double point_segment_m(const Point2& p, const Point2& a, const Point2& b) {
  const Point2 ab = b - a;
  const double len_sq = ab.squaredNorm();
  const double t = len_sq > 0.0 ? std::clamp((p - a).dot(ab) / len_sq, 0.0, 1.0) : 0.0;
  return (p - (a + t * ab)).norm();
}

double cross(const Point2& a, const Point2& b) { return a.x() * b.y() - a.y() * b.x(); }

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

}  // namespace

void add_contacts(NavMetrics& nav, TrajectoryView rows, std::span<const mapper::Segment> surfaces,
                  const mapper::RobotGeometry& robot, const SegmentIndex* index) {
  // footprint_clearance_m tests a surface only when its centre is within `reach` of it; a pose
  // with no surface that near (a little beyond, against rounding) has clearance +infinity.
  const double reach =
      std::hypot(0.5 * robot.length_m, 0.5 * robot.width_m) + kContactDistanceM + 1e-9;
  std::size_t episodes = 0;
  double time_s = 0.0;
  nav.contact_start_s.clear();
  bool touching = false;
  std::optional<double> last_t;
  for (const TrajectoryRow& r : rows) {
    if (!r.truth) continue;
    const bool near = !index || index->any_within_m(r.truth->translation(), reach);
    const bool now = near && footprint_clearance_m(*r.truth, surfaces, robot) <= kContactDistanceM;
    if (now && !touching) {
      ++episodes;
      nav.contact_start_s.push_back(r.t_s);
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
