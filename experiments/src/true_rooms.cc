#include "cogmap/experiments/true_rooms.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include "cogmap/mapper/seam/geometry.h"

namespace cogmap::experiments {
namespace {

using mapper::Point2;

constexpr double kInf = std::numeric_limits<double>::infinity();

/// A raster of square cells; cell (i, j) spans [x0 + i·res, x0 + (i+1)·res) in x, likewise y.
struct Raster {
  double x0 = 0.0, y0 = 0.0, res = 0.0;
  std::size_t nx = 0, ny = 0;
  std::size_t cells() const { return nx * ny; }
};

/// Indices of the cells whose centres lie in [lo, hi] along an axis starting at `origin`,
/// clamped to [0, n); empty when first > last.
std::pair<std::ptrdiff_t, std::ptrdiff_t> centre_range(double lo, double hi, double origin,
                                                       double res, std::size_t n) {
  const double first = std::max(0.0, std::ceil((lo - origin) / res - 0.5));
  const double last = std::min(static_cast<double>(n) - 1.0, std::floor((hi - origin) / res - 0.5));
  if (!(first <= last)) return {0, -1};
  return {static_cast<std::ptrdiff_t>(first), static_cast<std::ptrdiff_t>(last)};
}

/// Marks the cells whose centre lies within `h` of `s`. Row by row, only the cells near the
/// part of the segment within h of the row are tested, so the cost follows the wall's area.
void mark_segment(const Raster& r, const mapper::Segment& s, double h,
                  std::vector<std::uint8_t>& wall) {
  const double dy = s.b.y() - s.a.y();
  const auto [j0, j1] = centre_range(std::min(s.a.y(), s.b.y()) - h, std::max(s.a.y(), s.b.y()) + h,
                                     r.y0, r.res, r.ny);
  for (std::ptrdiff_t j = j0; j <= j1; ++j) {
    const double y = r.y0 + (static_cast<double>(j) + 0.5) * r.res;
    double xa = std::min(s.a.x(), s.b.x()), xb = std::max(s.a.x(), s.b.x());
    if (std::abs(dy) > 0.0) {  // the part of the segment with |y' − y| <= h
      const double t0 = std::clamp((y - h - s.a.y()) / dy, 0.0, 1.0);
      const double t1 = std::clamp((y + h - s.a.y()) / dy, 0.0, 1.0);
      const double x0 = s.a.x() + t0 * (s.b.x() - s.a.x());
      const double x1 = s.a.x() + t1 * (s.b.x() - s.a.x());
      xa = std::min(x0, x1);
      xb = std::max(x0, x1);
    }
    const auto [i0, i1] = centre_range(xa - h, xb + h, r.x0, r.res, r.nx);
    for (std::ptrdiff_t i = i0; i <= i1; ++i) {
      const Point2 c(r.x0 + (static_cast<double>(i) + 0.5) * r.res, y);
      if (mapper::distance_to_segment_m(c, mapper::Segment{s.a, s.b}) <= h)
        wall[static_cast<std::size_t>(j) * r.nx + i] = 1;
    }
  }
}

/// Exact squared Euclidean distance (cells²) from every cell centre to the nearest wall cell
/// centre, infinity with no wall: a column pass, then the lower envelope of parabolas along
/// every row (Felzenszwalb & Huttenlocher 2012).
std::vector<float> squared_distance_cells(const Raster& r, const std::vector<std::uint8_t>& wall) {
  std::vector<float> d2(r.cells(), std::numeric_limits<float>::infinity());
  for (std::size_t i = 0; i < r.nx; ++i) {
    double g = kInf;
    for (std::size_t j = 0; j < r.ny; ++j) {
      g = wall[j * r.nx + i] ? 0.0 : g + 1.0;
      d2[j * r.nx + i] = static_cast<float>(g);
    }
    g = kInf;
    for (std::size_t j = r.ny; j-- > 0;) {
      g = wall[j * r.nx + i] ? 0.0 : g + 1.0;
      const double best = std::min<double>(g, d2[j * r.nx + i]);
      d2[j * r.nx + i] = static_cast<float>(best * best);
    }
  }
  std::vector<double> f(r.nx), z(r.nx + 1);
  std::vector<std::size_t> v(r.nx);
  for (std::size_t j = 0; j < r.ny; ++j) {
    float* row = d2.data() + j * r.nx;
    std::ptrdiff_t k = -1;  // parabolas of the lower envelope: v[0..k], boundaries z
    for (std::size_t q = 0; q < r.nx; ++q) {
      f[q] = row[q];
      if (!std::isfinite(f[q])) continue;
      const double fq = f[q] + static_cast<double>(q) * static_cast<double>(q);
      double s = -kInf;
      while (k >= 0) {
        const double p = static_cast<double>(v[k]);
        s = (fq - (f[v[k]] + p * p)) / (2.0 * (static_cast<double>(q) - p));
        if (s > z[k]) break;
        --k;
      }
      ++k;
      v[k] = q;
      z[k] = k == 0 ? -kInf : s;
      z[k + 1] = kInf;
    }
    if (k < 0) continue;  // no wall in this row's columns: stays infinite
    std::ptrdiff_t e = 0;
    for (std::size_t q = 0; q < r.nx; ++q) {
      while (z[e + 1] < static_cast<double>(q)) ++e;
      const double dq = static_cast<double>(q) - static_cast<double>(v[e]);
      row[q] = static_cast<float>(dq * dq + f[v[e]]);
    }
  }
  return d2;
}

/// The raster over the finite surfaces' bounding box plus the margin, coarsened until it has
/// at most max_cells cells; empty (nx = 0) when there is nothing finite to rasterise.
Raster make_raster(std::span<const mapper::Segment> surfaces, const TrueRoomsOptions& o) {
  double min_x = kInf, min_y = kInf, max_x = -kInf, max_y = -kInf;
  for (const mapper::Segment& s : surfaces) {
    if (!s.a.allFinite() || !s.b.allFinite()) continue;
    min_x = std::min({min_x, s.a.x(), s.b.x()});
    min_y = std::min({min_y, s.a.y(), s.b.y()});
    max_x = std::max({max_x, s.a.x(), s.b.x()});
    max_y = std::max({max_y, s.a.y(), s.b.y()});
  }
  Raster r;
  double res = o.resolution_m;
  if (!(min_x <= max_x) || !(res > 0.0) || !std::isfinite(res)) return r;
  const double max_cells = static_cast<double>(std::max<std::size_t>(o.max_cells, 1));
  for (int attempt = 0; attempt < 64; ++attempt) {
    // Wider than the erosion, so the outside stays connected around the building.
    const double margin = std::max(o.margin_m, o.door_close_radius_m + 2.0 * res);
    const double nx = std::max(1.0, std::ceil((max_x - min_x + 2.0 * margin) / res));
    const double ny = std::max(1.0, std::ceil((max_y - min_y + 2.0 * margin) / res));
    if (!std::isfinite(nx * ny)) return r;
    if (nx * ny <= max_cells) {
      r.x0 = min_x - margin;
      r.y0 = min_y - margin;
      r.res = res;
      r.nx = static_cast<std::size_t>(nx);
      r.ny = static_cast<std::size_t>(ny);
      return r;
    }
    res *= std::sqrt(nx * ny / max_cells) * 1.01;
  }
  return r;
}

/// The cell of the run's start: the first row's finite true position. A position off the raster
/// is outside the building, so it is clamped to the nearest border cell (the margin keeps the
/// border free and connected to the outside). A start on a wall cell (a coarsened raster's walls
/// are thicker than the true ones) moves to the nearest free cell within a few cells. Empty when
/// no row has a finite true position, or no free cell is near it.
std::optional<std::size_t> start_cell(const Raster& r, TrajectoryView rows,
                                      const std::vector<float>& d2, double h) {
  std::optional<TrajectoryRow> first;  // a copy: a row is valid only while it is being read
  for (const TrajectoryRow& row : rows) {
    if (row.truth && std::isfinite(row.truth->x_m) && std::isfinite(row.truth->y_m)) {
      first = row;
      break;
    }
  }
  if (!first) return std::nullopt;
  const auto clamp_index = [](double v, std::size_t n) {
    return static_cast<std::ptrdiff_t>(
        std::clamp(std::floor(v), 0.0, static_cast<double>(n) - 1.0));
  };
  const std::ptrdiff_t si = clamp_index((first->truth->x_m - r.x0) / r.res, r.nx);
  const std::ptrdiff_t sj = clamp_index((first->truth->y_m - r.y0) / r.res, r.ny);
  const auto nx = static_cast<std::ptrdiff_t>(r.nx), ny = static_cast<std::ptrdiff_t>(r.ny);
  const auto reach = static_cast<std::ptrdiff_t>(std::ceil(2.0 * (h + r.res) / r.res));
  std::optional<std::size_t> best;
  std::ptrdiff_t best_d2 = std::numeric_limits<std::ptrdiff_t>::max();
  for (std::ptrdiff_t j = std::max<std::ptrdiff_t>(0, sj - reach);
       j <= std::min(ny - 1, sj + reach); ++j) {
    for (std::ptrdiff_t i = std::max<std::ptrdiff_t>(0, si - reach);
         i <= std::min(nx - 1, si + reach); ++i) {
      const std::ptrdiff_t dd = (i - si) * (i - si) + (j - sj) * (j - sj);
      const auto c = static_cast<std::size_t>(j * nx + i);
      if (d2[c] > 0.5f && dd < best_d2) {  // squared cells: 0 on wall cells, else >= 1
        best_d2 = dd;
        best = c;
      }
    }
  }
  return best;
}

/// Calls `visit` with each 4-connected neighbour of cell `c` inside the raster.
template <typename Visit>
void for_each_neighbour4(const Raster& r, std::size_t c, Visit&& visit) {
  const std::size_t i = c % r.nx, j = c / r.nx;
  if (i > 0) visit(c - 1);
  if (i + 1 < r.nx) visit(c + 1);
  if (j > 0) visit(c - r.nx);
  if (j + 1 < r.ny) visit(c + r.nx);
}

bool on_border(const Raster& r, std::size_t c) {
  const std::size_t i = c % r.nx, j = c / r.nx;
  return i == 0 || j == 0 || i + 1 == r.nx || j + 1 == r.ny;
}

}  // namespace

TrueRooms count_true_rooms(std::span<const mapper::Segment> surfaces, TrajectoryView rows,
                           const TrueRoomsOptions& options) {
  const Raster r = make_raster(surfaces, options);
  if (r.cells() == 0) return {};
  if (r.res > options.max_measurable_resolution_m) return {0, 0, false};

  // 1. Walls. Half a cell diagonal at least, so a wall never leaks between diagonal cells.
  const double h = std::max(options.wall_half_thickness_m, 0.75 * r.res);
  std::vector<std::uint8_t> wall(r.cells(), 0);
  for (const mapper::Segment& s : surfaces) {
    if (s.a.allFinite() && s.b.allFinite()) mark_segment(r, s, h, wall);
  }

  // 2. Room core: farther than door_close_radius_m from every wall cell.
  std::vector<float> d2 = squared_distance_cells(r, wall);
  std::vector<std::uint8_t>().swap(wall);  // memory: one raster at a time
  const double radius_cells = options.door_close_radius_m / r.res;
  const double core_d2 = radius_cells * radius_cells;

  // 3. Reachable: the 4-connected free (not wall) cells around the run's start, on the
  // un-eroded raster (doors are open here), marked kReached in `label`. Without a start (no
  // finite true position in the rows) every component counts as reachable.
  constexpr std::int32_t kUnlabelled = -1, kReached = -2;
  std::vector<std::int32_t> label(r.cells(), kUnlabelled);
  std::vector<std::size_t> stack;
  const std::optional<std::size_t> start_at = start_cell(r, rows, d2, h);
  if (start_at) {
    label[*start_at] = kReached;
    stack.assign(1, *start_at);
    while (!stack.empty()) {
      const std::size_t c = stack.back();
      stack.pop_back();
      const auto visit = [&](std::size_t n) {
        if (d2[n] > 0.5f && label[n] == kUnlabelled) {  // not wall: d2 >= 1 off wall cells
          label[n] = kReached;
          stack.push_back(n);
        }
      };
      for_each_neighbour4(r, c, visit);
    }
  }

  // 4. 4-connected components of the core; rooms are those off the border, large enough and
  // reachable from the start (some cell of theirs reached in 3).
  std::vector<std::int32_t> room_of;  // per component: room index, or -1
  std::size_t total = 0;
  const auto is_core = [&](std::size_t c) {
    return options.door_close_radius_m >= 0.0 && d2[c] > core_d2 && label[c] < 0;
  };
  for (std::size_t start = 0; start < r.cells(); ++start) {
    if (!is_core(start)) continue;
    const auto id = static_cast<std::int32_t>(room_of.size());
    std::size_t count = 0;
    bool border = false;
    bool reached = !start_at || label[start] == kReached;
    label[start] = id;
    stack.assign(1, start);
    while (!stack.empty()) {
      const std::size_t c = stack.back();
      stack.pop_back();
      ++count;
      border = border || on_border(r, c);
      const auto visit = [&](std::size_t n) {
        if (is_core(n)) {
          reached = reached || label[n] == kReached;
          label[n] = id;
          stack.push_back(n);
        }
      };
      for_each_neighbour4(r, c, visit);
    }
    const double area_m2 = static_cast<double>(count) * r.res * r.res;
    const bool room = !border && reached && area_m2 >= options.min_room_area_m2;
    room_of.push_back(room ? static_cast<std::int32_t>(total++) : -1);
  }

  // 5. Visited: some true position lies in the room's core.
  std::vector<bool> seen(total, false);
  std::size_t visited = 0;
  for (const TrajectoryRow& row : rows) {
    if (!row.truth) continue;
    const double fi = std::floor((row.truth->x_m - r.x0) / r.res);
    const double fj = std::floor((row.truth->y_m - r.y0) / r.res);
    if (!(fi >= 0.0 && fj >= 0.0 && fi < static_cast<double>(r.nx) &&
          fj < static_cast<double>(r.ny))) {
      continue;  // outside the raster, or not finite
    }
    const std::int32_t comp =
        label[static_cast<std::size_t>(fj) * r.nx + static_cast<std::size_t>(fi)];
    if (comp < 0 || room_of[comp] < 0 || seen[room_of[comp]]) continue;
    seen[room_of[comp]] = true;
    ++visited;
  }
  return {total, visited};
}

}  // namespace cogmap::experiments
