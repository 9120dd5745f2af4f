#pragma once
// Helpers shared by the renderer's tests: a scratch directory and pixel predicates.

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "cogmap/render/image.h"
#include "cogmap/render/style.h"
#include "cogmap/test_support/scratch_dir.h"

namespace cogmap::render::testing {

// A fresh directory per test, removed afterwards unless the test failed.
class TempDir : public cogmap::test_support::ScratchDir {
 public:
  TempDir()
      : ScratchDir("cogmap_render_" +
                   std::string(::testing::UnitTest::GetInstance()->current_test_info()->name())) {}
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
