#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "cogmap/render/renderer.h"

namespace cogmap::render {
namespace {

constexpr const char* kThreads = "LP_NUM_THREADS";

TEST(RasteriserThreads, UnsetTheRasteriserIsToldToStartNoThreadsOfItsOwn) {
  ::unsetenv(kThreads);
  EXPECT_TRUE(rasterise_on_drawing_threads_only());
  ASSERT_NE(std::getenv(kThreads), nullptr);
  EXPECT_EQ(std::string(std::getenv(kThreads)), "0");
  ::unsetenv(kThreads);
}

TEST(RasteriserThreads, AValueTheUserSetIsKept) {
  ::setenv(kThreads, "3", 1);
  EXPECT_FALSE(rasterise_on_drawing_threads_only());
  EXPECT_EQ(std::string(std::getenv(kThreads)), "3");
  ::unsetenv(kThreads);
}

}  // namespace
}  // namespace cogmap::render
