#pragma once
/// Heading correction inside a room (our extension of thesis §3.1.2 and §3.1.9). The thesis's
/// EM corrects between ASRs, and its answer to long travel is to cut more often (a new ASR every
/// 4.5 m); a room toured for minutes instead smears its own walls with the drift accumulated
/// inside it. A *glimpse* is that short cut made for the heading only: a second grid collects
/// the echoes of the last few metres, the ASR pipeline turns it into wall lines, and EM measures
/// their rotation against the walls already mapped (the previous rooms and this room's earlier
/// glimpses). Rooms, exits and the map are unchanged; only the pose estimate turns.
/// docs/algorithms.md, "In-room heading correction", has the measurements behind the defaults.

#include <cstddef>
#include <memory>
#include <span>
#include <vector>

#include "cogmap/mapper/asr/asr_builder.h"
#include "cogmap/mapper/grid/grid_updater.h"
#include "cogmap/mapper/localization/localizer.h"

namespace cogmap::mapper {

/// Options of GlimpseHeading (experiment keys `mapper.glimpse_*`).
struct GlimpseOptions {
  /// Off by default: measured on generated buildings it does not improve the maps yet
  /// (docs/algorithms.md); false = the thesis, the heading is corrected only between ASRs.
  bool enabled = false;
  /// A glimpse ends after this much travel: the thesis's own ASR length (§3.1.2, 4.5 m)
  /// shortened so a 5 m room gets two or three glimpses.
  double distance_m = 3.0;
  /// ... or after this much turning (a robot turning on the spot drifts without travelling).
  double turn_rad = 3.1416;
  /// Only walls at least this long carry a direction in a glimpse: a 10 cm grid quantises a
  /// 0.5 m piece's direction to ±11°, a 1 m wall's to ±6°, and a few metres of travel see
  /// door jambs and furniture faces as short pieces.
  double min_wall_length_m = 1.0;
  /// A glimpse with less accepted wall than this measures nothing (EM leaves the pose alone).
  double min_total_wall_m = 3.0;
  /// Earlier glimpses of the current room kept as EM reference, newest last.
  std::size_t reference_glimpses = 6;
};

/// What one finished glimpse measured.
struct GlimpseFix {
  Localization localization;    ///< EM against the reference (rotation_rad is what to apply)
  std::vector<Polyline> walls;  ///< the glimpse's accepted walls, estimate frame, uncorrected
};

class GlimpseHeading {
 public:
  GlimpseHeading(const GlimpseOptions& options, std::unique_ptr<GridUpdater> grid,
                 const AsrBuilderOptions& builder, const LocalizerOptions& localizer,
                 double path_spacing_m);

  /// Starts a new glimpse at `pose` (estimate frame); the previous one is dropped.
  void begin(const Pose2& pose);
  /// One reading at `pose` (the same reading the room grid gets).
  void integrate(const Pose2& pose, const SonarReading& reading) {
    grid_->integrate(pose, reading);
  }
  /// The robot moved to `pose` turning `turned_rad`: marks the path. True when the glimpse is due.
  bool visit(const Pose2& pose, double turned_rad);

  /// Builds the glimpse's walls and measures their rotation against `reference` (world frame,
  /// corrected), with the odometry prior N(0, prior²) (infinite = none).
  GlimpseFix measure(std::span<const Polyline> reference, const RotationPrior& prior) const;

  double travelled_m() const { return travelled_m_; }
  double turned_rad() const { return turned_rad_; }

 private:
  GlimpseOptions options_;
  std::unique_ptr<GridUpdater> grid_;
  AsrBuilderOptions builder_;
  Localizer localizer_;
  double path_spacing_m_;
  std::vector<Point2> path_;
  Point2 last_position_{0.0, 0.0};
  double travelled_m_ = 0.0;
  double turned_rad_ = 0.0;
};

}  // namespace cogmap::mapper
