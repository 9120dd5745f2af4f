// The translation of a new ASR from wall offsets (docs/algorithms.md, "Translation from
// revisited walls"): pairs of parallel walls seen from the same side, least squares along
// their normals, re-paired a few times, each direction corrected only where enough wall
// overlaps to measure it.

#include "cogmap/mapper/localization/wall_offsets.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace cogmap::mapper {
namespace {

/// One pair of the current round: the reference normal, the offset along it still to close,
/// and the overlap that weighs it.
struct Pair {
  Point2 normal;
  double offset_m;
  double weight_m;
};

/// The reference piece nearest (along its normal) to `c` shifted by `shift` that faces the same
/// way, is parallel within the angle, overlaps it and lies within max_offset_m.
bool best_pair(std::span<const FacingSegment> reference, const FacingSegment& c,
               const Point2& shift, const TranslationOptions& o, Pair& out) {
  const Point2 ca = c.a + shift, cb = c.b + shift;
  const double c_len = (cb - ca).norm();
  if (c_len <= 0.0) return false;
  const Point2 uc = (cb - ca) / c_len;
  const double sin_max = std::sin(o.max_angle_deg * std::numbers::pi / 180.0);
  bool found = false;
  double best_abs = std::numeric_limits<double>::infinity();
  for (const FacingSegment& r : reference) {
    if (c.normal.dot(r.normal) <= 0.0) continue;  // seen from the other side (or across)
    const double r_len = (r.b - r.a).norm();
    if (r_len <= 0.0) continue;
    const Point2 ur = (r.b - r.a) / r_len;
    if (std::abs(cross(uc, ur)) > sin_max) continue;
    // Where the current piece's ends fall along the reference piece, and their overlap.
    const double s0 = ur.dot(ca - r.a), s1 = ur.dot(cb - r.a);
    const double lo = std::max(std::min(s0, s1), 0.0), hi = std::min(std::max(s0, s1), r_len);
    const double overlap = hi - lo;
    if (overlap < o.min_overlap_m || s1 == s0) continue;
    // The offset at the middle of the overlap (the pieces need not be exactly parallel).
    const double mid = 0.5 * (lo + hi);
    const Point2 p = ca + (mid - s0) / (s1 - s0) * (cb - ca);
    const double offset = r.normal.dot(r.a - p);
    if (std::abs(offset) > o.max_offset_m || std::abs(offset) >= best_abs) continue;
    best_abs = std::abs(offset);
    out = {r.normal, offset, overlap};
    found = true;
  }
  return found;
}

}  // namespace

std::vector<FacingSegment> facing_segments(std::span<const Polyline> walls,
                                           std::span<const Point2> path, double min_length_m) {
  std::vector<FacingSegment> out;
  if (path.empty()) return out;
  for (const Polyline& line : walls) {
    for (std::size_t i = 1; i < line.size(); ++i) {
      const Point2 a = line[i - 1], b = line[i];
      const double length = (b - a).norm();
      if (!(length >= min_length_m) || length <= 0.0) continue;
      const Point2 mid = 0.5 * (a + b);
      const Point2* nearest = &path.front();
      for (const Point2& p : path) {
        if ((p - mid).squaredNorm() < (*nearest - mid).squaredNorm()) nearest = &p;
      }
      Point2 normal(-(b - a).y() / length, (b - a).x() / length);
      const double side = normal.dot(*nearest - a);
      if (side == 0.0) continue;  // seen along its own line: no side to tell
      if (side < 0.0) normal = -normal;
      out.push_back({a, b, normal});
    }
  }
  return out;
}

std::vector<FacingSegment> placed_facing_segments(std::span<const Polyline> walls,
                                                  std::span<const Point2> path, const Pose2& pose,
                                                  double min_length_m) {
  std::vector<Polyline> placed(walls.begin(), walls.end());
  for (Polyline& line : placed) {
    for (Point2& p : line) p = pose.transform(p);
  }
  std::vector<Point2> placed_path;
  placed_path.reserve(path.size());
  for (const Point2& p : path) placed_path.push_back(pose.transform(p));
  return facing_segments(placed, placed_path, min_length_m);
}

TranslationFix estimate_translation(std::span<const FacingSegment> reference,
                                    std::span<const FacingSegment> current,
                                    const TranslationOptions& o) {
  TranslationFix fix;
  Point2 shift(0.0, 0.0);
  std::vector<Pair> pairs;
  for (int round = 0; round < std::max(o.iterations, 1); ++round) {
    pairs.clear();
    for (const FacingSegment& c : current) {
      Pair p;
      if (best_pair(reference, c, shift, o, p)) pairs.push_back(p);
    }
    fix.pairs = static_cast<int>(pairs.size());
    if (pairs.empty()) return fix;
    // Normal equations of Σ w (n · step − offset)²: A step = b, A = Σ w n nᵀ.
    double axx = 0.0, axy = 0.0, ayy = 0.0;
    Point2 b(0.0, 0.0);
    for (const Pair& p : pairs) {
      axx += p.weight_m * p.normal.x() * p.normal.x();
      axy += p.weight_m * p.normal.x() * p.normal.y();
      ayy += p.weight_m * p.normal.y() * p.normal.y();
      b += p.weight_m * p.offset_m * p.normal;
    }
    // Eigen-decomposition of the symmetric 2 x 2: λ is the overlap along the direction v.
    const double mean = 0.5 * (axx + ayy);
    const double spread = std::hypot(0.5 * (axx - ayy), axy);
    const double lambda[2] = {mean + spread, mean - spread};
    const double angle = 0.5 * std::atan2(2.0 * axy, axx - ayy);
    const Point2 v[2] = {Point2(std::cos(angle), std::sin(angle)),
                         Point2(-std::sin(angle), std::cos(angle))};
    Point2 step(0.0, 0.0);
    for (int k = 0; k < 2; ++k) {
      fix.support_m[k] = lambda[k];
      if (lambda[k] >= o.min_support_m) step += (v[k].dot(b) / lambda[k]) * v[k];
    }
    shift += step;
    // What the fit leaves unexplained, weighted as the fit was.
    double sum_w = 0.0, sum_sq = 0.0;
    for (const Pair& p : pairs) {
      const double left = p.offset_m - p.normal.dot(step);
      sum_w += p.weight_m;
      sum_sq += p.weight_m * left * left;
    }
    fix.residual_m = sum_w > 0.0 ? std::sqrt(sum_sq / sum_w) : 0.0;
    if (step.norm() < 1e-4) break;
  }
  fix.shift = shift;
  fix.applied = (fix.support_m[0] >= o.min_support_m) && shift.norm() <= o.max_offset_m &&
                fix.residual_m <= o.max_residual_m && shift.allFinite();
  if (!fix.applied) fix.shift = Point2(0.0, 0.0);
  return fix;
}

}  // namespace cogmap::mapper
