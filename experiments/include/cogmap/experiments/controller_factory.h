#pragma once
/// The controller an experiment's `controller:` block asks for (route follower, explorer or
/// none), with the options the block sets and the nav module's defaults for the rest.

#include <memory>

#include "cogmap/experiments/experiment_config.h"
#include "cogmap/mapper/nav/controller.h"

namespace cogmap::experiments {

/// A new controller for `c` (ControllerKind::kNone: one that never moves).
std::unique_ptr<mapper::nav::Controller> make_controller(const ControllerConfig& c);

}  // namespace cogmap::experiments
