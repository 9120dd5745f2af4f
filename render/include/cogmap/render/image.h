#pragma once
/// An 8-bit RGBA raster, rows top to bottom: what the renderer draws into and what PNG files hold.

#include <cstdint>
#include <filesystem>
#include <vector>

namespace cogmap::render {

/// One pixel, 8 bits per channel.
struct Rgba8 {
  std::uint8_t r = 0;    ///< red
  std::uint8_t g = 0;    ///< green
  std::uint8_t b = 0;    ///< blue
  std::uint8_t a = 255;  ///< alpha (255 opaque)
  /// Channel-wise equality.
  bool operator==(const Rgba8&) const = default;
};
// An Image's pixels are read and written as packed RGBA bytes (OSMesa's buffer, libpng's rows).
static_assert(sizeof(Rgba8) == 4, "Rgba8 must be 4 packed bytes");

/// A width x height RGBA image; row 0 is the top row.
class Image {
 public:
  /// An empty 0 x 0 image.
  Image() = default;
  /// A new image filled with `fill`.
  Image(int width_px, int height_px, Rgba8 fill = {255, 255, 255, 255})
      : width_(width_px),
        height_(height_px),
        pixels_(static_cast<std::size_t>(width_px) * height_px, fill) {}

  int width() const { return width_; }    ///< pixels
  int height() const { return height_; }  ///< pixels
  /// True when column x, row y lies inside the image.
  bool contains(int x, int y) const { return x >= 0 && y >= 0 && x < width_ && y < height_; }
  /// Pixel at column x, row y (row 0 at the top); must be inside.
  const Rgba8& at(int x, int y) const { return pixels_[index(x, y)]; }
  /// Mutable pixel at column x, row y; must be inside.
  Rgba8& at(int x, int y) { return pixels_[index(x, y)]; }
  /// Raw pixels, row-major from the top row.
  const std::vector<Rgba8>& pixels() const { return pixels_; }
  /// Mutable raw pixels; keep the size at width * height.
  std::vector<Rgba8>& pixels() { return pixels_; }

 private:
  std::size_t index(int x, int y) const { return static_cast<std::size_t>(y) * width_ + x; }
  int width_ = 0;
  int height_ = 0;
  std::vector<Rgba8> pixels_;
};

/// Writes `image` as an RGB PNG atomically: a temporary file beside `png`, then a rename, so an
/// existing file is replaced whole or not at all. Creates missing parent directories. Throws
/// std::runtime_error with the path on any failure.
void write_png(const Image& image, const std::filesystem::path& png);

/// Reads any PNG as RGBA. Throws std::runtime_error with the path on failure.
Image read_png(const std::filesystem::path& png);

}  // namespace cogmap::render
