#pragma once
/// Heading correction between consecutive ASRs from their wall directions (thesis §3.1.9).

#include <optional>
#include <span>

#include "cogmap/mapper/asr/asr.h"
#include "cogmap/mapper/localization/em.h"

namespace cogmap::mapper {

enum class LocalizationKind { kNone, kEm };

struct LocalizerOptions {
  EmOptions em;
  bool weight_by_length = true;      ///< long walls count more than short noisy pieces
  double max_correction_rad = 0.35;  ///< refuse corrections beyond ~20° (no evidence can fold)
  double min_wall_length_m = 1.0;    ///< total wall length needed on each side to try
};

struct Localization {
  double rotation_rad = 0.0;  ///< rotate the new ASR by this about its reference point
  EmResult em;
  bool applied = false;  ///< false when there was too little evidence
};

class Localizer {
 public:
  explicit Localizer(LocalizerOptions options) : options_(options) {}
  /// Rotation that best aligns the wall directions of `current` (world frame, uncorrected)
  /// with those of `reference` (world frame, already corrected ASRs).
  Localization estimate(std::span<const Polyline> reference_world,
                        std::span<const Polyline> current_world) const;

 private:
  LocalizerOptions options_;
};

}  // namespace cogmap::mapper
