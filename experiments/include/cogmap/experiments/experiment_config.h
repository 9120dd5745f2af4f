#pragma once
/// One experiment (experiments/*.yaml, docs/experiment-format.md): which world, which robot
/// source, how to drive, how to map. Parsed strictly: unknown keys, wrong types and values out
/// of range are ConfigErrors naming file, line and key.

#include <yaml-cpp/yaml.h>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "cogmap/mapper/mapper.h"
#include "cogmap/mapper/nav/controller.h"
#include "cogmap/mapper/seam/geometry.h"
#include "cogmap/sim/yaml_strict.h"

namespace cogmap::experiments {

/// Where the frames come from (docs/formats.md `robot.source`).
enum class RobotSource { kSim, kP2os, kLog };

/// How the robot is driven (docs/formats.md `controller.type`).
enum class ControllerKind { kRoute, kExplore, kNone };

std::string_view to_string(RobotSource source);
std::string_view to_string(ControllerKind kind);

/// The `controller` block.
struct ControllerConfig {
  ControllerKind type = ControllerKind::kNone;
  double speed_mps = 0.5;                 ///< cruise speed, thesis §4: about 0.5 m/s
  std::vector<mapper::Point2> waypoints;  ///< world frame, metres (route only)
  double waypoint_tolerance_m = 0.4;      ///< a waypoint counts as reached within this
  /// `pose`: what the controller steers by. `estimate` (default) is the mapper's corrected
  /// pose, all a real robot has. `truth` (simulation only) steers by the true pose, like the
  /// human operator or scripted path of a mapping experiment: the mapper still sees only
  /// odometry and sonar, so map metrics are unaffected, but a drifting estimate can no longer
  /// send the robot into a door post. With `truth` the controller avoids obstacles with its own
  /// short-term sonar memory (placed by the true pose), not with the mapper's grid, which lives
  /// in the estimate frame.
  bool steer_by_truth = false;
  /// `pose: plain_estimate`: the controller steers by a second mapper, fed the same frames,
  /// whose map-only refinements (plain_mapper_options: scan matching, glimpses, the odometry
  /// recalibration, the translation moving the estimate) are off; the map, the trajectory and
  /// every metric come from the first, with the experiment's own `mapper:` settings. The robot
  /// then drives as it would without those refinements, so a map refinement can be measured
  /// on the very same drive (docs/experiment-format.md). Both see only odometry and sonar.
  bool steer_by_plain_estimate = false;
  /// Explore only: `strategy` (frontier, the default, or heading: the thesis's Fig. 1.2
  /// explorer, which never finishes), and budgets after which exploration stops unfinished
  /// (`time_budget_s`, `distance_budget_m`; 0 = none, the run's duration_s still applies).
  mapper::nav::ExploreStrategy explore_strategy = mapper::nav::ExploreStrategy::kFrontier;
  double explore_time_budget_s = 0.0;
  double explore_distance_budget_m = 0.0;
  /// `door_search`: sweep a wall for its door when the probe stalls (DoorOptions); unset =
  /// the controller's default (on for route, off for explore; docs/algorithms.md).
  std::optional<bool> door_search;
  /// `grazing_walls`: while crossing a doorway, a wall closed in on at a grazing angle, seen
  /// only by the side transducers, stops the crossing (DoorOptions::cross_side_walls; off by
  /// default, docs/algorithms.md "Walls met at a grazing angle").
  bool grazing_walls = false;
  /// `plan_over_trail` (explore only): with no frontier reachable, the frontier explorer plans
  /// once more through the cells its centre has passed (ExploreOptions::plan_over_trail, on).
  bool plan_over_trail = true;
  /// `progress_along_path` (explore only): the give-up clock counts progress along what is
  /// left of the planned path, not as the crow flies (ExploreOptions::progress_along_path, off).
  bool progress_along_path = mapper::nav::ExploreOptions{}.progress_along_path;
  /// `blocked_path_s` (explore only): the frontier explorer plans again once the rest of its
  /// path has crossed an obstacle for this long (ExploreOptions::blocked_path_s; 0 = never).
  double blocked_path_s = mapper::nav::ExploreOptions{}.blocked_path_s;
  /// `arc_guard_s` (route and explore): how far ahead in time a move on an arc is checked
  /// against the sensed points (SafetyOptions::arc_guard_s; 0 = off); unset = the
  /// controller's default (off for route, 0.5 s for explore; docs/algorithms.md).
  std::optional<double> arc_guard_s;
};

/// Bounds on what an experiment may ask for (docs/reliability.md "Limits"): beyond them a
/// run would not end in useful time or would fill the disk, so they are input errors.
struct ExperimentLimits {
  /// Longest `duration_s`, seconds: 4 h, past a P2-AT battery (2-3 h, P2AT.md) and 16x the
  /// longest shipped experiment (900 s). An explorer asked for 1e12 s ran forever.
  double max_duration_s = 14400.0;
  /// Largest side of a room grid `mapper:` may ask for, cells: (max_room_extent_m + 2 x 5 m of
  /// sonar range) / cell_scale_mm. 4000 keeps every shipped value (200 m at 55 mm: 3 818) and
  /// a grid under ~16 M cells (a 200 m room at 55 mm peaked at 0.5 GB, 0.8 GB with figures);
  /// 10 mm cells at the default 200 m (21 000 cells a side) grew past 11 GB in 90 s, 2000 m at
  /// 100 mm to 9 GB.
  double max_room_grid_side_cells = 4000.0;
};

/// A fully parsed experiment, overrides applied.
struct Experiment {
  std::filesystem::path file;   ///< the experiment file as given
  std::string name;             ///< `name`
  std::filesystem::path world;  ///< `world`, resolved against the experiment file's folder
  int world_line = 0;           ///< line of the `world` key (errors about the world file)
  std::string world_override;   ///< "(from --set world=...)" when an override set it, else ""
  std::uint64_t seed = 1;       ///< `seed` (or --seed)
  double duration_s = 600.0;    ///< `duration_s`: upper bound of simulated (or real) time
  /// `start` {x_m, y_m, theta_deg}: replaces the world's start pose (e.g. to map only some
  /// rooms of a world); empty = the world's own start.
  std::optional<mapper::Pose2> start;
  RobotSource robot_source = RobotSource::kSim;
  /// The whole `robot` block, validated later by the source's own parser
  /// (sim::parse_sim_robot_options for `sim`, the hw module for `p2os`/`log`).
  std::optional<yaml::Node> robot;
  ControllerConfig controller;
  mapper::MapperOptions mapper;  ///< `mapper` block; sonar range is filled in by the runner
  /// `mapper.max_room_travel_m` was given: else it follows the controller
  /// (apply_controller_defaults).
  bool room_travel_given = false;
  /// `mapper.scan_match`, `mapper.scan_match_shift` and `controller.pose` were given: else
  /// they follow the controller too (apply_controller_defaults).
  bool scan_match_given = false;
  bool scan_match_shift_given = false;
  bool steering_given = false;
  bool figures = true;       ///< `output.figures`
  bool nav_trace = false;    ///< `output.nav_trace`: write nav_trace.csv (diagnostics)
  bool explore_map = false;  ///< `output.explore_map`: the explorer's map (diagnostics)
  /// The document after every override, as YAML text (saved into the run directory so a run
  /// can be repeated exactly).
  std::string resolved_yaml;
};

/// Loads and validates an experiment file. Each `overrides` entry is "a.b.c=value" (--set) and
/// is applied to the document BEFORE validation, so an override naming an unknown key fails
/// like a typo in the file. `seed_override` replaces `seed` (--seed).
/// Throws yaml::ConfigError ("file:line: key: message") on any problem.
Experiment load_experiment(const std::filesystem::path& path,
                           const std::vector<std::string>& overrides = {},
                           std::optional<std::uint64_t> seed_override = std::nullopt);

/// The same for a document given as text; `name` stands for the file in error messages and
/// relative paths resolve against the current directory (drive/replay without --experiment).
Experiment load_experiment_text(const std::string& text, const std::string& name,
                                const std::vector<std::string>& overrides = {});

/// Parses an already loaded document (used by load_experiment and by sweeps, which apply
/// their own overrides). `file` is the path errors name and relative paths resolve against.
Experiment parse_experiment(const yaml::Node& root, const std::filesystem::path& file);

/// The message of a ConfigError without its "file:line: key: " prefix (for re-raising it
/// with more context).
std::string bare_message(const yaml::ConfigError& error);

/// The explorer's `mapper.max_room_travel_m` when the experiment gives none: the thesis's
/// hallway cut (§3.1.2). An exploration tours each room for minutes and the cut halved its
/// corrected heading error; routes cross a room once and keep the thesis's one ASR per room
/// (docs/algorithms.md, "Long rooms cut").
inline constexpr double kExploreMaxRoomTravelM = 4.5;

/// Sets what depends on the controller and was not given: `mapper.max_room_travel_m`
/// (kExploreMaxRoomTravelM for an explorer, 0 otherwise) and, for an explorer, the echo
/// matcher in the map alone: `mapper.scan_match` on, `mapper.scan_match_shift` off and
/// `controller.pose: plain_estimate` (otherwise the library's defaults and `estimate`; docs/
/// algorithms.md, "The matcher in the map only"). load_experiment calls it; call it again after
/// changing `controller.type` (cogmap drive --controller).
void apply_controller_defaults(Experiment& e);

/// Parses the `mapper` block into MapperOptions (defaults: thesis Table 4.1).
mapper::MapperOptions parse_mapper_options(const yaml::Node& block);

}  // namespace cogmap::experiments
