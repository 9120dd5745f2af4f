#include "grid/updaters.h"

namespace cogmap::mapper {

std::unique_ptr<GridUpdater> make_grid_updater(GridKind kind, const GridOptions& options,
                                               const RobotGeometry& robot) {
  switch (kind) {
    case GridKind::kHimm:
      return make_himm_updater(options, robot);
    case GridKind::kMhimm:
      return make_mhimm_updater(options, robot);
    case GridKind::kBayes:
      return make_bayes_updater(options, robot);
    case GridKind::kDempsterShafer:
      return make_dempster_shafer_updater(options, robot);
  }
  return nullptr;
}

}  // namespace cogmap::mapper
