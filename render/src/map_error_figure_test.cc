// figures/map_error.png: the error scale's colours, and pieces drawn in the colour of their
// error where they belong.

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

#include "cogmap/render/figures.h"
#include "cogmap/render/image.h"
#include "error_colors.h"
#include "test_support.h"

namespace cogmap::render {
namespace {

using mapper::Point2;
using testing::near;
using testing::TempDir;

bool same(Rgb a, Rgb b) { return a.r == b.r && a.g == b.g && a.b == b.b; }

TEST(ErrorColors, AnchorsAndClamps) {
  const Style style;
  EXPECT_TRUE(same(error_color(0.0, style), style.error_good));
  EXPECT_TRUE(same(error_color(0.05, style), style.error_good));
  EXPECT_TRUE(same(error_color(0.15, style), style.error_mid));
  EXPECT_TRUE(same(error_color(0.3, style), style.error_bad));
  EXPECT_TRUE(same(error_color(2.0, style), style.error_bad));
  // Halfway between good (0.05) and mid (0.15): the mean of the two colours.
  const Rgb half = error_color(0.1, style);
  EXPECT_NEAR(half.g, 0.5f * (style.error_good.g + style.error_mid.g), 1e-6f);
  EXPECT_NEAR(half.r, 0.5f * (style.error_good.r + style.error_mid.r), 1e-6f);
}

// The x-range of the pixels near `color` on image row `y`: {first, last}, {-1, -1} if none.
std::pair<int, int> columns_near(const Image& image, int y, Rgb color) {
  int first = -1, last = -1;
  for (int x = 0; x < image.width(); ++x) {
    if (!near(image.at(x, y), color, 12)) continue;
    if (first < 0) first = x;
    last = x;
  }
  return {first, last};
}

// Three map pieces on one line 1 m above a true wall: 0 m error (left), 0.15 m (middle) and
// 0.4 m (right). The errors are given, so the colours are known without any metric.
TEST(MapErrorFigure, PiecesTakeTheColourOfTheirError) {
  TempDir dir;
  const Style style;
  MapErrorFigure figure;
  figure.title = "map error";
  figure.true_surfaces = {{Point2(0.0, 0.0), Point2(4.0, 0.0)}};
  figure.pieces = {{Point2(0.0, 1.0), Point2(1.2, 1.0)},
                   {Point2(1.4, 1.0), Point2(2.6, 1.0)},
                   {Point2(2.8, 1.0), Point2(4.0, 1.0)}};
  figure.error_m = {0.0, 0.15, 0.4};
  const auto path = dir.path() / "map_error.png";
  write_map_error_figure(figure, path, style);
  const Image image = read_png(path);
  EXPECT_EQ(image.width(), style.panel_width_px + 2 * style.margin_px);

  // The topmost row holding the green piece (the legend's swatches sit below the plot).
  int row = -1;
  for (int y = 0; y < image.height() && row < 0; ++y) {
    if (columns_near(image, y, style.error_good).first >= 0) row = y;
  }
  ASSERT_GE(row, 0);
  row += 1;  // into the 3.5 px line, off its blended edge
  const auto green = columns_near(image, row, style.error_good);
  const auto yellow = columns_near(image, row, style.error_mid);
  const auto red = columns_near(image, row, style.error_bad);
  ASSERT_GE(yellow.first, 0);
  ASSERT_GE(red.first, 0);
  // Left to right as placed, each about 1.2 m long and about as long as the others.
  EXPECT_LT(green.second, yellow.first);
  EXPECT_LT(yellow.second, red.first);
  EXPECT_GT(green.second - green.first, 60);
  EXPECT_NEAR(red.second - red.first, green.second - green.first, 4);
  EXPECT_NEAR(yellow.second - yellow.first, green.second - green.first, 4);

  MapErrorFigure ragged = figure;
  ragged.error_m.pop_back();
  EXPECT_THROW(write_map_error_figure(ragged, path, style), std::invalid_argument);
}

}  // namespace
}  // namespace cogmap::render
