#pragma once
/// Our extension beyond §3.1.9 (which corrects the heading only): the translation of a new ASR
/// from the offsets between its walls and the same walls in rooms mapped before it, once EM's
/// rotation is applied. A room the robot comes back to is the common case: its walls are seen
/// again from the same side, and their offsets measure the position drift since the first
/// visit. docs/algorithms.md, "Translation from revisited walls".

#include <span>
#include <vector>

#include "cogmap/mapper/seam/geometry.h"
#include "cogmap/mapper/seam/pose2.h"

namespace cogmap::mapper {

/// A straight piece of a wall and the side it was seen from.
struct FacingSegment {
  Point2 a{0.0, 0.0}, b{0.0, 0.0};
  Point2 normal{0.0, 0.0};  ///< unit, pointing to the side the robot saw the wall from
};

/// The pieces of `walls` (consecutive vertices) at least `min_length_m` long, each facing the
/// side of its line where the point of `path` nearest its middle lies (the robot saw it from
/// there: a desk's face from the aisle, a corridor wall from the corridor). None without a path.
std::vector<FacingSegment> facing_segments(std::span<const Polyline> walls,
                                           std::span<const Point2> path, double min_length_m);

/// facing_segments of a room's `walls` and `path` (its local frame) placed in the world by
/// `pose`.
std::vector<FacingSegment> placed_facing_segments(std::span<const Polyline> walls,
                                                  std::span<const Point2> path, const Pose2& pose,
                                                  double min_length_m);

struct TranslationOptions {
  /// On (default, measured on generated buildings: docs/algorithms.md): a revisited room is
  /// placed onto its first visit's walls. Off: rooms are only rotated (the thesis's EM).
  bool enabled = true;
  /// The robot's estimate takes the shift too. Off (default): the map alone; moving the
  /// estimate mapped better still but navigated worse on half the sets measured.
  bool moves_estimate = false;
  double max_angle_deg = 5.0;    ///< a pair of walls: parallel within this (EM's scatter 1-3°)
  double max_offset_m = 1.0;     ///< ...at most this far apart along their normal
  double min_overlap_m = 0.5;    ///< ...overlapping this much along their direction
  double min_segment_m = 0.5;    ///< shorter pieces are not matched (on 0.1 m cells a 0.5 m
                                 ///< piece's direction is only known to ±11°)
  double min_support_m = 1.5;    ///< overlap needed along a normal before it is corrected
  double max_residual_m = 0.15;  ///< rms offset left after the fit, else nothing is applied
  int iterations = 4;            ///< re-pairing rounds (each pairs with the shift so far)
};

/// The shift that moves the new room's walls onto the reference's.
struct TranslationFix {
  Point2 shift{0.0, 0.0};            ///< add to every point of the new room (world frame)
  int pairs = 0;                     ///< wall pairs in the last round
  double support_m[2] = {0.0, 0.0};  ///< overlap along the two principal normals, strong first
  double residual_m = 0.0;           ///< rms offset left, weighted by overlap
  bool applied = false;              ///< false: too little support, too large, or inconsistent
};

/// Least squares over wall pairs (same side, parallel, overlapping, within max_offset_m): each
/// pair says normal · shift = offset. Iterated with re-pairing; a direction with less than
/// min_support_m of overlapping wall is left alone (one corridor wall fixes only the lateral
/// position).
TranslationFix estimate_translation(std::span<const FacingSegment> reference,
                                    std::span<const FacingSegment> current,
                                    const TranslationOptions& options);

}  // namespace cogmap::mapper
