#pragma once
/// The `nav` block of metrics.json (docs/metrics.md): how the robot drove itself. Everything
/// but `contacts`/`contact_s` comes from what the robot itself knows (odometry, stall flags,
/// the controller's own account); contacts need the true pose and the true surfaces.

#include <cstddef>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "cogmap/experiments/metrics.h"
#include "cogmap/experiments/segment_index.h"
#include "cogmap/mapper/nav/controller.h"
#include "cogmap/mapper/seam/geometry.h"
#include "cogmap/mapper/seam/robot_geometry.h"

namespace cogmap::experiments {

/// How a contact episode began (needs truth): what the controller was doing and where on the
/// body the touch was.
struct ContactOnset {
  double t_s = 0.0;
  /// The mode that commanded the motion into the contact (`to_string(NavMode)`: the last
  /// command before the frame that touched).
  std::string mode;
  /// The point of the footprint's outline nearest the surface touched, body frame (x forward,
  /// y left), metres: a front corner is (0.313, ±0.2525) on a P2-AT.
  mapper::Point2 body_m{0.0, 0.0};
};

/// From row `first_row` on (until the next change), the controller mode whose command led into
/// each row's frame.
struct ModeChange {
  std::size_t first_row = 0;
  mapper::nav::NavMode mode = mapper::nav::NavMode::kIdle;
};

/// The nav block.
struct NavMetrics {
  std::optional<bool> route_completed;       ///< route controllers only
  std::size_t waypoints_total = 0;           ///< route controllers only
  std::size_t waypoints_skipped = 0;         ///< given up after bounded recoveries
  std::size_t recoveries = 0;                ///< back-off-and-turn recoveries started
  std::size_t door_passages = 0;             ///< doorways passed by the door behaviour
  std::optional<std::size_t> contacts;       ///< touches of a wall or obstacle (needs truth)
  std::optional<double> contact_s;           ///< frames in contact × frame time (needs truth)
  std::vector<double> contact_start_s;       ///< when each contact episode began (needs truth)
  std::vector<ContactOnset> contact_onsets;  ///< the same episodes: mode and place on the body
  double distance_m = 0.0;                   ///< odometry path length (the robot's own count)
  double stalled_s = 0.0;                    ///< time with either stall flag set
  std::optional<std::size_t> rooms_visited;  ///< explore: rooms the explorer entered
  /// explore: rooms of the true world (true_rooms.h; needs truth)
  std::optional<std::size_t> rooms_total_true;
  /// explore: true rooms the true trajectory entered (needs truth)
  std::optional<std::size_t> rooms_visited_true;
  std::optional<bool> exploration_complete;  ///< explore: stopped with no unexplored exit left
  /// Odometry heading change summed over frames, degrees: every turn costs heading on a
  /// skid-steer base (docs/odometry-model.md), so this says what the drift had to work with.
  double turn_deg = 0.0;
  /// The same turning and the time, split by the controller mode that commanded it
  /// (`to_string(NavMode)`); modes never entered are absent.
  std::map<std::string, double> turn_deg_by_mode;
  std::map<std::string, double> time_s_by_mode;
  /// Needs ground truth (empty otherwise): the odometry heading error each mode's frames added,
  /// signed, degrees (Σ of odometry Δθ − true Δθ over the mode's frame intervals). Their sum is
  /// the final odometry heading error, so this says which behaviour the drift came from.
  std::map<std::string, double> heading_drift_deg_by_mode;
};

/// Adds one frame interval to the turning tallies: `dtheta_rad` is the odometry heading change
/// over the interval (wrapped to [-π, π)), `dt_s` its length, `mode` the mode commanding it.
void add_mode_interval(NavMetrics& nav, const std::string& mode, double dtheta_rad, double dt_s);

/// Adds one frame interval's odometry heading error to `mode`'s drift tally: the odometry
/// heading change minus the true one, each wrapped to [-π, π) (a change across ±180° counts
/// as the short way round).
void add_mode_drift(NavMetrics& nav, const std::string& mode, double odometry_dtheta_rad,
                    double true_dtheta_rad);

/// A frame counts as a contact when the true footprint (a length_m × width_m rectangle about
/// the centre) is within this of a true surface: Box2D keeps polygons 0.01 m apart (its
/// polygon skin), so a touching body sits 0.00-0.02 m from the surface.
inline constexpr double kContactDistanceM = 0.02;

/// Counts contact episodes (a run of consecutive frames in contact is one) and their time,
/// from the true poses of `rows` (rows without truth are skipped) against `surfaces`, and how
/// each began (contact_onsets): `modes`, in row order, says from which row on which controller
/// mode's command led into the rows' frames (rows before the first change: "unknown").
/// `index`, if given, must index exactly `surfaces`: it only skips, untested, the poses with no
/// surface within reach of the footprint (the answer is the same).
void add_contacts(NavMetrics& nav, TrajectoryView rows, std::span<const mapper::Segment> surfaces,
                  const mapper::RobotGeometry& robot, const SegmentIndex* index = nullptr,
                  std::span<const ModeChange> modes = {});

/// The point of the footprint's outline (a length_m × width_m rectangle about `pose`) nearest
/// any of `surfaces`, in the body frame (x forward, y left); nullopt without surfaces.
std::optional<mapper::Point2> nearest_outline_point(const mapper::Pose2& pose,
                                                    std::span<const mapper::Segment> surfaces,
                                                    const mapper::RobotGeometry& robot);

/// Odometry path length of `rows`, metres.
double odometry_distance_m(TrajectoryView rows);

}  // namespace cogmap::experiments
