// Fig. 4.1 (b): rooms as numbered nodes at their reference points, joined through their exits.

#include <map>
#include <optional>

#include "canvas.h"
#include "cogmap/render/figures.h"
#include "panel.h"

namespace cogmap::render {
namespace {

constexpr double kGraphViewMarginM = 1.0;  // room for the node discs around the outermost nodes
constexpr double kGraphMinViewSizeM = 4.0;
constexpr double kNodeRadiusPx = 15.0;

}  // namespace

void write_graph_figure(const mapper::AsrGraph& graph, const std::string& title,
                        const std::filesystem::path& png, const Style& style) {
  write_graph_figure(graph.nodes(), graph.edges(), title, png, style);
}

void write_graph_figure(const std::vector<mapper::AsrNode>& nodes,
                        const std::vector<mapper::AsrEdge>& edges, const std::string& title,
                        const std::filesystem::path& png, const Style& style) {
  Font& font = thread_font();
  std::map<int, mapper::Point2> node_at;
  Bounds bounds;
  for (const auto& n : nodes) {
    node_at[n.id] = n.reference_point_world;
    bounds.add(n.reference_point_world);
  }
  // An edge is drawn node -> exit -> node, so a bend shows where the doorway is.
  std::vector<std::vector<mapper::Point2>> edge_lines;
  std::vector<mapper::Point2> exits;
  for (const auto& e : edges) {
    std::vector<mapper::Point2> line;
    if (auto it = node_at.find(e.from); it != node_at.end()) line.push_back(it->second);
    line.push_back(e.exit_world);
    if (auto it = node_at.find(e.to); it != node_at.end()) line.push_back(it->second);
    exits.push_back(e.exit_world);
    bounds.add(e.exit_world);
    edge_lines.push_back(std::move(line));
  }
  bounds = bounds.padded(kGraphViewMarginM, kGraphMinViewSizeM);

  const int title_h = title.empty() ? 0 : font.line_height_px(style.title_font_px) + 8;
  const FigureLayout layout = layout_figure(1, 1, !title.empty(), title_h, style);
  Canvas canvas(layout.width_px, layout.height_px, style, font);
  draw_title(canvas, layout.title, title);

  const std::vector<LegendEntry> legend = {
      {"room (ASR id)", style.graph_node, Swatch::kDisc},
      {"edge", style.graph_edge, Swatch::kLine, style.path_width_px},
      {"exit", style.exit_marker, Swatch::kPoints, style.point_size_px + 3},
  };
  const PanelLayout pl = layout_panel(canvas, layout.panels[0], legend, true);
  const WorldView view(pl.plot, bounds);
  canvas.use_world(view);
  for (const auto& line : edge_lines) canvas.polyline(line, style.graph_edge, style.path_width_px);
  canvas.points(exits, style.exit_marker, style.point_size_px + 3);
  // Discs in pixel space so a node keeps its size whatever the map's extent.
  canvas.use_pixels();
  for (const auto& n : nodes) {
    const mapper::Point2 p = view.to_pixel(n.reference_point_world);
    canvas.disc(p, kNodeRadiusPx, style.graph_node, style.graph_edge, 1.5f);
    canvas.text(std::to_string(n.id), style.label_font_px, style.text, p.x(), p.y(),
                HAlign::kCenter, VAlign::kMiddle);
  }
  const std::string caption = "room graph: " + std::to_string(nodes.size()) + " rooms, " +
                              std::to_string(edges.size()) + " edges";
  draw_panel_furniture(canvas, pl, "", caption, legend, &view);
  write_png(canvas.finish(), png);
}

}  // namespace cogmap::render
