// Point extraction, thesis §3.1.6, Fig. 3.9: follow-and-remove nearest-neighbour chaining.
//
// Reading of Fig. 3.9: the raster scan (rows outer, columns inner) only finds the first cell;
// from then on every step appends the current cell, removes it from H and jumps to the next
// closest remaining occupied cell. A jump longer than γ ends the current polyline and the cell
// jumped to starts the next one, until H holds no occupied cell.
//
// The nearest remaining cell is found by a search in growing square rings around the current
// cell (a ring at Chebyshev radius r holds no cell nearer than r, so the search stops as soon as
// r exceeds the best distance found); only when the rings up to kRingLimit are empty does a
// linear scan over the remaining cells run. Ties in distance go to the cell that keeps the
// direction of the last step best, so a wall is followed rather than crossed.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "cogmap/mapper/asr/stages.h"

namespace cogmap::mapper {
namespace {

struct Candidate {
  CellIndex cell{0, 0};
  long distance2 = std::numeric_limits<long>::max();
  long alignment = std::numeric_limits<long>::min();  // dot product with the last step
  bool found() const { return distance2 != std::numeric_limits<long>::max(); }
};

class RemainingCells {
 public:
  RemainingCells(const HistogramGrid& grid, double occupied_threshold)
      : width_(grid.width()), height_(grid.height()) {
    occupied_.assign(static_cast<std::size_t>(width_) * height_, 0);
    for (int y = 0; y < height_; ++y) {
      for (int x = 0; x < width_; ++x) {
        if (static_cast<double>(grid.get({x, y})) > occupied_threshold) {
          occupied_[index({x, y})] = 1;
          list_.push_back({x, y});
        }
      }
    }
    count_ = list_.size();
  }

  std::size_t count() const { return count_; }
  /// The first remaining cell in raster order (rows outer, as Fig. 3.9's loops).
  CellIndex first() const {
    for (const CellIndex& c : list_) {
      if (occupied_[index(c)]) return c;
    }
    return {0, 0};
  }
  void remove(CellIndex c) {
    occupied_[index(c)] = 0;
    --count_;
  }

  /// The remaining cell nearest to `from` within kRingLimit cells along x and y, else the
  /// nearest anywhere (docs/algorithms.md, Stage 2: a corner of the window wins over a nearer
  /// cell just beyond it); ties broken by alignment with `step`.
  Candidate nearest(CellIndex from, CellIndex step) const {
    Candidate best;
    for (int r = 1; r <= kRingLimit; ++r) {
      if (best.found() && static_cast<long>(r) * r > best.distance2) return best;
      visit_ring(from, r, step, best);
    }
    if (best.found()) return best;
    for (const CellIndex& c : list_) {
      if (occupied_[index(c)]) consider(from, c, step, best);
    }
    return best;
  }

 private:
  static constexpr int kRingLimit = 16;  // beyond this a linear scan is cheaper than rings

  std::size_t index(CellIndex c) const { return static_cast<std::size_t>(c.y) * width_ + c.x; }
  bool is_occupied(int x, int y) const {
    return x >= 0 && y >= 0 && x < width_ && y < height_ && occupied_[index({x, y})];
  }
  static void consider(CellIndex from, CellIndex c, CellIndex step, Candidate& best) {
    const long dx = c.x - from.x, dy = c.y - from.y;
    const long d2 = dx * dx + dy * dy;
    const long alignment = dx * step.x + dy * step.y;
    if (d2 < best.distance2 || (d2 == best.distance2 && alignment > best.alignment)) {
      best = {c, d2, alignment};
    }
  }
  void visit_ring(CellIndex from, int r, CellIndex step, Candidate& best) const {
    for (int dx = -r; dx <= r; ++dx) {
      for (const int dy : {-r, r}) {
        if (is_occupied(from.x + dx, from.y + dy)) {
          consider(from, {from.x + dx, from.y + dy}, step, best);
        }
      }
    }
    for (int dy = -r + 1; dy <= r - 1; ++dy) {
      for (const int dx : {-r, r}) {
        if (is_occupied(from.x + dx, from.y + dy)) {
          consider(from, {from.x + dx, from.y + dy}, step, best);
        }
      }
    }
  }

  int width_ = 0;
  int height_ = 0;
  std::vector<std::uint8_t> occupied_;
  std::vector<CellIndex> list_;  // every initially occupied cell, raster order
  std::size_t count_ = 0;
};

}  // namespace

std::vector<std::vector<CellIndex>> extract_points(const HistogramGrid& grid,
                                                   double occupied_threshold, double gap_cells) {
  std::vector<std::vector<CellIndex>> lines;
  RemainingCells remaining(grid, occupied_threshold);
  if (remaining.count() == 0) return lines;
  const double gap2 = gap_cells * gap_cells;

  std::vector<CellIndex> current;
  CellIndex cell = remaining.first();
  CellIndex step{0, 0};
  while (true) {
    current.push_back(cell);
    remaining.remove(cell);
    if (remaining.count() == 0) break;
    const Candidate next = remaining.nearest(cell, step);
    if (static_cast<double>(next.distance2) > gap2) {
      lines.push_back(std::move(current));
      current.clear();
      step = {0, 0};
    } else {
      step = {next.cell.x - cell.x, next.cell.y - cell.y};
    }
    cell = next.cell;
  }
  lines.push_back(std::move(current));
  return lines;
}

}  // namespace cogmap::mapper
