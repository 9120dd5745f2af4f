#pragma once
// The table of figure writers the render plugin hands to the program that loads it
// (figures_loader.cc). Plugin and program come from the same build; the version and the sizes
// of the structs passed across catch a plugin left over from another build.

#include "cogmap/render/figures.h"

namespace cogmap::render::plugin {

/// Raise when any signature below or a struct passed through it changes.
inline constexpr int kFigureApiVersion = 3;

/// The plugin's one exported symbol: `const FigureApi* cogmap_render_figure_api()`.
inline constexpr const char* kEntryPoint = "cogmap_render_figure_api";

/// The plugin's file name; dlopen finds it through the program's run path
/// ($ORIGIN/../lib/cogmap once installed, the build tree's lib/cogmap before) or in
/// $COGMAP_PLUGIN_DIR.
inline constexpr const char* kFileName = "libcogmap_render_plugin.so";

struct FigureApi {
  int version = kFigureApiVersion;
  unsigned long style_size = sizeof(Style);
  unsigned long map_figure_size = sizeof(MapFigure);
  unsigned long plot_series_size = sizeof(PlotSeries);
  unsigned long map_error_figure_size = sizeof(MapErrorFigure);
  // The mapper's own types cross too: a plugin built against another AsrTrace reads garbage.
  unsigned long asr_trace_size = sizeof(mapper::AsrTrace);
  unsigned long asr_graph_size = sizeof(mapper::AsrGraph);
  unsigned long asr_node_size = sizeof(mapper::AsrNode);
  unsigned long asr_edge_size = sizeof(mapper::AsrEdge);
  void (*room_stages)(const mapper::AsrTrace&, const std::string&, const std::filesystem::path&,
                      const Style&) = nullptr;
  void (*map)(const MapFigure&, const std::filesystem::path&, const Style&) = nullptr;
  void (*graph)(const mapper::AsrGraph&, const std::string&, const std::filesystem::path&,
                const Style&) = nullptr;
  void (*graph_parts)(const std::vector<mapper::AsrNode>&, const std::vector<mapper::AsrEdge>&,
                      const std::string&, const std::filesystem::path&, const Style&) = nullptr;
  void (*metric_plot)(const std::string&, const std::string&, const std::string&,
                      const std::vector<PlotSeries>&, const std::filesystem::path&,
                      const Style&) = nullptr;
  void (*map_error)(const MapErrorFigure&, const std::filesystem::path&, const Style&) = nullptr;
};

}  // namespace cogmap::render::plugin
