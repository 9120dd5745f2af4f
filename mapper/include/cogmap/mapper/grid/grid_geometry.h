#pragma once
/// World <-> cell conversion for square-celled grids. Cell (0, 0) covers
/// [origin_x_m, origin_x_m + cell_size_m) x [origin_y_m, origin_y_m + cell_size_m);
/// x grows with the column index, y with the row index (docs/grids.md has a picture).

#include <cmath>
#include <cstdint>

#include "cogmap/mapper/seam/geometry.h"

namespace cogmap::mapper {

struct CellIndex {
  int x = 0;  ///< column
  int y = 0;  ///< row
  bool operator==(const CellIndex&) const = default;
};

class GridGeometry {
 public:
  GridGeometry() = default;
  /// `cell_scale_mm` is ℘ (thesis Table 4.1): millimetres per cell side.
  GridGeometry(double origin_x_m, double origin_y_m, double cell_scale_mm, int width, int height)
      : origin_x_m_(origin_x_m),
        origin_y_m_(origin_y_m),
        cell_size_m_(cell_scale_mm / 1000.0),
        width_(width),
        height_(height) {}

  double origin_x_m() const { return origin_x_m_; }
  double origin_y_m() const { return origin_y_m_; }
  double cell_size_m() const { return cell_size_m_; }
  double cell_scale_mm() const { return cell_size_m_ * 1000.0; }
  int width() const { return width_; }
  int height() const { return height_; }
  std::size_t cell_count() const { return static_cast<std::size_t>(width_) * height_; }

  /// The cell containing world point p (may lie outside the grid; see contains()).
  CellIndex cell_of(const Point2& p) const {
    return {static_cast<int>(std::floor((p.x() - origin_x_m_) / cell_size_m_)),
            static_cast<int>(std::floor((p.y() - origin_y_m_) / cell_size_m_))};
  }
  /// World position of a cell's centre.
  Point2 center_of(CellIndex c) const {
    return {origin_x_m_ + (c.x + 0.5) * cell_size_m_, origin_y_m_ + (c.y + 0.5) * cell_size_m_};
  }
  bool contains(CellIndex c) const { return c.x >= 0 && c.y >= 0 && c.x < width_ && c.y < height_; }
  std::size_t linear(CellIndex c) const { return static_cast<std::size_t>(c.y) * width_ + c.x; }

 private:
  double origin_x_m_ = 0.0;
  double origin_y_m_ = 0.0;
  double cell_size_m_ = 0.1;
  int width_ = 0;
  int height_ = 0;
};

}  // namespace cogmap::mapper
