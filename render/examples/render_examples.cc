// render_examples OUT_DIR: writes the example figures shown in docs/figures.md from the synthetic
// scenes (render/src/synthetic_scenes.h), so the documentation's pictures can be regenerated.

#include <exception>
#include <filesystem>
#include <iostream>

#include "cogmap/render/figures.h"
#include "synthetic_scenes.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: render_examples OUT_DIR\n";
    return 2;
  }
  namespace render = cogmap::render;
  const std::filesystem::path out(argv[1]);
  try {
    render::write_room_stages_figure(render::testing::synthetic_room_trace(),
                                     "Room 3: from grid to polylines (synthetic)",
                                     out / "room_stages.png");
    render::write_map_figure(render::testing::synthetic_map_figure(), out / "map.png");
    std::vector<cogmap::mapper::AsrNode> nodes;
    std::vector<cogmap::mapper::AsrEdge> edges;
    render::testing::synthetic_graph(&nodes, &edges);
    render::write_graph_figure(nodes, edges, "nine_rooms: room graph (synthetic)",
                               out / "graph.png");
    render::write_metric_plot("Wall error against cell size (synthetic)", "cell scale ℘ (mm)",
                              "median wall error (m)", render::testing::synthetic_sweep(),
                              out / "metric_plot.png");
  } catch (const std::exception& e) {
    std::cerr << "render_examples: " << e.what() << "\n";
    return 1;
  }
  std::cout << "wrote example figures to " << out << "\n";
  return 0;
}
