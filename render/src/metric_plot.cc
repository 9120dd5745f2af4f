// Sweep plots: a metric's mean ± sd over seeds against the varied key, one line per series.

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "canvas.h"
#include "cogmap/render/figures.h"
#include "panel.h"

namespace cogmap::render {
namespace {

// Distinguishable on screen and in grey-scale print (the usual "tab10" start).
constexpr std::array<Rgb, 8> kSeriesColors = {Rgb{0.12f, 0.47f, 0.71f}, Rgb{1.00f, 0.50f, 0.05f},
                                              Rgb{0.17f, 0.63f, 0.17f}, Rgb{0.84f, 0.15f, 0.16f},
                                              Rgb{0.58f, 0.40f, 0.74f}, Rgb{0.55f, 0.34f, 0.29f},
                                              Rgb{0.89f, 0.47f, 0.76f}, Rgb{0.50f, 0.50f, 0.50f}};
constexpr double kCapHalfPx = 5.0;  // half width of an error bar's cap
constexpr double kTickPx = 5.0;
constexpr Rgb kGridLine{0.90f, 0.90f, 0.90f};

bool finite(double v) { return std::isfinite(v); }

// A linear map from [lo, hi] onto [a_px, b_px].
struct Axis {
  double lo, hi, a_px, b_px;
  double operator()(double v) const { return a_px + (v - lo) / (hi - lo) * (b_px - a_px); }
};

}  // namespace

void write_metric_plot(const std::string& title, const std::string& x_label,
                       const std::string& y_label, const std::vector<PlotSeries>& series,
                       const std::filesystem::path& png, const Style& style) {
  double x_lo = INFINITY, x_hi = -INFINITY, y_lo = INFINITY, y_hi = -INFINITY;
  for (const auto& s : series) {
    if (s.y_mean.size() != s.x.size() || (!s.y_sd.empty() && s.y_sd.size() != s.x.size())) {
      throw std::invalid_argument("cogmap render: series '" + s.label +
                                  "' has x, y_mean and y_sd of different lengths (" + png.string() +
                                  ")");
    }
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      if (!finite(s.x[i]) || !finite(s.y_mean[i])) continue;
      const double sd = s.y_sd.empty() || !finite(s.y_sd[i]) ? 0.0 : std::abs(s.y_sd[i]);
      x_lo = std::min(x_lo, s.x[i]);
      x_hi = std::max(x_hi, s.x[i]);
      y_lo = std::min(y_lo, s.y_mean[i] - sd);
      y_hi = std::max(y_hi, s.y_mean[i] + sd);
    }
  }
  if (!(x_hi >= x_lo)) x_lo = 0.0, x_hi = 1.0, y_lo = 0.0, y_hi = 1.0;  // nothing to plot
  // A little air so no marker or error bar sits on the axes box.
  const double x_pad = 0.03 * (x_hi - x_lo), y_pad = 0.05 * (y_hi - y_lo);
  const bool non_negative = y_lo >= 0.0;  // errors, fractions: keep the axis from going below 0
  x_lo -= x_pad, x_hi += x_pad, y_lo -= y_pad, y_hi += y_pad;
  if (non_negative) y_lo = std::max(y_lo, 0.0);
  const std::vector<double> x_ticks = nice_ticks(x_lo, x_hi, 6);
  const std::vector<double> y_ticks = nice_ticks(y_lo, y_hi, 6);

  Font& font = thread_font();
  const int title_h = title.empty() ? 0 : font.line_height_px(style.title_font_px) + 8;
  const FigureLayout layout = layout_figure(1, 1, !title.empty(), title_h, style);
  Canvas canvas(layout.width_px, layout.height_px, style, font);
  draw_title(canvas, layout.title, title);

  std::vector<LegendEntry> legend;
  for (std::size_t k = 0; k < series.size(); ++k) {
    legend.push_back({series[k].label, kSeriesColors[k % kSeriesColors.size()], Swatch::kLine,
                      style.plot_line_width_px});
  }
  const PanelLayout pl = layout_panel(canvas, layout.panels[0], legend, false);

