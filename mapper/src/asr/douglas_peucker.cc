// Douglas-Peucker edge simplification, thesis Fig. A.5 and §2.4.4 (η).

#include <utility>
#include <vector>

#include "cogmap/mapper/asr/stages.h"

namespace cogmap::mapper {

// Fig. A.5: the farthest vertex from the finite segment L_j L_k is marked and both halves
// recurse while it lies farther than η. An explicit stack replaces the recursion so a long
// polyline cannot exhaust the call stack. Distances (not squared, unlike the figure's d_v2) are
// compared with η so η keeps the unit of the line.
std::vector<std::size_t> douglas_peucker_indices(const Polyline& line, double tolerance) {
  std::vector<std::size_t> kept;
  if (line.empty()) return kept;
  std::vector<bool> mark(line.size(), false);
  mark.front() = mark.back() = true;
  std::vector<std::pair<std::size_t, std::size_t>> stack;
  if (line.size() > 2) stack.push_back({0, line.size() - 1});
  while (!stack.empty()) {
    const auto [j, k] = stack.back();
    stack.pop_back();
    const Segment s{line[j], line[k]};
    double max_distance = 0.0;
    std::size_t max_i = j;
    for (std::size_t i = j + 1; i < k; ++i) {
      const double d = distance_to_segment_m(line[i], s);
      if (d > max_distance) {
        max_distance = d;
        max_i = i;
      }
    }
    if (max_distance > tolerance) {
      mark[max_i] = true;
      if (max_i - j > 1) stack.push_back({j, max_i});
      if (k - max_i > 1) stack.push_back({max_i, k});
    }
  }
  for (std::size_t i = 0; i < line.size(); ++i) {
    if (mark[i]) kept.push_back(i);
  }
  return kept;
}

Polyline douglas_peucker(const Polyline& line, double tolerance) {
  Polyline out;
  for (const std::size_t i : douglas_peucker_indices(line, tolerance)) out.push_back(line[i]);
  return out;
}

}  // namespace cogmap::mapper
