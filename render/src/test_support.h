#pragma once
// Helpers shared by the renderer's tests: a scratch directory and pixel predicates.

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "cogmap/render/image.h"
#include "cogmap/render/style.h"

namespace cogmap::render::testing {

// A fresh directory per test, removed afterwards.
class TempDir {
 public:
  TempDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = std::filesystem::temp_directory_path() /
            ("cogmap_render_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~TempDir() { std::filesystem::remove_all(path_); }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

inline bool is_white(const Rgba8& p) { return p.r == 255 && p.g == 255 && p.b == 255; }
inline bool is_dark(const Rgba8& p) { return p.r < 90 && p.g < 90 && p.b < 90; }
inline bool near(const Rgba8& p, Rgb c, int tolerance) {
  return std::abs(p.r - c.r * 255.0f) <= tolerance && std::abs(p.g - c.g * 255.0f) <= tolerance &&
         std::abs(p.b - c.b * 255.0f) <= tolerance;
}
inline int count_near(const Image& image, Rgb c, int tolerance) {
  int n = 0;
  for (const auto& p : image.pixels()) n += near(p, c, tolerance) ? 1 : 0;
  return n;
}

}  // namespace cogmap::render::testing
