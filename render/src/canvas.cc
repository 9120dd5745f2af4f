#include "canvas.h"

#include <GL/gl.h>
#include <GL/osmesa.h>

#include <cmath>
#include <cstring>
#include <stdexcept>
#include <utility>
#include <vector>

#include "grid_colors.h"

namespace cogmap::render {
namespace {

void set_color(Rgb c) { glColor3f(c.r, c.g, c.b); }

// A dash pattern long enough to read as dashed at figure scale but not as dotted.
constexpr GLushort kDashPattern = 0x00FF;
constexpr GLint kDashFactor = 1;

void begin_lines(Rgb color, float width_px, bool dashed) {
  set_color(color);
  glLineWidth(width_px);
  if (dashed) {
    glEnable(GL_LINE_STIPPLE);
    glLineStipple(kDashFactor, kDashPattern);
  }
}

void end_lines(bool dashed) {
  if (dashed) glDisable(GL_LINE_STIPPLE);
}

// One OSMesa context per thread, kept from figure to figure: a new context costs llvmpipe's
// set-up and the JIT compilation of its shaders again (docs/performance.md, "Figures"). A
// second canvas alive on the thread (the figures never make one) gets a context of its own.
class KeptContext {
 public:
  KeptContext() = default;
  KeptContext(const KeptContext&) = delete;
  KeptContext& operator=(const KeptContext&) = delete;
  ~KeptContext() {
    if (context_ == nullptr) return;
    OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
    OSMesaDestroyContext(context_);
  }
  /// The thread's context, or nullptr if it is taken (or cannot be made).
  OSMesaContext take() {
    if (taken_) return nullptr;
    if (context_ == nullptr) context_ = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, nullptr);
    taken_ = context_ != nullptr;
    return context_;
  }
  void give_back() { taken_ = false; }

  /// The last canvas's colour buffer, kept with the context: its pages are mapped already
  /// (a stage figure's buffer is 10 MB, and faulting it in again cost ~8 % of a figure run).
  std::vector<std::uint8_t> buffer;

 private:
  OSMesaContext context_ = nullptr;
  bool taken_ = false;
};

thread_local KeptContext kept_context;

}  // namespace

Canvas::Canvas(int width_px, int height_px, const Style& style, Font& font)
    : width_(width_px), height_(height_px), style_(style), font_(font) {
  if (width_px <= 0 || height_px <= 0) throw std::runtime_error("cogmap render: empty canvas");
  OSMesaContext context = kept_context.take();
  owns_context_ = context == nullptr;
  if (owns_context_) {
    context = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, nullptr);
  } else {
    buffer_ = std::move(kept_context.buffer);
  }
  buffer_.assign(static_cast<std::size_t>(width_px) * height_px * 4, 0);
  if (context == nullptr) throw std::runtime_error("cogmap render: cannot create OSMesa context");
  context_ = context;
  if (!OSMesaMakeCurrent(context, buffer_.data(), GL_UNSIGNED_BYTE, width_px, height_px)) {
    release_context();
    throw std::runtime_error("cogmap render: cannot bind OSMesa context to a " +
                             std::to_string(width_px) + "x" + std::to_string(height_px) +
                             " buffer");
  }
  // A kept context holds what the last figure left: every state a figure sets is set again.
  glDisable(GL_LINE_STIPPLE);
  glDisable(GL_TEXTURE_2D);
  glLineWidth(1.0f);
  glPointSize(1.0f);
  glClearColor(style.background.r, style.background.g, style.background.b, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glDisable(GL_DEPTH_TEST);
  // Antialiasing by coverage: smooth lines and points blended over what is below.
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glEnable(GL_LINE_SMOOTH);
  glEnable(GL_POINT_SMOOTH);
  glHint(GL_LINE_SMOOTH_HINT, GL_NICEST);
  glHint(GL_POINT_SMOOTH_HINT, GL_NICEST);
  use_pixels();
}

Canvas::~Canvas() { release_context(); }

