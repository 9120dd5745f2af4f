#pragma once
/// The mapper facade (thesis Fig. 1.3): consumes frames, keeps the current room's grid,
/// builds an ASR at each boundary, localises it, stores it, and exposes the merged map.

#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "cogmap/mapper/asr/asr.h"
#include "cogmap/mapper/asr/asr_builder.h"
#include "cogmap/mapper/boundary/asr_boundary_detector.h"
#include "cogmap/mapper/graph/asr_graph.h"
#include "cogmap/mapper/graph/asr_store.h"
#include "cogmap/mapper/grid/grid_updater.h"
#include "cogmap/mapper/localization/door_fixes.h"
#include "cogmap/mapper/localization/glimpse_heading.h"
#include "cogmap/mapper/localization/held_turn.h"
#include "cogmap/mapper/localization/localizer.h"
#include "cogmap/mapper/localization/map_relaxation.h"
#include "cogmap/mapper/localization/odometry_recalibration.h"
#include "cogmap/mapper/localization/scan_match.h"
#include "cogmap/mapper/localization/wall_offsets.h"
#include "cogmap/mapper/seam/robot_geometry.h"
#include "cogmap/mapper/seam/sensor_frame.h"

namespace cogmap::mapper {

struct MapperOptions {
  GridKind grid = GridKind::kMhimm;
  GridOptions grid_options;
  AsrBuilderOptions builder;
  BoundaryKind boundary = BoundaryKind::kDoorway;
  DoorwayOptions doorway;
  DistanceOptions distance;
  LocalizationKind localization = LocalizationKind::kEm;
  LocalizerOptions localizer;
  TranslationOptions translation;  ///< a room's shift from the offsets of walls seen before
  GlimpseOptions glimpse;          ///< in-room heading correction by short glimpses
  ScanMatchOptions scan_match;     ///< the estimate kept on the echoes of the last minute
  DoorFixOptions door_fix;         ///< position fixes at doorways passed again
  RelaxationOptions relaxation;    ///< the rooms' positions adjusted together when the run ends
  /// A skid-steer's odometry re-integrated with a curvature-dependent track before anything uses
  /// it (curvature_gain 0, or a differential drive: as reported).
  OdometryCalibration odometry_calibration;
  /// Turns the wheels made while the body was held (the sonar ring unchanged after a turn on
  /// the spot) are taken out of that odometry (docs/algorithms.md, "Turns made while held").
  HeldTurnOptions held_turn;
  double min_room_duration_s = 2.0;  ///< boundaries closer in time than this are ignored
  /// A room whose path would span more than this (metres, either axis) ends before the pose
  /// that would stretch it, as a distance cut would, whatever min_room_duration_s says: it
  /// bounds a room grid to (extent + 2 x sonar range)^2, 210 m -> 4.4 M cells of 10 cm (18 MB),
  /// however long a doorway-less corridor or a broken odometry runs, and across a jump (a log's
  /// time gap). The thesis's rooms and hallway cuts are under 80 m.
  double max_room_extent_m = 200.0;
  /// A room whose path (the estimate's, metres) grows longer than this ends there, as the
  /// thesis cuts its hallways every 4.5 m (§3.1.2), so that EM corrects a room toured for
  /// minutes before its drift smears it (ours; docs/algorithms.md, "Long rooms cut"). 0 (the
  /// thesis's rule): rooms end only at doorways (and at max_room_extent_m). Experiments that
  /// explore default to 4.5 m (kExploreMaxRoomTravelM). With BoundaryKind::kDistance the cut is
  /// the boundary itself and this adds nothing.
  double max_room_travel_m = 0.0;
};

/// The path length after which the mapper cuts a room (0: never): max_room_travel_m with the
/// doorway rule; with distance cuts the boundary is that rule already, at its own length.
inline double applied_max_room_travel_m(const MapperOptions& options) {
  return options.boundary == BoundaryKind::kDoorway ? options.max_room_travel_m : 0.0;
}

/// Counters for the run report.
struct MapperStats {
  std::size_t frames = 0;
  std::size_t readings_used = 0;
  RejectedReadings rejected;
  std::size_t rooms = 0;
  double build_time_s = 0.0;         ///< CPU spent in the room -> ASR pipeline
  double localization_time_s = 0.0;  ///< CPU spent in EM and the translation
  std::size_t peak_grid_bytes = 0;
  std::size_t glimpses = 0;                  ///< glimpses measured (in-room heading correction)
  std::size_t glimpse_corrections = 0;       ///< of which EM applied a rotation
  double glimpse_correction_abs_rad = 0.0;   ///< Σ |glimpse rotations|
  std::size_t scan_matches = 0;              ///< matches tried (options.scan_match)
  std::size_t scan_matches_measured = 0;     ///< of which enough echoes met memory walls
  double scan_match_rotation_abs_rad = 0.0;  ///< Σ |rotations applied|
  double scan_match_shift_abs_m = 0.0;       ///< Σ |shifts applied|
  std::size_t translations = 0;              ///< rooms shifted by their wall offsets
  double translation_abs_m = 0.0;            ///< Σ |those shifts|
  std::size_t door_fixes = 0;                ///< doorways passed again that moved the estimate
  double door_fix_abs_m = 0.0;               ///< Σ |those moves|
  std::size_t relaxed_rooms = 0;             ///< rooms the end-of-run relaxation moved
  double relaxation_abs_m = 0.0;             ///< Σ |those shifts|
  double relaxation_max_m = 0.0;             ///< the largest
  double relaxation_wall_thickness_m = 0.0;  ///< as the relaxation estimated it
  std::size_t held_turns = 0;                ///< times the body was found held in a turn
  double held_turn_removed_abs_rad = 0.0;    ///< Σ |turn taken out of the odometry|
  std::size_t relaxation_pairs = 0;          ///< wall pairs it used (same side and two faces)
};

class Mapper {
 public:
  /// Called once per finished room with the ASR (already localised and stored), the trace of
  /// its pipeline stages (dropped after the call: bounded memory) and what EM measured for it
  /// (none for the first room, or with localisation off).
  using RoomListener =
      std::function<void(const Asr&, const AsrTrace&, const std::optional<Localization>&)>;

