#include "grid/sensor_models.h"

#include <algorithm>

#include "cogmap/mapper/grid/grid.h"

namespace cogmap::mapper {

double table_weight(double distance_m, double max_range_m, double alpha_rad,
                    double half_width_rad) {
  const double range_term = (max_range_m - distance_m) / max_range_m;
  const double angle_term = (half_width_rad - alpha_rad) / half_width_rad;
  return std::clamp(0.5 * (range_term + angle_term), 0.0, 1.0);
}

// Table 2.2 read literally turns against itself when its weight drops below 0.5 (far from the
// sensor and near the cone's edge): region I would then lower Pr(H) and region II raise it, so a
// beam that passed through a cell would make it "more occupied". Weak evidence is made neutral
// (likelihood ratio 1) instead; docs/algorithms.md.
SensorLikelihood bayes_region_one(double weight, double max_occupied) {
  const double occupied = std::max(weight * max_occupied, 0.5);
  return {occupied, 1.0 - occupied};
}

SensorLikelihood bayes_region_two(double weight) {
  const double empty = std::max(weight, 0.5);
  return {1.0 - empty, empty};
}

double bayes_posterior(double prior, const SensorLikelihood& likelihood) {
  const double num = likelihood.given_occupied * prior;
  const double den = num + likelihood.given_empty * (1.0 - prior);
  // den is 0 only for a certain prior against certain contrary evidence; the clamp keeps the
  // prior away from 0 and 1, so keep the prior rather than divide by zero.
  if (den <= 0.0) return std::clamp(prior, kMinProbability, kMaxProbability);
  return std::clamp(num / den, kMinProbability, kMaxProbability);
}

float bayes_to_histogram(double probability) {
  if (probability >= 0.5) return static_cast<float>((probability - 0.5) * 2.0 * kHistogramMax);
  return static_cast<float>((0.5 - probability) * 2.0 * kHistogramFloor);
}

DsMass ds_region_one(double weight, double max_occupied) {
  const double occupied = weight * max_occupied;
  return {static_cast<float>(occupied), 0.0f, static_cast<float>(1.0 - occupied)};
}

DsMass ds_region_two(double weight) {
  return {0.0f, static_cast<float>(weight), static_cast<float>(1.0 - weight)};
}

DsCombination dempster_combine(const DsMass& a, const DsMass& b) {
  const double ao = a.occupied, ae = a.empty, au = a.unknown;
  const double bo = b.occupied, be = b.empty, bu = b.unknown;
  const double conflict = ao * be + ae * bo;  // O ∧ E = ∅
  const double norm = 1.0 - conflict;
  if (norm <= 0.0) return {a, 1.0};
  const double occupied = ao * bo + ao * bu + au * bo;  // O∧O, O∧Θ, Θ∧O  (Eq. 2.11)
  const double empty = ae * be + ae * bu + au * be;     // E∧E, E∧Θ, Θ∧E  (Eq. 2.12)
  const double unknown = au * bu;                       // Θ∧Θ            (Eq. 2.13)
  return {{static_cast<float>(occupied / norm), static_cast<float>(empty / norm),
           static_cast<float>(unknown / norm)},
          conflict};
}

DsMass keep_open(const DsMass& m, double min_unknown) {
  if (m.unknown >= min_unknown) return m;
  const double focal = static_cast<double>(m.occupied) + m.empty;
  if (focal <= 0.0) return {0.0f, 0.0f, 1.0f};
  const double scale = (1.0 - min_unknown) / focal;
  return {static_cast<float>(m.occupied * scale), static_cast<float>(m.empty * scale),
          static_cast<float>(min_unknown)};
}

float ds_to_histogram(const DsMass& m) {
  return kHistogramMax * m.occupied + kHistogramFloor * m.empty;
}

}  // namespace cogmap::mapper