void Canvas::release_context() {
  OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);  // the buffer dies with this canvas
  if (owns_context_) {
    if (context_ != nullptr) OSMesaDestroyContext(static_cast<OSMesaContext>(context_));
  } else {
    kept_context.buffer = std::move(buffer_);
    kept_context.give_back();
  }
  context_ = nullptr;
}

void Canvas::use_pixels() {
  glDisable(GL_SCISSOR_TEST);
  glViewport(0, 0, width_, height_);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0.0, width_, height_, 0.0, -1.0, 1.0);  // y down, like the final image
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

void Canvas::use_world(const WorldView& view) {
  const PixelRect& r = view.rect();
  const int gl_y = height_ - r.y - r.h;  // GL windows count rows from the bottom
  glViewport(r.x, gl_y, r.w, r.h);
  glScissor(r.x, gl_y, r.w, r.h);  // wide lines and points must not bleed out of the panel
  glEnable(GL_SCISSOR_TEST);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(view.left_m(), view.right_m(), view.bottom_m(), view.top_m(), -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

void Canvas::segments(const std::vector<mapper::Segment>& segments, Rgb color, float width_px,
                      bool dashed) {
  begin_lines(color, width_px, dashed);
  glBegin(GL_LINES);
  for (const auto& s : segments) {
    glVertex2d(s.a.x(), s.a.y());
    glVertex2d(s.b.x(), s.b.y());
  }
  glEnd();
  end_lines(dashed);
}

void Canvas::polyline(const std::vector<mapper::Point2>& line, Rgb color, float width_px,
                      bool dashed) {
  if (line.size() < 2) return;
  begin_lines(color, width_px, dashed);
  glBegin(GL_LINE_STRIP);
  for (const auto& p : line) glVertex2d(p.x(), p.y());
  glEnd();
  end_lines(dashed);
}

void Canvas::points(const std::vector<mapper::Point2>& points, Rgb color, float size_px) {
  set_color(color);
  glPointSize(size_px);
  glBegin(GL_POINTS);
  for (const auto& p : points) glVertex2d(p.x(), p.y());
  glEnd();
}

void Canvas::fill_rect(double x0, double y0, double x1, double y1, Rgb color) {
  set_color(color);
  glRectd(x0, y0, x1, y1);
}

void Canvas::stroke_rect(double x0, double y0, double x1, double y1, Rgb color, float width_px) {
  begin_lines(color, width_px, false);
  glBegin(GL_LINE_LOOP);
  glVertex2d(x0, y0);
  glVertex2d(x1, y0);
  glVertex2d(x1, y1);
  glVertex2d(x0, y1);
  glEnd();
}

void Canvas::disc(const mapper::Point2& center, double radius, Rgb fill, Rgb outline,
                  float outline_px) {
  constexpr int kSides = 48;
  set_color(fill);
  glBegin(GL_TRIANGLE_FAN);
  glVertex2d(center.x(), center.y());
  for (int i = 0; i <= kSides; ++i) {
    const double a = 2.0 * M_PI * i / kSides;
    glVertex2d(center.x() + radius * std::cos(a), center.y() + radius * std::sin(a));
  }
  glEnd();
  if (outline_px <= 0.0f) return;
  begin_lines(outline, outline_px, false);
  glBegin(GL_LINE_LOOP);
  for (int i = 0; i < kSides; ++i) {
    const double a = 2.0 * M_PI * i / kSides;
    glVertex2d(center.x() + radius * std::cos(a), center.y() + radius * std::sin(a));
  }
  glEnd();
}

void Canvas::grid(const mapper::HistogramGrid& grid, const Bounds& crop) {
  const mapper::GridGeometry& g = grid.geometry();
  if (grid.width() <= 0 || grid.height() <= 0 || crop.empty()) return;
  mapper::CellIndex lo = g.cell_of({crop.min_x(), crop.min_y()});
  mapper::CellIndex hi = g.cell_of({crop.max_x(), crop.max_y()});
  lo = {std::max(lo.x, 0), std::max(lo.y, 0)};
  hi = {std::min(hi.x, grid.width() - 1), std::min(hi.y, grid.height() - 1)};
  if (lo.x > hi.x || lo.y > hi.y) return;
  const int w = hi.x - lo.x + 1, h = hi.y - lo.y + 1;
  GLint max_size = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_size);
  if (w > max_size || h > max_size) {
    throw std::runtime_error("cogmap render: grid of " + std::to_string(w) + "x" +
                             std::to_string(h) + " cells exceeds the GL texture limit");
  }
  std::vector<std::uint8_t> texels(static_cast<std::size_t>(w) * h * 4);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const Rgb c = grid_cell_color(grid.get({lo.x + x, lo.y + y}), style_);
      std::uint8_t* t = &texels[(static_cast<std::size_t>(y) * w + x) * 4];
      t[0] = static_cast<std::uint8_t>(std::lround(c.r * 255.0f));
      t[1] = static_cast<std::uint8_t>(std::lround(c.g * 255.0f));
      t[2] = static_cast<std::uint8_t>(std::lround(c.b * 255.0f));
      t[3] = 255;
    }
  }
  GLuint texture = 0;
  glGenTextures(1, &texture);
  glBindTexture(GL_TEXTURE_2D, texture);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  // Nearest filtering keeps every cell a crisp square, as in the thesis's grid figures.
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glEnable(GL_TEXTURE_2D);
  const double cell = g.cell_size_m();
  const double x0 = g.origin_x_m() + lo.x * cell, y0 = g.origin_y_m() + lo.y * cell;
  const double x1 = x0 + w * cell, y1 = y0 + h * cell;
  glColor3f(1.0f, 1.0f, 1.0f);
  glBegin(GL_QUADS);  // texture row 0 is grid row lo.y, the bottom of the quad
  glTexCoord2f(0.0f, 0.0f);
  glVertex2d(x0, y0);
  glTexCoord2f(1.0f, 0.0f);
  glVertex2d(x1, y0);
  glTexCoord2f(1.0f, 1.0f);
  glVertex2d(x1, y1);
  glTexCoord2f(0.0f, 1.0f);
  glVertex2d(x0, y1);
  glEnd();
  glDisable(GL_TEXTURE_2D);
  glDeleteTextures(1, &texture);
}

