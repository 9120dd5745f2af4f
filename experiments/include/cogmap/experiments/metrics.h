#pragma once
/// The run metrics of docs/metrics.md, computed against ground truth in the world frame using
/// only the known start pose (no alignment, no fitting).

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "cogmap/experiments/trajectory_rows.h"
#include "cogmap/mapper/seam/geometry.h"
#include "cogmap/mapper/seam/pose2.h"

namespace cogmap::experiments {

/// Knobs of the map metrics; the defaults are the definitions of docs/formats.md.
struct MapMetricsOptions {
  double sample_step_m = 0.05;       ///< samples along every segment
  double coverage_radius_m = 0.2;    ///< a visible true sample is covered within this
  double spurious_distance_m = 0.3;  ///< extracted length farther than this is spurious
  double sonar_max_range_m = 5.0;    ///< visibility range from a true pose
  double trajectory_step_m = 0.25;   ///< true path subsampling for the visibility test
  double index_cell_m = 0.5;         ///< cell of the spatial indexes
};

/// One sample on a segment: the point and the segment it came from.
struct SurfaceSample {
  mapper::Point2 point{0.0, 0.0};
  std::size_t segment = 0;
  double weight_m = 0.0;  ///< length of segment this sample stands for
};

/// Splits each segment into ceil(L / step) equal pieces and samples each piece's midpoint,
/// so every sample stands for the same length of its segment (zero-length segments: none).
std::vector<SurfaceSample> sample_segments(std::span<const mapper::Segment> segments,
                                           double step_m);

/// Keeps the first pose, every pose at least `step_m` from the last kept one, and the last.
std::vector<mapper::Point2> subsample_path(std::span<const mapper::Point2> path, double step_m);

/// subsample_path fed one pose at a time, so a long run's full path is never held in memory
/// (7644 frames of a 6 x 6 block: 122 KB per path, twice that while a vector doubles).
class PathSubsampler {
 public:
  explicit PathSubsampler(double step_m) : step_m_(step_m) {}
  /// True when `p` is kept (the first pose, or step_m from the last kept one).
  bool add(const mapper::Point2& p);
  /// The subsampled path so far (the last pose added included).
  std::vector<mapper::Point2> path() const;
  /// The last pose added when it was not kept (path() ends with it), else nothing.
  std::optional<mapper::Point2> unkept_last() const;

