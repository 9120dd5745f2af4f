#include "panel.h"

#include <algorithm>
#include <cmath>

namespace cogmap::render {
namespace {

constexpr int kSwatchWidthPx = 26;    // legend sample length
constexpr int kSwatchGapPx = 6;       // sample to label
constexpr int kEntryGapPx = 16;       // between legend entries
constexpr int kScaleBarMaxPx = 110;   // the bar is the longest nice length up to this
constexpr int kScaleBarSlotPx = 170;  // bar plus its "10 m" label
constexpr int kPadPx = 6;             // inner padding of header and footer

struct Placed {
  int x;
  int row;
};

// Flows entries left to right after the scale-bar slot, wrapping at the footer's width.
std::vector<Placed> flow(Canvas& canvas, int width_px, const std::vector<LegendEntry>& legend,
                         bool scale_bar, int* rows) {
  const int size = canvas.style().label_font_px;
  std::vector<Placed> placed;
  int x = scale_bar ? kScaleBarSlotPx : 0, row = 0;
  for (const auto& e : legend) {
    const int w = kSwatchWidthPx + kSwatchGapPx + canvas.font().width_px(e.label, size);
    if (x > 0 && x + w > width_px) {
      x = 0;
      ++row;
    }
    placed.push_back({x, row});
    x += w + kEntryGapPx;
  }
  *rows = (legend.empty() && !scale_bar) ? 0 : row + 1;
  return placed;
}

int row_height(Canvas& canvas) {
  return canvas.font().line_height_px(canvas.style().label_font_px) + 4;
}

void draw_swatch(Canvas& canvas, const LegendEntry& e, double x, double y_mid) {
  const double x1 = x + kSwatchWidthPx;
  switch (e.swatch) {
    case Swatch::kLine:
    case Swatch::kDashedLine:
      canvas.segments({{mapper::Point2(x, y_mid), mapper::Point2(x1, y_mid)}}, e.color, e.width_px,
                      e.swatch == Swatch::kDashedLine);
      break;
    case Swatch::kPoints:
      canvas.points({{x + 5, y_mid}, {x + 13, y_mid}, {x1 - 5, y_mid}}, e.color, e.width_px);
      break;
    case Swatch::kBox:
      canvas.fill_rect(x + 4, y_mid - 7, x1 - 4, y_mid + 7, e.color);
      canvas.stroke_rect(x + 4, y_mid - 7, x1 - 4, y_mid + 7, canvas.style().frame, 1.0f);
      break;
    case Swatch::kDisc:
      canvas.disc({x + kSwatchWidthPx / 2.0, y_mid}, 7.0, e.color, canvas.style().graph_edge, 1.5f);
      break;
  }
}

}  // namespace

std::string panel_letter(int index) { return "(" + std::string(1, char('a' + index)) + ")"; }

int legend_rows(Canvas& canvas, int width_px, const std::vector<LegendEntry>& legend,
                bool scale_bar) {
  int rows = 0;
  flow(canvas, width_px, legend, scale_bar, &rows);
  return rows;
}

PanelLayout layout_panel(Canvas& canvas, const PixelRect& panel,
                         const std::vector<LegendEntry>& legend, bool scale_bar, int min_rows) {
  const int rows = std::max(min_rows, legend_rows(canvas, panel.w, legend, scale_bar));
  const int header_h = canvas.font().line_height_px(canvas.style().caption_font_px) + 2 * kPadPx;
  const int footer_h = rows > 0 ? rows * row_height(canvas) + kPadPx : 0;
  PanelLayout out;
  out.header = {panel.x, panel.y, panel.w, header_h};
  out.footer = {panel.x, panel.bottom() - footer_h, panel.w, footer_h};
  out.plot = {panel.x, panel.y + header_h, panel.w, std::max(1, panel.h - header_h - footer_h)};
  return out;
}

void draw_panel_furniture(Canvas& canvas, const PanelLayout& layout, const std::string& letter,
                          const std::string& caption, const std::vector<LegendEntry>& legend,
                          const WorldView* view) {
  const Style& style = canvas.style();
  canvas.use_pixels();
  const std::string header = letter.empty() ? caption : letter + " " + caption;
  canvas.text(header, style.caption_font_px, style.text, layout.header.x,
              layout.header.y + layout.header.h / 2.0, HAlign::kLeft, VAlign::kMiddle);
  const PixelRect& p = layout.plot;
  // Map panels get a frame so the window's edge is visible; plots draw their own axes box.
  if (view != nullptr) {
    canvas.stroke_rect(p.x + 0.5, p.y + 0.5, p.right() - 0.5, p.bottom() - 0.5, style.frame, 1.0f);
  }

  int rows = 0;
  const std::vector<Placed> placed = flow(canvas, layout.footer.w, legend, view != nullptr, &rows);
  const int rh = row_height(canvas);
  const double first_mid = layout.footer.y + kPadPx + rh / 2.0;
  if (view != nullptr) {
    const double bar_m = choose_scale_bar_m(kScaleBarMaxPx / view->px_per_m());
    const double bar_px = bar_m * view->px_per_m();
    const double x0 = layout.footer.x + 2, x1 = x0 + bar_px;
    // A bar with end ticks, like a map's scale, so its length reads at a glance.
    canvas.fill_rect(x0, first_mid - 2, x1, first_mid + 2, style.text);
    canvas.fill_rect(x0, first_mid - 6, x0 + 2, first_mid + 6, style.text);
    canvas.fill_rect(x1 - 2, first_mid - 6, x1, first_mid + 6, style.text);
    canvas.text(format_number(bar_m) + " m", style.label_font_px, style.text, x1 + 6, first_mid,
                HAlign::kLeft, VAlign::kMiddle);
  }
  for (std::size_t i = 0; i < legend.size(); ++i) {
    const double x = layout.footer.x + placed[i].x;
    const double y_mid = first_mid + placed[i].row * rh;
    draw_swatch(canvas, legend[i], x, y_mid);
    canvas.text(legend[i].label, style.label_font_px, style.text, x + kSwatchWidthPx + kSwatchGapPx,
                y_mid, HAlign::kLeft, VAlign::kMiddle);
  }
}

}  // namespace cogmap::render
