#pragma once
/// Heading correction between consecutive ASRs from their wall directions (thesis §3.1.9).
/// docs/algorithms.md explains each step and where we depart from the text.

#include <optional>
#include <span>

#include "cogmap/mapper/asr/asr.h"
#include "cogmap/mapper/localization/em.h"

namespace cogmap::mapper {

/// Which localisation a run uses (experiment key `mapper.localization`).
enum class LocalizationKind { kNone, kEm };

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
};

/// The answer of one estimate.
struct Localization {
  double rotation_rad =
      0.0;  ///< rotate the new ASR by this (CCW) about its pivot; 0 unless applied
  double reference_direction_rad = 0.0;  ///< μ_m in the world frame, folded to [−π/4, π/4)
  double current_direction_rad = 0.0;    ///< μ_s in the world frame, folded to [−π/4, π/4)
  EmResult em;                           ///< EM on the data centred on the reference direction
  bool applied = false;  ///< false when there was too little evidence or the fix was too big
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

 private:
  LocalizerOptions options_;
};

}  // namespace cogmap::mapper