 private:
  double step_m_;
  std::vector<mapper::Point2> kept_;
  std::optional<mapper::Point2> last_;
};

/// The true surface samples the robot could have seen: within `sonar_max_range_m` of some
/// (subsampled) true pose with the straight line to it not crossing any other true surface.
/// `true_path` is the full true trajectory; it is subsampled here. Only the samples' points
/// are kept (half the memory of SurfaceSample: the coverage needs nothing else).
std::vector<mapper::Point2> visible_truth_samples(std::span<const mapper::Segment> truth,
                                                  std::span<const mapper::Point2> true_path,
                                                  const MapMetricsOptions& options);

class SegmentIndex;

/// The test of visible_truth_samples in pieces: sets `seen[k]` for every sample k (in
/// sample_segments order) of `truth` that one of `poses` sees (`index` built over `truth`).
/// Samples already set are not tested again, so the poses can come in batches, in any order;
/// `seen` grows to the sample count. The surface that last hid each sample is tried first
/// against the next position (a wall's back face is hidden by its front face from everywhere),
/// which changes only the speed, never the flags; `hidden_by`, if given, keeps it from call to
/// call.
void mark_visible_samples(std::span<const mapper::Segment> truth, const SegmentIndex& index,
                          std::span<const mapper::Point2> poses, const MapMetricsOptions& options,
                          std::vector<std::uint8_t>& seen,
                          std::vector<std::uint32_t>* hidden_by = nullptr);

/// The points of the samples of `truth` marked in `seen`, in sample_segments order.
std::vector<mapper::Point2> marked_samples(std::span<const mapper::Segment> truth,
                                           double sample_step_m,
                                           std::span<const std::uint8_t> seen);

/// The map block of metrics.json for one map (empty optionals: undefined, written as null).
struct MapAccuracy {
  std::optional<double> wall_error_median_m;  ///< empty when the map has no segments
  std::optional<double> wall_error_p90_m;
  std::optional<double> wall_coverage;      ///< empty when nothing was visible
  std::optional<double> spurious_fraction;  ///< empty when the map has no length
  std::size_t segment_count = 0;
  double map_length_m = 0.0;
  std::size_t error_samples = 0;
  std::size_t visible_truth_samples = 0;
};

/// Compares `map` (world frame) with the true surfaces. `visible` comes from
/// visible_truth_samples over the same `truth`.
MapAccuracy evaluate_map(std::span<const mapper::Segment> map,
                         std::span<const mapper::Segment> truth,
                         std::span<const mapper::Point2> visible, const MapMetricsOptions& options);

/// The same with an index already built over the true surfaces (any cell size: the distances
/// it answers are exact), so a run scoring several maps builds it once.
MapAccuracy evaluate_map(std::span<const mapper::Segment> map, const SegmentIndex& truth_index,
                         std::span<const mapper::Point2> visible, const MapMetricsOptions& options);

/// The q-quantile (0..1) with linear interpolation between order statistics (index q·(n−1),
/// the numpy default); the median of an even count is the mean of the middle two.
/// `values` is reordered. Requires a non-empty input.
double quantile(std::vector<double>& values, double q);

/// How much of a trajectory's error one scale and one rotation about its start explain: the
/// least-squares a = s·e^{iφ} (complex plane) with p − p₀ ≈ a·(p_true − p_true,0) over the frames
/// with ground truth, anchored at the first of them. A heading-only correction (EM) cannot see a
/// distance scale error of the odometry, nor a heading error made before the first correction;
/// this says how much of the ATE they are (docs/metrics.md).
struct SimilarityFit {
  double scale = 1.0;            ///< s: 1.01 draws the path 1 % too large
  double rotation_deg = 0.0;     ///< φ, counter-clockwise
  double residual_rmse_m = 0.0;  ///< sqrt(mean |(p − p₀) − a·(p_true − p_true,0)|²)
};

/// The localization block of metrics.json.
struct LocalizationAccuracy {
  double heading_error_final_odometry_deg = 0.0;  ///< |wrap(θ_odom − θ_true)| at the last frame
  double heading_error_final_corrected_deg = 0.0;  ///< |wrap(θ_est − θ_true)| at the last frame
  double ate_rmse_odometry_m = 0.0;   ///< sqrt(mean |p_odom − p_true|²) over all frames
  double ate_rmse_corrected_m = 0.0;  ///< sqrt(mean |p_est − p_true|²) over all frames
  std::size_t frames = 0;             ///< frames with ground truth
  /// heading_error_final_corrected_deg for the estimate once the run's last room is closed (its
  /// EM correction applied, Mapper::finish), when given to evaluate_trajectory.
  std::optional<double> heading_error_final_closed_deg;
  SimilarityFit similarity_odometry;   ///< the odometry path's fit to the true one
  SimilarityFit similarity_corrected;  ///< the estimate's
};

/// Empty when no row has ground truth. Rows without truth are skipped; the final heading
/// error uses the last row that has truth. `closed_heading_rad`: the estimate's heading at the
/// last row once the last room is closed (Mapper::finish), for heading_error_final_closed_deg.
std::optional<LocalizationAccuracy> evaluate_trajectory(
    TrajectoryView rows, std::optional<double> closed_heading_rad = std::nullopt);

/// Per-room sizes for the memory comparison (thesis Table 4.2).
struct RoomSize {
  int id = -1;
  std::size_t wall_count = 0;              ///< polylines
  std::size_t vertex_count = 0;            ///< polyline vertices after simplification
  std::size_t extracted_vertex_count = 0;  ///< vertices before simplification
  std::size_t polyline_bytes = 0;          ///< 8 bytes per vertex (two floats)
  std::size_t grid_bytes = 0;              ///< the room's grid cells
};

/// The memory part of the map block.
struct MemoryMetrics {
  std::size_t polyline_bytes = 0;          ///< Σ rooms
  std::size_t grid_bytes = 0;              ///< peak single-room grid (what RAM must hold)
  std::size_t grid_bytes_total = 0;        ///< Σ rooms
  std::size_t extracted_vertex_bytes = 0;  ///< Σ rooms, 8 bytes per vertex
  std::size_t vertex_count = 0;            ///< Σ rooms
  std::size_t extracted_vertex_count = 0;  ///< Σ rooms
  /// polyline_bytes / grid_bytes_total (both summed over rooms); empty with no grid bytes.
  std::optional<double> compression_ratio;
};

MemoryMetrics memory_metrics(std::span<const RoomSize> rooms);

}  // namespace cogmap::experiments
