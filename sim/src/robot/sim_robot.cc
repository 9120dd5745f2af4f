// One cycle = physics_substeps of: firmware ramp -> wheel speeds -> floor twist -> Box2D step ->
// encoders -> stall flags; then the sonars that fired during the cycle, against the true poses.
#include "cogmap/sim/sim_robot.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "cogmap/mapper/seam/robot_models.h"
#include "cogmap/sim/seed.h"
#include "cogmap/sim/world_geometry.h"

namespace cogmap::sim {

namespace {

// The model's geometry (robot.model); the options parser has already refused unknown names.
mapper::RobotGeometry geometry_of(const std::string& model) {
  const mapper::RobotModel* m = mapper::find_robot_model(model);
  if (!m) throw std::invalid_argument("SimRobot: unknown robot model '" + model + "'");
  return m->geometry;
}

// Independent random streams derived from the run seed.
constexpr std::uint64_t kSonarStream = 1;
constexpr std::uint64_t kOdometryStream = 2;

const SimRobotOptions& checked(const SimRobotOptions& options) {
  if (!(options.cycle_s > 0.0)) throw std::invalid_argument("SimRobot: cycle_s must be positive");
  if (options.physics_substeps < 1) {
    throw std::invalid_argument("SimRobot: physics_substeps must be at least 1");
  }
  return options;
}

PhysicsOptions physics_for(const SimRobotOptions& options, const mapper::RobotGeometry& g) {
  PhysicsOptions physics = options.physics;
  physics.body_length_m = g.length_m;
  physics.body_width_m = g.width_m;
  return physics;
}

MotionLimits limits_for(const SimRobotOptions& options, const mapper::RobotGeometry& g) {
  MotionLimits limits = MotionLimits::from_geometry(g);
  limits.rot_accel_radps2 = options.rot_accel_radps2;
  limits.rot_decel_radps2 = options.rot_accel_radps2;
  return limits;
}

StallOptions stall_for(const SimRobotOptions& options) {
  StallOptions stall = options.stall;
  stall.track_m = options.odometry.track_m;
  return stall;
}

// The twist that carried the body from `before` to `after` in dt_s, robot frame.
BodyTwist measured_twist(const mapper::Pose2& before, const mapper::Pose2& after, double dt_s) {
  const double dtheta = mapper::wrap_angle_rad(after.theta_rad - before.theta_rad);
  const double mid = before.theta_rad + 0.5 * dtheta;
  const mapper::Point2 d = after.translation() - before.translation();
  return {(d.x() * std::cos(mid) + d.y() * std::sin(mid)) / dt_s, dtheta / dt_s};
}

}  // namespace

SimRobot::SimRobot(const WorldSpec& world, const SimRobotOptions& options, std::uint64_t seed)
    : options_(checked(options)),
      geometry_(geometry_of(options.model)),
      scene_(surface_segments(world)),
      physics_(std::make_unique<PhysicsWorld>(world, physics_for(options, geometry_))),
      limiter_(limits_for(options, geometry_)),
      drive_(options.odometry, derive_seed(seed, kOdometryStream)),
      sonar_(options.sonar, geometry_, derive_seed(seed, kSonarStream)),
      stall_(stall_for(options)) {}

SimRobot::~SimRobot() = default;

double SimRobot::sim_time_s() const { return static_cast<double>(cycles_) * options_.cycle_s; }

void SimRobot::command(const mapper::VelocityCommand& cmd) { target_ = limiter_.clamp(cmd); }

void SimRobot::stop() { target_ = {}; }

std::optional<mapper::SensorFrame> SimRobot::next_frame() {
  const int n = options_.physics_substeps;
  const double dt_s = options_.cycle_s / n;
  const double t0_s = sim_time_s();
  const double t1_s = static_cast<double>(cycles_ + 1) * options_.cycle_s;
  step_times_s_.assign(1, t0_s);
  step_poses_.assign(1, physics_->pose());
  for (int k = 1; k <= n; ++k) {
    const mapper::VelocityCommand& ramped = limiter_.step(target_, dt_s);
    const WheelSpeeds wheels = drive_.wheel_speeds(ramped);
    const BodyTwist expected = drive_.body_twist(wheels, dt_s);
    const mapper::Pose2 before = physics_->pose();
    const mapper::Pose2& after = physics_->step(expected, dt_s);
    // Encoders count wheel turns whether or not the body moved: a stalled robot's odometry
    // keeps running, as a real one's does.
    drive_.integrate_encoders(wheels, dt_s);
    stall_.update(wheels, expected, measured_twist(before, after, dt_s), physics_->in_contact(),
                  dt_s);
    step_times_s_.push_back(k == n ? t1_s : t0_s + k * dt_s);
    step_poses_.push_back(after);
  }
  ++cycles_;

  mapper::SensorFrame frame;
  frame.time_s = t1_s;
  frame.odometry = drive_.odometry();
  frame.sonar = sonar_.cycle(scene_, t0_s, t1_s, [this](double t) { return pose_at(t); });
  frame.stall_left = stall_.left();
  frame.stall_right = stall_.right();
  frame.true_pose = physics_->pose();
  return frame;
}

mapper::Pose2 SimRobot::pose_at(double time_s) const {
  if (time_s <= step_times_s_.front()) return step_poses_.front();
  if (time_s >= step_times_s_.back()) return step_poses_.back();
  const auto it = std::upper_bound(step_times_s_.begin(), step_times_s_.end(), time_s);
  const std::size_t i = static_cast<std::size_t>(it - step_times_s_.begin());
  const double f = (time_s - step_times_s_[i - 1]) / (step_times_s_[i] - step_times_s_[i - 1]);
  const mapper::Pose2& a = step_poses_[i - 1];
  const mapper::Pose2& b = step_poses_[i];
  return {
      a.x_m + f * (b.x_m - a.x_m), a.y_m + f * (b.y_m - a.y_m),
      mapper::wrap_angle_rad(a.theta_rad + f * mapper::wrap_angle_rad(b.theta_rad - a.theta_rad))};
}

}  // namespace cogmap::sim
