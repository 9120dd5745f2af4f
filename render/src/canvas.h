#pragma once
// One figure being drawn: an OSMesa context over an RGBA buffer, GL 1.x drawing in either the
// figure's pixel space or a panel's world window, and text queued for after the GL pass
// (glyphs are blended on the read-back pixels by FreeType, see font.h).

#include <memory>
#include <string>
#include <vector>

#include "cogmap/mapper/grid/grid.h"
#include "cogmap/mapper/seam/geometry.h"
#include "cogmap/render/image.h"
#include "cogmap/render/style.h"
#include "font.h"
#include "layout.h"

namespace cogmap::render {

/// Off-screen GL canvas of one figure: its own OSMesa context, current on the constructing thread
/// for the canvas's lifetime, and its own Font (FreeType library and face), so figures on
/// different threads draw in parallel (a sweep's runs do). A process-wide lock used to serialise
/// them; sweeps of 57 figures on 2 threads came out byte-identical without it, 6 times of 6.
/// Only one canvas at a time per thread.
class Canvas {
 public:
  /// A width x height canvas cleared to style.background. Throws std::runtime_error when no
  /// OSMesa context can be made.
  Canvas(int width_px, int height_px, const Style& style, Font& font);
  ~Canvas();
  Canvas(const Canvas&) = delete;
  Canvas& operator=(const Canvas&) = delete;

  int width() const { return width_; }    ///< pixels
  int height() const { return height_; }  ///< pixels
  Font& font() { return font_; }
  const Style& style() const { return style_; }

  /// Subsequent drawing is in the whole figure's pixel coordinates (top-left origin, y down).
  void use_pixels();
  /// Subsequent drawing is in world metres through `view`, clipped to its rectangle.
  void use_world(const WorldView& view);

  /// Independent line segments.
  void segments(const std::vector<mapper::Segment>& segments, Rgb color, float width_px,
                bool dashed = false);
  /// A connected chain.
  void polyline(const std::vector<mapper::Point2>& line, Rgb color, float width_px,
                bool dashed = false);
  /// Round dots of `size_px` diameter.
  void points(const std::vector<mapper::Point2>& points, Rgb color, float size_px);
  /// A filled axis-aligned rectangle from corner (x0, y0) to (x1, y1), current coordinates.
  void fill_rect(double x0, double y0, double x1, double y1, Rgb color);
  /// The outline of a rectangle, current coordinates.
  void stroke_rect(double x0, double y0, double x1, double y1, Rgb color, float width_px);
  /// A filled disc (with an outline when outline_px > 0), current coordinates.
  void disc(const mapper::Point2& center, double radius, Rgb fill, Rgb outline, float outline_px);
  /// The grid's cells as one nearest-neighbour texture in world space, coloured per style
  /// (grid_colors.h); only cells inside `crop` (world) are uploaded.
  void grid(const mapper::HistogramGrid& grid, const Bounds& crop);

  /// Queues text, drawn after the GL pass; see Font::draw for the anchor.
  void text(const std::string& text, int size_px, Rgb color, double x_px, double y_px, HAlign h,
            VAlign v, bool vertical = false);

  /// Finishes GL, reads the pixels back top row first, blends the queued text.
  Image finish();

 private:
  /// Unbinds the context; destroys it if this canvas made its own, else gives it back.
  void release_context();

  struct QueuedText {
    std::string text;
    int size_px;
    Rgb color;
    double x_px, y_px;
    HAlign h;
    VAlign v;
    bool vertical;
  };
  int width_;
  int height_;
  const Style& style_;
  Font& font_;
  std::vector<std::uint8_t> buffer_;  // OSMesa's colour buffer, bottom row first
  void* context_ = nullptr;           // OSMesaContext, opaque so GL headers stay in canvas.cc
  bool owns_context_ = false;         // false: the thread's kept context (canvas.cc)
  std::vector<QueuedText> texts_;
};

/// Convenience: the figure title centred in `rect`.
void draw_title(Canvas& canvas, const PixelRect& rect, const std::string& title);

}  // namespace cogmap::render
