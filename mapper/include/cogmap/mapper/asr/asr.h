#pragma once
/// An Absolute Space Representation (thesis §2.4.1): one room as polylines, its exits and a
/// reference point, placed in the world by a pose that localisation may correct.

#include <cstddef>
#include <optional>
#include <vector>

#include "cogmap/mapper/seam/geometry.h"
#include "cogmap/mapper/seam/pose2.h"

namespace cogmap::mapper {

/// A doorway (or a fixed-distance cut) through which the robot left or entered a room.
struct Exit {
  Point2 center{0.0, 0.0};       ///< local frame of the ASR, metres
  double width_m = 0.0;          ///< free width measured by the side sonars (0 when unknown)
  double heading_rad = 0.0;      ///< direction of travel through the exit, local frame
  std::optional<int> neighbour;  ///< id of the ASR on the other side, once known
};

/// One finished room.
///
/// Frames: the room is mapped in the mapper's estimate frame as it stood while the robot was
/// in the room; that frame is the ASR's local frame. `pose` maps local -> world after
/// localisation, `odometry_pose` maps local -> world as raw odometry (composed with the known
/// start pose) had it. Without localisation the two are equal.
struct Asr {
  int id = -1;
  Pose2 pose;                           ///< local -> world, corrected
  Pose2 odometry_pose;                  ///< local -> world, odometry only
  std::vector<Polyline> walls;          ///< fitted polylines, local frame, metres
  std::vector<Exit> exits;              ///< exits[0] is the entry (the start pose for room 0)
  Point2 reference_point{0.0, 0.0};     ///< pivot of rotational corrections, local frame
  std::optional<int> parent;            ///< the room the robot came from
  double heading_correction_rad = 0.0;  ///< EM rotation applied to this room about its pivot
  std::vector<Point2> path;             ///< robot path through the room, local frame (for figures)
  double cell_scale_mm = 100.0;         ///< ℘ the room was mapped at
  std::size_t grid_bytes = 0;           ///< memory the room's grid used
  std::size_t extracted_vertex_count = 0;  ///< vertices before simplification (Table 4.2)
  double start_time_s = 0.0;
  double end_time_s = 0.0;

  /// Number of polyline vertices (the thesis's measure of map size, Table 4.2).
  std::size_t vertex_count() const;
  /// Bytes of the polyline representation: 2 floats (4 bytes each) per vertex.
  std::size_t polyline_bytes() const { return vertex_count() * 2 * sizeof(float); }
  /// The walls as world-frame segments, corrected (`corrected`) or odometry-only.
  std::vector<Segment> world_segments(bool corrected) const;
};

}  // namespace cogmap::mapper
