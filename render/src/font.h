#pragma once
// Text for figures: a FreeType face rasterised into alpha masks and blended into an Image.
// Figures draw text after the GL pass, on the read-back pixels, so glyphs never go through GL.

#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <string_view>
#include <utility>
#include <vector>

#include "cogmap/render/image.h"
#include "cogmap/render/style.h"

namespace cogmap::render {

/// The font file figures use: $COGMAP_FONT when set (it must exist), else the first of the usual
/// DejaVu Sans locations. Throws std::runtime_error naming what was tried when none exists.
std::filesystem::path find_font_file();

/// Horizontal alignment of a text anchor.
enum class HAlign { kLeft, kCenter, kRight };
/// Vertical alignment of a text anchor: the top, middle or bottom of the line box, or the baseline.
enum class VAlign { kTop, kMiddle, kBaseline, kBottom };

/// Glyph coverage of one line of text: 0 transparent .. 255 full ink, row 0 at the top.
struct AlphaMask {
  int width_px = 0;                 ///< advance width of the whole line
  int height_px = 0;                ///< ascent + descent of the face at this size
  int baseline_px = 0;              ///< rows from the top to the baseline
  std::vector<std::uint8_t> alpha;  ///< width_px * height_px coverage values
};

/// One FreeType face, with the glyphs it has rendered kept by size. Not thread-safe: each
/// thread draws with its own (thread_font()).
class Font {
 public:
  /// Loads `file`; throws std::runtime_error with the path if FreeType cannot read it.
  explicit Font(const std::filesystem::path& file);
  ~Font();
  Font(const Font&) = delete;
  Font& operator=(const Font&) = delete;

  /// Rasterises UTF-8 `text` at a pixel size of `size_px` (the em height).
  AlphaMask rasterize(std::string_view text, int size_px);
  /// Advance width of `text` in pixels at `size_px`.
  int width_px(std::string_view text, int size_px) { return rasterize(text, size_px).width_px; }
  /// Line height (ascent + descent) in pixels at `size_px`.
  int line_height_px(int size_px);

  /// Blends `text` into `image` in `color` with its anchor at (x_px, y_px), top-left pixel
  /// coordinates. `vertical` turns the text 90° counter-clockwise (reads bottom to top), with
  /// the alignments applied to the turned box (h along x, v along y).
  void draw(Image& image, std::string_view text, int size_px, Rgb color, double x_px, double y_px,
            HAlign h, VAlign v, bool vertical = false);

 private:
  /// A rendered glyph: what rasterize() reads of FreeType's glyph slot.
  struct Glyph {
    bool loaded = false;  // false: FreeType could not load it (drawn as nothing, no advance)
    long advance_x = 0;   // 26.6 fixed point
    int left = 0, top = 0;
    unsigned width = 0, rows = 0;
    std::vector<std::uint8_t> coverage;  // rows * width
  };
  const Glyph& glyph(unsigned index, int size_px);
  friend Font& thread_font();

  void set_size(int size_px);
  void* library_ = nullptr;  // FT_Library, kept opaque so no FreeType header leaks out
  void* face_ = nullptr;     // FT_Face
  std::filesystem::path file_;
  std::map<std::pair<int, unsigned>, Glyph> glyphs_;  // (size_px, glyph index)
};

/// The figures' font on this thread (find_font_file()), loaded once and kept with its rendered
/// glyphs: a figure's labels repeat the same few glyphs, and the face is parsed once, not per
/// figure. Loaded again if find_font_file() names another file.
Font& thread_font();

}  // namespace cogmap::render