  // Room for tick labels and axis titles to the left of and below the axes.
  const int label_h = font.line_height_px(style.label_font_px);
  int y_tick_w = 0;
  for (double t : y_ticks)
    y_tick_w = std::max(y_tick_w, font.width_px(format_number(t), style.label_font_px));
  const int left = pl.plot.x + label_h + 8 + y_tick_w + 8;
  const int right = pl.plot.right() - 12;
  const int top = pl.plot.y + 8;
  const int bottom = pl.plot.bottom() - (2 * label_h + 14);
  const Axis ax{x_ticks.front(), x_ticks.back(), static_cast<double>(left),
                static_cast<double>(right)};
  const Axis ay{y_ticks.front(), y_ticks.back(), static_cast<double>(bottom),
                static_cast<double>(top)};

  canvas.use_pixels();
  for (double t : x_ticks) {
    canvas.segments({{{ax(t), double(top)}, {ax(t), double(bottom)}}}, kGridLine, 1.0f);
    canvas.segments({{{ax(t), double(bottom)}, {ax(t), bottom + kTickPx}}}, style.text, 1.0f);
    canvas.text(format_number(t), style.label_font_px, style.text, ax(t), bottom + kTickPx + 2,
                HAlign::kCenter, VAlign::kTop);
  }
  for (double t : y_ticks) {
    canvas.segments({{{double(left), ay(t)}, {double(right), ay(t)}}}, kGridLine, 1.0f);
    canvas.segments({{{left - kTickPx, ay(t)}, {double(left), ay(t)}}}, style.text, 1.0f);
    canvas.text(format_number(t), style.label_font_px, style.text, left - kTickPx - 3, ay(t),
                HAlign::kRight, VAlign::kMiddle);
  }
  canvas.stroke_rect(left + 0.5, top + 0.5, right - 0.5, bottom - 0.5, style.text, 1.0f);
  canvas.text(x_label, style.label_font_px, style.text, 0.5 * (left + right), pl.plot.bottom() - 4,
              HAlign::kCenter, VAlign::kBottom);
  canvas.text(y_label, style.label_font_px, style.text, pl.plot.x + 2, 0.5 * (top + bottom),
              HAlign::kLeft, VAlign::kMiddle, true);

  for (std::size_t k = 0; k < series.size(); ++k) {
    const PlotSeries& s = series[k];
    const Rgb color = kSeriesColors[k % kSeriesColors.size()];
    std::vector<std::size_t> order(s.x.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](auto a, auto b) { return s.x[a] < s.x[b]; });
    std::vector<mapper::Point2> line;
    std::vector<mapper::Segment> bars;
    for (std::size_t i : order) {
      if (!finite(s.x[i]) || !finite(s.y_mean[i])) continue;
      const double px = ax(s.x[i]);
      line.emplace_back(px, ay(s.y_mean[i]));
      if (s.y_sd.empty() || !finite(s.y_sd[i]) || s.y_sd[i] == 0.0) continue;
      const double lo = ay(s.y_mean[i] - std::abs(s.y_sd[i]));
      const double hi = ay(s.y_mean[i] + std::abs(s.y_sd[i]));
      bars.push_back({{px, lo}, {px, hi}});
      bars.push_back({{px - kCapHalfPx, lo}, {px + kCapHalfPx, lo}});
      bars.push_back({{px - kCapHalfPx, hi}, {px + kCapHalfPx, hi}});
    }
    canvas.segments(bars, color, 1.5f);
    canvas.polyline(line, color, style.plot_line_width_px);
    canvas.points(line, color, style.plot_line_width_px * 3.5f);
  }
  // Only sweeps carry error bars; a plain curve (e.g. the sonar echo model) says nothing of seeds.
  const bool any_sd = std::any_of(series.begin(), series.end(),
                                  [](const PlotSeries& s) { return !s.y_sd.empty(); });
  draw_panel_furniture(canvas, pl, "", any_sd ? "mean ± sd over seeds" : "", legend, nullptr);
  write_png(canvas.finish(), png);
}

}  // namespace cogmap::render
