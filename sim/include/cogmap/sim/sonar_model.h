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
#include "cogmap/sim/sonar_material.h"
#include "cogmap/sim/yaml_strict.h"

namespace cogmap::sim {

namespace sonar_detail {
class SceneIndex;
struct Cone;
class HelperThread;
}  // namespace sonar_detail

/// What sonar can hit, world frame, metres.
struct SonarScene {
  std::vector<mapper::Segment>
      surfaces;  ///< every true surface (walls both faces, obstacle outlines)
  std::vector<mapper::Point2> corners;  ///< convex corners/edges that echo from any angle
  /// Material of each surface, an index into `materials`; empty means materials[0] everywhere.
  std::vector<int> surface_material;
  /// The material table; empty means builtin_sonar_materials().
  std::vector<SonarMaterial> materials;

  /// The material of surface `i`.
  const SonarMaterial& material_of(int i) const;
};

/// Parameters of the sonar ring. Defaults model the Polaroid 600-series ring of a P2-AT as the
/// P2OS/AROS firmware fires it (docs/p2at.md, docs/sonar-model.md, where each value comes from).
struct SonarModelOptions {
  /// Standard deviation of the two-way beam pattern (transmit x receive), degrees. The nominal
  /// 30 deg cone is where strong targets are still heard; fitted to the corridor recording.
  double beam_sigma_deg = 6.0;
  /// Rays are cast over +/- this angle from the axis, degrees: far enough out that the beam
  /// pattern (not the ray fan) decides what is heard.
  double fan_half_width_deg = 20.0;
  /// Rays across the fan; 17 over +/-20 deg gives 2.5 deg spacing, finer than the mirror lobes.
  int rays_per_cone = 17;
  /// Receiver sensitivity in dB added to every echo strength (a calibration knob per robot:
  /// +3 dB doubles every expected detection count).
  double detection_gain_db = 0.0;
  /// Expected detections of a convex corner or edge on the beam axis (edges diffract the pulse
  /// in every direction).
  double corner_strength = 20.0;
  /// g in (range / 1 m)^g, the factor on every diffuse echo: the receiver's gain ramps up over
  /// the listening time faster than spreading weakens a rough wall's backscatter, so oblique
  /// walls are heard better far than near. Fitted to the corridor recording.
  double diffuse_range_gain_exponent = 1.0;
  /// Range walk of the threshold detector, metres: a weak echo crosses the receiver's threshold
  /// late in its envelope, so an echo heard with probability p reads threshold_walk_m * (1 - p)
  /// long (a strong mirror echo reads true). Fitted to the corridor recording.
  double threshold_walk_m = 0.15;
  /// Range noise standard deviation as a fraction of range: ~1 % (docs/p2at.md).
  double range_noise_fraction = 0.01;
  /// Constant noise floor (sd), metres: timer and threshold jitter of the receiver, ~1 cm.
  double range_noise_floor_m = 0.01;
  /// Probability that a ping reports no echo regardless of the scene (missed threshold,
  /// crosstalk rejection). The real +/-90 deg transducers answer 99-100 % of firings.
  double dropout_probability = 0.01;
  /// Follow one mirror bounce; an echo via a second surface reads longer than the truth.
  bool multipath = true;
  /// Time between two firings of an array, milliseconds (P2OS SONAR_CYCLE, #48: 2-120 ms,
  /// default 40 ms).
  double cycle_ms = 40.0;
  /// Firing sequence per array (array a holds transducers 8a..8a+7, P2OS POLLING, #3; up to 16
  /// entries, repeats allowed); every array fires one disc each cycle, all at the same moment.
  /// Empty: every array in index order (the P2OS default, 1-8 and 9-16). An empty inner list
  /// silences that array.
  std::vector<std::vector<int>> polling;
  /// A ray whose hit point lies within this distance of a listed corner counts as hitting the
  /// corner; also the line-of-sight tolerance for corners, metres.
  double corner_radius_m = 0.05;
};

/// Reads the experiment's `robot.sonar` block; every key is optional, unknown keys and wrong
/// types throw yaml::ConfigError with file, line and key.
SonarModelOptions parse_sonar_options(const yaml::Node& node);

/// One way an echo can reach the receiver, before the threshold detector decides.
struct EchoCandidate {
  double range_m = 0.0;    ///< one-way range (half the out-and-back path), metres
  double strength = 0.0;   ///< expected detections: heard with probability 1 - exp(-strength)
  bool multipath = false;  ///< true when the echo came via a mirror bounce
};

/// The echo of one transducer before range noise, blanking and dropouts.
struct SonarEcho {
  bool echo = false;       ///< false when nothing returns within max range
  double range_m = 0.0;    ///< one-way range (half the out-and-back path), metres
  bool multipath = false;  ///< true when the first echo came via a specular bounce
};

/// The sonar ring: its random stream and firing schedule are its only state, so readings
/// depend only on the seed, the scene, the true poses, the firing times and schedule changes.
class SonarModel {
 public:
  /// Throws std::invalid_argument for options out of range or a polling sequence naming a
  /// transducer the geometry does not have.
  SonarModel(const SonarModelOptions& options, const mapper::RobotGeometry& geometry,
             std::uint64_t seed);
  ~SonarModel();
  SonarModel(SonarModel&&) noexcept;
  SonarModel& operator=(SonarModel&&) noexcept;

