// Renderer building blocks: layout maths, pixel-exact GL drawing of known scenes, glyphs, PNG I/O.

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <string>
#include <thread>

#include "canvas.h"
#include "cogmap/render/figures.h"
#include "cogmap/render/image.h"
#include "grid_colors.h"
#include "layout.h"
#include "synthetic_scenes.h"
#include "test_support.h"

namespace cogmap::render {
namespace {

using mapper::Point2;
using testing::count_near;
using testing::is_dark;
using testing::is_white;
using testing::near;
using testing::TempDir;

TEST(Layout, WorldViewKeepsMetresSquareAndCentresTheBounds) {
  Bounds b;
  b.add(Point2(0.0, 0.0));
  b.add(Point2(9.0, 4.0));
  const WorldView view({10, 10, 180, 80}, b);
  EXPECT_DOUBLE_EQ(view.px_per_m(), 20.0);  // min(180 / 9, 80 / 4)
  EXPECT_DOUBLE_EQ(view.to_pixel({0.0, 4.0}).x(), 10.0);
  EXPECT_DOUBLE_EQ(view.to_pixel({0.0, 4.0}).y(), 10.0);  // top-left corner of the rect
  EXPECT_DOUBLE_EQ(view.to_pixel({9.0, 0.0}).x(), 190.0);
  EXPECT_DOUBLE_EQ(view.to_pixel({9.0, 0.0}).y(), 90.0);
  // A tall box in a wide rect: x gets the slack, the scale still follows y.
  Bounds tall;
  tall.add(Point2(0.0, 0.0));
  tall.add(Point2(1.0, 4.0));
  const WorldView v2({0, 0, 200, 100}, tall);
  EXPECT_DOUBLE_EQ(v2.px_per_m(), 25.0);
  EXPECT_DOUBLE_EQ(v2.to_pixel({0.5, 2.0}).x(), 100.0);
  EXPECT_DOUBLE_EQ(v2.right_m() - v2.left_m(), 8.0);
}

TEST(Layout, PaddedBoundsGrowAndEmptyBoundsGetAWindow) {
  Bounds b;
  b.add(Point2(1.0, 1.0));
  const Bounds p = b.padded(0.5, 2.0);
  EXPECT_DOUBLE_EQ(p.min_x(), 0.0);
  EXPECT_DOUBLE_EQ(p.max_x(), 2.0);
  const Bounds e = Bounds().padded(0.5, 2.0);
  EXPECT_FALSE(e.empty());
  EXPECT_DOUBLE_EQ(e.max_y() - e.min_y(), 2.0);
  b.add(Point2(std::nan(""), 3.0));  // ignored, not a NaN window
  EXPECT_DOUBLE_EQ(b.max_y(), 1.0);
}

TEST(Layout, ScaleBarAndTicksAreRoundNumbers) {
  EXPECT_DOUBLE_EQ(choose_scale_bar_m(1.3), 1.0);
  EXPECT_DOUBLE_EQ(choose_scale_bar_m(0.7), 0.5);
  EXPECT_DOUBLE_EQ(choose_scale_bar_m(4.99), 2.0);
  EXPECT_DOUBLE_EQ(choose_scale_bar_m(12.0), 10.0);
  const std::vector<double> t = nice_ticks(0.036, 0.072, 5);
  ASSERT_GE(t.size(), 2u);
  EXPECT_LE(t.front(), 0.036);
  EXPECT_GE(t.back(), 0.072);
  EXPECT_NEAR(t[1] - t[0], 0.01, 1e-12);
  EXPECT_EQ(format_number(0.1 + 0.2), "0.3");
  EXPECT_EQ(format_number(-0.0 * 1.0 + 0.0), "0");
}

TEST(Canvas, SegmentLandsOnItsProjectedPixels) {
  Style style;
  Font font(find_font_file());
  Image image;
  {
    Canvas canvas(200, 100, style, font);
    Bounds b;
    b.add(Point2(0.0, 0.0));
    b.add(Point2(9.0, 4.0));
    const WorldView view({10, 10, 180, 80}, b);
    canvas.use_world(view);
    // y = 2 m projects to row 50; x from 1 m to 8 m to columns 30..170.
    canvas.segments({{Point2(1.0, 2.0), Point2(8.0, 2.0)}}, {0, 0, 0}, 3.0f);
    image = canvas.finish();
  }
  ASSERT_EQ(image.width(), 200);
  ASSERT_EQ(image.height(), 100);
  for (int x = 34; x <= 166; ++x) {
    EXPECT_TRUE(is_dark(image.at(x, 49))) << "x=" << x;
    EXPECT_TRUE(is_dark(image.at(x, 50))) << "x=" << x;
  }
  for (int y : {20, 30, 44, 56, 70, 90}) EXPECT_TRUE(is_white(image.at(100, y))) << "y=" << y;
  EXPECT_TRUE(is_white(image.at(20, 50)));   // left of the segment's start
  EXPECT_TRUE(is_white(image.at(180, 50)));  // right of its end
  EXPECT_TRUE(is_white(image.at(0, 0)));
}

TEST(Canvas, ClipsWorldDrawingToThePanel) {
  Style style;
  Font font(find_font_file());
  Canvas canvas(100, 100, style, font);
  Bounds b;
  b.add(Point2(0.0, 0.0));
  b.add(Point2(1.0, 1.0));
  canvas.use_world(WorldView({25, 25, 50, 50}, b));
  canvas.segments({{Point2(-5.0, 0.5), Point2(5.0, 0.5)}}, {0, 0, 0}, 4.0f);
  const Image image = canvas.finish();
  EXPECT_TRUE(is_dark(image.at(50, 50)));
  EXPECT_TRUE(is_white(image.at(10, 50)));  // the line runs on in world space but not on paper
  EXPECT_TRUE(is_white(image.at(90, 50)));
}

TEST(Canvas, GridCellsTakeTheirHimmColours) {
  Style style;
  Font font(find_font_file());
  // Four 1 m cells in a row: occupied, seen empty, unexplored, robot path.
  mapper::HistogramGrid grid(mapper::GridGeometry(0.0, 0.0, 1000.0, 4, 1), 0.0f);
  grid.set({0, 0}, 15.0f);
  grid.set({1, 0}, -3.0f);
  grid.set({3, 0}, mapper::kRobotPathValue);
  Bounds b;
  b.add(Point2(0.0, 0.0));
  b.add(Point2(4.0, 1.0));
  Canvas canvas(80, 20, style, font);
  canvas.use_world(WorldView({0, 0, 80, 20}, b));
  canvas.grid(grid, b);
  const Image image = canvas.finish();
  const float values[4] = {15.0f, -3.0f, 0.0f, mapper::kRobotPathValue};
  for (int i = 0; i < 4; ++i) {
    EXPECT_TRUE(near(image.at(20 * i + 10, 10), grid_cell_color(values[i], style), 2)) << i;
  }
  EXPECT_TRUE(is_dark(image.at(10, 10)));
  EXPECT_GT(image.at(30, 10).r, image.at(50, 10).r);  // empty lighter than unexplored
}

// A scene that sets every piece of GL state a figure uses: dashes, wide lines, points, a
// textured grid, a clipped panel.
Image busy_scene(int width_px, int height_px) {
  Style style;
  Font font(find_font_file());
  Canvas canvas(width_px, height_px, style, font);
  Bounds b;
  b.add(Point2(0.0, 0.0));
  b.add(Point2(4.0, 2.0));
  canvas.use_world(WorldView({5, 5, width_px - 10, height_px - 10}, b));
  mapper::HistogramGrid grid(mapper::GridGeometry(0.0, 0.0, 1000.0, 4, 2), 0.0f);
  grid.set({1, 1}, 15.0f);
  canvas.grid(grid, b);
  canvas.segments({{Point2(0.2, 0.2), Point2(3.8, 1.8)}}, {0, 0, 0}, 5.0f, true);
  canvas.points({Point2(2.0, 1.0)}, {0.8f, 0.0f, 0.0f}, 9.0f);
  canvas.use_pixels();
  canvas.stroke_rect(2, 2, width_px - 3, height_px - 3, {0.0f, 0.0f, 0.8f}, 3.0f);
  return canvas.finish();
}

TEST(Canvas, AFigureAfterAnotherOnOneThreadDrawsAsTheFirstFigureOfAThread) {
  // The thread's OSMesa context is kept from canvas to canvas: nothing the last figure left
  // (its size, its state) may show in the next.
  Image first_of_a_thread;
  std::thread([&] { first_of_a_thread = busy_scene(120, 70); }).join();
  const Image bigger = busy_scene(300, 200);
  const Image after_another = busy_scene(120, 70);
  ASSERT_EQ(bigger.width(), 300);
  ASSERT_EQ(after_another.width(), 120);
  ASSERT_EQ(after_another.height(), 70);
  EXPECT_TRUE(after_another.pixels() == first_of_a_thread.pixels());
  EXPECT_GT(count_near(after_another, {0.0f, 0.0f, 0.0f}, 60), 20);  // the dashed line is there
}

TEST(Font, TextInksOnlyItsBox) {
  Font font(find_font_file());
  Image image(200, 60);
  font.draw(image, "Wall 1 m", 20, {0, 0, 0}, 10, 30, HAlign::kLeft, VAlign::kMiddle);
  int inked_inside = 0, inked_outside = 0;
  const int w = font.width_px("Wall 1 m", 20);
  for (int y = 0; y < 60; ++y) {
    for (int x = 0; x < 200; ++x) {
      const bool inside = x >= 10 && x <= 10 + w && y >= 15 && y <= 45;
      (inside ? inked_inside : inked_outside) += is_white(image.at(x, y)) ? 0 : 1;
    }
  }
  EXPECT_GT(inked_inside, 50);
  EXPECT_EQ(inked_outside, 0);
  EXPECT_GT(w, 40);
}

TEST(Font, KeptGlyphsRasteriseAsAFreshFaceDoes) {
  // The glyphs of "room" are kept at 20 px after the first text; at 13 px they are new.
  Font& kept = thread_font();
  (void)kept.rasterize("room 12", 20);
  const AlphaMask again = kept.rasterize("mirror", 20);
  const AlphaMask other_size = kept.rasterize("mirror", 13);
  Font fresh(find_font_file());
  const AlphaMask first = fresh.rasterize("mirror", 20);
  EXPECT_EQ(again.width_px, first.width_px);
  EXPECT_EQ(again.height_px, first.height_px);
  EXPECT_EQ(again.baseline_px, first.baseline_px);
  EXPECT_TRUE(again.alpha == first.alpha);
  const AlphaMask first_small = fresh.rasterize("mirror", 13);
  EXPECT_LT(other_size.width_px, again.width_px);
  EXPECT_TRUE(other_size.alpha == first_small.alpha);
  EXPECT_EQ(&thread_font(), &kept);  // the same face while the font file is the same
}

TEST(Png, RoundTripsSizeAndPixels) {
  TempDir dir;
  Image image(7, 5);
  image.at(0, 0) = {255, 0, 0, 255};
  image.at(6, 4) = {0, 0, 255, 255};
  image.at(3, 2) = {12, 34, 56, 255};
  const auto path = dir.path() / "nested" / "x.png";  // parents are created
  write_png(image, path);
  const Image back = read_png(path);
  ASSERT_EQ(back.width(), 7);
  ASSERT_EQ(back.height(), 5);
  EXPECT_EQ(back.at(0, 0), (Rgba8{255, 0, 0, 255}));
  EXPECT_EQ(back.at(6, 4), (Rgba8{0, 0, 255, 255}));
  EXPECT_EQ(back.at(3, 2), (Rgba8{12, 34, 56, 255}));
  EXPECT_EQ(back.at(1, 1), (Rgba8{255, 255, 255, 255}));
}

TEST(Png, ReplacesAnExistingFileAndLeavesNoTemporaries) {
  TempDir dir;
  const auto path = dir.path() / "fig.png";
  write_png(Image(4, 4, {0, 0, 0, 255}), path);
  write_png(Image(9, 3), path);
  EXPECT_EQ(read_png(path).width(), 9);
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir.path())) {
    (void)entry;
    ++files;
  }
  EXPECT_EQ(files, 1);
}

TEST(Png, UnwritableTargetThrowsWithThePath) {
  TempDir dir;
  const auto blocker = dir.path() / "not_a_dir";
  std::ofstream(blocker) << "x";
  const auto path = blocker / "fig.png";
  try {
    write_png(Image(4, 4), path);
    FAIL() << "expected a throw";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
  }
  // A directory in the figure's place: the rename fails, the directory and no temp remain.
  const auto occupied = dir.path() / "taken.png";
  std::filesystem::create_directories(occupied / "inner");
  EXPECT_THROW(write_png(Image(4, 4), occupied), std::runtime_error);
  EXPECT_TRUE(std::filesystem::is_directory(occupied / "inner"));
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir.path())) {
    files += entry.path().filename().string().find(".tmp.") != std::string::npos ? 1 : 0;
  }
  EXPECT_EQ(files, 0);
  EXPECT_THROW(read_png(dir.path() / "missing.png"), std::runtime_error);
}
}  // namespace
}  // namespace cogmap::render