void Canvas::text(const std::string& text, int size_px, Rgb color, double x_px, double y_px,
                  HAlign h, VAlign v, bool vertical) {
  texts_.push_back({text, size_px, color, x_px, y_px, h, v, vertical});
}

Image Canvas::finish() {
  glFinish();
  if (glGetError() != GL_NO_ERROR)
    throw std::runtime_error("cogmap render: GL error while drawing");
  Image image(width_, height_);
  // OSMesa's buffer has the bottom row first (OSMESA_Y_UP); images have the top row first. Its
  // RGBA bytes are an Rgba8's, but blending left alpha below 255 where lines were drawn: rows
  // are copied whole, then made opaque (both passes vectorise; a pixel-by-pixel copy was 9 %
  // of a run with figures).
  const std::size_t row_bytes = static_cast<std::size_t>(width_) * 4;
  auto* pixels = reinterpret_cast<std::uint8_t*>(image.pixels().data());
  for (int y = 0; y < height_; ++y) {
    std::memcpy(pixels + static_cast<std::size_t>(y) * row_bytes,
                &buffer_[static_cast<std::size_t>(height_ - 1 - y) * row_bytes], row_bytes);
  }
  for (Rgba8& p : image.pixels()) p.a = 255;
  for (const auto& t : texts_) {
    font_.draw(image, t.text, t.size_px, t.color, t.x_px, t.y_px, t.h, t.v, t.vertical);
  }
  return image;
}

void draw_title(Canvas& canvas, const PixelRect& rect, const std::string& title) {
  if (title.empty() || rect.h <= 0) return;
  canvas.text(title, canvas.style().title_font_px, canvas.style().text, rect.x + rect.w / 2.0,
              rect.y + rect.h / 2.0, HAlign::kCenter, VAlign::kMiddle);
}

}  // namespace cogmap::render
