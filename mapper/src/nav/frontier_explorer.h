#pragma once
#include <memory>

#include "cogmap/mapper/nav/controller.h"

namespace cogmap::mapper::nav {

/// ExploreStrategy::kFrontier (docs/algorithms.md, "Exploration").
std::unique_ptr<Controller> make_frontier_explorer(const ExploreOptions& options);
/// ExploreStrategy::kEdge (docs/algorithms.md, "Exploration").
std::unique_ptr<Controller> make_edge_explorer(const ExploreOptions& options);

}  // namespace cogmap::mapper::nav
