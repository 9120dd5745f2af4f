// Corner refinement between Douglas-Peucker and the fit (not in the thesis; see
// docs/algorithms.md). VertexSimplify keeps only every τ-th cell, so the cell
// that forms a room corner is often dropped and DP marks one or two chamfer vertices up to τ
// away from it instead. The fit then spans a corner with a two-cell DP segment, finds |ρ| far
// below 0.9 and rejects it. Moving each DP vertex to the extracted point that DP itself would
// pick there (the one farthest from its neighbours' chord, among the cells VertexSimplify
// dropped around it) restores the corner; a vertex left within η of that chord is redundant
// and goes, exactly as DP would have decided on the unsimplified points.

#include <algorithm>
#include <vector>

#include "cogmap/mapper/asr/stages.h"

namespace cogmap::mapper {

std::vector<std::size_t> refine_vertices(const Polyline& points,
                                         std::span<const std::size_t> simplified_indices,
                                         std::span<const std::size_t> dp_positions,
                                         double tolerance) {
  std::vector<std::size_t> out;
  if (dp_positions.empty()) return out;
  out.push_back(simplified_indices[dp_positions.front()]);
  for (std::size_t k = 1; k + 1 < dp_positions.size(); ++k) {
    const std::size_t position = dp_positions[k];
    const std::size_t before = out.back();
    const std::size_t after = simplified_indices[dp_positions[k + 1]];
    // The cells VertexSimplify dropped on either side of this vertex, inside the neighbours.
    const std::size_t lo = std::max(simplified_indices[position - 1], before) + 1;
    const std::size_t hi = std::min(simplified_indices[position + 1], after) - 1;
    const Segment chord{points[before], points[after]};
    std::size_t best = simplified_indices[position];
    double best_distance = distance_to_segment_m(points[best], chord);
    for (std::size_t i = lo; i <= hi; ++i) {
      const double d = distance_to_segment_m(points[i], chord);
      if (d > best_distance) {
        best_distance = d;
        best = i;
      }
    }
    if (best_distance > tolerance) out.push_back(best);
  }
  if (dp_positions.size() > 1) {
    const std::size_t last = simplified_indices[dp_positions.back()];
    if (last != out.back()) out.push_back(last);
  }
  return out;
}

}  // namespace cogmap::mapper
