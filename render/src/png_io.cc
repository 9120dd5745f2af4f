// PNG in and out through libpng. Reading uses the simplified API (png_image), which reports
// errors through a message field. Writing uses the full API, for the one setting the simplified
// API does not offer (the row filter, below); its errors arrive by longjmp, so the encoder is a
// function whose frame holds C objects only.

#include <png.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <csetjmp>
#include <cstdio>
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

// libpng's error message, kept for the exception the caller throws.
struct PngErrorSink {
  char message[256] = {};
};

[[noreturn]] void on_png_error(png_structp png, png_const_charp message) {
  auto* sink = static_cast<PngErrorSink*>(png_get_error_ptr(png));
  std::snprintf(sink->message, sizeof(sink->message), "%s", message);
  png_longjmp(png, 1);
}

void on_png_warning(png_structp, png_const_charp) {}

// Encodes `rgba` (rows top first, 4 bytes a pixel, the alpha byte dropped) into `file` as RGB. Only
// C objects live in this frame, as libpng leaves it by longjmp on an error.
//
// The row filter is None: the figures are line art on flat fills, for which libpng's default
// (every filter tried per row, the one with the smallest sum of differences kept) spends half the
// encoding time choosing filters that compress no better. Measured on a nine-room run's figures
// (zlib level 6 either way): a room's stage figure (2480 x 1045) 50 -> 26 ms and 61.0 -> 66.6 kB,
// the room graph 7.8 -> 4.3 ms and 27.8 -> 25.0 kB, the map before/after 16.7 -> 9.9 ms and
// 78.6 -> 81.7 kB (docs/performance.md, "Figures").
bool encode_as_rgb(std::FILE* file, const std::uint8_t* rgba, png_uint_32 width, png_uint_32 height,
                   PngErrorSink* sink) {
  png_structp png =
      png_create_write_struct(PNG_LIBPNG_VER_STRING, sink, on_png_error, on_png_warning);
  if (png == nullptr) {
    std::snprintf(sink->message, sizeof(sink->message), "cannot start libpng");
    return false;
  }
  png_infop info = png_create_info_struct(png);
  if (info == nullptr) {
    png_destroy_write_struct(&png, nullptr);
    std::snprintf(sink->message, sizeof(sink->message), "cannot start libpng");
    return false;
  }
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return false;
  }
  png_init_io(png, file);
  png_set_IHDR(png, info, width, height, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_BASE, PNG_FILTER_TYPE_BASE);
  png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_NONE);
  png_set_compression_level(png, 6);  // zlib's default, as the simplified API used
  png_write_info(png, info);
  png_set_filler(png, 0, PNG_FILLER_AFTER);  // the rows carry a fourth byte: drop it
  const std::size_t stride = static_cast<std::size_t>(width) * 4;
  for (png_uint_32 y = 0; y < height; ++y) {
    png_write_row(png, rgba + static_cast<std::size_t>(y) * stride);
  }
  png_write_end(png, info);
  png_destroy_write_struct(&png, &info);
  return true;
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

  // The file carries no alpha: figures are opaque, and RGB is a quarter smaller. libpng drops
  // the alpha byte of each pixel as it writes the rows (png_set_filler).
  const auto* rgba = reinterpret_cast<const std::uint8_t*>(image.pixels().data());
  const std::filesystem::path temp = temp_path_for(png);
  std::FILE* file = std::fopen(temp.c_str(), "wb");
  if (file == nullptr) {
    throw png_error(
        png, "cannot write PNG (cannot open " + temp.string() + ": " + std::strerror(errno) + ")");
  }
  PngErrorSink sink;
  const bool encoded = encode_as_rgb(file, rgba, static_cast<png_uint_32>(image.width()),
                                     static_cast<png_uint_32>(image.height()), &sink);
  const bool flushed = std::fflush(file) == 0 && std::ferror(file) == 0;
  const bool closed = std::fclose(file) == 0;
  if (!encoded || !flushed || !closed) {
    const std::string message =
        !encoded ? std::string(sink.message) : "write error: " + std::string(std::strerror(errno));
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
  if (!png_image_finish_read(&info, nullptr, image.pixels().data(), 0, nullptr)) {
    const std::string message = info.message;
    png_image_free(&info);
    throw png_error(png, "cannot decode PNG (" + message + ")");
  }
  return image;
}

}  // namespace cogmap::render
