// The experiment's `robot:` block for a simulated P2-AT (docs/simulator.md).
#include <string>

#include "cogmap/mapper/seam/robot_models.h"
#include "cogmap/sim/sim_robot.h"

namespace cogmap::sim {
namespace {

// OdometryOptions' defaults describe the P2-AT's skid-steer. Two wheels and a caster do not
// skid: the track is the calibrated one (ARIA's 2 / DiffConvFactor) and turns do not slip, unless
// the experiment's robot.odometry block says otherwise (its keys win; `preset: ideal` too).
void apply_drive_defaults(const mapper::RobotModel& model, const yaml::Node* odometry,
                          OdometryOptions& o) {
  if (model.geometry.drive != mapper::DriveKind::kDifferential) return;
  auto unset = [&](const char* key) { return !odometry || !odometry->child(key); };
  if (!unset("preset")) return;
  if (unset("track_m")) o.track_m = model.geometry.odometry_track_m;
  if (unset("calibrated_track_factor")) o.calibrated_track_factor = 1.0;
  if (unset("effective_track_factor")) o.effective_track_factor = 1.0;
  if (unset("curvature_gain")) o.curvature_gain = 0.0;
}
constexpr double kMinCycleS = 0.01;  // shortest control cycle, seconds (see cycle_s below)
}  // namespace

SimRobotOptions parse_sim_robot_options(const yaml::Node& robot_block) {
  robot_block.expect_keys(
      {"source", "model", "sonar", "odometry", "cycle_s", "physics_substeps", "rot_accel_radps2"});
  SimRobotOptions options;
  if (const auto source = robot_block.child("source")) {
    if (source->as<std::string>() != "sim") {
      source->fail("a simulated robot needs source: sim (got '" + source->as<std::string>() + "')");
    }
  }
  const mapper::RobotModel* model = mapper::find_robot_model(options.model);
  if (const auto node = robot_block.child("model")) {
    model = mapper::find_robot_model(node->as<std::string>());
    if (!model) {
      node->fail("unknown robot model '" + node->as<std::string>() + "' (one of " +
                 mapper::robot_model_names() + ")");
    }
    options.model = model->name;
  }
  if (const auto sonar = robot_block.child("sonar")) {
    options.sonar = parse_sonar_options(*sonar);
    // Array a holds transducers 8a..8a+7: a sequence for an array the model lacks is a mistake
    // in this file, so say so here (with its line) rather than when the robot is built.
    const std::size_t sonars = model->geometry.sonars.size();
    if (const auto polling = sonar->child("polling")) {
      for (std::size_t a = 0; a < options.sonar.polling.size(); ++a) {
        for (const int i : options.sonar.polling[a]) {
          if (static_cast<std::size_t>(i) >= sonars) {
            polling->at(a).fail("transducer " + std::to_string(i) + " is not on a " + model->name +
                                " (" + std::to_string(sonars) + " sonars)");
          }
        }
        if (a * kSonarsPerArray >= sonars) {
          polling->at(a).fail("a " + model->name + " has no sonar array " + std::to_string(a));
        }
      }
    }
  }
  const auto odometry = robot_block.child("odometry");
  if (odometry) options.odometry = parse_odometry_options(*odometry);
  apply_drive_defaults(*model, odometry ? &*odometry : nullptr, options.odometry);
  if (const auto cycle = robot_block.child("cycle_s")) {
    options.cycle_s = cycle->as<double>();
    // At least 10 ms: a P2-AT reports every 100 ms (P2AT.md), and 1e-9 s made a 600 s run a
    // 6e11-frame loop that never ended and grew memory by 5 MB/s.
    if (options.cycle_s < kMinCycleS || options.cycle_s > 10.0) {
      cycle->fail("cycle_s must be in [0.01, 10] seconds");
    }
  }
  if (const auto substeps = robot_block.child("physics_substeps")) {
    options.physics_substeps = substeps->as<int>();
    if (options.physics_substeps < 1 || options.physics_substeps > 1000) {
      substeps->fail("physics_substeps must be in 1..1000");
    }
  }
  if (const auto rot = robot_block.child("rot_accel_radps2")) {
    options.rot_accel_radps2 = rot->as<double>();
    if (options.rot_accel_radps2 <= 0.0) rot->fail("rot_accel_radps2 must be positive");
  }
  return options;
}

}  // namespace cogmap::sim
