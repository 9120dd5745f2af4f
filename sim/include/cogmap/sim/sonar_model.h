#pragma once
/// The Polaroid sonar ring of a simulated Pioneer: specular reflection (no echo from a wall seen
/// obliquely), echoes from corners at any angle, one-bounce multipath (a longer, wrong range),
/// range-proportional noise, dropouts, receiver blanking and the sequential firing schedule.
/// docs/sonar-model.md explains the physics and every parameter.

#include <cstdint>
#include <functional>
#include <memory>
#include <random>
#include <vector>

#include "cogmap/mapper/seam/geometry.h"
#include "cogmap/mapper/seam/pose2.h"
#include "cogmap/mapper/seam/robot_geometry.h"
#include "cogmap/mapper/seam/sensor_frame.h"
#include "cogmap/sim/yaml_strict.h"

namespace cogmap::sim {

namespace sonar_detail {
class SceneIndex;
}  // namespace sonar_detail

/// What sonar can hit, world frame, metres.
struct SonarScene {
  std::vector<mapper::Segment>
      surfaces;  ///< every true surface (walls both faces, obstacle outlines)
  std::vector<mapper::Point2> corners;  ///< convex corners/edges that echo from any angle
};

/// Parameters of the sonar model. Defaults model a Polaroid 600-series ring on a P2-AT
/// (docs/p2at.md, docs/sonar-model.md).
struct SonarModelOptions {
  /// Largest angle between the ray and the surface normal that still echoes, degrees.
  /// Smooth walls return the 50 kHz pulse only within roughly 20-25 deg of normal (docs/p2at.md).
  double critical_angle_deg = 22.5;
  /// Rays cast across the 30 deg cone; 9 gives 3.75 deg spacing, finer than the critical angle.
  int rays_per_cone = 9;
  /// Range noise standard deviation as a fraction of range: ~1 % (docs/p2at.md).
  double range_noise_fraction = 0.01;
  /// Constant noise floor (sd), metres: timer and threshold jitter of the receiver, ~1 cm.
  double range_noise_floor_m = 0.01;
  /// Probability that a ping reports no echo regardless of the scene (absorbing surfaces, missed
  /// threshold). Assumed 2 %; measure on the real robot.
  double dropout_probability = 0.02;
  /// Follow one specular bounce; an echo via a second surface reads longer than the truth.
  bool multipath = true;
  /// Time between two consecutive transducer firings, seconds: the P2 sonar board fires one
  /// transducer every 40 ms (25 Hz over the ring).
  double transducer_period_s = 0.04;
  /// Transducer indices in firing order, cyclic; empty means 0, 1, ..., N-1 (the P2-AT default:
  /// front 0..7 then rear 8..15).
  std::vector<int> firing_order;
  /// A ray whose hit point lies within this distance of a listed corner echoes whatever the
  /// incidence; also the line-of-sight tolerance for corners, metres.
  double corner_radius_m = 0.05;
};

/// Reads the experiment's `robot.sonar` block; every key is optional, unknown keys and wrong
/// types throw yaml::ConfigError with file, line and key.
SonarModelOptions parse_sonar_options(const yaml::Node& node);

/// The geometric echo of one transducer before noise: what the receiver would hear first.
struct SonarEcho {
  bool echo = false;       ///< false when nothing returns within max range
  double range_m = 0.0;    ///< one-way range (half the out-and-back path), metres
  bool multipath = false;  ///< true when the first echo came via a specular bounce
};

/// The sonar ring: stateless apart from its random stream, so readings depend only on the seed,
/// the scene, the true poses and the firing times.
class SonarModel {
 public:
  /// Throws std::invalid_argument for options out of range or a firing order naming a transducer
  /// the geometry does not have.
  SonarModel(const SonarModelOptions& options, const mapper::RobotGeometry& geometry,
             std::uint64_t seed);

  /// Readings of the transducers that fire in (t0_s, t1_s]; true_pose_at(t) gives the true pose
  /// (world) at time t. Firing k (k = 0, 1, ...) happens at (k + 1) * transducer_period_s and
  /// uses firing_order[k mod size], so consecutive intervals partition the pings exactly.
  std::vector<mapper::SonarReading> cycle(const SonarScene& scene, double t0_s, double t1_s,
                                          const std::function<mapper::Pose2(double)>& true_pose_at);

  /// One noisy reading of transducer `index` at `true_pose` (world); time_s is copied through.
  mapper::SonarReading ping(const SonarScene& scene, const mapper::Pose2& true_pose, int index,
                            double time_s);

  /// The noise-free first echo of transducer `index` at `true_pose` (world), before blanking,
  /// noise and dropouts. Deterministic; consumes no random numbers.
  SonarEcho geometric_echo(const SonarScene& scene, const mapper::Pose2& true_pose,
                           int index) const;

  /// The configured range noise standard deviation at `range_m`, metres.
  double range_noise_sd_m(double range_m) const;

  /// The firing order in use (the default filled in).
  const std::vector<int>& firing_order() const { return order_; }

 private:
  SonarModelOptions options_;
  mapper::RobotGeometry geometry_;
  std::vector<int> order_;
  std::mt19937_64 rng_;
  /// Spatial index of the last scene pinged, rebuilt when a scene differs from it bit for bit.
  /// It only speeds up the ray casts (results are identical to a full scan); mutable because it
  /// is a cache, so geometric_echo stays const (one model is not meant to be shared between
  /// threads: ping() already advances its random stream).
  mutable std::shared_ptr<const sonar_detail::SceneIndex> index_;
};

}  // namespace cogmap::sim
