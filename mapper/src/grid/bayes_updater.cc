// Bayes occupancy grid, thesis §2.2.1: each cell holds Pr(H), prior 0.5. A reading's cone
// (half-angle β/2) is rasterised; cells in region I take Table 2.2's region I likelihoods,
// cells in region II its region II ones, and Eq. 2.9 turns them into the new Pr(H). No window w:
// the model already discounts far evidence through (R - r)/R. No-echo readings are all region II.

#include "grid/cone_evidence_updater.h"
#include "grid/updaters.h"

namespace cogmap::mapper {
namespace {

struct BayesModel {
  using Cell = float;  ///< Pr(H)
  static constexpr GridKind kKind = GridKind::kBayes;
  static Cell prior() { return 0.5f; }
  static void absorb(Cell& p, double weight, bool region_one, const GridOptions& options) {
    const SensorLikelihood l = region_one ? bayes_region_one(weight, options.bayes_max_occupied)
                                          : bayes_region_two(weight);
    p = static_cast<float>(bayes_posterior(p, l));  // Eq. 2.9
  }
  static float to_histogram(const Cell& p) { return bayes_to_histogram(p); }
};

}  // namespace

std::unique_ptr<GridUpdater> make_bayes_updater(const GridOptions& options,
                                                const RobotGeometry& robot) {
  return std::make_unique<ConeEvidenceUpdater<BayesModel>>(options, robot);
}

}  // namespace cogmap::mapper