  /// `start_pose` places the odometry frame in the world (the known start pose).
  Mapper(const MapperOptions& options, const RobotGeometry& robot, AsrStore& store,
         const Pose2& start_pose);
  ~Mapper();
  Mapper(const Mapper&) = delete;
  Mapper& operator=(const Mapper&) = delete;

  void set_room_listener(RoomListener listener);

  /// Integrates one frame; returns the id of a room finished during this frame.
  std::optional<int> process(const SensorFrame& frame);

  /// Closes the current room (end of run); returns its id if it produced an ASR. The room's
  /// correction (EM) then applies to pose_estimate() as well. With options.relaxation, every
  /// room is then re-placed (store and graph updated); room_moves() says how.
  std::optional<int> finish();

  /// The rooms finish() re-placed: room id -> the world-frame transform that takes the room as
  /// it was placed on leaving it (what the room listener saw) to where it stands now.
  const std::vector<std::pair<int, Pose2>>& room_moves() const;

  /// Odometry composed with the start pose, world frame.
  Pose2 odometry_pose() const;
  /// The corrected pose estimate, world frame.
  Pose2 pose_estimate() const;

  /// The current room's grid (for navigation and live display).
  const GridUpdater& grid() const;
  const AsrGraph& graph() const;
  const AsrStore& store() const;
  const MapperStats& stats() const;

  /// The merged master map (Fig. 4.4) as world-frame segments with their room ids, loaded
  /// from the store: after localisation (`corrected`) or odometry only.
  struct MapSegment {
    int asr_id = -1;
    Segment segment;
  };
  std::vector<MapSegment> master_map(bool corrected) const;
  /// One room's part of the master map, appended to `map` (what master_map does per room; a
  /// caller that reads the rooms back anyway builds both maps in that one pass).
  static void append_room_segments(const Asr& asr, bool corrected, std::vector<MapSegment>& map);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace cogmap::mapper
