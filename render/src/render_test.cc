// Renderer tests: pure layout maths, pixel-exact drawing of known scenes, PNG I/O and the error
// paths the experiments rely on (unwritable output, missing font).

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <string>

#include "canvas.h"
#include "cogmap/render/figures.h"
#include "cogmap/render/image.h"
#include "grid_colors.h"
#include "layout.h"
#include "synthetic_scenes.h"

namespace cogmap::render {
namespace {

using mapper::Point2;

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

bool is_white(const Rgba8& p) { return p.r == 255 && p.g == 255 && p.b == 255; }
bool is_dark(const Rgba8& p) { return p.r < 90 && p.g < 90 && p.b < 90; }
bool near(const Rgba8& p, Rgb c, int tolerance) {
  return std::abs(p.r - c.r * 255.0f) <= tolerance && std::abs(p.g - c.g * 255.0f) <= tolerance &&
         std::abs(p.b - c.b * 255.0f) <= tolerance;
}
int count_near(const Image& image, Rgb c, int tolerance) {
  int n = 0;
  for (const auto& p : image.pixels()) n += near(p, c, tolerance) ? 1 : 0;
  return n;
}

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

TEST(Png, FigureWriterReportsTheUnwritablePath) {
  TempDir dir;
  const auto blocker = dir.path() / "file";
  std::ofstream(blocker) << "x";
  const auto path = blocker / "map.png";
  try {
    write_map_figure(testing::synthetic_map_figure(), path);
    FAIL() << "expected a throw";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
  }
}

// A known map: one true wall along y = 0 and one map segment along y = 1, x from 0 to 4 m.
TEST(MapFigure, DrawsTheMapSegmentWhereItBelongs) {
  TempDir dir;
  Style style;
  style.panel_width_px = 400;
  style.panel_height_px = 300;
  MapFigure figure;
  figure.true_surfaces = {{Point2(0.0, 0.0), Point2(4.0, 0.0)}};
  figure.map_odometry = {{Point2(0.0, 1.0), Point2(4.0, 1.0)}};
  figure.map_corrected = figure.map_odometry;
  const auto path = dir.path() / "map.png";
  write_map_figure(figure, path, style);
  const Image image = read_png(path);
  ASSERT_EQ(image.width(), 2 * 400 + 3 * style.margin_px);  // no title: two panels and margins
  ASSERT_EQ(image.height(), 300 + 2 * style.margin_px);
  EXPECT_TRUE(is_white(image.at(0, 0)));
  EXPECT_TRUE(is_white(image.at(image.width() - 1, image.height() - 1)));

  // In panel (b) find the black map line and the grey true wall on the panel's centre column.
  const int cx = style.margin_px * 2 + 400 + 200;
  // Centres of the runs, as the two lines are drawn at different widths.
  auto run_centre = [&](auto&& in_run) {
    int first = -1, last = -1;
    for (int y = 0; y < image.height(); ++y) {
      if (!in_run(image.at(cx, y))) continue;
      if (first < 0) first = y;
      last = y;
    }
    return 0.5 * (first + last);
  };
  const double map_centre = run_centre(is_dark);
  const double true_centre =
      run_centre([&](const Rgba8& p) { return near(p, style.true_wall, 3); });
  ASSERT_GT(map_centre, 0.0);
  ASSERT_GT(true_centre, 0.0);
  const double px_per_m = true_centre - map_centre;  // the lines are 1 m apart, map above
  ASSERT_GT(px_per_m, 20.0);
  const int map_row = static_cast<int>(map_centre);
  // The map line spans 4 m and ends there: dark across, white beyond its ends.
  const int line_row = map_row;
  int left = cx, right = cx;
  while (is_dark(image.at(left - 1, line_row))) --left;
  while (is_dark(image.at(right + 1, line_row))) ++right;
  EXPECT_NEAR(right - left, 4.0 * px_per_m, 3.0);
  EXPECT_TRUE(is_white(image.at(left - 6, line_row)));
  EXPECT_TRUE(is_white(image.at(right + 6, line_row)));
  // Half a metre above the map line and between the lines: nothing drawn.
  EXPECT_TRUE(is_white(image.at(cx, map_row - static_cast<int>(0.5 * px_per_m))));
  EXPECT_TRUE(is_white(image.at(cx, map_row + static_cast<int>(0.5 * px_per_m))));
  // Panel (a) shows the same view: its map line is on the same row.
  EXPECT_TRUE(is_dark(image.at(cx - 400 - style.margin_px, line_row)));
}

TEST(MapFigure, PathsUseTheirColours) {
  TempDir dir;
  const auto path = dir.path() / "map.png";
  const MapFigure figure = testing::synthetic_map_figure();
  write_map_figure(figure, path);
  const Image image = read_png(path);
  const Style style;
  EXPECT_GT(count_near(image, style.odometry_path, 40), 100);
  EXPECT_GT(count_near(image, style.estimated_path, 40), 100);
  EXPECT_GT(count_near(image, style.true_path, 40), 30);
  MapFigure bad = figure;
  bad.room_labels.pop_back();
  EXPECT_THROW(write_map_figure(bad, path), std::invalid_argument);
}

TEST(RoomStages, WritesSevenPanelsOfTheExpectedSize) {
  TempDir dir;
  const Style style;
  const auto path = dir.path() / "room.png";
  write_room_stages_figure(testing::synthetic_room_trace(), "Room 3", path, style);
  const Image image = read_png(path);
  Font font(find_font_file());
  const int title_h = font.line_height_px(style.title_font_px) + 8;
  EXPECT_EQ(image.width(), 4 * style.panel_width_px + 5 * style.margin_px);
  EXPECT_EQ(image.height(), title_h + 2 * style.panel_height_px + 3 * style.margin_px);
  EXPECT_GT(count_near(image, style.grid_robot_path, 10), 200);  // (a), (b): path cells
  EXPECT_GT(count_near(image, style.rejected_fit, 30), 20);      // (f), (g): rejected clutter
  EXPECT_GT(count_near(image, style.grid_unexplored, 3), 1000);
  // The eighth slot (bottom right) stays empty.
  const int x8 = 3 * style.panel_width_px + 4 * style.margin_px + style.panel_width_px / 2;
  const int y8 = title_h + style.margin_px * 2 + style.panel_height_px * 3 / 2;
  EXPECT_TRUE(is_white(image.at(x8, y8)));
}

TEST(RoomStages, EmptyTraceStillRenders) {
  TempDir dir;
  const auto path = dir.path() / "empty.png";
  write_room_stages_figure(mapper::AsrTrace{}, "", path);
  EXPECT_GT(read_png(path).width(), 0);
}

TEST(GraphFigure, NodesAndExitsAreDrawn) {
  TempDir dir;
  std::vector<mapper::AsrNode> nodes;
  std::vector<mapper::AsrEdge> edges;
  testing::synthetic_graph(&nodes, &edges);
  const auto path = dir.path() / "graph.png";
  const Style style;
  write_graph_figure(nodes, edges, "graph", path, style);
  const Image image = read_png(path);
  EXPECT_EQ(image.width(), style.panel_width_px + 2 * style.margin_px);
  EXPECT_GT(count_near(image, style.graph_node, 4), 9 * 300);  // nine discs of radius 15 px
  EXPECT_GT(count_near(image, style.exit_marker, 30), 8 * 10);
}

TEST(MetricPlot, DrawsSeriesAndRejectsRaggedInput) {
  TempDir dir;
  const auto path = dir.path() / "plot.png";
  write_metric_plot("t", "x", "y", testing::synthetic_sweep(), path);
  const Image image = read_png(path);
  EXPECT_GT(count_near(image, {0.12f, 0.47f, 0.71f}, 30), 100);  // first series colour
  std::vector<PlotSeries> ragged = {{"bad", {1, 2, 3}, {1, 2}, {}}};
  EXPECT_THROW(write_metric_plot("t", "x", "y", ragged, path), std::invalid_argument);
  write_metric_plot("empty", "x", "y", {}, dir.path() / "empty.png");
  EXPECT_TRUE(std::filesystem::exists(dir.path() / "empty.png"));
}

TEST(Font, MissingFontIsAClearError) {
  TempDir dir;
  const auto missing = dir.path() / "no_such_font.ttf";
  ::setenv("COGMAP_FONT", missing.c_str(), 1);
  const auto path = dir.path() / "map.png";
  try {
    write_map_figure(testing::synthetic_map_figure(), path);
    ::unsetenv("COGMAP_FONT");
    FAIL() << "expected a throw";
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("COGMAP_FONT"), std::string::npos) << what;
    EXPECT_NE(what.find(missing.string()), std::string::npos) << what;
  }
  EXPECT_FALSE(std::filesystem::exists(path));
  // A file that is no font: FreeType's refusal names the file.
  const auto junk = dir.path() / "junk.ttf";
  std::ofstream(junk) << "not a font";
  ::setenv("COGMAP_FONT", junk.c_str(), 1);
  try {
    write_metric_plot("t", "x", "y", {}, path);
    FAIL() << "expected a throw";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(junk.string()), std::string::npos) << e.what();
  }
  ::unsetenv("COGMAP_FONT");
}

}  // namespace
}  // namespace cogmap::render
