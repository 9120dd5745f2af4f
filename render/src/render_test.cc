// Whole figures: known scenes drawn where they belong, sizes, colours, and the error paths the
// experiments rely on (unwritable output, missing font).

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <string>

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
