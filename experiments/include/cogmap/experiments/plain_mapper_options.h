#pragma once
/// What the controller's mapper uses with `controller.pose: plain_estimate`: the experiment's
/// mapper settings with the map-only refinements back at the library's defaults, so that the
/// robot drives as it would without them while the map is drawn with them
/// (docs/experiment-format.md, "controller.pose").

#include "cogmap/mapper/mapper.h"

namespace cogmap::experiments {

/// `map` with scan matching, glimpses, the odometry's curvature recalibration, the
/// translation's move of the estimate, EM's wall directions from the echoes
/// (`localizer.echo_refit`) and its sd from the longest wall (`localizer.measurement_sd_rad_m`)
/// as `mapper::MapperOptions{}` has them; everything else
/// (grid, boundaries, EM, the cuts, door fixes, held turns) as `map` says, since those decide
/// when rooms end and what EM corrects.
mapper::MapperOptions plain_mapper_options(const mapper::MapperOptions& map);

/// Whether `map` has any of those refinements on. Off, plain_mapper_options(map) draws and
/// estimates exactly as `map` does (each refinement is gated by its own switch), so a second
/// mapper would repeat the first frame for frame.
bool has_map_only_refinements(const mapper::MapperOptions& map);

}  // namespace cogmap::experiments
