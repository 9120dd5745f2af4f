// PNG in and out through libpng's simplified API (png_image), which reports errors through a
// message field instead of longjmp, so no C++ frame is ever jumped over.

#include <png.h>
#include <unistd.h>

#include <atomic>
#include <cstring>
#include <stdexcept>
#include <string>
#include <system_error>

#include "cogmap/render/image.h"

namespace cogmap::render {
namespace {

std::runtime_error png_error(const std::filesystem::path& path, const std::string& what) {
  return std::runtime_error("cogmap render: " + what + ": " + path.string());
}

// A name no other writer (thread or process) uses for its temporary file.
std::filesystem::path temp_path_for(const std::filesystem::path& png) {
  static std::atomic<unsigned> counter{0};
  std::string name = "." + png.filename().string() + ".tmp." + std::to_string(::getpid()) + "." +
                     std::to_string(counter.fetch_add(1));
  return png.parent_path() / name;
}

}  // namespace

void write_png(const Image& image, const std::filesystem::path& png) {
  if (image.width() <= 0 || image.height() <= 0) throw png_error(png, "empty image");
  const std::filesystem::path parent = png.parent_path();
  if (!parent.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(parent, ec);
    if (ec)
      throw png_error(png,
                      "cannot create directory " + parent.string() + " (" + ec.message() + ")");
  }

  // The file carries no alpha: figures are opaque, and RGB is a quarter smaller.
  std::vector<std::uint8_t> rgb(static_cast<std::size_t>(image.width()) * image.height() * 3);
  for (std::size_t i = 0; i < image.pixels().size(); ++i) {
    rgb[3 * i] = image.pixels()[i].r;
    rgb[3 * i + 1] = image.pixels()[i].g;
    rgb[3 * i + 2] = image.pixels()[i].b;
  }
  png_image info;
  std::memset(&info, 0, sizeof(info));
  info.version = PNG_IMAGE_VERSION;
  info.width = static_cast<png_uint_32>(image.width());
  info.height = static_cast<png_uint_32>(image.height());
  info.format = PNG_FORMAT_RGB;

  const std::filesystem::path temp = temp_path_for(png);
  if (!png_image_write_to_file(&info, temp.c_str(), 0, rgb.data(), 0, nullptr)) {
    const std::string message = info.message;
    png_image_free(&info);
    std::error_code ignored;
    std::filesystem::remove(temp, ignored);
    throw png_error(png, "cannot write PNG (" + message + ")");
  }
  std::error_code ec;
  std::filesystem::rename(temp, png, ec);
  if (ec) {
    std::error_code ignored;
    std::filesystem::remove(temp, ignored);
    throw png_error(png, "cannot rename " + temp.string() + " (" + ec.message() + ")");
  }
}

Image read_png(const std::filesystem::path& png) {
  png_image info;
  std::memset(&info, 0, sizeof(info));
  info.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&info, png.c_str())) {
    throw png_error(png, std::string("cannot read PNG (") + info.message + ")");
  }
  info.format = PNG_FORMAT_RGBA;
  Image image(static_cast<int>(info.width), static_cast<int>(info.height));
  static_assert(sizeof(Rgba8) == 4, "Rgba8 must be tightly packed for libpng");
  if (!png_image_finish_read(&info, nullptr, image.pixels().data(), 0, nullptr)) {
    const std::string message = info.message;
    png_image_free(&info);
    throw png_error(png, "cannot decode PNG (" + message + ")");
  }
  return image;
}

}  // namespace cogmap::render
