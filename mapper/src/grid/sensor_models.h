#pragma once
/// The sonar models of the probabilistic updaters: thesis Table 2.2 and Eq. 2.9 (Bayes,
/// Moravec/Murphy), Table 2.3 and Eqs. 2.11-2.13 (Dempster-Shafer), and how each maps onto the
/// HIMM scale so the same ε applies downstream. Pure functions, testable on their own.

namespace cogmap::mapper {

/// ((R - r)/R + (β - α)/β) / 2 of Tables 2.2-2.3, clamped to [0, 1]. `distance_m` is r, the
/// cell's distance from the transducer; `alpha_rad` is α, the cell's angle off the beam axis;
/// `half_width_rad` is β, the cone's half-angle (Murphy's convention: α runs 0..β across half
/// the cone, so the angular term falls to 0 at the cone's edge).
double table_weight(double distance_m, double max_range_m, double alpha_rad, double half_width_rad);

/// Pr(ς|Occupied) and Pr(ς|Empty) of one cell for one reading (Table 2.2).
struct SensorLikelihood {
  double given_occupied = 0.5;  ///< Pr(ς|H)
  double given_empty = 0.5;     ///< Pr(ς|¬H)
};

/// Table 2.2 region I (cells at the measured range): Pr(ς|H) = weight × MO, Pr(ς|¬H) = 1 - that;
/// Pr(ς|H) is held >= 0.5 so region I evidence never lowers a cell (deviation, see .cc).
SensorLikelihood bayes_region_one(double weight, double max_occupied);
/// Table 2.2 region II (cells short of the range): Pr(ς|¬H) = weight, Pr(ς|H) = 1 - weight;
/// Pr(ς|¬H) is held >= 0.5 so region II evidence never raises a cell (deviation, see .cc).
SensorLikelihood bayes_region_two(double weight);

inline constexpr double kMinProbability = 0.001;  ///< clamp so a cell can recover
inline constexpr double kMaxProbability = 0.999;  ///< clamp so a cell can recover

/// Eq. 2.9: Pr(H|ς) = Pr(ς|H) Pr(H) / (Pr(ς|H) Pr(H) + Pr(ς|¬H) Pr(¬H)), the prior Pr(H)
/// being the cell's current probability; the result is clamped to [kMin, kMaxProbability].
double bayes_posterior(double prior, const SensorLikelihood& likelihood);

/// Probability on the HIMM scale: 0.5 -> 0 (unexplored), linear up to 1 -> 15 and down to
/// 0 -> -3, so ε = 7 means p > 0.5 + 7/30 ≈ 0.733.
float bayes_to_histogram(double probability);

/// Dempster-Shafer masses over {Occupied}, {Empty} and Θ = "don't know"; they sum to 1.
struct DsMass {
  float occupied = 0.0f;  ///< m(Occupied)
  float empty = 0.0f;     ///< m(Empty)
  float unknown = 1.0f;   ///< m(Don't Know) = m(Θ)
};

/// Table 2.3 region I: m(O) = weight × MO, m(E) = 0, m(Θ) = 1 - m(O).
DsMass ds_region_one(double weight, double max_occupied);
/// Table 2.3 region II: m(O) = 0, m(E) = weight, m(Θ) = 1 - m(E).
DsMass ds_region_two(double weight);

/// The combined masses and K, the mass the two bodies of evidence give to ∅ (O ∧ E).
struct DsCombination {
  DsMass mass;
  double conflict = 0.0;  ///< K = m1(O) m2(E) + m1(E) m2(O)
};

/// Dempster's rule, Eqs. 2.11-2.13: products of masses whose intersection is O, E or Θ,
/// divided by 1 - K. With K = 1 (total conflict) the rule is undefined: `a` comes back
/// unchanged with conflict 1.
DsCombination dempster_combine(const DsMass& a, const DsMass& b);

/// Keeps m(Θ) >= `min_unknown` by scaling m(O) and m(E) down in proportion, so a cell never
/// becomes certain and later evidence can still move it (the DS analogue of the Bayes clamp).
DsMass keep_open(const DsMass& m, double min_unknown);

/// Belief on the HIMM scale: 15 m(O) - 3 m(E); (0, 0, 1) -> 0 unexplored, certain occupied
/// -> 15, certain empty -> -3.
float ds_to_histogram(const DsMass& m);

}  // namespace cogmap::mapper
