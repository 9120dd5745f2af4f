#include "cogmap/sim/sonar_model.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <system_error>

#include "helper_thread.h"
#include "sonar_raycast.h"

namespace cogmap::sim {

namespace {

// P2OS SONAR_CYCLE limits, milliseconds (ARCOS manual: "two and 120 milliseconds").
constexpr double kMinCycleMs = 2.0;
constexpr double kMaxCycleMs = 120.0;
// ARCOS: "up to 16 SONAR numbers in the sequence for any single array".
constexpr std::size_t kMaxPollingEntries = 16;

void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument("SonarModel: " + what);
}

// splitmix64: a small, well-mixed stream seeded once per ping, so a ping consumes a fixed
// number of draws from the model's main stream however many echo candidates it has.
struct PingStream {
  std::uint64_t state;
  double uniform() {
    std::uint64_t z = (state += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    z ^= z >> 31;
    return static_cast<double>(z >> 11) * 0x1.0p-53;
  }
};

double detection_probability(double strength) { return -std::expm1(-std::max(strength, 0.0)); }

}  // namespace

const SonarMaterial& SonarScene::material_of(int i) const {
  const std::vector<SonarMaterial>& table =
      materials.empty() ? builtin_sonar_materials() : materials;
  const int m = surface_material.empty() ? 0 : surface_material[static_cast<std::size_t>(i)];
  return table[static_cast<std::size_t>(m)];
}

SonarModel::SonarModel(const SonarModelOptions& options, const mapper::RobotGeometry& geometry,
                       std::uint64_t seed)
    : options_(options), geometry_(geometry), rng_(seed) {
  const int count = static_cast<int>(geometry_.sonars.size());
  require(count > 0, "the robot geometry has no sonars");
  require(options_.beam_sigma_deg > 0.0 && options_.beam_sigma_deg <= 90.0,
          "beam_sigma_deg must lie in (0, 90]");
  require(options_.fan_half_width_deg > 0.0 && options_.fan_half_width_deg < 90.0,
          "fan_half_width_deg must lie in (0, 90)");
  require(options_.rays_per_cone >= 1, "rays_per_cone must be at least 1");
  require(std::isfinite(options_.detection_gain_db) && std::abs(options_.detection_gain_db) <= 60,
          "detection_gain_db must lie in [-60, 60]");
  require(options_.corner_strength >= 0.0, "corner_strength must be >= 0");
  require(options_.threshold_walk_m >= 0.0 && options_.threshold_walk_m <= 1.0,
          "threshold_walk_m must lie in [0, 1]");
  require(options_.range_noise_fraction >= 0.0, "range_noise_fraction must be >= 0");
  require(options_.range_noise_floor_m >= 0.0, "range_noise_floor_m must be >= 0");
  require(options_.dropout_probability >= 0.0 && options_.dropout_probability <= 1.0,
          "dropout_probability must lie in [0, 1]");
  require(options_.corner_radius_m >= 0.0, "corner_radius_m must be >= 0");
  require(geometry_.sonar_min_range_m >= 0.0 &&
              geometry_.sonar_max_range_m > geometry_.sonar_min_range_m,
          "sonar range limits must satisfy 0 <= min < max");
  require(options_.cycle_ms >= kMinCycleMs && options_.cycle_ms <= kMaxCycleMs,
          "cycle_ms must lie in [2, 120] (P2OS SONAR_CYCLE)");
  cycle_s_ = options_.cycle_ms / 1000.0;
  const int arrays = (count + kSonarsPerArray - 1) / kSonarsPerArray;
  require(static_cast<int>(options_.polling.size()) <= arrays,
          "polling names " + std::to_string(options_.polling.size()) +
              " arrays but the robot has " + std::to_string(arrays));
  polling_.resize(static_cast<std::size_t>(arrays));
  position_.assign(static_cast<std::size_t>(arrays), 0);
  for (int a = 0; a < arrays; ++a) {
    if (a < static_cast<int>(options_.polling.size())) {
      set_polling(a, options_.polling[static_cast<std::size_t>(a)]);
    } else {
      for (int i = a * kSonarsPerArray; i < std::min(count, (a + 1) * kSonarsPerArray); ++i) {
        polling_[static_cast<std::size_t>(a)].push_back(i);
      }
    }
  }
}

SonarModel::~SonarModel() = default;
SonarModel::SonarModel(SonarModel&&) noexcept = default;
SonarModel& SonarModel::operator=(SonarModel&&) noexcept = default;

void SonarModel::set_threads(int threads) {
  require(threads == 1 || threads == 2, "threads must be 1 or 2");
  if (threads == 1) {
    helper_.reset();
  } else if (!helper_) {
    try {
      helper_ = std::make_unique<sonar_detail::HelperThread>();
    } catch (const std::system_error&) {
      // No thread to be had (a process or container thread limit): one thread traces every
      // ping, with the very same readings; threads() then says 1.
      helper_.reset();
    }
  }
}

int SonarModel::threads() const { return helper_ ? 2 : 1; }

void SonarModel::set_cycle_ms(double cycle_ms, double now_s) {
  require(cycle_ms >= kMinCycleMs && cycle_ms <= kMaxCycleMs,
          "cycle_ms must lie in [2, 120] (P2OS SONAR_CYCLE)");
  cycle_s_ = cycle_ms / 1000.0;
  schedule_start_s_ = now_s;
  next_firing_ = 0;
}

void SonarModel::set_polling(int array, const std::vector<int>& sequence) {
  require(array >= 0 && array < static_cast<int>(polling_.size()),
          "no sonar array " + std::to_string(array));
  require(sequence.size() <= kMaxPollingEntries, "a polling sequence holds at most 16 entries");
  const int count = static_cast<int>(geometry_.sonars.size());
  for (int i : sequence) {
    require(i >= 0 && i < count && i / kSonarsPerArray == array,
            "polling of array " + std::to_string(array) + " names transducer " + std::to_string(i) +
                ", which is not on that array of this robot");
  }
  polling_[static_cast<std::size_t>(array)] = sequence;
  position_[static_cast<std::size_t>(array)] = 0;
}

double SonarModel::range_noise_sd_m(double range_m) const {
  return std::hypot(options_.range_noise_fraction * range_m, options_.range_noise_floor_m);
}

sonar_detail::Cone SonarModel::cone_at(const mapper::Pose2& true_pose, int index) const {
  if (index < 0 || index >= static_cast<int>(geometry_.sonars.size())) {
    throw std::out_of_range("SonarModel: no transducer " + std::to_string(index));
  }
  const mapper::SonarMount& m = geometry_.sonars[static_cast<std::size_t>(index)];
  sonar_detail::Cone cone;
  cone.origin = true_pose.transform(mapper::Point2(m.x_m, m.y_m));
  cone.axis_rad = true_pose.theta_rad + m.heading_rad;
  cone.max_range_m = geometry_.sonar_max_range_m;
  return cone;
}

void SonarModel::update_index(const SonarScene& scene) const {
  // The scene is normally the same object every ping (SimRobot builds it once), so the check is
  // one byte comparison; the index is rebuilt only when the geometry really changed.
  if (!index_ || !index_->matches(scene)) {
    index_ = std::make_shared<const sonar_detail::SceneIndex>(scene);
  }
}

sonar_detail::Cone SonarModel::cone_for(const SonarScene& scene, const mapper::Pose2& true_pose,
                                        int index) const {
  sonar_detail::Cone cone = cone_at(true_pose, index);
  update_index(scene);
  return cone;
}

std::vector<EchoCandidate> SonarModel::echo_candidates(const SonarScene& scene,
                                                       const mapper::Pose2& true_pose,
                                                       int index) const {
  const sonar_detail::Cone cone = cone_for(scene, true_pose, index);
  return sonar_detail::echo_candidates(scene, cone, options_, index_.get());
}

SonarEcho SonarModel::geometric_echo(const SonarScene& scene, const mapper::Pose2& true_pose,
                                     int index) const {
  SonarEcho out;
  for (const EchoCandidate& c : echo_candidates(scene, true_pose, index)) {
    const double p = detection_probability(c.strength);
    if (p >= 0.5) {
      out = {true, c.range_m + options_.threshold_walk_m * (1.0 - p), c.multipath};
      break;
    }
  }
  return out;
}

double SonarModel::echo_probability(const SonarScene& scene, const mapper::Pose2& true_pose,
                                    int index) const {
  double silent = 1.0;
  for (const EchoCandidate& c : echo_candidates(scene, true_pose, index)) {
    silent *= 1.0 - detection_probability(c.strength);
  }
  return 1.0 - silent;
}

mapper::SonarReading SonarModel::ping(const SonarScene& scene, const mapper::Pose2& true_pose,
                                      int index, double time_s) {
  update_index(scene);
  return ping_indexed(scene, true_pose, index, time_s);
}

struct SonarModel::PingDraws {
  sonar_detail::Cone cone;
  int index = 0;
  double time_s = 0.0;
  double z = 0.0;          // range noise, standard normal
  double u = 0.0;          // dropout, uniform in [0, 1)
  std::uint64_t seed = 0;  // the ping's own stream: which echo candidates are heard
};

SonarModel::PingDraws SonarModel::draw_ping(const mapper::Pose2& true_pose, int index,
                                            double time_s) {
  PingDraws d;
  d.cone = cone_at(true_pose, index);  // throws before anything is drawn
  d.index = index;
  d.time_s = time_s;
  // Draw the same three numbers on every ping so the main stream advances identically whatever
  // the scene; a change in one wall then does not reshuffle the noise of every later reading.
  d.z = std::normal_distribution<double>(0.0, 1.0)(rng_);
  d.u = std::uniform_real_distribution<double>(0.0, 1.0)(rng_);
  d.seed = rng_();
  return d;
}

mapper::SonarReading SonarModel::trace_ping(const SonarScene& scene, const PingDraws& d) const {
  PingStream detector{d.seed};
  const double min_m = geometry_.sonar_min_range_m;
  const double max_m = geometry_.sonar_max_range_m;
  mapper::SonarReading r;
  r.index = d.index;
  r.time_s = d.time_s;
  r.echo = false;
  r.range_m = max_m;
  if (d.u < options_.dropout_probability) return r;  // nothing to trace
  // The receiver triggers on the first echo that crosses its threshold: candidates in range
  // order, each heard independently (speckle of a rough surface) with its own probability.
  struct Receiver final : sonar_detail::EchoListener {
    PingStream& detector;
    double p = 0.0;
    explicit Receiver(PingStream& s) : detector(s) {}
    bool hears(const EchoCandidate& c) override {
      p = detection_probability(c.strength);
      return detector.uniform() < p;
    }
  } receiver(detector);
  const std::optional<EchoCandidate> heard =
      sonar_detail::first_heard(scene, d.cone, options_, index_.get(), receiver);
  if (!heard) return r;
  // A weak echo crosses the threshold late in its envelope (threshold walk). The receiver is
  // blanked for the first ~0.1 m (transducer ringing): a nearer surface is heard only once
  // the blanking ends, so it reads as min range; noise never takes it below.
  const double range_m = heard->range_m + options_.threshold_walk_m * (1.0 - receiver.p);
  const double noisy = range_m + d.z * range_noise_sd_m(range_m);
  r.echo = true;
  r.range_m = std::clamp(noisy, min_m, max_m);
  return r;
}

mapper::SonarReading SonarModel::ping_indexed(const SonarScene& scene,
                                              const mapper::Pose2& true_pose, int index,
                                              double time_s) {
  return trace_ping(scene, draw_ping(true_pose, index, time_s));
}

std::vector<mapper::SonarReading> SonarModel::cycle(
    const SonarScene& scene, double t0_s, double t1_s,
    const std::function<mapper::Pose2(double)>& true_pose_at) {
  std::vector<mapper::SonarReading> out;
  if (!(t1_s > t0_s)) return out;
  // First every firing's pose and random draws, in order; then the tracing, which needs nothing
  // but the draws and the scene and so may be shared with the helper thread.
  thread_local std::vector<PingDraws> kept;
  std::vector<PingDraws>& draws = kept;  // the helper must see this thread's list, not its own
  draws.clear();
  for (;; ++next_firing_) {
    // Firing k of the current schedule happens at start + (k + 1) * cycle, computed from k
    // rather than accumulated, so rounding never drifts the schedule.
    const double t = schedule_start_s_ + static_cast<double>(next_firing_ + 1) * cycle_s_;
    if (t > t1_s) break;
    if (t <= t0_s) continue;  // a firing before this interval (only after a schedule change)
    const mapper::Pose2 pose = true_pose_at(t);
    for (std::size_t a = 0; a < polling_.size(); ++a) {
      const std::vector<int>& sequence = polling_[a];
      if (sequence.empty()) continue;
      const int index = sequence[position_[a] % sequence.size()];
      position_[a] = (position_[a] + 1) % sequence.size();
      draws.push_back(draw_ping(pose, index, t));
    }
  }
  if (draws.empty()) return out;
  update_index(scene);  // the scene is checked against the index once per call
  out.resize(draws.size());
  auto trace = [&](int i) {
    const auto k = static_cast<std::size_t>(i);
    out[k] = trace_ping(scene, draws[k]);
  };
  if (helper_ && draws.size() > 1) {
    helper_->run(static_cast<int>(draws.size()), trace);
  } else {
    for (std::size_t k = 0; k < draws.size(); ++k) trace(static_cast<int>(k));
  }
  return out;
}

}  // namespace cogmap::sim
