#pragma once
/// One interface, four occupancy models (thesis §2.2, §3.1.3-3.1.4, Figs. A.1-A.3): HIMM,
/// Modified HIMM, Bayes and Dempster-Shafer. Each integrates sonar readings taken at a robot
/// pose into the current room's grid and presents it on the HIMM scale for the ASR pipeline.

#include <cstddef>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "cogmap/mapper/grid/grid.h"
#include "cogmap/mapper/seam/robot_geometry.h"
#include "cogmap/mapper/seam/sensor_frame.h"

namespace cogmap::mapper {

enum class GridKind { kHimm, kMhimm, kBayes, kDempsterShafer };

/// "himm" | "mhimm" | "bayes" | "dempster_shafer"; nullopt for anything else.
std::optional<GridKind> parse_grid_kind(std::string_view name);
std::string_view to_string(GridKind kind);

struct GridOptions {
  double cell_scale_mm = 100.0;  ///< ℘, thesis Table 4.1 (10 cm cells)
  /// w, thesis §3.1.4: readings within w update the grid. The thesis gives no value. At 3 m
  /// the 30° beam is 1.6 m wide, about the width a room wall is seen at from a route through
  /// the room; measured (docs/results.md) coverage 0.17 -> 0.40 in two_rooms and 0.13 -> 0.26
  /// in nine_rooms going from 2 m to 3 m, while 3.5-4 m added spurious walls.
  double window_m = 3.0;
  /// HIMM/MHIMM: the hit cell gets hit_increment, then every cell of its 3x3 block, the hit
  /// cell included, gets neighbour_increment. The defaults are thesis §2.2.3 (+3 on the cell,
  /// +0.5 on neighbours). Figs. A.2-A.3 (1.5 and 1.5: +3 / +1.5) fatten every wall by a cell
  /// toward the robot, because the neighbour on the beam nets +0.5 per reading, and the clean
  /// map then keeps that inner face: measured 0.12 m median wall error against 0.05 m or less
  /// on the same synthetic room (docs/algorithms.md). Fig. A.2 remains selectable.
  double hit_increment = 2.5;        ///< thesis §2.2.3 (+3 in total on the hit cell)
  double neighbour_increment = 0.5;  ///< each of the 3x3 incl. the hit cell, thesis §2.2.3
  /// MHIMM: how far along its beam a reading WITHOUT an echo clears (metres; capped at w).
  /// Thesis Fig. A.3 clears to the window edge for every reading beyond w, echo or not; a
  /// specular sonar returns nothing from a wall met at more than ~22° from its normal, so a
  /// no-echo beam usually crosses a wall it did not see and Fig. A.3 erodes exactly the walls
  /// parallel to the robot's path. -1 = the thesis (clear to w). docs/algorithms.md.
  double no_echo_clear_m = 0.0;
  double miss_decrement = 1.0;       ///< decrement along the beam, thesis §2.2.3
  double bayes_max_occupied = 0.98;  ///< MO, thesis Table 2.1 (Moravec's maximum occupancy)
  double initial_extent_m = 12.0;    ///< side of a new room's grid before it grows
  /// Bayes/DS region I half-depth as a fraction of the range r; at least one cell. The thesis
  /// gives no tolerance; 1 % is the sonar's range noise (docs/p2at.md).
  double region_one_range_fraction = 0.01;
};

/// Why readings were refused; they are counted, never written into the grid.
struct RejectedReadings {
  std::size_t not_finite = 0;     ///< NaN or infinite range
  std::size_t non_positive = 0;   ///< range <= 0
  std::size_t beyond_max = 0;     ///< range > sonar_max_range_m
  std::size_t unknown_sonar = 0;  ///< index outside RobotGeometry::sonars
  std::size_t total() const { return not_finite + non_positive + beyond_max + unknown_sonar; }
};

class GridUpdater {
 public:
  virtual ~GridUpdater() = default;

  virtual GridKind kind() const = 0;

  /// Starts a fresh room grid centred on `center` (the previous room's cells are dropped).
  virtual void reset(const Point2& center) = 0;

  /// Marks the cell under the robot's centre as robot path (MHIMM: -100, never overwritten).
  virtual void mark_robot(const Pose2& robot_pose) = 0;

  /// Integrates one reading taken with the robot at `robot_pose` (same frame as the grid).
  /// Returns false, and counts the reason, for a reading that must not touch the grid.
  virtual bool integrate(const Pose2& robot_pose, const SonarReading& reading) = 0;

  /// The current room on the HIMM scale (see HistogramGrid).
  virtual HistogramGrid histogram() const = 0;

  /// One cell on the HIMM scale without copying the grid (for obstacle avoidance).
  virtual float histogram_at(CellIndex cell) const = 0;

  /// Row `y` (0 <= y < geometry().height()) on the HIMM scale, geometry().width() values
  /// with x ascending, read in place: the same values as histogram_at, one virtual call per
  /// row instead of per cell. Only updaters that store their cells on the HIMM scale (MHIMM)
  /// provide it; the others return an empty span and are read with histogram_at. Valid until
  /// the next non-const call.
  virtual std::span<const float> histogram_row(int y) const {
    static_cast<void>(y);
    return {};
  }

  virtual const GridGeometry& geometry() const = 0;

  /// Memory the grid's cells occupy, bytes.
  virtual std::size_t grid_bytes() const = 0;

  virtual const RejectedReadings& rejected() const = 0;
};

std::unique_ptr<GridUpdater> make_grid_updater(GridKind kind, const GridOptions& options,
                                               const RobotGeometry& robot);

}  // namespace cogmap::mapper
