// Figs. 4.4-4.6: the merged map before and after localisation over the ground truth.

#include <algorithm>
#include <initializer_list>
#include <stdexcept>
#include <utility>

#include "canvas.h"
#include "cogmap/render/figures.h"
#include "panel.h"

namespace cogmap::render {
namespace {

constexpr double kMapViewMarginM = 0.5;   // white space around the data
constexpr double kMapMinViewSizeM = 2.0;  // a lone point still gets a readable window
constexpr double kStartDotRadiusPx = 4.5;

struct MapPanel {
  std::string caption;
  const std::vector<mapper::Segment>* map;
  const std::vector<mapper::Point2>* path;
  Rgb path_color;
  std::string path_label;
  const std::vector<mapper::Point2>* labels_at;
};

void draw_labels(Canvas& canvas, const WorldView& view, const std::vector<mapper::Point2>& at,
                 const std::vector<std::string>& labels) {
  const Style& style = canvas.style();
  canvas.use_pixels();
  for (std::size_t i = 0; i < at.size() && i < labels.size(); ++i) {
    const mapper::Point2 p = view.to_pixel(at[i]);
    canvas.disc(p, 3.0, style.text, style.text, 0.0f);
    canvas.text(labels[i], style.label_font_px, style.text, p.x() + 5, p.y() - 3, HAlign::kLeft,
                VAlign::kBottom);
  }
}

// A dot where each path begins, so the direction of travel can be read off the figure.
void mark_starts(Canvas& canvas, const WorldView& view,
                 std::initializer_list<std::pair<const std::vector<mapper::Point2>*, Rgb>> paths) {
  canvas.use_pixels();
  for (const auto& [path, color] : paths) {
    if (path->empty()) continue;
    canvas.disc(view.to_pixel(path->front()), kStartDotRadiusPx, color, color, 0.0f);
  }
}

}  // namespace

void write_map_figure(const MapFigure& figure, const std::filesystem::path& png,
                      const Style& style) {
  if (figure.room_labels_at.size() != figure.room_labels.size()) {
    throw std::invalid_argument("cogmap render: room_labels_at and room_labels differ in size (" +
                                png.string() + ")");
  }
  Font& font = thread_font();
  // One window for both panels, so a wall's shift under localisation is visible as a shift.
  Bounds bounds;
  bounds.add(figure.true_surfaces);
  bounds.add(figure.map_odometry);
  bounds.add(figure.map_corrected);
  bounds.add(figure.true_path);
  bounds.add(figure.odometry_path);
  bounds.add(figure.estimated_path);
  bounds = bounds.padded(kMapViewMarginM, kMapMinViewSizeM);

  const int title_h = figure.title.empty() ? 0 : font.line_height_px(style.title_font_px) + 8;
  const FigureLayout layout = layout_figure(2, 2, !figure.title.empty(), title_h, style);
  Canvas canvas(layout.width_px, layout.height_px, style, font);
  draw_title(canvas, layout.title, figure.title);

  const MapPanel panels[2] = {
      {"before localisation (odometry)", &figure.map_odometry, &figure.odometry_path,
       style.odometry_path, "odometry path", &figure.room_labels_at_odometry},
      {"after localisation", &figure.map_corrected, &figure.estimated_path, style.estimated_path,
       "estimated path", &figure.room_labels_at},
  };
  std::vector<LegendEntry> legends[2];
  for (int i = 0; i < 2; ++i) {
    const MapPanel& panel = panels[i];
    std::vector<LegendEntry>& legend = legends[i];
    if (!figure.true_surfaces.empty()) {
      legend.push_back({"true walls", style.true_wall, Swatch::kLine, style.true_wall_width_px});
    }
    legend.push_back({"map walls", style.map_wall, Swatch::kLine, style.map_wall_width_px});
    if (!figure.true_path.empty()) {
      legend.push_back({"true path", style.true_path, Swatch::kLine, style.path_width_px});
    }
    if (!panel.path->empty()) {
      legend.push_back({panel.path_label, panel.path_color, Swatch::kLine, style.path_width_px});
    }
  }
  // Equal footers keep both panels at one scale, so they can be compared wall by wall.
  const int footer_rows = std::max(legend_rows(canvas, layout.panels[0].w, legends[0], true),
                                   legend_rows(canvas, layout.panels[1].w, legends[1], true));
  for (int i = 0; i < 2; ++i) {
    const MapPanel& panel = panels[i];
    const std::vector<LegendEntry>& legend = legends[i];
    const PanelLayout pl = layout_panel(canvas, layout.panels[i], legend, true, footer_rows);
    const WorldView view(pl.plot, bounds);
    canvas.use_world(view);
    // Truth first and wide, so the map drawn over it shows where it agrees.
    canvas.segments(figure.true_surfaces, style.true_wall, style.true_wall_width_px);
    canvas.polyline(figure.true_path, style.true_path, style.path_width_px);
    canvas.polyline(*panel.path, panel.path_color, style.path_width_px);
    canvas.segments(*panel.map, style.map_wall, style.map_wall_width_px);
    mark_starts(canvas, view,
                {{&figure.true_path, style.true_path}, {panel.path, panel.path_color}});
    if (!panel.labels_at->empty()) draw_labels(canvas, view, *panel.labels_at, figure.room_labels);
    draw_panel_furniture(canvas, pl, panel_letter(i), panel.caption, legend, &view);
  }
  write_png(canvas.finish(), png);
}

}  // namespace cogmap::render
