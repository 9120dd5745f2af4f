// Dempster-Shafer evidence grid, thesis §2.2.2: each cell holds masses m(O), m(E), m(Θ),
// starting (0, 0, 1). A reading's cone is rasterised as for Bayes; region I and II cells get
// Table 2.3's masses, combined with the cell's by Dempster's rule (Eqs. 2.11-2.13) with the
// conflict normalised away. m(Θ) is kept >= kMinUnknownMass so a cell can always be revised.

#include "grid/cone_evidence_updater.h"
#include "grid/updaters.h"

namespace cogmap::mapper {
namespace {

constexpr double kMinUnknownMass = 0.001;  ///< mirrors the Bayes clamp [0.001, 0.999]

struct DempsterShaferModel {
  using Cell = DsMass;
  static constexpr GridKind kKind = GridKind::kDempsterShafer;
  static Cell prior() { return DsMass{}; }
  static void absorb(Cell& m, double weight, bool region_one, const GridOptions& options) {
    const DsMass evidence =
        region_one ? ds_region_one(weight, options.bayes_max_occupied) : ds_region_two(weight);
    m = keep_open(dempster_combine(m, evidence).mass, kMinUnknownMass);  // Eqs. 2.11-2.13
  }
  static float to_histogram(const Cell& m) { return ds_to_histogram(m); }
};

}  // namespace

std::unique_ptr<GridUpdater> make_dempster_shafer_updater(const GridOptions& options,
                                                          const RobotGeometry& robot) {
  return std::make_unique<ConeEvidenceUpdater<DempsterShaferModel>>(options, robot);
}

}  // namespace cogmap::mapper
