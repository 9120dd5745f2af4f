#include "cogmap/sim/sonar_model.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "sonar_raycast.h"

namespace cogmap::sim {

SonarModel::SonarModel(const SonarModelOptions& options, const mapper::RobotGeometry& geometry,
                       std::uint64_t seed)
    : options_(options), geometry_(geometry), order_(options.firing_order), rng_(seed) {
  auto require = [](bool ok, const std::string& what) {
    if (!ok) throw std::invalid_argument("SonarModel: " + what);
  };
  const int count = static_cast<int>(geometry_.sonars.size());
  require(count > 0, "the robot geometry has no sonars");
  require(options_.critical_angle_deg > 0.0 && options_.critical_angle_deg < 90.0,
          "critical_angle_deg must lie in (0, 90)");
  require(options_.rays_per_cone >= 1, "rays_per_cone must be at least 1");
  require(options_.range_noise_fraction >= 0.0, "range_noise_fraction must be >= 0");
  require(options_.range_noise_floor_m >= 0.0, "range_noise_floor_m must be >= 0");
  require(options_.dropout_probability >= 0.0 && options_.dropout_probability <= 1.0,
          "dropout_probability must lie in [0, 1]");
  require(options_.transducer_period_s > 0.0, "transducer_period_s must be > 0");
  require(options_.corner_radius_m >= 0.0, "corner_radius_m must be >= 0");
  require(geometry_.sonar_min_range_m >= 0.0 &&
              geometry_.sonar_max_range_m > geometry_.sonar_min_range_m,
          "sonar range limits must satisfy 0 <= min < max");
  if (order_.empty()) {
    for (int i = 0; i < count; ++i) order_.push_back(i);
  }
  for (int i : order_) {
    require(i >= 0 && i < count, "firing_order names transducer " + std::to_string(i) +
                                     " but the robot has " + std::to_string(count));
  }
}

double SonarModel::range_noise_sd_m(double range_m) const {
  return std::hypot(options_.range_noise_fraction * range_m, options_.range_noise_floor_m);
}

SonarEcho SonarModel::geometric_echo(const SonarScene& scene, const mapper::Pose2& true_pose,
                                     int index) const {
  if (index < 0 || index >= static_cast<int>(geometry_.sonars.size())) {
    throw std::out_of_range("SonarModel: no transducer " + std::to_string(index));
  }
  const mapper::SonarMount& m = geometry_.sonars[static_cast<std::size_t>(index)];
  sonar_detail::Cone cone;
  cone.origin = true_pose.transform(mapper::Point2(m.x_m, m.y_m));
  cone.axis_rad = true_pose.theta_rad + m.heading_rad;
  cone.half_beam_rad = 0.5 * geometry_.sonar_beam_width_rad;
  cone.max_range_m = geometry_.sonar_max_range_m;
  // The scene is normally the same object every ping (SimRobot builds it once), so the check is
  // one byte comparison; the index is rebuilt only when the geometry really changed.
  if (!index_ || !index_->matches(scene)) {
    index_ = std::make_shared<const sonar_detail::SceneIndex>(scene);
  }
  return sonar_detail::first_echo(scene, cone, options_, index_.get());
}

mapper::SonarReading SonarModel::ping(const SonarScene& scene, const mapper::Pose2& true_pose,
                                      int index, double time_s) {
  const SonarEcho e = geometric_echo(scene, true_pose, index);
  // Draw both numbers on every ping so the random stream advances identically whatever the scene;
  // a change in one wall then does not reshuffle the noise of every later reading.
  const double z = std::normal_distribution<double>(0.0, 1.0)(rng_);
  const double u = std::uniform_real_distribution<double>(0.0, 1.0)(rng_);

  const double min_m = geometry_.sonar_min_range_m;
  const double max_m = geometry_.sonar_max_range_m;
  mapper::SonarReading r;
  r.index = index;
  r.time_s = time_s;
  if (!e.echo || u < options_.dropout_probability) {
    r.echo = false;
    r.range_m = max_m;
    return r;
  }
  // The receiver is blanked for the first ~0.1 m (transducer ringing): a nearer surface is heard
  // only once the blanking ends, so it reads as min range; noise never takes it below.
  const double noisy = e.range_m + z * range_noise_sd_m(e.range_m);
  r.echo = true;
  r.range_m = std::clamp(noisy, min_m, max_m);
  return r;
}

std::vector<mapper::SonarReading> SonarModel::cycle(
    const SonarScene& scene, double t0_s, double t1_s,
    const std::function<mapper::Pose2(double)>& true_pose_at) {
  std::vector<mapper::SonarReading> out;
  if (!(t1_s > t0_s)) return out;
  const double period = options_.transducer_period_s;
  // Firing k happens at (k + 1) * period. Start a little before the first candidate and test
  // each time with the same comparison, so adjacent intervals never both claim (or both miss)
  // a firing whatever the rounding of t / period.
  const double first = std::floor(t0_s / period) - 2.0;
  std::int64_t k = first < 0.0 ? 0 : static_cast<std::int64_t>(first);
  const auto n = static_cast<std::int64_t>(order_.size());
  for (;; ++k) {
    const double t = static_cast<double>(k + 1) * period;
    if (t > t1_s) break;
    if (t <= t0_s) continue;
    const int index = order_[static_cast<std::size_t>(k % n)];
    out.push_back(ping(scene, true_pose_at(t), index, t));
  }
  return out;
}

}  // namespace cogmap::sim
