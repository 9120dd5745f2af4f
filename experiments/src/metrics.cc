#include "cogmap/experiments/metrics.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <optional>
#include <utility>

#include "cogmap/experiments/segment_index.h"

namespace cogmap::experiments {

using mapper::Point2;
using mapper::Segment;

namespace {

/// Calls `visit` with each sample of sample_segments, in the same order, without storing them.
template <typename Visit>
void for_each_sample(std::span<const Segment> segments, double step_m, Visit&& visit) {
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const Segment& s = segments[i];
    const double length = s.length_m();
    if (!(length > 0.0)) continue;
    // The small tolerance keeps a 1.0 m wall at 20 pieces, not 21, despite rounding.
    const auto n = static_cast<std::size_t>(std::max(1.0, std::ceil(length / step_m - 1e-9)));
    const double w = length / static_cast<double>(n);
    for (std::size_t k = 0; k < n; ++k) {
      const double t = (static_cast<double>(k) + 0.5) / static_cast<double>(n);
      visit(SurfaceSample{s.a + t * (s.b - s.a), i, w});
    }
  }
}

}  // namespace

std::vector<SurfaceSample> sample_segments(std::span<const Segment> segments, double step_m) {
  std::size_t count = 0;
  for_each_sample(segments, step_m, [&](const SurfaceSample&) { ++count; });
  std::vector<SurfaceSample> out;
  out.reserve(count);
  for_each_sample(segments, step_m, [&](const SurfaceSample& s) { out.push_back(s); });
  return out;
}

bool PathSubsampler::add(const Point2& p) {
  last_ = p;
  if (!kept_.empty() && (p - kept_.back()).norm() < step_m_) return false;
  kept_.push_back(p);
  return true;
}

std::optional<Point2> PathSubsampler::unkept_last() const {
  if (last_ && (*last_ - kept_.back()).norm() > 0.0) return last_;
  return std::nullopt;
}

std::vector<Point2> PathSubsampler::path() const {
  std::vector<Point2> out = kept_;
  if (const auto tail = unkept_last()) out.push_back(*tail);
  return out;
}

std::vector<Point2> subsample_path(std::span<const Point2> path, double step_m) {
  PathSubsampler sampler(step_m);
  for (const Point2& p : path) sampler.add(p);
  return sampler.path();
}

void mark_visible_samples(std::span<const Segment> truth, const SegmentIndex& index,
                          std::span<const Point2> poses, const MapMetricsOptions& options,
                          std::vector<std::uint8_t>& seen, std::vector<std::uint32_t>* hidden_by) {
  constexpr std::uint32_t kNoSurface = std::numeric_limits<std::uint32_t>::max();
  const double range2 = options.sonar_max_range_m * options.sonar_max_range_m;
  // The sight line stops just short of the sample: a neighbouring surface that shares the
  // sample's corner would otherwise "block" it.
  constexpr double kEndGap_m = 0.01;
  // Samples are visited, not stored (one flag each is kept): a large building's samples would
  // otherwise sit in memory. A sample farther than the range from the poses' bounding box along
  // x or y is out of range of every pose: skipped untested (the margin keeps the skip on the
  // safe side of rounding).
  Point2 lo = Point2::Constant(std::numeric_limits<double>::infinity());
  Point2 hi = -lo;
  for (const Point2& pose : poses) {
    lo = lo.cwiseMin(pose);
    hi = hi.cwiseMax(pose);
  }
  const double reach = options.sonar_max_range_m + 1e-6;
  std::vector<std::uint32_t> this_call_only;  // the caller keeps none: kept for this call
  std::vector<std::uint32_t>& hiding = hidden_by != nullptr ? *hidden_by : this_call_only;
  std::size_t k = 0;
  for_each_sample(truth, options.sample_step_m, [&](const SurfaceSample& s) {
    const std::size_t i = k++;
    if (i >= seen.size()) seen.resize(i + 1, 0);
    if (i >= hiding.size()) hiding.resize(i + 1, kNoSurface);
    if (seen[i]) return;
    if (s.point.x() < lo.x() - reach || s.point.x() > hi.x() + reach ||
        s.point.y() < lo.y() - reach || s.point.y() > hi.y() + reach) {
      return;
    }
    for (const Point2& pose : poses) {
      const Point2 d = pose - s.point;
      const double dist2 = d.squaredNorm();
      if (dist2 > range2) continue;
      const double dist = std::sqrt(dist2);
      if (dist <= kEndGap_m) {
        seen[i] = 1;
        return;
      }
      const Point2 near_sample = s.point + d * (kEndGap_m / dist);
      // The surface that hid the sample last is tried first: it crosses the sight line, so the
      // walk would find a crossing too (it is listed in every cell it touches).
      std::uint32_t& last = hiding[i];
      if (last != kNoSurface && index.crosses(near_sample, pose, last)) continue;
      const std::size_t blocker = index.first_blocker(near_sample, pose, s.segment);
      if (blocker != SegmentIndex::kNone) {
        last = static_cast<std::uint32_t>(blocker);
        continue;
      }
      seen[i] = 1;
      return;
    }
  });
}

