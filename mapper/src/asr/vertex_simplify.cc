// Vertex simplification, thesis Fig. A.4 (τ).

#include <vector>

#include "cogmap/mapper/asr/stages.h"

namespace cogmap::mapper {

// Fig. A.4 with its garbled loop variables read as: i is the last kept vertex, m walks forward;
// V_{i+m} is removed while Δ(V_i, V_{i+m}) < τ, and the first vertex at Δ >= τ becomes the new
// V_i. The thesis can drop the final vertex; we keep it so a wall keeps its full extent.
std::vector<std::size_t> vertex_simplify_indices(const Polyline& line, double tolerance) {
  std::vector<std::size_t> kept;
  if (line.empty()) return kept;
  kept.push_back(0);
  for (std::size_t i = 1; i < line.size(); ++i) {
    if ((line[i] - line[kept.back()]).norm() >= tolerance) kept.push_back(i);
  }
  if (kept.back() != line.size() - 1) kept.push_back(line.size() - 1);
  return kept;
}

Polyline vertex_simplify(const Polyline& line, double tolerance) {
  Polyline out;
  for (const std::size_t i : vertex_simplify_indices(line, tolerance)) out.push_back(line[i]);
  return out;
}

}  // namespace cogmap::mapper
