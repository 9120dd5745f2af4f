#pragma once
/// The simulated P2-AT behind the mapper's seam: Box2D body in a world from YAML, firmware
/// speed limits, skid-steer slip and encoders, the sonar ring. Every random draw comes from the
/// one seed, so the same world, options and seed give bit-identical frames.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cogmap/mapper/seam/robot.h"
#include "cogmap/sim/motion_limiter.h"
#include "cogmap/sim/physics_world.h"
#include "cogmap/sim/skid_steer.h"
#include "cogmap/sim/sonar_model.h"
#include "cogmap/sim/stall_detector.h"
#include "cogmap/sim/world_spec.h"
#include "cogmap/sim/yaml_strict.h"

namespace cogmap::sim {

/// Everything the experiment file's `robot:` block sets for a simulated robot
/// (docs/simulator.md lists the keys).
struct SimRobotOptions {
  std::string model = "p2at";       ///< robot.model: geometry and drive (mapper robot_models.h)
  SonarModelOptions sonar;          ///< robot.sonar (docs/sonar-model.md)
  OdometryOptions odometry;         ///< robot.odometry (docs/odometry-model.md)
  double cycle_s = 0.1;             ///< one frame per cycle: the P2-AT's 100 ms SIP period
  int physics_substeps = 10;        ///< Box2D steps per cycle (10 ms each by default)
  double rot_accel_radps2 = 1.745;  ///< turn-rate ramp, rad/s² (ARIA default 100 deg/s²)
  PhysicsOptions physics;           ///< body and solver (not in YAML: the P2-AT is fixed)
  StallOptions stall;               ///< stall thresholds (not in YAML)
};

/// Reads the experiment's `robot:` block for a simulated robot. Keys: source (must be `sim`),
/// model (any of mapper::robot_model_names(); a differential-drive model also sets the
/// odometry's track defaults, which robot.odometry keys override), sonar, odometry, cycle_s (> 0),
/// physics_substeps (1..1000), rot_accel_radps2 (> 0); all optional. Throws yaml::ConfigError
/// (file, line, key).
SimRobotOptions parse_sim_robot_options(const yaml::Node& robot_block);

/// A simulated robot. next_frame() never ends: the runner decides how long to drive.
class SimRobot final : public mapper::Robot {
 public:
  /// Builds the physics and sensor models. Throws std::invalid_argument for options out of
  /// range (non-positive cycle, fewer than one substep) and whatever the models throw.
  SimRobot(const WorldSpec& world, const SimRobotOptions& options, std::uint64_t seed);
  ~SimRobot() override;

  const mapper::RobotGeometry& geometry() const override { return geometry_; }

  /// Advances one cycle and returns its frame: time at the end of the cycle, odometry, the
  /// sonars fired during the cycle, stall flags and the true pose.
  std::optional<mapper::SensorFrame> next_frame() override;

  /// Sets the command (clamped to the speed limits) that holds from the next physics step.
  void command(const mapper::VelocityCommand& cmd) override;
  void stop() override;

  /// The true pose now, world frame.
  const mapper::Pose2& true_pose() const { return physics_->pose(); }
  /// Simulated time now, seconds since the start.
  double sim_time_s() const;
  /// The surfaces and corners the sonar sees (world frame).
  const SonarScene& scene() const { return scene_; }
  /// The options in use.
  const SimRobotOptions& options() const { return options_; }

  /// The sonar firing cycle from now on, milliseconds (P2OS SONAR_CYCLE, 2-120 ms); throws
  /// std::invalid_argument outside that range.
  void set_sonar_cycle_ms(double cycle_ms) { sonar_.set_cycle_ms(cycle_ms, sim_time_s()); }
  /// Traces each frame's pings on 1 or 2 threads (SonarModel::set_threads); the frames are
  /// bit-identical either way.
  void set_sonar_threads(int threads) { sonar_.set_threads(threads); }
  /// Re-sequences one sonar array (P2OS POLLING); throws std::invalid_argument for a
  /// transducer not on that array.
  void set_sonar_polling(int array, const std::vector<int>& sequence) {
    sonar_.set_polling(array, sequence);
  }
  /// The sonar model (its schedule and echo candidates), for diagnostics and tests.
  const SonarModel& sonar() const { return sonar_; }

 private:
  mapper::Pose2 pose_at(double time_s) const;

  SimRobotOptions options_;
  mapper::RobotGeometry geometry_;
  SonarScene scene_;
  std::unique_ptr<PhysicsWorld> physics_;
  MotionLimiter limiter_;
  SkidSteerDrive drive_;
  SonarModel sonar_;
  StallDetector stall_;
  mapper::VelocityCommand target_;
  std::uint64_t cycles_ = 0;
  // Substep times and true poses of the cycle being built, for the sonar's pose interpolation.
  std::vector<double> step_times_s_;
  std::vector<mapper::Pose2> step_poses_;
};

}  // namespace cogmap::sim
