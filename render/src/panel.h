#pragma once
// The furniture every map panel shares: "(a) caption" header, a framed plot area, and a footer
// holding a metric scale bar and a legend that wraps onto as many rows as it needs.

#include <string>
#include <vector>

#include "canvas.h"
#include "layout.h"

namespace cogmap::render {

/// How a legend entry's sample is drawn.
enum class Swatch { kLine, kDashedLine, kPoints, kBox, kDisc };

/// One legend entry: a sample in `color` and its label.
struct LegendEntry {
  std::string label;
  Rgb color;
  Swatch swatch = Swatch::kLine;
  float width_px = 2.0f;  ///< line width or point size of the sample
};

/// The parts of a panel once header and footer are reserved.
struct PanelLayout {
  PixelRect header;  ///< letter and caption
  PixelRect plot;    ///< the framed data area
  PixelRect footer;  ///< scale bar and legend
};

/// Rows the footer needs for `legend` (and a scale bar slot when `scale_bar`) in `width_px`.
int legend_rows(Canvas& canvas, int width_px, const std::vector<LegendEntry>& legend,
                bool scale_bar);

/// Splits `panel` so the legend (and a scale bar slot when `scale_bar`) fit in the footer, with
/// at least `min_rows` footer rows (sibling panels pass their maximum so their maps share a scale).
PanelLayout layout_panel(Canvas& canvas, const PixelRect& panel,
                         const std::vector<LegendEntry>& legend, bool scale_bar, int min_rows = 0);

/// Draws "(letter) caption" in the header, the plot frame, and the footer: a scale bar for
/// `view` (when `scale_bar`) and the legend. Leaves the canvas in pixel space.
void draw_panel_furniture(Canvas& canvas, const PanelLayout& layout, const std::string& letter,
                          const std::string& caption, const std::vector<LegendEntry>& legend,
                          const WorldView* view);

/// The panel letter for index i: "(a)", "(b)", ...
std::string panel_letter(int index);

}  // namespace cogmap::render
