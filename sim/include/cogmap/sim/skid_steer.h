#pragma once
/// Skid-steer drive and wheel odometry of a simulated P2-AT. The firmware turns (v, w) into wheel
/// speeds with a calibrated track; the floor lets the body turn with an effective track that
/// differs from it, varies with curvature and drifts slowly; encoders count wheel motion (also
/// when stalled) and odometry integrates them with the calibrated track. So odometry heading
/// drifts the way a real Pioneer's does, not as white noise. docs/odometry-model.md explains it.

#include <cstdint>
#include <random>

#include "cogmap/mapper/seam/pose2.h"
#include "cogmap/mapper/seam/velocity_command.h"
#include "cogmap/sim/yaml_strict.h"

namespace cogmap::sim {

/// Surface speeds of the left and right wheel pairs, metres per second.
struct WheelSpeeds {
  double left_mps = 0;   ///< left side, forward positive
  double right_mps = 0;  ///< right side, forward positive
};

/// What the body actually does over one step, robot frame.
struct BodyTwist {
  double v_mps = 0;    ///< forward speed, metres per second
  double w_radps = 0;  ///< turn rate, radians per second, CCW positive
};

/// Slip and encoder parameters. Defaults: a P2-AT on a hard indoor floor (docs/p2at.md,
/// docs/odometry-model.md). Track values are B = track_m × factor.
struct OdometryOptions {
  /// Physical distance between the left and right wheel centres, metres (P2-AT ~394 mm).
  double track_m = 0.394;
  /// Track the firmware and odometry use, over track_m: ARIA's DiffConvFactor 0.0034 for the
  /// P2-AT implies ~588 mm, i.e. 1.5 (docs/p2at.md).
  double calibrated_track_factor = 1.5;
  /// Mean effective track the floor allows in a spin in place, over track_m. Equal to the
  /// calibrated value by default (a robot calibrated on this floor); raise it for a slippier one.
  double effective_track_factor = 1.5;
  /// Relative change of the effective track from a spin in place (spin fraction 1) to a gentle
  /// arc (spin fraction 0): B_eff ∝ 1 + curvature_gain × (spin_fraction - 1). Gentle arcs skid
  /// less, so the track shrinks toward the physical one. 5 % is an assumption; measure it.
  double curvature_gain = 0.05;
  /// Stationary standard deviation of the slowly varying relative track error (floor texture,
  /// dust, tyre temperature), an Ornstein-Uhlenbeck process. Assumed 2 %.
  double track_noise_sd = 0.02;
  /// Correlation time of that process, seconds. Assumed 5 s (a few metres of floor).
  double track_noise_correlation_s = 5.0;
  /// Heading random walk while driving, radians per sqrt(metre) travelled: uneven floor and
  /// tyre deformation. 0.005 rad/sqrt(m) gives ~0.9 deg sd after 10 m. Assumed.
  double heading_walk_sd_rad_per_sqrt_m = 0.005;
  /// Mean relative error of forward speed against the encoders (tyre radius), unitless.
  double speed_scale_bias = 0.0;
  /// Per-run spread of that error, drawn once from the seed (tyre pressure and wear), ~0.5 %.
  double speed_scale_sd = 0.005;
  /// Encoder resolution at the tyre, metres per tick; 0 counts continuously. ~76 ticks per mm
  /// (ARIA's TicksMM for Pioneer 3 ATs; verify on a P2-AT).
  double encoder_tick_m = 1.0 / 76000.0;
};

/// Options with every error switched off: effective track == calibrated track, no noise, no
/// quantisation. Odometry then equals the truth.
OdometryOptions ideal_odometry_options();

/// Reads the experiment's `robot.odometry` block; every key is optional. `preset: ideal` starts
/// from ideal_odometry_options() (`preset: p2at`, the default, from OdometryOptions{}), then the
/// other keys override. Unknown keys and wrong types throw yaml::ConfigError (file, line, key).
OdometryOptions parse_odometry_options(const yaml::Node& node);

/// Advances `pose` by a forward arc of length ds_m turning by dtheta_rad (midpoint rule), the
/// integrator odometry uses; simulation truth may use it too so both integrate alike.
mapper::Pose2 advance_pose(const mapper::Pose2& pose, double ds_m, double dtheta_rad);

/// The drive train: firmware, floor and encoders. Random draws come only from the seed.
class SkidSteerDrive {
 public:
  /// Throws std::invalid_argument for non-positive tracks or negative spreads.
  SkidSteerDrive(const OdometryOptions& options, std::uint64_t seed);

  /// Firmware: (v, w) -> wheel surface speeds with the calibrated track.
  WheelSpeeds wheel_speeds(const mapper::VelocityCommand& cmd) const;

  /// What the floor allows over the next dt_s: the effective track varies with curvature and a
  /// slowly varying seeded error, forward speed carries the per-run scale error, and driving adds
  /// a heading random walk. Advances the random state (call once per step).
  BodyTwist body_twist(const WheelSpeeds& wheels, double dt_s);

  /// Encoders count the wheel motion over dt_s (also when the body is stalled); odometry
  /// integrates the counts with the calibrated track.
  void integrate_encoders(const WheelSpeeds& wheels, double dt_s);

  /// Encoder-integrated pose in the odometry frame, which starts at (0, 0, 0).
  const mapper::Pose2& odometry() const { return odometry_; }

  /// Distance counted by the left / right encoders since the start, metres (quantised).
  double left_counted_m() const { return left_counted_m_; }
  double right_counted_m() const { return right_counted_m_; }

  /// Calibrated track B_cal = track_m × calibrated_track_factor, metres.
  double calibrated_track_m() const { return calibrated_track_m_; }
  /// Effective track the floor applies to `wheels` right now (mean value, curvature and the
  /// current slow error included), metres.
  double effective_track_m(const WheelSpeeds& wheels) const;
  /// The per-run forward speed scale error drawn from the seed (plus the bias), unitless.
  double speed_scale_error() const { return speed_scale_error_; }

 private:
  OdometryOptions options_;
  std::mt19937_64 rng_;
  double calibrated_track_m_;
  double speed_scale_error_;
  double track_error_ = 0.0;  ///< current value of the Ornstein-Uhlenbeck track error
  double left_travel_m_ = 0.0;
  double right_travel_m_ = 0.0;
  double left_counted_m_ = 0.0;
  double right_counted_m_ = 0.0;
  mapper::Pose2 odometry_;
};

}  // namespace cogmap::sim
