// The figure writers of figures.h as the program sees them: each forwards to the render plugin,
// loaded with dlopen on first use, so OSMesa and LLVM are mapped only by a process that draws.
#include <dlfcn.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "cogmap/plugins/open_plugin.h"
#include "cogmap/render/figures.h"
#include "cogmap/render/renderer.h"
#include "figure_api.h"

namespace cogmap::render {
namespace {

using plugin::FigureApi;

const FigureApi* load_plugin() {
  std::string file = plugin::kFileName;
  if (const char* dir = std::getenv("COGMAP_PLUGIN_DIR"); dir != nullptr && *dir != '\0') {
    file = (std::filesystem::path(dir) / plugin::kFileName).string();
  }
  const std::string advice =
      "; reinstall cogmap (the plugin belongs in lib/cogmap beside its bin/), set "
      "COGMAP_PLUGIN_DIR to the folder that holds it, or run without figures (--no-figures)";
  // RTLD_LOCAL: the plugin's OSMesa, LLVM and its own copy of the drawing code stay out of the
  // program's symbol lookup. The handle is kept for the life of the process.
  std::string why;
  void* handle = plugins::open_plugin(file, RTLD_NOW | RTLD_LOCAL, why);
  if (handle == nullptr) {
    throw RendererUnavailable("cannot load the figure renderer " + file + " (" + why + ")" +
                              advice);
  }
  using Entry = const FigureApi* (*)();
  const auto entry = reinterpret_cast<Entry>(::dlsym(handle, plugin::kEntryPoint));
  const FigureApi* api = entry != nullptr ? entry() : nullptr;
  if (api == nullptr || api->version != plugin::kFigureApiVersion ||
      api->style_size != sizeof(Style) || api->map_figure_size != sizeof(MapFigure) ||
      api->plot_series_size != sizeof(PlotSeries) ||
      api->map_error_figure_size != sizeof(MapErrorFigure) ||
      api->asr_trace_size != sizeof(mapper::AsrTrace) ||
      api->asr_graph_size != sizeof(mapper::AsrGraph) ||
      api->asr_node_size != sizeof(mapper::AsrNode) ||
      api->asr_edge_size != sizeof(mapper::AsrEdge)) {
    throw RendererUnavailable("the figure renderer " + file +
                              " comes from another cogmap build (figure API mismatch)" + advice);
  }
  return api;
}

const FigureApi& api() {
  // A failed load throws out of the initialiser, so the next call tries again.
  static const FigureApi* const loaded = load_plugin();
  return *loaded;
}

}  // namespace

void require_renderer() { api(); }

bool rasterise_on_drawing_threads_only() {
  constexpr const char* kThreads = "LP_NUM_THREADS";  // llvmpipe's helper threads (0: none)
  if (std::getenv(kThreads) != nullptr) return false;
  return ::setenv(kThreads, "0", /*overwrite=*/0) == 0;
}

void write_room_stages_figure(const mapper::AsrTrace& trace, const std::string& title,
                              const std::filesystem::path& png, const Style& style) {
  api().room_stages(trace, title, png, style);
}

void write_map_figure(const MapFigure& figure, const std::filesystem::path& png,
                      const Style& style) {
  api().map(figure, png, style);
}

void write_map_error_figure(const MapErrorFigure& figure, const std::filesystem::path& png,
                            const Style& style) {
  api().map_error(figure, png, style);
}

void write_graph_figure(const mapper::AsrGraph& graph, const std::string& title,
                        const std::filesystem::path& png, const Style& style) {
  api().graph(graph, title, png, style);
}

void write_graph_figure(const std::vector<mapper::AsrNode>& nodes,
                        const std::vector<mapper::AsrEdge>& edges, const std::string& title,
                        const std::filesystem::path& png, const Style& style) {
  api().graph_parts(nodes, edges, title, png, style);
}

void write_metric_plot(const std::string& title, const std::string& x_label,
                       const std::string& y_label, const std::vector<PlotSeries>& series,
                       const std::filesystem::path& png, const Style& style) {
  api().metric_plot(title, x_label, y_label, series, png, style);
}

}  // namespace cogmap::render
