#pragma once
/// The explorer's last look before it stops: a doorway the jambs' echoes painted shut in the
/// explore map (a ±6° arc per echo, from up to 3 m) is often open in the current room's grid,
/// which marks echoes on the beam's axis alone and sweeps the doorway free with every beam
/// that passes through it. Explore-map obstacle cells that the room grid holds as swept and
/// never echoed are reopened, on a copy, for one more plan.

#include <cstddef>

#include "cogmap/mapper/grid/grid_updater.h"
#include "nav/explore_map.h"

namespace cogmap::mapper::nav {

/// Clears the echo weight of every obstacle cell of `map` whose area the room grid covers with
/// at least one cell seen empty (below 0: a beam's axis passed through it) and no cell at
/// `echo_himm` or above (no echo marked there on an axis). Returns how many cells it cleared.
std::size_t reopen_swept_cells(ExploreMap& map, const GridUpdater& room_grid, double echo_himm);

}  // namespace cogmap::mapper::nav