  /// How many threads trace the pings of one cycle() call: 1 (the default) or 2 (a helper
  /// thread shares them). The readings are bit-identical either way: each ping's random draws
  /// are taken in order on the calling thread before any is traced, and tracing reads only the
  /// scene. Throws std::invalid_argument for anything else. When the system refuses a new
  /// thread, the model stays on one (threads() tells).
  void set_threads(int threads);
  int threads() const;

  /// Readings of the transducers that fire in (t0_s, t1_s]; true_pose_at(t) gives the true pose
  /// (world) at time t. Every cycle_ms each array fires the next disc of its polling sequence,
  /// all arrays at the same moment (array order within a firing), so consecutive intervals
  /// partition the pings exactly. Intervals must follow each other in time.
  std::vector<mapper::SonarReading> cycle(const SonarScene& scene, double t0_s, double t1_s,
                                          const std::function<mapper::Pose2(double)>& true_pose_at);

  /// Changes the firing cycle (P2OS SONAR_CYCLE) from time `now_s` on: the next firing comes one
  /// new cycle after now_s. `now_s` must be the end of the last interval given to cycle() (as
  /// SimRobot does); firings of the old schedule after it would be skipped. Throws
  /// std::invalid_argument outside 2-120 ms.
  void set_cycle_ms(double cycle_ms, double now_s);

  /// Re-sequences array `array` (P2OS POLLING); the sequence restarts at its first entry. An
  /// empty sequence silences the array. Throws std::invalid_argument for a transducer outside
  /// the array or more than 16 entries.
  void set_polling(int array, const std::vector<int>& sequence);

  /// One noisy reading of transducer `index` at `true_pose` (world); time_s is copied through.
  /// Draws the same three values (a normal, a uniform, a 64-bit seed) whatever the scene.
  mapper::SonarReading ping(const SonarScene& scene, const mapper::Pose2& true_pose, int index,
                            double time_s);

  /// Every echo candidate of transducer `index` at `true_pose` (world), sorted by range.
  /// Deterministic; consumes no random numbers.
  std::vector<EchoCandidate> echo_candidates(const SonarScene& scene,
                                             const mapper::Pose2& true_pose, int index) const;

  /// The most likely first echo: the nearest candidate heard at least half the time (none:
  /// echo = false). Deterministic; consumes no random numbers.
  SonarEcho geometric_echo(const SonarScene& scene, const mapper::Pose2& true_pose,
                           int index) const;

  /// The probability that transducer `index` at `true_pose` hears anything (before dropouts).
  double echo_probability(const SonarScene& scene, const mapper::Pose2& true_pose, int index) const;

  /// The configured range noise standard deviation at `range_m`, metres.
  double range_noise_sd_m(double range_m) const;

  /// The polling sequence of every array in use (defaults filled in).
  const std::vector<std::vector<int>>& polling() const { return polling_; }

  /// The firing cycle in use, milliseconds.
  double cycle_ms() const { return cycle_s_ * 1000.0; }

 private:
  SonarModelOptions options_;
  mapper::RobotGeometry geometry_;
  std::vector<std::vector<int>> polling_;  // per array
  std::vector<std::size_t> position_;      // next entry of each array's sequence
  double cycle_s_ = 0.04;
  double schedule_start_s_ = 0.0;  // firing k of the current schedule is at start + (k+1) cycle
  std::int64_t next_firing_ = 0;
  std::mt19937_64 rng_;
  /// Spatial index of the last scene pinged, rebuilt when a scene differs from it bit for bit.
  /// It only speeds up the ray casts (results are identical to a full scan); mutable because it
  /// is a cache, so echo_candidates stays const. One model is driven by one thread (ping() and
  /// cycle() advance its random stream); only cycle()'s own helper traces pings beside it.
  mutable std::shared_ptr<const sonar_detail::SceneIndex> index_;
  std::unique_ptr<sonar_detail::HelperThread> helper_;  // set_threads(2)

  /// Transducer `index`'s cone at `true_pose` (throws std::out_of_range for an unknown one),
  /// with index_ brought up to date for `scene`.
  sonar_detail::Cone cone_for(const SonarScene& scene, const mapper::Pose2& true_pose,
                              int index) const;
  /// Transducer `index`'s cone at `true_pose` (throws std::out_of_range for an unknown one).
  sonar_detail::Cone cone_at(const mapper::Pose2& true_pose, int index) const;
  /// Rebuilds index_ if `scene` is not bit for bit the one it was built from.
  void update_index(const SonarScene& scene) const;
  /// A ping's cone and random draws, taken in firing order from the main stream.
  struct PingDraws;
  PingDraws draw_ping(const mapper::Pose2& true_pose, int index, double time_s);
  /// The reading of a drawn ping: reads only the options, the scene and its index, so any
  /// number of threads may trace pings at once.
  mapper::SonarReading trace_ping(const SonarScene& scene, const PingDraws& draws) const;
  /// ping() against the scene index_ was last brought up to date for: cycle() checks the scene
  /// once for all its pings (the check compares every surface).
  mapper::SonarReading ping_indexed(const SonarScene& scene, const mapper::Pose2& true_pose,
                                    int index, double time_s);
};

/// Transducers of one P2OS sonar array: array a holds indices 8a .. 8a+7.
inline constexpr int kSonarsPerArray = 8;

}  // namespace cogmap::sim
