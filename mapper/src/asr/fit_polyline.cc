// The fitting stage, thesis §3.1.8 and Fig. 3.11: the Douglas-Peucker vertices delimit which
// extracted points each least-squares line is fitted to; the fitted lines replace the DP
// segments.
//
// Readings (docs/algorithms.md): "reject the fitted line" keeps the DP segment
// itself in the wall (so coverage is not lost) and reports it in `rejected`; a fitted segment's
// ends are where it meets its fitted neighbours (their intersection, if that lies near the
// shared DP vertex) or else the projections of the DP vertices onto the line.

#include <cmath>
#include <optional>
#include <vector>

#include "cogmap/mapper/asr/stages.h"

namespace cogmap::mapper {
namespace {

std::optional<Point2> intersect(const LineFit& a, const LineFit& b) {
  const double cross = a.direction.x() * b.direction.y() - a.direction.y() * b.direction.x();
  if (std::abs(cross) < 1e-9) return std::nullopt;  // parallel: no meaningful corner
  const Point2 d = b.point - a.point;
  const double t = (d.x() * b.direction.y() - d.y() * b.direction.x()) / cross;
  return a.point + t * a.direction;
}

void append(Polyline& line, const Point2& p) {
  if (line.empty() || (line.back() - p).norm() > 1e-12) line.push_back(p);
}

}  // namespace

PolylineFit fit_polyline(const Polyline& points, std::span<const std::size_t> vertex_indices,
                         double min_abs_correlation, double join_max_distance) {
  PolylineFit out;
  if (vertex_indices.size() < 2) {
    for (const std::size_t i : vertex_indices) append(out.wall, points[i]);
    return out;
  }
  const std::size_t segments = vertex_indices.size() - 1;
  std::vector<std::optional<LineFit>> fits(segments);
  for (std::size_t k = 0; k < segments; ++k) {
    const std::size_t i0 = vertex_indices[k], i1 = vertex_indices[k + 1];
    const LineFit fit = fit_line(std::span<const Point2>(points).subspan(i0, i1 - i0 + 1));
    if (fit.valid && fit.correlation >= min_abs_correlation) {
      fits[k] = fit;
    } else {
      out.rejected.push_back({points[i0], points[i1]});
    }
  }

  // Vertex k joins segment k-1 (before) and segment k (after).
  for (std::size_t k = 0; k <= segments; ++k) {
    const Point2& vertex = points[vertex_indices[k]];
    const std::optional<LineFit>* before = k > 0 ? &fits[k - 1] : nullptr;
    const std::optional<LineFit>* after = k < segments ? &fits[k] : nullptr;
    const bool fitted_before = before != nullptr && before->has_value();
    const bool fitted_after = after != nullptr && after->has_value();
    if (fitted_before && fitted_after) {
      const std::optional<Point2> corner = intersect(**before, **after);
      if (corner && (*corner - vertex).norm() <= join_max_distance) {
        append(out.wall, *corner);
      } else {
        append(out.wall, (*before)->project(vertex));
        append(out.wall, (*after)->project(vertex));
      }
      continue;
    }
    // A rejected (or absent) neighbour keeps the DP vertex itself as its end, so the wall stays
    // connected: fitted end first, then the DP vertex, then the next fitted start.
    if (fitted_before) append(out.wall, (*before)->project(vertex));
    if (before != nullptr && !fitted_before) append(out.wall, vertex);
    if (after != nullptr && !fitted_after) append(out.wall, vertex);
    if (fitted_after) append(out.wall, (*after)->project(vertex));
  }
  return out;
}

}  // namespace cogmap::mapper
