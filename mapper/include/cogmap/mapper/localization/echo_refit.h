#pragma once
/// Wall directions refitted to the room's own echoes, for EM's measurement of the room's
/// rotation (not in the thesis; docs/algorithms.md, "Wall directions from the echoes").
/// A wall fitted to the cleaned grid's cells has a direction quantised by the cells: a 1-2 m
/// segment's direction scatters by ~1.5° (median) about its room's. The echoes that drew it lie
/// along the wall within the sonar's ~1-2 cm of noise, hundreds to a segment.

#include <span>
#include <vector>

#include "cogmap/mapper/seam/geometry.h"

namespace cogmap::mapper {

struct EchoRefitOptions {
  /// Echo endpoints within this distance of a wall segment (and between its ends) refit its
  /// direction; 0 = off: EM measures the fitted lines' own directions, as the thesis does.
  double band_m = 0.0;
  int min_echoes = 20;             ///< fewer echoes near a segment leave it as fitted
  double max_turn_rad = 0.087266;  ///< a refit turning its segment by more (5°) is refused
};

/// Each segment of `walls` as a two-point polyline: along the principal axis (total least
/// squares) of the `echoes` within `band_m` of the segment and between its ends, centred on
/// their mean, as long as the segment and pointing the same way; the segment as it is when
/// fewer than `min_echoes` lie there or the axis turns it by more than `max_turn_rad`. Walls and
/// echoes are in one frame. Segments of zero length are dropped.
std::vector<Polyline> refit_wall_directions(std::span<const Polyline> walls,
                                            std::span<const Point2> echoes,
                                            const EchoRefitOptions& options);

}  // namespace cogmap::mapper
