#pragma once
/// metrics.json of one run (docs/metrics.md): the required keys of docs/formats.md plus
/// extras (per-room sizes, rejected readings, the map before localisation). Metrics that need
/// ground truth are omitted, not faked, when there is none.

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "cogmap/experiments/error_breakdown.h"
#include "cogmap/experiments/metrics.h"
#include "cogmap/experiments/nav_metrics.h"
#include "cogmap/mapper/grid/grid_updater.h"
#include "cogmap/mapper/localization/localizer.h"
#include "cogmap/mapper/mapper.h"

namespace cogmap::experiments {

/// What EM measured for one room against the rooms before it (docs/algorithms.md, §3.1.9
/// and "Odometry prior on the rotation"): enough to check its claimed sd against the truth.
struct RoomLocalizationReport {
  double measured_rotation_deg = 0.0;  ///< EM's answer before the prior
  double measurement_sd_deg = 0.0;     ///< the sd EM claims for it
  double longest_wall_m = 0.0;         ///< the room's longest straight piece of wall
  std::optional<double> prior_sd_deg;  ///< odometry's prior on the rotation (none: no prior)
  double gain = 0.0;                   ///< the share of the measurement applied
  bool applied = false;                ///< false: too little wall, too big, or gated out
  /// With mapper.translation: the shift applied after the rotation (metres, x and y; zero when
  /// not applied), whether it was, and the wall pairs that measured it. None otherwise.
  std::optional<std::array<double, 2>> translation_m;
  bool translation_applied = false;
  int translation_pairs = 0;
};

/// The report of EM's answer, in degrees.
RoomLocalizationReport room_localization_report(const mapper::Localization& l);

/// One finished room as reported in metrics.json "rooms".
struct RoomReport {
  RoomSize size;
  std::optional<int> parent;
  double heading_correction_deg = 0.0;  ///< EM rotation applied about the reference point
  std::optional<RoomLocalizationReport> localization;  ///< none: the first room, or EM off
  double start_time_s = 0.0;
  double end_time_s = 0.0;
};

/// Everything metrics.json holds.
struct RunMetrics {
  std::string name;  ///< experiment name
  std::string world;
  std::uint64_t seed = 0;
  std::string source;                 ///< sim | p2os | log
  std::string controller;             ///< route | explore | none
  std::string steering = "estimate";  ///< controller.pose: estimate | plain_estimate | truth
  std::string grid;                   ///< himm | mhimm | bayes | dempster_shafer
  std::string boundary;               ///< doorway | distance
  std::string localization_kind;      ///< em | none
  /// The odometry recalibration the mapper used (mapper.odometry_curvature_gain, 0 for a
  /// differential drive) and the robot's odometry track: scripts/fit-odometry-curvature adds its
  /// fit to the gain the runs were made with.
  double odometry_curvature_gain = 0.0;
  double odometry_track_m = 0.0;
  double max_room_travel_m = 0.0;  ///< the long-room cut the mapper used (0: doorways only)
  std::size_t asr_count = 0;
  std::size_t frames = 0;
  std::optional<bool> route_completed;      ///< route controllers only
  NavMetrics nav;                           ///< how the robot drove itself (the nav block)
  std::optional<MapAccuracy> map;           ///< after localisation; needs ground truth
  std::optional<MapAccuracy> map_odometry;  ///< before localisation; needs ground truth
  MemoryMetrics memory;
  std::optional<LocalizationAccuracy> localization;  ///< needs ground truth
  std::optional<ErrorBreakdown> error_breakdown;     ///< per-stage error; needs ground truth
  std::size_t readings_used = 0;
  mapper::RejectedReadings rejected;
  std::size_t door_fixes = 0;          ///< doorways passed again that moved the estimate
  double door_fix_total_m = 0.0;       ///< the sum of those moves' lengths
  std::size_t held_turns = 0;          ///< turns on the spot found made while the body was held
  double held_turn_removed_deg = 0.0;  ///< the turn taken out of the odometry for them
  /// The end-of-run relaxation of the rooms' positions (mapper.relax; absent when off).
  struct Relaxation {
    std::size_t rooms_moved = 0;
    double total_m = 0.0;  ///< Σ |shift| over the rooms
    double max_m = 0.0;
    double wall_thickness_m = 0.0;  ///< as estimated from walls seen from both sides
    std::size_t pairs = 0;          ///< wall pairs in its last round
  };
  std::optional<Relaxation> relaxation;
  /// The estimate kept on the echoes of the last minute (mapper.scan_match; absent when off).
  struct ScanMatch {
    std::size_t matches = 0;          ///< tried
    std::size_t measured = 0;         ///< of which enough echoes met the memory's walls
    double rotation_total_deg = 0.0;  ///< Σ |rotation applied|
    double shift_total_m = 0.0;       ///< Σ |shift applied|
  };
  std::optional<ScanMatch> scan_match;
  std::vector<RoomReport> rooms;
  double sim_time_s = 0.0;           ///< time of the last frame
  double wall_time_s = 0.0;          ///< run loop + metrics, figures excluded
  double build_time_s = 0.0;         ///< CPU in the ASR pipeline (mapper stats)
  double localization_time_s = 0.0;  ///< CPU in EM (mapper stats)
  /// Per finished room, in order: time in its ASR pipeline and EM (the thesis claims it flat
  /// however many rooms came before; issue 13).
  std::vector<double> room_cpu_s;
  /// Per finished room, in order: wall time of the run loop from the previous room's end (the
  /// loop's start for the first) to this room's, figures excluded: everything a user waits for
  /// while the room is driven and mapped (simulation, navigation, mapping, metrics).
  std::vector<double> room_wall_s;
};

/// The relaxation block from the mapper's figures; none when the relaxation did not run
/// (mapper.relax off, or no localisation).
std::optional<RunMetrics::Relaxation> relaxation_metrics(const mapper::MapperOptions& options,
                                                         const mapper::MapperStats& stats);

/// The scan-match block from the mapper's figures; none when mapper.scan_match is off.
std::optional<RunMetrics::ScanMatch> scan_match_metrics(const mapper::MapperOptions& options,
                                                        const mapper::MapperStats& stats);

/// The JSON text (2-space indent, keys in a fixed order, shortest round-trip doubles, null for
/// undefined values). Everything outside "timing" is a pure function of the run's inputs.
std::string metrics_json_text(const RunMetrics& metrics);

}  // namespace cogmap::experiments
