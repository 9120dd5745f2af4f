#pragma once
// Geometry of a figure: panel rectangles in pixels, the world window each panel shows, and the
// "nice" numbers used for scale bars and axis ticks.

#include <string>
#include <vector>

#include "cogmap/mapper/seam/geometry.h"
#include "cogmap/render/style.h"

namespace cogmap::render {

/// A pixel rectangle, top-left origin, y down.
struct PixelRect {
  int x = 0;  ///< left column
  int y = 0;  ///< top row
  int w = 0;  ///< width, pixels
  int h = 0;  ///< height, pixels
  int right() const { return x + w; }
  int bottom() const { return y + h; }
};

/// An axis-aligned box in world metres that grows as data is added.
class Bounds {
 public:
  void add(const mapper::Point2& p);
  void add(const std::vector<mapper::Point2>& points);
  void add(const std::vector<mapper::Segment>& segments);
  void add(const std::vector<mapper::Polyline>& lines);
  bool empty() const { return empty_; }
  double min_x() const { return min_x_; }  ///< metres
  double min_y() const { return min_y_; }  ///< metres
  double max_x() const { return max_x_; }  ///< metres
  double max_y() const { return max_y_; }  ///< metres
  /// Grown by `margin_m` on every side and to at least `min_size_m` per side; a unit box about
  /// the origin when empty.
  Bounds padded(double margin_m, double min_size_m) const;

 private:
  bool empty_ = true;
  double min_x_ = 0.0, min_y_ = 0.0, max_x_ = 0.0, max_y_ = 0.0;
};

/// A world window shown in a pixel rectangle at one scale for x and y (metres are square).
class WorldView {
 public:
  /// The largest scale at which `bounds` fits `rect`; the bounds are centred.
  WorldView(const PixelRect& rect, const Bounds& bounds);
  const PixelRect& rect() const { return rect_; }
  double px_per_m() const { return px_per_m_; }
  /// Top-left pixel coordinates of world point `p`.
  mapper::Point2 to_pixel(const mapper::Point2& p) const;
  double left_m() const { return center_x_m_ - rect_.w / (2.0 * px_per_m_); }  ///< rect's left edge
  double right_m() const { return center_x_m_ + rect_.w / (2.0 * px_per_m_); }   ///< right edge
  double bottom_m() const { return center_y_m_ - rect_.h / (2.0 * px_per_m_); }  ///< bottom edge
  double top_m() const { return center_y_m_ + rect_.h / (2.0 * px_per_m_); }     ///< top edge

 private:
  PixelRect rect_;
  double px_per_m_ = 1.0;
  double center_x_m_ = 0.0, center_y_m_ = 0.0;
};

/// Panels laid out row by row under an optional title, with style.margin_px between them.
struct FigureLayout {
  int width_px = 0;
  int height_px = 0;
  PixelRect title;                ///< empty (h = 0) without a title
  std::vector<PixelRect> panels;  ///< row-major
};
FigureLayout layout_figure(int panel_count, int columns, bool with_title, int title_height_px,
                           const Style& style);

/// The longest of 0.1, 0.2, 0.5, 1, 2, 5, 10, 20, 50, 100... metres that is at most `max_m`
/// (0.1 when even that is too long).
double choose_scale_bar_m(double max_m);

/// About `target_count` evenly spaced round values, the first <= lo and the last >= hi (1, 2 or
/// 5 times a power of ten apart).
std::vector<double> nice_ticks(double lo, double hi, int target_count);

/// A short decimal form of `value` for labels, with no trailing zeros ("0.5", "12", "1e+06").
std::string format_number(double value);

}  // namespace cogmap::render
