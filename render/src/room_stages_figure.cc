// Fig. 3.3 (a)-(g): one room from raw grid to fitted polylines, one panel a stage.

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "canvas.h"
#include "cogmap/render/figures.h"
#include "grid_colors.h"
#include "panel.h"

namespace cogmap::render {
namespace {

constexpr int kColumns = 4;               // 7 panels in 2 rows; the 8th slot stays white
constexpr double kRoomViewMarginM = 0.3;  // white space around the room
constexpr double kRoomMinViewSizeM = 1.0;

// Dark, distinguishable colours so neighbouring point runs (split at γ breaks) can be told apart.
constexpr std::array<Rgb, 4> kRunColors = {Rgb{0.10f, 0.10f, 0.10f}, Rgb{0.75f, 0.10f, 0.45f},
                                           Rgb{0.05f, 0.45f, 0.55f}, Rgb{0.45f, 0.30f, 0.05f}};

// Points under the fitted lines in (f): visible, yet lighter than the black lines over them.
constexpr Rgb kFaintPoints{0.55f, 0.55f, 0.55f};

// The cells worth showing: everything the robot observed (non-zero), as a world box.
void add_explored(Bounds& bounds, const mapper::HistogramGrid& grid) {
  const mapper::GridGeometry& g = grid.geometry();
  const double half = 0.5 * g.cell_size_m();
  for (int y = 0; y < grid.height(); ++y) {
    for (int x = 0; x < grid.width(); ++x) {
      if (grid.get({x, y}) == 0.0f) continue;
      const mapper::Point2 c = g.center_of({x, y});
      bounds.add(mapper::Point2(c.x() - half, c.y() - half));
      bounds.add(mapper::Point2(c.x() + half, c.y() + half));
    }
  }
}

std::size_t vertex_count(const std::vector<mapper::Polyline>& lines) {
  std::size_t n = 0;
  for (const auto& l : lines) n += l.size();
  return n;
}

std::vector<mapper::Point2> all_vertices(const std::vector<mapper::Polyline>& lines) {
  std::vector<mapper::Point2> out;
  for (const auto& l : lines) out.insert(out.end(), l.begin(), l.end());
  return out;
}

std::vector<LegendEntry> grid_legend(const Style& style, bool with_path_line) {
  std::vector<LegendEntry> legend = {
      {"unexplored", style.grid_unexplored, Swatch::kBox},
      {"empty", grid_cell_color(mapper::kHistogramFloor, style), Swatch::kBox},
      {"occupied", grid_cell_color(mapper::kHistogramMax, style), Swatch::kBox},
      {"path cells", style.grid_robot_path, Swatch::kBox},
  };
  if (with_path_line) {
    legend.push_back({"robot path", style.true_path, Swatch::kLine, style.path_width_px});
  }
  return legend;
}

}  // namespace

void write_room_stages_figure(const mapper::AsrTrace& trace, const std::string& title,
                              const std::filesystem::path& png, const Style& style) {
  Font& font = thread_font();
  Bounds data;
  add_explored(data, trace.raw);
  add_explored(data, trace.cleaned);
  data.add(trace.extracted);
  data.add(trace.fitted);
  data.add(trace.rejected);
  data.add(trace.robot_path);
  const Bounds bounds = data.padded(kRoomViewMarginM, kRoomMinViewSizeM);

  const int title_h = title.empty() ? 0 : font.line_height_px(style.title_font_px) + 8;
  const FigureLayout layout = layout_figure(7, kColumns, !title.empty(), title_h, style);
  Canvas canvas(layout.width_px, layout.height_px, style, font);
  draw_title(canvas, layout.title, title);

  const std::string n_points = std::to_string(vertex_count(trace.extracted));
  const std::vector<mapper::Point2> extracted_points = all_vertices(trace.extracted);
  const LegendEntry polylines{"polylines", style.map_wall, Swatch::kLine, style.map_wall_width_px};
  const LegendEntry vertices{"vertices", style.map_wall, Swatch::kPoints, style.point_size_px + 1};
  const LegendEntry rejected{"rejected fits (|ρ| too low)", style.rejected_fit, Swatch::kDashedLine,
                             style.map_wall_width_px};
  const LegendEntry faint_points{"extracted points", kFaintPoints, Swatch::kPoints,
                                 style.point_size_px};

  std::string captions[7];
  std::vector<LegendEntry> legends[7];
  int footer_rows = 0;
  for (int i = 0; i < 7; ++i) {
    std::string& caption = captions[i];
    std::vector<LegendEntry>& legend = legends[i];
    switch (i) {
      case 0:
        caption = "raw grid with the robot path";
        legend = grid_legend(style, true);
        break;
      case 1:
        caption = "cleaned grid";
        legend = grid_legend(style, false);
        break;
      case 2:
        caption = "extracted points (" + n_points + ", " + std::to_string(trace.extracted.size()) +
                  " runs)";
        legend = {{"points, colour per run", style.points, Swatch::kPoints, style.point_size_px}};
        break;
      case 3:
        caption = "vertex-simplified (" + std::to_string(vertex_count(trace.vertex_simplified)) +
                  " vertices)";
        legend = {polylines, vertices};
        break;
      case 4:
        caption = "Douglas-Peucker (" + std::to_string(vertex_count(trace.douglas_peucker)) +
                  " vertices)";
        legend = {polylines, vertices};
        break;
      case 5:
        caption = "fitted lines over the points";
        legend = {faint_points,
                  {"fitted lines", style.map_wall, Swatch::kLine, style.map_wall_width_px}};
        if (!trace.rejected.empty()) legend.push_back(rejected);
        break;
      default:
        caption = "final polylines (" + std::to_string(vertex_count(trace.fitted)) + " vertices)";
        legend = {polylines, vertices};
        if (!trace.rejected.empty()) legend.push_back(rejected);
        break;
    }
    footer_rows = std::max(footer_rows, legend_rows(canvas, layout.panels[i].w, legend, true));
  }

  for (int i = 0; i < 7; ++i) {
    const PanelLayout pl = layout_panel(canvas, layout.panels[i], legends[i], true, footer_rows);
    const WorldView view(pl.plot, bounds);
    canvas.use_world(view);
    switch (i) {
      case 0:
        canvas.grid(trace.raw, bounds);
        canvas.polyline(trace.robot_path, style.true_path, style.path_width_px);
        break;
      case 1:
        canvas.grid(trace.cleaned, bounds);
        break;
      case 2:
        for (std::size_t k = 0; k < trace.extracted.size(); ++k) {
          canvas.points(trace.extracted[k], kRunColors[k % kRunColors.size()], style.point_size_px);
        }
        break;
      case 3:
      case 4: {
        const auto& lines = i == 3 ? trace.vertex_simplified : trace.douglas_peucker;
        for (const auto& line : lines)
          canvas.polyline(line, style.map_wall, style.map_wall_width_px);
        canvas.points(all_vertices(lines), style.map_wall, style.point_size_px + 1);
        break;
      }
      case 5:
        canvas.points(extracted_points, kFaintPoints, style.point_size_px);
        for (const auto& line : trace.fitted) {
          canvas.polyline(line, style.map_wall, style.map_wall_width_px);
        }
        canvas.segments(trace.rejected, style.rejected_fit, style.map_wall_width_px, true);
        break;
      default:
        for (const auto& line : trace.fitted) {
          canvas.polyline(line, style.map_wall, style.map_wall_width_px);
        }
        canvas.points(all_vertices(trace.fitted), style.map_wall, style.point_size_px + 1);
        canvas.segments(trace.rejected, style.rejected_fit, style.map_wall_width_px, true);
        break;
    }
    draw_panel_furniture(canvas, pl, panel_letter(i), captions[i], legends[i], &view);
  }
  write_png(canvas.finish(), png);
}

}  // namespace cogmap::render
