#pragma once
/// A uniform-grid spatial index over wall segments: nearest-segment distance and line-of-sight
/// queries stay fast on large worlds (the 78 m hallway has thousands of surface samples).

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "cogmap/mapper/seam/geometry.h"

namespace cogmap::experiments {

class SegmentIndex {
 public:
  /// Sentinel for "exclude no segment".
  static constexpr std::size_t kNone = static_cast<std::size_t>(-1);

  /// Indexes `segments` (world frame, metres) in square cells of about `cell_m` metres (shrunk
  /// where the segments are so many that a cell would hold more than about eight on average;
  /// grown when the world is so large that the cell count would exceed a few million). The
  /// cell size changes only the speed: every query answers as a brute-force scan would.
  explicit SegmentIndex(std::span<const mapper::Segment> segments, double cell_m = 0.5);

  const std::vector<mapper::Segment>& segments() const { return segments_; }
  bool empty() const { return segments_.empty(); }
  /// The side of the cells, metres (see the constructor).
  double cell_m() const { return cell_m_; }

  /// Distance from `p` to the nearest segment, metres; +infinity when the index is empty.
  double nearest_distance_m(const mapper::Point2& p) const;

  /// The point of the nearest segment closest to `p` when it lies within `radius_m` (the cells
  /// of the box p ± radius_m are looked at); empty otherwise.
  std::optional<mapper::Point2> nearest_point_within(const mapper::Point2& p,
                                                     double radius_m) const;

  /// True when some segment passes within `radius_m` of `p` (a few cells looked at, never a
  /// ring search): the same answer as nearest_distance_m(p) <= radius_m.
  bool any_within_m(const mapper::Point2& p, double radius_m) const;

  /// True when some segment other than `exclude` intersects the closed segment from `a` to `b`.
  bool blocked(const mapper::Point2& a, const mapper::Point2& b, std::size_t exclude) const {
    return first_blocker(a, b, exclude) != kNone;
  }
  /// The first segment other than `exclude` found to intersect the closed segment from `a` to
  /// `b`, walking from `a`; kNone when none does (then blocked() is false).
  std::size_t first_blocker(const mapper::Point2& a, const mapper::Point2& b,
                            std::size_t exclude) const;
  /// True when segment `i` intersects the closed segment from `a` to `b` (the test the walk
  /// makes: a segment found so implies blocked(), as it is listed in every cell it touches).
  bool crosses(const mapper::Point2& a, const mapper::Point2& b, std::size_t i) const;

 private:
  struct Cell {
    int x = 0;
    int y = 0;
  };
  Cell cell_of(const mapper::Point2& p) const;
  /// The segments listed in cell (x, y); none outside the grid.
  std::span<const std::uint32_t> bucket(int x, int y) const;

  std::vector<mapper::Segment> segments_;
  double cell_m_ = 0.5;
  double origin_x_m_ = 0.0;
  double origin_y_m_ = 0.0;
  int width_ = 0;
  int height_ = 0;
  /// Cell c (row-major) lists bucket_items_[bucket_start_[c] .. bucket_start_[c + 1]).
  std::vector<std::uint32_t> bucket_start_;
  std::vector<std::uint32_t> bucket_items_;  ///< segment indices, cell by cell
};

/// True when the closed segments p1-p2 and q1-q2 share a point (touching counts).
bool segments_intersect(const mapper::Point2& p1, const mapper::Point2& p2,
                        const mapper::Point2& q1, const mapper::Point2& q2);

}  // namespace cogmap::experiments
