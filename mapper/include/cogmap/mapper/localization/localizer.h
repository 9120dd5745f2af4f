#pragma once
/// Heading correction between consecutive ASRs from their wall directions (thesis §3.1.9).
/// docs/algorithms.md explains each step and where we depart from the text.

#include <limits>
#include <optional>
#include <span>

#include "cogmap/mapper/asr/asr.h"
#include "cogmap/mapper/localization/echo_refit.h"
#include "cogmap/mapper/localization/em.h"

namespace cogmap::mapper {

/// Which localisation a run uses (experiment key `mapper.localization`).
enum class LocalizationKind { kNone, kEm };

/// How fast a skid-steer's heading drifts, for the prior of the rotation EM looks for.
struct HeadingDriftModel {
  /// sd of the heading error per radian turned: the effective track of a skid-steer varies
  /// with floor and turn curvature by a few per cent (docs/odometry-model.md: 2 % slowly
  /// varying track noise with a 5 s correlation time, which partly averages out over a room).
  /// Measured on the simulated P2-AT: rms 1.2 % of the rotation per room; 1.5 % keeps the prior
  /// on the cautious (wide) side.
  double per_rad_turned = 0.015;
  /// Heading random walk while driving, rad/√m (uneven floor, tyre deformation; ~0.005 for a
  /// P2-AT on a hard floor).
  double rad_per_sqrt_m = 0.005;
  /// sd that is always there (encoder quantisation, the drift left over from the previous
  /// room after its own correction): 0.5°.
  double floor_rad = 0.0087;
  /// Chord length over which the path heading is measured: path vertices are half a cell
  /// apart, so their raw directions jitter by tens of degrees; 0.5 m chords smooth that.
  double chord_m = 0.5;
};

/// Options of Localizer::estimate.
struct LocalizerOptions {
  EmOptions em;                      ///< ε, iteration bound and σ floor of Fig. A.6
  bool weight_by_length = true;      ///< long walls count more than short noisy pieces
  double max_correction_rad = 0.35;  ///< refuse corrections beyond ~20° (no evidence can fold)
  double min_wall_length_m = 1.0;    ///< total wall length needed on each side to try
  /// Initial weight of the uniform clutter component (0 = the thesis's pure two-component
  /// mixture). It soaks up short segments at random angles that would otherwise drag μ_s, μ_m.
  double clutter_weight = 0.1;
  /// Tell EM which set each direction came from (s or m). false = the thesis's pooled,
  /// unlabelled mixture, which cannot separate s from m when they overlap (small drift).
  bool label_sources = true;
  DominantDirectionOptions dominant;      ///< outlier-robust initialisation of μ_s and μ_m
  double min_initial_sigma_rad = 0.0087;  ///< floor of the initial σ_s, σ_m (0.5°)
  /// Innovation gate: a measured rotation further than this many standard deviations of
  /// sqrt(prior² + measurement²) from 0 is an outlier (a wrong match modulo 90°, a room whose
  /// walls are mostly clutter) and is not applied. 3σ keeps 99.7 % of consistent measurements.
  /// Only active when a finite prior is given.
  double gate_sigmas = 3.0;
  /// Floor of σ_s, σ_m when computing the sd of the measured rotation: walls come from a grid
  /// of 0.1 m cells, so a 5 m wall's direction is quantised to ~atan(0.1/5) ≈ 1.1°; a room
  /// whose segments agree exactly (σ collapsed to EM's 1e-4 floor) is not known better than that.
  double min_direction_sigma_rad = 0.0175;
  /// When positive, the sd of a room's measured rotation is this over the length of the room's
  /// longest straight piece of wall (rad·m; 0.077 = 4.4° at 1 m, 1.5° at 3 m), plus the smear
  /// term below, in place of the sd EM's mixture claims (σ/√n over its Kish count). Over 7 300
  /// rooms of four sets of buildings (docs/algorithms.md, "A room's measurement is as sharp as
  /// its longest wall") EM's own sd is about 2° whatever the room, while the error's median is
  /// 5° with no piece as long as 0.8 m (chair arcs, desk faces) and under 1° with a 4 m wall;
  /// 0.077/L matches that median within a quarter from 0.6 to 5 m. 0 (the default) = EM's own
  /// sd: on, in both of an explorer's mappers it kept more labs' corrected heading within
  /// odometry's but more explorations stopped short; in the map alone it changed no set beyond
  /// its spread.
  double measurement_sd_rad_m = 0.0;
  /// The walls of a room are seen at headings spread over the drift inside the room, so their
  /// mean direction matches the heading error at an unknown moment of the visit, not at its end:
  /// uniform over the visit, that adds prior²/3 to the measurement variance. This flag adds it.
  bool smear_variance = true;
  /// Whether the mapper facade checks EM's answer against the odometry prior. On: measured on
  /// 17 generated and shipped worlds (docs/algorithms.md), the prior used as a gate only
  /// refuses the rare wrong matches (an 18° "correction" of a 1° drift) and changes nothing
  /// else, mean median wall error 0.093 -> 0.073 m on unseen worlds (truth-steered).
  bool odometry_prior = true;
  /// With the prior: true (default) applies the posterior mean (gain·measured); false uses the
  /// prior only as the innovation gate and applies a measurement that passes it whole. Against
  /// the last 2 rooms the posterior lagged real corrections of the hallway's short ASRs (ATE 0.9
  /// -> 2.5 m: consecutive measurements share a room's noise with opposite signs); against a long
  /// reference (below) each measurement carries only the new room's noise and the posterior is
  /// the better estimate (docs/algorithms.md, "A long reference and the Kalman filter": with the
  /// door search, shipped routes seeds 1-10 41 -> 48 of 50 completed, hallway median wall
  /// error 0.42 -> 0.31 m).
  bool prior_shrinks = true;
  /// How many of the latest localised rooms' accepted walls are EM's reference for the next: 32,
  /// so the reference's direction is the building's own (2 was the default until 2026-12-02).
  std::size_t reference_rooms = 32;
  /// Width of the bins the reference's wall directions are pooled in before EM (each bin's
  /// weighted mean, length and spread stand for its members; direction_bins.h), so that EM's
  /// work per room is bounded by the bin count (360 at 0.25°) however many rooms the reference
  /// holds (`em_reference_rooms` 1000 and more). 0 (the default) keeps every direction on its
  /// own: measured on 418 estimates, 0.25° bins answer within 0.008° of it in half the time,
  /// but any change of EM's answers reshuffles every later drive (docs/algorithms.md, "A binned
  /// reference").
  double reference_bin_rad = 0.0;
  /// The odometry drift model the mapper facade turns a room's path into a RotationPrior with.
  HeadingDriftModel drift;
  /// The new room's wall directions refitted to its echoes before EM measures its rotation
  /// (echo_refit.h; the mapper facade keeps the room's echo endpoints while it is mapped). Off
  /// by default: the thesis measures the fitted lines.
  EchoRefitOptions echo_refit;
};

/// What odometry says about the rotation between the new ASR's frame and the reference's:
/// N(0, sigma_rad²). Infinite (the default) = no prior: the EM estimate is applied as it is.
struct RotationPrior {
  double sigma_rad = std::numeric_limits<double>::infinity();  ///< sd of the expected drift
};

/// Rotation (radians, ≥ 0) turned along a path: sum of |heading changes| between consecutive
/// chords of at least `chord_m`, starting from `start_heading_rad` (the entry heading) and, if
/// given, ending at `end_heading_rad` (the exit heading). Turns in place show up as corners.
double path_rotation_rad(std::span<const Point2> path, double start_heading_rad,
                         std::optional<double> end_heading_rad, double chord_m);

/// Path length in metres.
double path_length_m(std::span<const Point2> path);

/// The prior sd of the heading drift accumulated while turning `rotation_rad` and driving
/// `distance_m`: sqrt(floor² + (k_rot·rotation)² + k_walk²·distance).
double heading_drift_sigma_rad(const HeadingDriftModel& model, double rotation_rad,
                               double distance_m);

/// The answer of one estimate.
struct Localization {
  double rotation_rad =
      0.0;  ///< rotate the new ASR by this (CCW) about its pivot; 0 unless applied
  double reference_direction_rad = 0.0;  ///< μ_m in the world frame, folded to [−π/4, π/4)
  double current_direction_rad = 0.0;    ///< μ_s in the world frame, folded to [−π/4, π/4)
  EmResult em;                           ///< EM on the data centred on the reference direction
  bool applied = false;  ///< false when there was too little evidence or the fix was too big
  double measured_rotation_rad = 0.0;  ///< fold(μ_m − μ_s): EM's answer before the prior
  /// sd of measured_rotation_rad: LocalizerOptions::measurement_sd_rad_m over longest_wall_m,
  /// or (that option 0) σ_s²/n_s + σ_m²/n_m with n_k the effective number of independent
  /// segments EM gave to component k (Kish: (Σqw)²/Σ(qw)²); either plus the smear term.
  double measurement_sigma_rad = 0.0;
  /// The new room's longest straight piece of wall, metres (what measurement_sd_rad_m divides).
  double longest_wall_m = 0.0;
  double prior_sigma_rad = std::numeric_limits<double>::infinity();  ///< the prior used
  double gain = 1.0;  ///< prior² / (prior² + measurement²): the share of the measurement applied
  /// The shift applied after the rotation (mapper.translation, wall offsets; zero unless
  /// translation_applied) and the wall pairs that measured it.
  Point2 translation_m{0.0, 0.0};
  int translation_pairs = 0;
  bool translation_applied = false;
  bool translation_tried = false;  ///< the mapper measured a shift (mapper.translation on)
};

/// Estimates the drift in heading of a new ASR against the rooms mapped before it.
class Localizer {
 public:
  /// Takes the options once (configuration flows one way: options -> constructor).
  explicit Localizer(LocalizerOptions options) : options_(options) {}
  /// Rotation that best aligns the wall directions of `current` (world frame, uncorrected)
  /// with those of `reference` (world frame, already corrected ASRs).
  Localization estimate(std::span<const Polyline> reference_world,
                        std::span<const Polyline> current_world) const;
  /// The same, combined with the odometry prior N(0, prior.sigma_rad²) on the rotation: the
  /// applied rotation is the posterior mean gain·measured, gain = prior²/(prior² + meas²), and
  /// nothing is applied when |measured| > gate_sigmas·sqrt(prior² + meas²).
  Localization estimate(std::span<const Polyline> reference_world,
                        std::span<const Polyline> current_world, const RotationPrior& prior) const;

 private:
  LocalizerOptions options_;
};

}  // namespace cogmap::mapper
