#include "font.h"

#include <ft2build.h>
#include FT_FREETYPE_H

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace cogmap::render {
namespace {

// Where Debian/Ubuntu, Fedora, Arch and Homebrew put DejaVu Sans.
constexpr std::array<const char*, 5> kFontCandidates = {
    "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf",
    "/usr/share/fonts/dejavu/DejaVuSans.ttf",
    "/usr/share/fonts/dejavu-sans-fonts/DejaVuSans.ttf",
    "/usr/share/fonts/TTF/DejaVuSans.ttf",
    "/usr/local/share/fonts/DejaVuSans.ttf",
};

// Decodes UTF-8 into code points; malformed bytes become U+FFFD rather than an error because a
// caption with a stray byte should still render.
std::vector<char32_t> decode_utf8(std::string_view text) {
  std::vector<char32_t> out;
  for (std::size_t i = 0; i < text.size();) {
    const auto c = static_cast<unsigned char>(text[i]);
    int extra = c < 0x80           ? 0
                : (c >> 5) == 0x6  ? 1
                : (c >> 4) == 0xE  ? 2
                : (c >> 3) == 0x1E ? 3
                                   : -1;
    if (extra < 0 || (extra > 0 && i + extra >= text.size())) {
      out.push_back(0xFFFD);
      ++i;
      continue;
    }
    char32_t cp = extra == 0 ? c : c & (0x3F >> extra);
    bool ok = true;
    for (int k = 1; k <= extra; ++k) {
      const auto cc = static_cast<unsigned char>(text[i + k]);
      if ((cc >> 6) != 0x2) ok = false;
      cp = (cp << 6) | (cc & 0x3F);
    }
    out.push_back(ok ? cp : 0xFFFD);
    i += ok ? extra + 1 : 1;
  }
  return out;
}

std::uint8_t blend(std::uint8_t dst, float src, float alpha) {
  const float v = dst * (1.0f - alpha) + src * 255.0f * alpha;
  return static_cast<std::uint8_t>(std::clamp(std::lround(v), 0L, 255L));
}

}  // namespace

std::filesystem::path find_font_file() {
  if (const char* env = std::getenv("COGMAP_FONT"); env != nullptr && *env != '\0') {
    const std::filesystem::path path(env);
    if (!std::filesystem::is_regular_file(path)) {
      throw std::runtime_error("cogmap render: COGMAP_FONT names no font file: " + path.string());
    }
    return path;
  }
  std::string tried;
  for (const char* candidate : kFontCandidates) {
    if (std::filesystem::is_regular_file(candidate)) return candidate;
    tried += std::string(tried.empty() ? "" : ", ") + candidate;
  }
  throw std::runtime_error(
      "cogmap render: no font found for figure text; install fonts-dejavu-core or set "
      "COGMAP_FONT to a .ttf file (tried " +
      tried + ")");
}

Font::Font(const std::filesystem::path& file) : file_(file) {
  FT_Library library = nullptr;
  if (FT_Init_FreeType(&library) != 0) {
    throw std::runtime_error("cogmap render: cannot initialise FreeType for " + file.string());
  }
  library_ = library;
  FT_Face face = nullptr;
  if (FT_New_Face(library, file.c_str(), 0, &face) != 0) {
    FT_Done_FreeType(library);
    throw std::runtime_error("cogmap render: cannot load font file: " + file.string());
  }
  face_ = face;
}

Font::~Font() {
  FT_Done_Face(static_cast<FT_Face>(face_));
  FT_Done_FreeType(static_cast<FT_Library>(library_));
}

void Font::set_size(int size_px) {
  if (FT_Set_Pixel_Sizes(static_cast<FT_Face>(face_), 0, static_cast<FT_UInt>(size_px)) != 0) {
    throw std::runtime_error("cogmap render: font cannot be sized to " + std::to_string(size_px) +
                             " px: " + file_.string());
  }
}

int Font::line_height_px(int size_px) {
  set_size(size_px);
  const FT_Size_Metrics& m = static_cast<FT_Face>(face_)->size->metrics;
  return static_cast<int>((m.ascender - m.descender + 63) >> 6);
}

const Font::Glyph& Font::glyph(unsigned index, int size_px) {
  const auto key = std::make_pair(size_px, index);
  if (const auto it = glyphs_.find(key); it != glyphs_.end()) return it->second;
  Glyph g;
  auto face = static_cast<FT_Face>(face_);
  // One load renders the bitmap and gives the advance (rendering changes no metric).
  if (FT_Load_Glyph(face, index, FT_LOAD_RENDER) == 0) {
    const FT_GlyphSlot slot = face->glyph;
    const FT_Bitmap& bitmap = slot->bitmap;
    g.loaded = true;
    g.advance_x = slot->advance.x;
    g.left = slot->bitmap_left;
    g.top = slot->bitmap_top;
    g.width = bitmap.width;
    g.rows = bitmap.rows;
    g.coverage.resize(static_cast<std::size_t>(bitmap.width) * bitmap.rows);
    for (unsigned row = 0; row < bitmap.rows; ++row) {
      for (unsigned col = 0; col < bitmap.width; ++col) {
        g.coverage[static_cast<std::size_t>(row) * bitmap.width + col] =
            bitmap.buffer[static_cast<std::ptrdiff_t>(row) * bitmap.pitch + col];
      }
    }
  }
  return glyphs_.emplace(key, std::move(g)).first->second;
}

Font& thread_font() {
  thread_local std::unique_ptr<Font> font;
  const std::filesystem::path file = find_font_file();
  if (!font || font->file_ != file) font = std::make_unique<Font>(file);
  return *font;
}

AlphaMask Font::rasterize(std::string_view text, int size_px) {
  set_size(size_px);
  auto face = static_cast<FT_Face>(face_);
  const FT_Size_Metrics& m = face->size->metrics;
  AlphaMask mask;
  mask.baseline_px = static_cast<int>((m.ascender + 63) >> 6);
  mask.height_px = mask.baseline_px + static_cast<int>((-m.descender + 63) >> 6);

  // First pass: total advance (26.6 fixed point) with kerning, so the mask is allocated once.
  const std::vector<char32_t> code_points = decode_utf8(text);
  std::vector<FT_UInt> glyphs;
  for (char32_t cp : code_points) glyphs.push_back(FT_Get_Char_Index(face, cp));
  const bool kerning = FT_HAS_KERNING(face);
  std::vector<long> pen_x(glyphs.size(), 0);
  long pen = 0;
  for (std::size_t i = 0; i < glyphs.size(); ++i) {
    if (kerning && i > 0) {
      FT_Vector delta;
      if (FT_Get_Kerning(face, glyphs[i - 1], glyphs[i], FT_KERNING_DEFAULT, &delta) == 0) {
        pen += delta.x;
      }
    }
    pen_x[i] = pen;
    const Glyph& g = glyph(glyphs[i], size_px);
    if (g.loaded) pen += g.advance_x;
  }
  mask.width_px = static_cast<int>((pen + 63) >> 6) + 1;
  mask.alpha.assign(static_cast<std::size_t>(mask.width_px) * mask.height_px, 0);

  for (std::size_t i = 0; i < glyphs.size(); ++i) {
    const Glyph& g = glyph(glyphs[i], size_px);
    if (!g.loaded) continue;
    const int left = static_cast<int>(pen_x[i] >> 6) + g.left;
    const int top = mask.baseline_px - g.top;
    for (unsigned row = 0; row < g.rows; ++row) {
      for (unsigned col = 0; col < g.width; ++col) {
        const int x = left + static_cast<int>(col), y = top + static_cast<int>(row);
        if (x < 0 || y < 0 || x >= mask.width_px || y >= mask.height_px) continue;
        std::uint8_t& dst = mask.alpha[static_cast<std::size_t>(y) * mask.width_px + x];
        dst = std::max(dst, g.coverage[static_cast<std::size_t>(row) * g.width + col]);
      }
    }
  }
  return mask;
}

void Font::draw(Image& image, std::string_view text, int size_px, Rgb color, double x_px,
                double y_px, HAlign h, VAlign v, bool vertical) {
  const AlphaMask mask = rasterize(text, size_px);
  // Box of the (possibly turned) text on the image.
  const int box_w = vertical ? mask.height_px : mask.width_px;
  const int box_h = vertical ? mask.width_px : mask.height_px;
  double left = x_px;
  if (h == HAlign::kCenter) left -= box_w / 2.0;
  if (h == HAlign::kRight) left -= box_w;
  double top = y_px;
  if (v == VAlign::kMiddle) top -= box_h / 2.0;
  if (v == VAlign::kBottom) top -= box_h;
  if (v == VAlign::kBaseline) top -= vertical ? box_h / 2.0 : mask.baseline_px;
  const int x0 = static_cast<int>(std::lround(left)), y0 = static_cast<int>(std::lround(top));

  for (int my = 0; my < mask.height_px; ++my) {
    for (int mx = 0; mx < mask.width_px; ++mx) {
      const std::uint8_t a = mask.alpha[static_cast<std::size_t>(my) * mask.width_px + mx];
      if (a == 0) continue;
      // Turning counter-clockwise sends the mask's right end to the top of the box.
      const int x = vertical ? x0 + my : x0 + mx;
      const int y = vertical ? y0 + (mask.width_px - 1 - mx) : y0 + my;
      if (!image.contains(x, y)) continue;
      Rgba8& p = image.at(x, y);
      const float alpha = a / 255.0f;
      p.r = blend(p.r, color.r, alpha);
      p.g = blend(p.g, color.g, alpha);
      p.b = blend(p.b, color.b, alpha);
    }
  }
}

}  // namespace cogmap::render