std::vector<Point2> marked_samples(std::span<const Segment> truth, double sample_step_m,
                                   std::span<const std::uint8_t> seen) {
  std::vector<Point2> out;
  std::size_t k = 0;
  for_each_sample(truth, sample_step_m, [&](const SurfaceSample& s) {
    if (k < seen.size() && seen[k]) out.push_back(s.point);
    ++k;
  });
  return out;
}

std::vector<Point2> visible_truth_samples(std::span<const Segment> truth,
                                          std::span<const Point2> true_path,
                                          const MapMetricsOptions& options) {
  const SegmentIndex index(truth, options.index_cell_m);
  const std::vector<Point2> poses = subsample_path(true_path, options.trajectory_step_m);
  std::vector<std::uint8_t> seen;
  mark_visible_samples(truth, index, poses, options, seen);
  return marked_samples(truth, options.sample_step_m, seen);
}

double quantile(std::vector<double>& values, double q) {
  std::sort(values.begin(), values.end());
  const double pos = q * static_cast<double>(values.size() - 1);
  const auto lo = static_cast<std::size_t>(std::floor(pos));
  const std::size_t hi = std::min(lo + 1, values.size() - 1);
  const double frac = pos - static_cast<double>(lo);
  return frac == 0.0 ? values[lo] : values[lo] + frac * (values[hi] - values[lo]);
}

MapAccuracy evaluate_map(std::span<const Segment> map, std::span<const Segment> truth,
                         std::span<const Point2> visible, const MapMetricsOptions& options) {
  return evaluate_map(map, SegmentIndex(truth, options.index_cell_m), visible, options);
}

MapAccuracy evaluate_map(std::span<const Segment> map, const SegmentIndex& truth_index,
                         std::span<const Point2> visible, const MapMetricsOptions& options) {
  MapAccuracy out;
  out.segment_count = map.size();
  std::vector<double> errors;
  double spurious_m = 0.0;
  // Visited, not materialised: the samples would sit in memory beside their errors.
  for_each_sample(map, options.sample_step_m, [&](const SurfaceSample& s) {
    const double e = truth_index.nearest_distance_m(s.point);
    errors.push_back(e);
    out.map_length_m += s.weight_m;
    if (e > options.spurious_distance_m) spurious_m += s.weight_m;
  });
  out.error_samples = errors.size();
  if (!errors.empty()) {
    out.wall_error_median_m = quantile(errors, 0.5);
    out.wall_error_p90_m = quantile(errors, 0.9);
  }
  if (out.map_length_m > 0.0) out.spurious_fraction = spurious_m / out.map_length_m;

  out.visible_truth_samples = visible.size();
  if (!visible.empty()) {
    const SegmentIndex map_index(map, options.index_cell_m);
    std::size_t covered = 0;
    for (const Point2& p : visible) {
      // Covered or not is all that counts: a look at the cells within the radius, not a ring
      // search out to the nearest map segment (most uncovered samples have none near).
      if (map_index.any_within_m(p, options.coverage_radius_m)) ++covered;
    }
    out.wall_coverage = static_cast<double>(covered) / static_cast<double>(visible.size());
  }
  return out;
}

