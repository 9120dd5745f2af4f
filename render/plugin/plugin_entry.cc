// The render plugin's entry point: the OSMesa-backed figure writers as one table. Everything
// else in the plugin is hidden (-Wl,--exclude-libs,ALL), so its copy of the drawing code never
// mixes with the program's symbols.
#include "figure_api.h"

namespace {

using cogmap::render::plugin::FigureApi;

const FigureApi kApi = [] {
  namespace r = cogmap::render;
  FigureApi api;
  api.room_stages = &r::write_room_stages_figure;
  api.map = &r::write_map_figure;
  api.map_error = &r::write_map_error_figure;
  api.graph =
      static_cast<void (*)(const cogmap::mapper::AsrGraph&, const std::string&,
                           const std::filesystem::path&, const r::Style&)>(&r::write_graph_figure);
  api.graph_parts = static_cast<void (*)(
      const std::vector<cogmap::mapper::AsrNode>&, const std::vector<cogmap::mapper::AsrEdge>&,
      const std::string&, const std::filesystem::path&, const r::Style&)>(&r::write_graph_figure);
  api.metric_plot = &r::write_metric_plot;
  return api;
}();

}  // namespace

extern "C" __attribute__((visibility("default"))) const FigureApi* cogmap_render_figure_api() {
  return &kApi;
}
