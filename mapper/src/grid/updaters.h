#pragma once
/// Constructors of the four GridUpdater implementations; make_grid_updater picks one by kind.

#include <memory>

#include "cogmap/mapper/grid/grid_updater.h"

namespace cogmap::mapper {

/// HIMM as printed in thesis Fig. A.2 (Borenstein & Koren, §2.2.3).
std::unique_ptr<GridUpdater> make_himm_updater(const GridOptions& options,
                                               const RobotGeometry& robot);
/// MHIMM, thesis Fig. A.3 and §3.1.4.
std::unique_ptr<GridUpdater> make_mhimm_updater(const GridOptions& options,
                                                const RobotGeometry& robot);
/// Bayes occupancy, thesis §2.2.1, Table 2.2, Eq. 2.9.
std::unique_ptr<GridUpdater> make_bayes_updater(const GridOptions& options,
                                                const RobotGeometry& robot);
/// Dempster-Shafer evidence, thesis §2.2.2, Table 2.3, Eqs. 2.11-2.13.
std::unique_ptr<GridUpdater> make_dempster_shafer_updater(const GridOptions& options,
                                                          const RobotGeometry& robot);

}  // namespace cogmap::mapper