namespace {

/// The sums a SimilarityFit needs, gathered in one pass over the rows (they are streamed):
/// with e = p − p₀ and t = p_true − p_true,0 as complex numbers, S = Σ e·conj(t), T = Σ |t|²,
/// E = Σ |e|²; then a = S / T and Σ |e − a·t|² = E − |S|² / T.
class SimilaritySums {
 public:
  void add(const mapper::Point2& p, const mapper::Point2& p_true) {
    if (!origin_) origin_ = {p, p_true};
    const mapper::Point2 e = p - origin_->first, t = p_true - origin_->second;
    s_re_ += e.x() * t.x() + e.y() * t.y();
    s_im_ += e.y() * t.x() - e.x() * t.y();
    t_ += t.squaredNorm();
    e_ += e.squaredNorm();
    ++n_;
  }
  SimilarityFit fit() const {
    SimilarityFit f;
    if (n_ == 0) return f;
    // A path that never leaves its start (T = 0) has no scale or direction to fit.
    if (t_ > 0.0) {
      f.scale = std::hypot(s_re_, s_im_) / t_;
      f.rotation_deg = std::atan2(s_im_, s_re_) * 180.0 / std::numbers::pi;
    }
    const double explained = t_ > 0.0 ? (s_re_ * s_re_ + s_im_ * s_im_) / t_ : 0.0;
    // E − |S|²/T ≥ 0 (Cauchy-Schwarz); rounding may leave it a hair below.
    f.residual_rmse_m = std::sqrt(std::max(0.0, e_ - explained) / static_cast<double>(n_));
    return f;
  }

 private:
  std::optional<std::pair<mapper::Point2, mapper::Point2>> origin_;
  double s_re_ = 0.0, s_im_ = 0.0, t_ = 0.0, e_ = 0.0;
  std::size_t n_ = 0;
};

}  // namespace

std::optional<LocalizationAccuracy> evaluate_trajectory(TrajectoryView rows,
                                                        std::optional<double> closed_heading_rad) {
  LocalizationAccuracy out;
  double sum_odom = 0.0, sum_est = 0.0;
  SimilaritySums fit_odom, fit_est;
  std::optional<TrajectoryRow> last;  // a copy: a row is valid only until the next one is read
  for (const TrajectoryRow& r : rows) {
    if (!r.truth) continue;
    sum_odom += (r.odometry.translation() - r.truth->translation()).squaredNorm();
    sum_est += (r.estimate.translation() - r.truth->translation()).squaredNorm();
    fit_odom.add(r.odometry.translation(), r.truth->translation());
    fit_est.add(r.estimate.translation(), r.truth->translation());
    ++out.frames;
    last = r;
  }
  if (!last) return std::nullopt;
  const double n = static_cast<double>(out.frames);
  out.ate_rmse_odometry_m = std::sqrt(sum_odom / n);
  out.ate_rmse_corrected_m = std::sqrt(sum_est / n);
  out.similarity_odometry = fit_odom.fit();
  out.similarity_corrected = fit_est.fit();
  constexpr double kDeg = 180.0 / std::numbers::pi;
  out.heading_error_final_odometry_deg =
      std::abs(mapper::wrap_angle_rad(last->odometry.theta_rad - last->truth->theta_rad)) * kDeg;
  out.heading_error_final_corrected_deg =
      std::abs(mapper::wrap_angle_rad(last->estimate.theta_rad - last->truth->theta_rad)) * kDeg;
  if (closed_heading_rad) {
    out.heading_error_final_closed_deg =
        std::abs(mapper::wrap_angle_rad(*closed_heading_rad - last->truth->theta_rad)) * kDeg;
  }
  return out;
}

MemoryMetrics memory_metrics(std::span<const RoomSize> rooms) {
  MemoryMetrics m;
  for (const RoomSize& r : rooms) {
    m.polyline_bytes += r.polyline_bytes;
    m.grid_bytes = std::max(m.grid_bytes, r.grid_bytes);
    m.grid_bytes_total += r.grid_bytes;
    m.vertex_count += r.vertex_count;
    m.extracted_vertex_count += r.extracted_vertex_count;
  }
  m.extracted_vertex_bytes = m.extracted_vertex_count * 2 * sizeof(float);
  if (m.grid_bytes_total > 0) {
    m.compression_ratio =
        static_cast<double>(m.polyline_bytes) / static_cast<double>(m.grid_bytes_total);
  }
  return m;
}

}  // namespace cogmap::experiments
