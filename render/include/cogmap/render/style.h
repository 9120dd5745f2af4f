#pragma once
/// Colours, sizes and fonts shared by every figure, so the same thing looks the same in all of
/// them (true walls light grey, map walls black, true path green, odometry red, estimate blue).

namespace cogmap::render {

/// A colour with components in [0, 1].
struct Rgb {
  float r = 0.0f;  ///< red, [0, 1]
  float g = 0.0f;  ///< green, [0, 1]
  float b = 0.0f;  ///< blue, [0, 1]
};

/// Everything a figure's look depends on. Defaults give print-ready figures; every field may be
/// changed independently.
struct Style {
  int panel_width_px = 600;   ///< one panel, caption and legend included, pixels
  int panel_height_px = 480;  ///< one panel, caption and legend included, pixels
  int margin_px = 16;         ///< white space around and between panels, pixels

  int title_font_px = 24;    ///< figure title text height, pixels
  int caption_font_px = 17;  ///< panel letter and caption, pixels
  int label_font_px = 14;    ///< legend, scale bar, axis and node labels, pixels

  float map_wall_width_px = 2.5f;   ///< extracted map walls and fitted polylines, pixels
  float true_wall_width_px = 6.0f;  ///< ground-truth surfaces (drawn wide and pale under the map)
  float path_width_px = 2.0f;       ///< robot paths, pixels
  float point_size_px = 4.0f;       ///< extracted points and polyline vertices, pixels
  float plot_line_width_px = 2.0f;  ///< metric plot series, pixels

  Rgb background{1.0f, 1.0f, 1.0f};         ///< page and panel background
  Rgb text{0.1f, 0.1f, 0.1f};               ///< all text
  Rgb frame{0.55f, 0.55f, 0.55f};           ///< the thin frame around each plot area
  Rgb true_wall{0.80f, 0.80f, 0.80f};       ///< ground-truth surfaces
  Rgb map_wall{0.0f, 0.0f, 0.0f};           ///< map segments and fitted polylines
  Rgb true_path{0.10f, 0.62f, 0.15f};       ///< ground-truth robot path
  Rgb odometry_path{0.88f, 0.12f, 0.10f};   ///< raw odometry path
  Rgb estimated_path{0.10f, 0.35f, 0.95f};  ///< localised (EM) path
  Rgb rejected_fit{1.0f, 0.55f, 0.0f};      ///< line fits rejected by the |ρ| test
  Rgb points{0.15f, 0.15f, 0.15f};          ///< extracted wall points
  Rgb graph_node{0.85f, 0.90f, 1.0f};       ///< room-graph node fill
  Rgb graph_edge{0.25f, 0.25f, 0.25f};      ///< room-graph edges
  Rgb exit_marker{0.88f, 0.12f, 0.10f};     ///< exits (doorways) in the room graph

  // The map-error scale (figures/map_error.png): a map sample's distance to the nearest true
  // surface, good at or below error_good_m, bad at or above error_bad_m, linear in between.
  double error_good_m = 0.05;           ///< at or below: error_good colour
  double error_mid_m = 0.15;            ///< error_mid colour
  double error_bad_m = 0.30;            ///< at or above: error_bad colour
  Rgb error_good{0.10f, 0.65f, 0.20f};  ///< green
  Rgb error_mid{0.95f, 0.80f, 0.05f};   ///< yellow
  Rgb error_bad{0.85f, 0.10f, 0.10f};   ///< red

  // Grid colouring on the HIMM scale (mapper/grid/grid.h): unexplored mid-grey, seen-empty
  // light, occupied darker the higher the count, robot path green.
  Rgb grid_unexplored{0.62f, 0.62f, 0.62f};  ///< H = 0
  Rgb grid_empty{0.96f, 0.96f, 0.93f};       ///< H at the empty floor (most certainly free)
  Rgb grid_occupied{0.0f, 0.0f, 0.0f};       ///< H at the cap (most certainly occupied)
  Rgb grid_robot_path{0.30f, 0.78f, 0.30f};  ///< H = kRobotPathValue
};

}  // namespace cogmap::render
