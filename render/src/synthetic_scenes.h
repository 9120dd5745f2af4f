#pragma once
// Hand-built scenes with known geometry for the renderer's tests and example figures, so both
// run without the mapper pipeline or the simulator.

#include <vector>

#include "cogmap/mapper/asr/asr_builder.h"
#include "cogmap/mapper/graph/asr_graph.h"
#include "cogmap/render/figures.h"

namespace cogmap::render::testing {

/// A 5 x 4 m room at 0.1 m cells with a doorway in the east wall, sonar-like noise, a few
/// spurious cells that cleaning removes, and every later stage derived by hand. Deterministic.
mapper::AsrTrace synthetic_room_trace();

/// The two-room world of FORMATS.md (10 x 6 m, doorway at x = 5) mapped with a heading drift
/// that localisation removes. Deterministic.
MapFigure synthetic_map_figure();

/// A 3 x 3 grid of rooms joined through doorways, numbered in visiting order.
void synthetic_graph(std::vector<mapper::AsrNode>* nodes, std::vector<mapper::AsrEdge>* edges);

/// Wall error against cell size for two grid models, mean ± sd over five seeds (made up).
std::vector<PlotSeries> synthetic_sweep();

}  // namespace cogmap::render::testing
