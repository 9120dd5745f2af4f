#include "synthetic_scenes.h"

#include <cmath>
#include <random>

namespace cogmap::render::testing {
namespace {

using mapper::Point2;

// Rotates p about pivot by angle_rad (counter-clockwise).
Point2 rotate_about(const Point2& p, const Point2& pivot, double angle_rad) {
  const double c = std::cos(angle_rad), s = std::sin(angle_rad);
  const Point2 d = p - pivot;
  return pivot + Point2(c * d.x() - s * d.y(), s * d.x() + c * d.y());
}

// Points every `step_m` along a -> b (a included, b excluded).
std::vector<Point2> sample(const Point2& a, const Point2& b, double step_m) {
  std::vector<Point2> out;
  const int n = std::max(1, static_cast<int>(std::round((b - a).norm() / step_m)));
  for (int i = 0; i < n; ++i) out.push_back(a + (b - a) * (static_cast<double>(i) / n));
  return out;
}

std::vector<Point2> densify(const std::vector<Point2>& line, double step_m) {
  std::vector<Point2> out;
  for (std::size_t i = 0; i + 1 < line.size(); ++i) {
    const auto part = sample(line[i], line[i + 1], step_m);
    out.insert(out.end(), part.begin(), part.end());
  }
  if (!line.empty()) out.push_back(line.back());
  return out;
}

}  // namespace

mapper::AsrTrace synthetic_room_trace() {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> occupied(8.0f, 15.0f), empty(-3.0f, -1.0f);
  std::normal_distribution<double> jitter(0.0, 0.02);

  mapper::AsrTrace trace;
  trace.asr_id = 3;
  // The room's walls run along x in [0, 5], y in [0, 4]; the doorway is x = 5, y in [1.5, 2.5].
  const mapper::GridGeometry geometry(-1.0, -1.0, 100.0, 72, 62);
  trace.raw = mapper::HistogramGrid(geometry, 0.0f);
  for (int y = 0; y < geometry.height(); ++y) {
    for (int x = 0; x < geometry.width(); ++x) {
      const Point2 c = geometry.center_of({x, y});
      const bool inside = c.x() > 0.05 && c.x() < 4.95 && c.y() > 0.05 && c.y() < 3.95;
      // The far north-west corner stays unexplored, as a sonar shadow would leave it.
      const bool shadow = c.x() < 1.0 && c.y() > 3.0;
      if (inside && !shadow) trace.raw.set({x, y}, empty(rng));
    }
  }
  const std::vector<std::vector<Point2>> walls = {
      {{5.0, 1.5}, {5.0, 0.0}, {0.0, 0.0}, {0.0, 4.0}, {5.0, 4.0}, {5.0, 2.5}}};
  for (const auto& p : densify(walls[0], 0.05)) {
    if (p.x() < 1.0 && p.y() > 3.0) continue;  // unseen wall in the shadow
    trace.raw.set(geometry.cell_of(p), occupied(rng));
  }
  trace.robot_path =
      densify({{5.8, 2.0}, {4.0, 2.0}, {2.5, 1.2}, {1.2, 1.5}, {1.5, 2.6}, {3.0, 2.8}}, 0.05);
  for (const auto& p : trace.robot_path)
    trace.raw.set(geometry.cell_of(p), mapper::kRobotPathValue);
  // Specular ghosts: occupied cells in free space that the clean-map rays reject.
  trace.cleaned = trace.raw;
  for (const Point2& ghost : {Point2(2.2, 3.3), Point2(3.6, 0.6), Point2(3.7, 0.6)}) {
    trace.raw.set(geometry.cell_of(ghost), 9.0f);
  }
  // A box of clutter against the south wall that the line fit will reject.
  const std::vector<Point2> clutter = {{3.0, 0.15}, {3.1, 0.35}, {3.05, 0.5}, {3.3, 0.45}};
  for (const auto& p : clutter) {
    trace.raw.set(geometry.cell_of(p), 10.0f);
    trace.cleaned.set(geometry.cell_of(p), 10.0f);
  }

  // (c): wall points as two runs broken at the doorway and at the shadow, plus the clutter run.
  auto noisy = [&](const std::vector<Point2>& line) {
    std::vector<Point2> out;
    for (const auto& p : densify(line, 0.1)) out.push_back(p + Point2(jitter(rng), jitter(rng)));
    return out;
  };
  trace.extracted = {noisy({{5.0, 1.5}, {5.0, 0.0}, {0.0, 0.0}, {0.0, 3.0}}),
                     noisy({{1.0, 4.0}, {5.0, 4.0}, {5.0, 2.5}}), clutter};
  // (d): every second point survives the vertex tolerance.
  for (const auto& run : trace.extracted) {
    mapper::Polyline kept;
    for (std::size_t i = 0; i < run.size(); i += 2) kept.push_back(run[i]);
    if (kept.back() != run.back()) kept.push_back(run.back());
    trace.vertex_simplified.push_back(kept);
  }
  // (e): Douglas-Peucker keeps the corners (noisy); (f-g) the fits straighten them.
  trace.douglas_peucker = {
      {trace.extracted[0].front(), {5.02, 0.01}, {-0.01, 0.02}, trace.extracted[0].back()},
      {trace.extracted[1].front(), {4.98, 4.02}, trace.extracted[1].back()},
      clutter};
  trace.fitted = {{{5.0, 1.5}, {5.0, 0.0}, {0.0, 0.0}, {0.0, 3.0}},
                  {{1.0, 4.0}, {5.0, 4.0}, {5.0, 2.5}}};
  trace.rejected = {{clutter[0], clutter[1]}, {clutter[1], clutter[3]}};
  return trace;
}

MapFigure synthetic_map_figure() {
  MapFigure figure;
  figure.title = "two_rooms: merged map";
  // Split at x = 5 so each room's walls can carry that room's drift.
  const std::vector<std::vector<Point2>> walls = {
      {{5, 2.5}, {5, 0}, {0, 0}, {0, 6}, {5, 6}, {5, 3.5}}, {{5, 0}, {10, 0}, {10, 6}, {5, 6}}};
  for (const auto& w : walls) {
    for (std::size_t i = 0; i + 1 < w.size(); ++i) figure.true_surfaces.push_back({w[i], w[i + 1]});
  }
  const Point2 start(1.0, 1.0);
  figure.true_path = densify({start, {2.5, 3.0}, {7.5, 3.0}, {7.5, 1.5}}, 0.1);
  // Odometry drifts in heading as the robot drives; the second room's map inherits the drift.
  const double drift_rad_per_m = 0.012;
  double travelled_m = 0.0;
  Point2 previous = start;
  for (const auto& p : figure.true_path) {
    travelled_m += (p - previous).norm();
    previous = p;
    figure.odometry_path.push_back(rotate_about(p, start, drift_rad_per_m * travelled_m));
    figure.estimated_path.push_back(p + Point2(0.03 * std::sin(3.0 * travelled_m), 0.02));
  }
  const double room2_drift_rad = drift_rad_per_m * 7.0;
  for (const auto& s : figure.true_surfaces) {
    const bool room2 = s.a.x() + s.b.x() > 10.0;  // east of the partition
    const double drift = room2 ? room2_drift_rad : 0.01;
    figure.map_odometry.push_back(
        {rotate_about(s.a, start, drift), rotate_about(s.b, start, drift)});
    figure.map_corrected.push_back({s.a + Point2(0.03, -0.02), s.b + Point2(0.03, -0.02)});
  }
  figure.room_labels_at = {{2.5, 3.0}, {7.5, 3.0}};
  figure.room_labels = {"ASR 0", "ASR 1"};
  for (const auto& p : figure.room_labels_at) {
    figure.room_labels_at_odometry.push_back(
        rotate_about(p, start, p.x() > 5.0 ? room2_drift_rad : 0.01));
  }
  return figure;
}

void synthetic_graph(std::vector<mapper::AsrNode>* nodes, std::vector<mapper::AsrEdge>* edges) {
  // Rooms 5 m apart, visited in a snake so the ids follow the route.
  const int order[3][3] = {{0, 1, 2}, {5, 4, 3}, {6, 7, 8}};
  nodes->clear();
  edges->clear();
  std::vector<Point2> at(9);
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) {
      const int id = order[r][c];
      at[id] = Point2(5.0 * c + 2.5, 5.0 * r + 2.5);
      mapper::AsrNode node;
      node.id = id;
      node.pose = {5.0 * c, 5.0 * r, 0.0};
      node.reference_point_world = at[id];
      nodes->push_back(node);
    }
  }
  for (int id = 0; id + 1 < 9; ++id) {
    const Point2 door = 0.5 * (at[id] + at[id + 1]) + Point2(0.0, 0.8);  // doors off-centre
    edges->push_back({id, id + 1, 1, door});
  }
}

std::vector<PlotSeries> synthetic_sweep() {
  return {
      {"himm", {55, 85, 100, 150}, {0.061, 0.052, 0.048, 0.071}, {0.006, 0.005, 0.007, 0.011}},
      {"mhimm", {55, 85, 100, 150}, {0.047, 0.041, 0.040, 0.058}, {0.004, 0.004, 0.005, 0.008}},
  };
}

}  // namespace cogmap::render::testing
