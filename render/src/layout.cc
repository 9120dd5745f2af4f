#include "layout.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace cogmap::render {

void Bounds::add(const mapper::Point2& p) {
  if (!std::isfinite(p.x()) || !std::isfinite(p.y())) return;  // one NaN must not blank a figure
  if (empty_) {
    min_x_ = max_x_ = p.x();
    min_y_ = max_y_ = p.y();
    empty_ = false;
    return;
  }
  min_x_ = std::min(min_x_, p.x());
  max_x_ = std::max(max_x_, p.x());
  min_y_ = std::min(min_y_, p.y());
  max_y_ = std::max(max_y_, p.y());
}

void Bounds::add(const std::vector<mapper::Point2>& points) {
  for (const auto& p : points) add(p);
}

void Bounds::add(const std::vector<mapper::Segment>& segments) {
  for (const auto& s : segments) {
    add(s.a);
    add(s.b);
  }
}

void Bounds::add(const std::vector<mapper::Polyline>& lines) {
  for (const auto& line : lines) add(line);
}

Bounds Bounds::padded(double margin_m, double min_size_m) const {
  Bounds out;
  if (empty_) {
    out.add(mapper::Point2(-0.5 * min_size_m, -0.5 * min_size_m));
    out.add(mapper::Point2(0.5 * min_size_m, 0.5 * min_size_m));
    return out;
  }
  const double cx = 0.5 * (min_x_ + max_x_), cy = 0.5 * (min_y_ + max_y_);
  const double half_w = std::max(0.5 * (max_x_ - min_x_) + margin_m, 0.5 * min_size_m);
  const double half_h = std::max(0.5 * (max_y_ - min_y_) + margin_m, 0.5 * min_size_m);
  out.add(mapper::Point2(cx - half_w, cy - half_h));
  out.add(mapper::Point2(cx + half_w, cy + half_h));
  return out;
}

WorldView::WorldView(const PixelRect& rect, const Bounds& bounds) : rect_(rect) {
  const double w_m = std::max(bounds.max_x() - bounds.min_x(), 1e-6);
  const double h_m = std::max(bounds.max_y() - bounds.min_y(), 1e-6);
  px_per_m_ = std::min(rect.w / w_m, rect.h / h_m);
  center_x_m_ = 0.5 * (bounds.min_x() + bounds.max_x());
  center_y_m_ = 0.5 * (bounds.min_y() + bounds.max_y());
}

mapper::Point2 WorldView::to_pixel(const mapper::Point2& p) const {
  return {rect_.x + 0.5 * rect_.w + (p.x() - center_x_m_) * px_per_m_,
          rect_.y + 0.5 * rect_.h - (p.y() - center_y_m_) * px_per_m_};
}

FigureLayout layout_figure(int panel_count, int columns, bool with_title, int title_height_px,
                           const Style& style) {
  FigureLayout layout;
  columns = std::max(1, std::min(columns, panel_count));
  const int rows = (panel_count + columns - 1) / columns;
  const int m = style.margin_px;
  const int title_h = with_title ? title_height_px : 0;
  layout.width_px = columns * style.panel_width_px + (columns + 1) * m;
  layout.height_px = title_h + rows * style.panel_height_px + (rows + 1) * m;
  layout.title = {m, m / 2, layout.width_px - 2 * m, title_h};
  for (int i = 0; i < panel_count; ++i) {
    const int r = i / columns, c = i % columns;
    layout.panels.push_back({m + c * (style.panel_width_px + m),
                             title_h + m + r * (style.panel_height_px + m), style.panel_width_px,
                             style.panel_height_px});
  }
  return layout;
}

double choose_scale_bar_m(double max_m) {
  double best = 0.1;
  for (double decade = 0.1; decade < 1e6; decade *= 10.0) {
    for (double step : {1.0, 2.0, 5.0}) {
      const double length = step * decade;
      if (length <= max_m * (1.0 + 1e-9)) best = length;
    }
  }
  return best;
}

std::vector<double> nice_ticks(double lo, double hi, int target_count) {
  if (!(hi > lo)) {
    const double pad = std::max(std::abs(lo) * 0.1, 1.0);
    lo -= pad;
    hi += pad;
  }
  const double raw = (hi - lo) / std::max(target_count, 1);
  const double decade = std::pow(10.0, std::floor(std::log10(raw)));
  double step = decade * 10.0;
  for (double k : {1.0, 2.0, 5.0, 10.0}) {
    if (k * decade >= raw) {
      step = k * decade;
      break;
    }
  }
  // Outward to whole steps, so the first and last ticks bracket every value.
  const long first = static_cast<long>(std::floor(lo / step + 1e-9));
  const long last = static_cast<long>(std::ceil(hi / step - 1e-9));
  std::vector<double> ticks;
  for (long k = first; k <= last; ++k) ticks.push_back(k == 0 ? 0.0 : k * step);  // no "-0"
  return ticks;
}

std::string format_number(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%.6g", value);
  return buffer;
}

}  // namespace cogmap::render
