#pragma once
/// Whether the walls enclose a start pose (docs/worlds.md "Start outside the walls"): a start
/// outside every wall loads (it is clear of everything), but the robot would hear almost
/// nothing. `cogmap world check` and `cogmap run` warn about it; it is never an error, because
/// test worlds of a single wall are legitimate.

#include <optional>
#include <string>

#include "cogmap/mapper/seam/geometry.h"
#include "cogmap/sim/world_spec.h"

namespace cogmap::sim {

/// Rays the enclosure test casts from the start, evenly spaced from +x counter-clockwise.
inline constexpr int kEnclosureDirections = 32;

/// How many of `directions` rays from `from` meet no wall or obstacle at any distance (the
/// solid pieces: walls with their thickness, obstacle outlines).
int open_directions(const WorldSpec& world, const mapper::Point2& from,
                    int directions = kEnclosureDirections);

/// The warning for a start the walls do not enclose (more than a quarter of the
/// kEnclosureDirections rays from it meet nothing), without a file prefix:
/// "start (x, y) is not enclosed by walls: N of 32 directions ..."; nullopt when enclosed.
std::optional<std::string> start_enclosure_warning(const WorldSpec& world,
                                                   const mapper::Point2& start);

}  // namespace cogmap::sim
