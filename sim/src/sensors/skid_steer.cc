#include "cogmap/sim/skid_steer.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace cogmap::sim {
namespace {

// The effective track never falls below this fraction of its mean, however large the configured
// noise: a negative or vanishing track would turn the robot the wrong way or infinitely fast.
constexpr double kMinTrackScale = 0.1;

// 0 for straight driving, 1 for a spin in place or a pivot on one side: how hard the tyres must
// skid sideways for this pair of wheel speeds.
double spin_fraction(const WheelSpeeds& w) {
  const double sum = std::abs(w.left_mps) + std::abs(w.right_mps);
  return sum > 0.0 ? std::abs(w.right_mps - w.left_mps) / sum : 0.0;
}

double quantise(double travel_m, double tick_m) {
  return tick_m > 0.0 ? tick_m * std::round(travel_m / tick_m) : travel_m;
}

}  // namespace

OdometryOptions ideal_odometry_options() {
  OdometryOptions o;
  o.effective_track_factor = o.calibrated_track_factor;
  o.curvature_gain = 0.0;
  o.track_noise_sd = 0.0;
  o.heading_walk_sd_rad_per_sqrt_m = 0.0;
  o.speed_scale_bias = 0.0;
  o.speed_scale_sd = 0.0;
  o.encoder_tick_m = 0.0;
  return o;
}

mapper::Pose2 advance_pose(const mapper::Pose2& pose, double ds_m, double dtheta_rad) {
  const double mid = pose.theta_rad + 0.5 * dtheta_rad;
  return {pose.x_m + ds_m * std::cos(mid), pose.y_m + ds_m * std::sin(mid),
          mapper::wrap_angle_rad(pose.theta_rad + dtheta_rad)};
}

SkidSteerDrive::SkidSteerDrive(const OdometryOptions& options, std::uint64_t seed)
    : options_(options), rng_(seed) {
  auto require = [](bool ok, const std::string& what) {
    if (!ok) throw std::invalid_argument("SkidSteerDrive: " + what);
  };
  require(options_.track_m > 0.0, "track_m must be > 0");
  require(options_.calibrated_track_factor > 0.0, "calibrated_track_factor must be > 0");
  require(options_.effective_track_factor > 0.0, "effective_track_factor must be > 0");
  require(options_.track_noise_sd >= 0.0, "track_noise_sd must be >= 0");
  require(options_.track_noise_correlation_s > 0.0, "track_noise_correlation_s must be > 0");
  require(options_.heading_walk_sd_rad_per_sqrt_m >= 0.0,
          "heading_walk_sd_rad_per_sqrt_m must be >= 0");
  require(options_.speed_scale_sd >= 0.0, "speed_scale_sd must be >= 0");
  require(options_.encoder_tick_m >= 0.0, "encoder_tick_m must be >= 0");
  calibrated_track_m_ = options_.track_m * options_.calibrated_track_factor;
  std::normal_distribution<double> normal(0.0, 1.0);
  speed_scale_error_ = options_.speed_scale_bias + options_.speed_scale_sd * normal(rng_);
  // Start the slow track error in its stationary distribution, so a run has no warm-up transient.
  track_error_ = options_.track_noise_sd * normal(rng_);
}

WheelSpeeds SkidSteerDrive::wheel_speeds(const mapper::VelocityCommand& cmd) const {
  const double half = 0.5 * calibrated_track_m_ * cmd.w_radps;
  return {cmd.v_mps - half, cmd.v_mps + half};
}

double SkidSteerDrive::effective_track_m(const WheelSpeeds& wheels) const {
  const double curvature = 1.0 + options_.curvature_gain * (spin_fraction(wheels) - 1.0);
  const double scale = std::max(kMinTrackScale, curvature * (1.0 + track_error_));
  return options_.track_m * options_.effective_track_factor * scale;
}

BodyTwist SkidSteerDrive::body_twist(const WheelSpeeds& wheels, double dt_s) {
  BodyTwist out;
  out.v_mps = 0.5 * (wheels.left_mps + wheels.right_mps) * (1.0 + speed_scale_error_);
  if (dt_s <= 0.0) {
    out.w_radps = (wheels.right_mps - wheels.left_mps) / effective_track_m(wheels);
    return out;
  }
  // Two draws every step whatever the motion, so the stream stays aligned across scenarios.
  std::normal_distribution<double> normal(0.0, 1.0);
  const double z_track = normal(rng_);
  const double z_walk = normal(rng_);
  // Exact Ornstein-Uhlenbeck step: keeps the stationary sd for any dt.
  const double decay = std::exp(-dt_s / options_.track_noise_correlation_s);
  track_error_ =
      decay * track_error_ + options_.track_noise_sd * std::sqrt(1.0 - decay * decay) * z_track;

  out.w_radps = (wheels.right_mps - wheels.left_mps) / effective_track_m(wheels);
  // Heading random walk: variance grows with distance travelled, not with time.
  const double ds_m = std::abs(out.v_mps) * dt_s;
  out.w_radps += options_.heading_walk_sd_rad_per_sqrt_m * std::sqrt(ds_m) * z_walk / dt_s;
  return out;
}

void SkidSteerDrive::integrate_encoders(const WheelSpeeds& wheels, double dt_s) {
  left_travel_m_ += wheels.left_mps * dt_s;
  right_travel_m_ += wheels.right_mps * dt_s;
  const double left_now = quantise(left_travel_m_, options_.encoder_tick_m);
  const double right_now = quantise(right_travel_m_, options_.encoder_tick_m);
  const double dl = left_now - left_counted_m_;
  const double dr = right_now - right_counted_m_;
  left_counted_m_ = left_now;
  right_counted_m_ = right_now;
  odometry_ = advance_pose(odometry_, 0.5 * (dl + dr), (dr - dl) / calibrated_track_m_);
}

}  // namespace cogmap::sim
