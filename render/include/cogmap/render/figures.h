#pragma once
/// The staged figures of the thesis, drawn off-screen (OSMesa) and written as PNG.
///
/// Every writer throws std::runtime_error naming the file when the PNG cannot be written or no
/// font is found (COGMAP_FONT overrides the font file). A PNG is written to a temporary file and
/// renamed, so an existing figure is never left half-written. Missing parent directories are
/// created. Calls from several threads are safe and draw in parallel (each figure has its own
/// OSMesa context and FreeType library). The drawing code is a plugin loaded on the first call
/// (renderer.h); without it every writer throws RendererUnavailable.

#include <filesystem>
#include <string>
#include <vector>

#include "cogmap/mapper/asr/asr_builder.h"
#include "cogmap/mapper/graph/asr_graph.h"
#include "cogmap/mapper/seam/geometry.h"
#include "cogmap/render/style.h"

namespace cogmap::render {

/// Fig. 3.3 (a)-(g) for one room: one PNG with panels (a) raw grid with the robot path,
/// (b) cleaned grid, (c) extracted points, (d) vertex-simplified, (e) Douglas-Peucker, (f) fitted
/// lines over the points, (g) final fitted polylines (rejected fits marked), each with its letter
/// and caption, a metric scale bar and a legend. All panels share one view, in the room's frame.
void write_room_stages_figure(const mapper::AsrTrace& trace, const std::string& title,
                              const std::filesystem::path& png, const Style& style = {});

/// The merged map (Figs. 4.4, 4.5, 4.6), world frame, metres.
struct MapFigure {
  std::string title;                           ///< figure title
  std::vector<mapper::Segment> true_surfaces;  ///< ground truth, may be empty (real robot)
  std::vector<mapper::Segment> map_odometry;   ///< the map before localisation
  std::vector<mapper::Segment> map_corrected;  ///< the map after localisation
  std::vector<mapper::Point2> true_path;       ///< may be empty (real robot)
  std::vector<mapper::Point2> odometry_path;   ///< may be empty
  std::vector<mapper::Point2> estimated_path;  ///< may be empty
  std::vector<mapper::Point2> room_labels_at;  ///< reference points after localisation
  std::vector<std::string> room_labels;        ///< one label (ASR id) per room_labels_at
  /// Optional: the reference points before localisation (same order as room_labels); when
  /// empty, the labels appear only on the "after localisation" panel.
  std::vector<mapper::Point2> room_labels_at_odometry;
};

/// Two panels over one shared view: (a) "before localisation" (map_odometry, odometry path) and
/// (b) "after localisation" (map_corrected, estimated path), each over the true surfaces (grey)
/// with the true path (green).
void write_map_figure(const MapFigure& figure, const std::filesystem::path& png,
                      const Style& style = {});

/// The corrected map coloured by its error (figures/map_error.png), world frame, metres.
struct MapErrorFigure {
  std::string title;                           ///< figure title (short: one panel wide)
  std::string caption;                         ///< panel caption, e.g. the experiment and seed
  std::vector<mapper::Segment> true_surfaces;  ///< ground truth, drawn thin grey underneath
  /// The map cut into the pieces its metric samples stand for (docs/metrics.md, "Sampling").
  std::vector<mapper::Segment> pieces;
  std::vector<double> error_m;  ///< per piece: its sample's distance to the nearest true surface
};

/// One panel: every map piece in the colour of its error on the style's scale (green at or
/// below error_good_m, yellow at error_mid_m, red at or above error_bad_m) over the true
/// surfaces, with the scale in metres as the legend. Throws std::invalid_argument when
/// pieces and error_m differ in length.
void write_map_error_figure(const MapErrorFigure& figure, const std::filesystem::path& png,
                            const Style& style = {});

/// The room graph (Fig. 4.1b): nodes at their reference points, numbered, edges drawn from node
/// to node through the exit they share. World frame.
void write_graph_figure(const mapper::AsrGraph& graph, const std::string& title,
                        const std::filesystem::path& png, const Style& style = {});

/// The same, from the graph's parts (what write_graph_figure draws).
void write_graph_figure(const std::vector<mapper::AsrNode>& nodes,
                        const std::vector<mapper::AsrEdge>& edges, const std::string& title,
                        const std::filesystem::path& png, const Style& style = {});

/// One line of a sweep plot: y_mean ± y_sd over seeds at each x. y_sd may be empty (no bars).
struct PlotSeries {
  std::string label;           ///< legend text
  std::vector<double> x;       ///< the varied key's values
  std::vector<double> y_mean;  ///< mean of the metric over seeds, one per x
  std::vector<double> y_sd;    ///< standard deviation over seeds, one per x, or empty
};

/// A sweep plot: one metric (y) against the varied key (x), mean ± sd over seeds per series.
/// Throws std::invalid_argument when a series' vectors differ in length.
void write_metric_plot(const std::string& title, const std::string& x_label,
                       const std::string& y_label, const std::vector<PlotSeries>& series,
                       const std::filesystem::path& png, const Style& style = {});

}  // namespace cogmap::render
