// figures/map_error.png: the corrected map with every metric sample's piece in the colour of
// its distance to the nearest true surface, so a bad wall can be found by eye (issue 10).

#include <stdexcept>

#include "canvas.h"
#include "cogmap/render/figures.h"
#include "error_colors.h"
#include "panel.h"

namespace cogmap::render {
namespace {

constexpr double kErrorMapViewMarginM = 0.5;
constexpr double kErrorMapMinViewSizeM = 2.0;
constexpr float kTrueWallWidthPx = 1.5f;  // thin: the coloured map must stay readable over it
constexpr float kPieceWidthPx = 3.5f;     // wider than a map wall, so the colour shows

// The scale as legend boxes: its three anchors and the two midpoints between them.
std::vector<LegendEntry> scale_legend(const Style& style) {
  const double good = style.error_good_m, mid = style.error_mid_m, bad = style.error_bad_m;
  std::vector<LegendEntry> legend;
  legend.push_back({"true walls", style.true_wall, Swatch::kLine, kTrueWallWidthPx});
  legend.push_back({"≤ " + format_number(good) + " m", error_color(good, style), Swatch::kBox});
  for (const double e : {0.5 * (good + mid), mid, 0.5 * (mid + bad)}) {
    legend.push_back({format_number(e) + " m", error_color(e, style), Swatch::kBox});
  }
  legend.push_back({"≥ " + format_number(bad) + " m", error_color(bad, style), Swatch::kBox});
  return legend;
}

}  // namespace

void write_map_error_figure(const MapErrorFigure& figure, const std::filesystem::path& png,
                            const Style& style) {
  if (figure.pieces.size() != figure.error_m.size()) {
    throw std::invalid_argument("cogmap render: pieces and error_m differ in size (" +
                                png.string() + ")");
  }
  Font& font = thread_font();
  Bounds bounds;
  bounds.add(figure.true_surfaces);
  bounds.add(figure.pieces);
  bounds = bounds.padded(kErrorMapViewMarginM, kErrorMapMinViewSizeM);

  const int title_h = figure.title.empty() ? 0 : font.line_height_px(style.title_font_px) + 8;
  const FigureLayout layout = layout_figure(1, 1, !figure.title.empty(), title_h, style);
  Canvas canvas(layout.width_px, layout.height_px, style, font);
  draw_title(canvas, layout.title, figure.title);

  const std::vector<LegendEntry> legend = scale_legend(style);
  const PanelLayout pl = layout_panel(canvas, layout.panels[0], legend, true);
  const WorldView view(pl.plot, bounds);
  canvas.use_world(view);
  canvas.segments(figure.true_surfaces, style.true_wall, kTrueWallWidthPx);
  for (std::size_t i = 0; i < figure.pieces.size(); ++i) {
    canvas.segments({figure.pieces[i]}, error_color(figure.error_m[i], style), kPieceWidthPx);
  }
  draw_panel_furniture(canvas, pl, "", figure.caption, legend, &view);
  write_png(canvas.finish(), png);
}

}  // namespace cogmap::render
